//! A glTF document made into a `Rig`: the file's bytes parsed by the `gltf` crate's
//! document model (`Gltf::from_slice`, which validates every index), the extensions it
//! requires checked, its buffers loaded (`source`), then its nodes, meshes, materials,
//! cameras, lights, skins and animations read with every count bounded first.

use super::accessor::Buffers;
use super::error::{at, GltfError};
use super::rig::{CameraDef, LightDef, LightType, Local, Node, Prim, Projection, Rig, Skin};
use super::source::{self, Named, Origin};
use crate::limits::{MAX_MESH_TRIANGLES, MAX_MESH_VERTICES};
use glam::{DMat4, DQuat, DVec3};
use gltf::mesh::{Mode, Semantic};
use std::path::Path;

/// The extensions the tracer implements (an `extensionsRequired` entry outside this list
/// is refused with its name).
pub const IMPLEMENTED: [&str; 5] = [
    "KHR_lights_punctual",
    "KHR_materials_emissive_strength",
    "KHR_materials_transmission",
    "KHR_materials_ior",
    "KHR_materials_volume",
];

/// Reads the glTF file whose bytes are `bytes`, named `file`, in folder `dir`.
pub fn read(bytes: &[u8], file: &str, dir: &Path) -> Result<Rig, GltfError> {
    let gltf = gltf::Gltf::from_slice(bytes).map_err(|e| document(file, e))?;
    let doc = &gltf.document;
    for ext in doc.extensions_required() {
        if !IMPLEMENTED.contains(&ext) {
            return Err(at(
                file,
                "extensionsRequired",
                format!("the file requires `{ext}`, which this tracer does not implement"),
            ));
        }
    }
    let mut rig = Rig {
        file: file.to_string(),
        source: crate::input::digest(bytes),
        ..Rig::default()
    };
    for ext in doc.extensions_used() {
        if !IMPLEMENTED.contains(&ext) {
            rig.warn(format!("{file}: the extension `{ext}` is not used"));
        }
    }
    let origin = Origin { file, dir };
    let mut named = Named::new();
    let data = source::buffers(doc, gltf.blob.as_deref(), &origin, &mut named)?;
    let buffers = Buffers { file, data: &data };
    super::material::read(doc, &buffers, &origin, &mut named, &mut rig)?;
    // The digest its meshes carry: the file's and every file it named.
    let mut all = rig.source.to_vec();
    named.iter().for_each(|(_, d)| all.extend_from_slice(d));
    rig.source = crate::input::digest(&all);
    rig.named = named;
    read_nodes(doc, &mut rig)?;
    read_meshes(doc, &buffers, &mut rig)?;
    read_skins(doc, &buffers, &mut rig)?;
    read_cameras_and_lights(doc, &mut rig);
    rig.clips = super::animations::read(doc, &buffers, &rig)?;
    Ok(rig)
}

/// The crate's refusal, with the line and column of a JSON syntax error.
fn document(file: &str, e: gltf::Error) -> GltfError {
    let (at, message) = match &e {
        gltf::Error::Deserialize(j) => (format!(":{}:{}", j.line(), j.column()), j.to_string()),
        gltf::Error::Validation(list) => (
            String::new(),
            list.iter()
                .take(3)
                .map(|(path, err)| format!("{}: {err}", path.as_str()))
                .collect::<Vec<_>>()
                .join("; "),
        ),
        other => (String::new(), other.to_string()),
    };
    GltfError::Document {
        file: file.to_string(),
        at,
        message,
    }
}

fn v3(a: [f32; 3]) -> DVec3 {
    DVec3::new(f64::from(a[0]), f64::from(a[1]), f64::from(a[2]))
}

/// The nodes, the scene's roots, and a check that the nodes form a forest.
fn read_nodes(doc: &gltf::Document, rig: &mut Rig) -> Result<(), GltfError> {
    let mut parent: Vec<Option<usize>> = vec![None; doc.nodes().len()];
    for n in doc.nodes() {
        let local = match n.transform() {
            gltf::scene::Transform::Matrix { matrix } => {
                Local::Matrix(DMat4::from_cols_array_2d(&matrix.map(|c| c.map(f64::from))))
            }
            gltf::scene::Transform::Decomposed {
                translation,
                rotation,
                scale,
            } => {
                let [x, y, z, w] = rotation.map(f64::from);
                Local::Trs {
                    t: v3(translation),
                    r: DQuat::from_xyzw(x, y, z, w).normalize(),
                    s: v3(scale),
                }
            }
        };
        let children: Vec<usize> = n.children().map(|c| c.index()).collect();
        for &c in &children {
            if parent[c].is_some() || c == n.index() {
                return Err(at(
                    &rig.file,
                    format!("nodes[{}].children", n.index()),
                    format!("node {c} has two parents, or is its own"),
                ));
            }
            parent[c] = Some(n.index());
        }
        rig.nodes.push(Node {
            name: n.name().map(str::to_string),
            children,
            local,
            mesh: n.mesh().map(|m| m.index()),
            camera: n.camera().map(|c| c.index()),
            light: n.light().map(|l| l.index()),
            skin: n.skin().map(|s| s.index()),
            weights: n
                .weights()
                .map(|w| w.iter().map(|&x| f64::from(x)).collect()),
        });
    }
    let scene = doc.default_scene().or_else(|| doc.scenes().next());
    rig.roots = scene.map_or_else(Vec::new, |s| s.nodes().map(|n| n.index()).collect());
    // A cycle shows as a node reached twice, or a root with a parent.
    if let Some(&r) = rig.roots.iter().find(|&&r| parent[r].is_some()) {
        return Err(at(
            &rig.file,
            "scenes",
            format!(
                "node {r} is a root of the scene and a child of node {}",
                parent[r].unwrap_or(0)
            ),
        ));
    }
    Ok(())
}

