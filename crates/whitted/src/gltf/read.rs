//! A glTF document made into a `Rig`: the file's bytes parsed by the `gltf` crate's
//! document model (`Gltf::from_slice`, which validates every index), the extensions it
//! requires checked, its buffers loaded (`source`), then its nodes, meshes (`prims`),
//! materials, cameras, lights, skins and animations read with every count bounded first.

use super::accessor::Buffers;
use super::error::{at, GltfError};
use super::rig::{CameraDef, LightDef, LightType, Local, Node, Projection, Rig, Skin};
use super::source::{self, Named, Origin};
use glam::{DMat4, DQuat, DVec3};
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
    super::prims::read(doc, &buffers, &mut rig)?;
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