/// Every mesh's primitives, within the vertex and triangle budgets.
fn read_meshes(doc: &gltf::Document, b: &Buffers, rig: &mut Rig) -> Result<(), GltfError> {
    let file = rig.file.clone();
    let (mut vertices, mut triangles) = (0u64, 0u64);
    let default_look = rig.looks.len() - 1;
    for mesh in doc.meshes() {
        let mut prims = Vec::new();
        for p in mesh.primitives() {
            let path = format!("meshes[{}].primitives[{}]", mesh.index(), p.index());
            if !matches!(
                p.mode(),
                Mode::Triangles | Mode::TriangleStrip | Mode::TriangleFan
            ) {
                rig.warn(format!(
                    "{}: {:?} primitives are not drawn (triangles only)",
                    rig.file,
                    p.mode()
                ));
                prims.push(Prim::default());
                continue;
            }
            let budget = MAX_MESH_VERTICES - vertices;
            let Some(pos) = p.get(&Semantic::Positions) else {
                return Err(at(&rig.file, format!("{path}.attributes"), "no POSITION"));
            };
            let positions: Vec<DVec3> = b
                .floats::<3>(&pos, budget)?
                .into_iter()
                .map(DVec3::from)
                .collect();
            if let Some(k) = positions.iter().position(|p| !p.is_finite()) {
                return Err(at(
                    &rig.file,
                    format!("accessors[{}]", pos.index()),
                    format!("position {k} is not a finite number"),
                ));
            }
            let n = positions.len() as u64;
            vertices += n;
            let same = |what: &str, len: usize| -> Result<(), GltfError> {
                if len as u64 != n {
                    return Err(at(
                        &file,
                        format!("{path}.attributes.{what}"),
                        format!("{len} values for {n} positions"),
                    ));
                }
                Ok(())
            };
            let mut prim = Prim {
                positions,
                look: p.material().index().unwrap_or(default_look),
                ..Prim::default()
            };
            if let Some(a) = p.get(&Semantic::Normals) {
                prim.normals = b.floats::<3>(&a, n)?.into_iter().map(DVec3::from).collect();
                same("NORMAL", prim.normals.len())?;
            }
            if let Some(a) = p.get(&Semantic::TexCoords(0)) {
                prim.uvs = b
                    .floats::<2>(&a, n)?
                    .into_iter()
                    .map(|[u, v]| [u, 1.0 - v])
                    .collect();
                same("TEXCOORD_0", prim.uvs.len())?;
            }
            if let Some(a) = p.get(&Semantic::Colors(0)) {
                prim.colors = match a.dimensions() {
                    gltf::accessor::Dimensions::Vec4 => b
                        .floats::<4>(&a, n)?
                        .into_iter()
                        .map(|[r, g, b, _]| DVec3::new(r, g, b))
                        .collect(),
                    _ => b.floats::<3>(&a, n)?.into_iter().map(DVec3::from).collect(),
                };
                same("COLOR_0", prim.colors.len())?;
            }
            if let Some(a) = p.get(&Semantic::Joints(0)) {
                prim.joints = b.indices::<4>(&a, n, u64::from(u32::MAX))?;
                same("JOINTS_0", prim.joints.len())?;
                prim.max_joint = prim.joints.iter().flatten().copied().max().unwrap_or(0);
                match p.get(&Semantic::Weights(0)) {
                    Some(w) => {
                        prim.weights = b.floats::<4>(&w, n)?;
                        same("WEIGHTS_0", prim.weights.len())?;
                    }
                    None => rig.warn(format!(
                        "{}: {path} has JOINTS_0 without WEIGHTS_0: drawn unskinned",
                        rig.file
                    )),
                }
            }
            for s in p.attributes().map(|(s, _)| s) {
                let used = matches!(
                    s,
                    Semantic::Positions
                        | Semantic::Normals
                        | Semantic::TexCoords(0)
                        | Semantic::Colors(0)
                        | Semantic::Joints(0)
                        | Semantic::Weights(0)
                );
                if !used {
                    rig.warn(format!(
                        "{}: the attribute {} is not used",
                        rig.file,
                        s.to_string()
                    ));
                }
            }
            for (k, t) in p.morph_targets().enumerate() {
                let mut target = super::rig::Target::default();
                if let Some(a) = t.positions() {
                    target.positions = b.floats::<3>(&a, n)?.into_iter().map(DVec3::from).collect();
                    same(&format!("targets[{k}].POSITION"), target.positions.len())?;
                }
                if let Some(a) = t.normals() {
                    target.normals = b.floats::<3>(&a, n)?.into_iter().map(DVec3::from).collect();
                    same(&format!("targets[{k}].NORMAL"), target.normals.len())?;
                }
                prim.targets.push(target);
            }
            let corners: Vec<u32> = match p.indices() {
                Some(a) => b
                    .indices::<1>(&a, 3 * MAX_MESH_TRIANGLES, n)?
                    .into_iter()
                    .map(|[i]| i)
                    .collect(),
                None => (0..n as u32).collect(),
            };
            prim.triangles = cut(p.mode(), &corners);
            triangles += prim.triangles.len() as u64;
            if triangles > MAX_MESH_TRIANGLES {
                return Err(at(
                    &rig.file,
                    path,
                    format!("the file's triangles pass the limit of {MAX_MESH_TRIANGLES}"),
                ));
            }
            prims.push(prim);
        }
        rig.meshes.push(prims);
        rig.mesh_weights.push(
            mesh.weights()
                .map_or_else(Vec::new, |w| w.iter().map(|&x| f64::from(x)).collect()),
        );
    }
    Ok(())
}

/// The triangles of a primitive's corners in `mode` (glTF 2.0 §3.7.2.1's orders).
pub fn cut(mode: Mode, c: &[u32]) -> Vec<[u32; 3]> {
    match mode {
        Mode::Triangles => c.chunks_exact(3).map(|t| [t[0], t[1], t[2]]).collect(),
        Mode::TriangleStrip => (0..c.len().saturating_sub(2))
            .map(|i| {
                if i % 2 == 0 {
                    [c[i], c[i + 1], c[i + 2]]
                } else {
                    [c[i + 1], c[i], c[i + 2]]
                }
            })
            .collect(),
        Mode::TriangleFan => (1..c.len().saturating_sub(1))
            .map(|i| [c[i], c[i + 1], c[0]])
            .collect(),
        _ => Vec::new(),
    }
}

/// The skins, each joint a node of the file.
fn read_skins(doc: &gltf::Document, b: &Buffers, rig: &mut Rig) -> Result<(), GltfError> {
    for s in doc.skins() {
        let joints: Vec<usize> = s.joints().map(|j| j.index()).collect();
        let inverse_bind = match s.inverse_bind_matrices() {
            Some(a) => {
                let m = b.floats::<16>(&a, joints.len() as u64)?;
                if m.len() != joints.len() {
                    return Err(at(
                        &rig.file,
                        format!("skins[{}].inverseBindMatrices", s.index()),
                        format!("{} matrices for {} joints", m.len(), joints.len()),
                    ));
                }
                m.into_iter().map(|a| DMat4::from_cols_array(&a)).collect()
            }
            None => vec![DMat4::IDENTITY; joints.len()],
        };
        rig.skins.push(Skin {
            joints,
            inverse_bind,
        });
    }
    Ok(())
}

/// The cameras and `KHR_lights_punctual` lights.
fn read_cameras_and_lights(doc: &gltf::Document, rig: &mut Rig) {
    for c in doc.cameras() {
        let projection = match c.projection() {
            gltf::camera::Projection::Perspective(p) => Projection::Perspective {
                yfov: f64::from(p.yfov()),
                aspect: p.aspect_ratio().map(f64::from),
            },
            gltf::camera::Projection::Orthographic(o) => Projection::Orthographic {
                xmag: f64::from(o.xmag()),
                ymag: f64::from(o.ymag()),
            },
        };
        rig.cameras.push(CameraDef {
            name: c.name().map(str::to_string),
            projection,
        });
    }
    for l in doc.lights().into_iter().flatten() {
        let kind = match l.kind() {
            gltf::khr_lights_punctual::Kind::Point => LightType::Point,
            gltf::khr_lights_punctual::Kind::Directional => LightType::Directional,
            gltf::khr_lights_punctual::Kind::Spot {
                inner_cone_angle,
                outer_cone_angle,
            } => LightType::Spot {
                inner: f64::from(inner_cone_angle),
                outer: f64::from(outer_cone_angle),
            },
        };
        rig.lights.push(LightDef {
            name: l.name().map(str::to_string),
            kind,
            color: v3(l.color()),
            intensity: f64::from(l.intensity()),
            range: l.range().map(f64::from),
        });
    }
}
