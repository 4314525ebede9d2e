//! The scene of a glTF file at one pose (SPEC §18): each primitive of each mesh node, in
//! depth-first order of the scene's node tree, one object numbered `gltf N` and named by
//! its node (`Wheel`, `Wheel#2` for the node's second primitive; a node without a name,
//! or with a name used before, is known by its number); its vertices placed by `pose`,
//! flat when the primitive has no normals, its coverage and emissive texture in the
//! mesh's `Extra`; each light node a `KHR_lights_punctual` light; the view from `view`.
//! The scene is shaded in linear light.

use super::error::{at, GltfError};
use super::model::{Model, Options};
use super::pose::{self, Pose, Put};
use super::rig::{LightType, LookExtra, Prim, Rig};
use super::view::{self, View};
use crate::base::Color;
use crate::fileloc::FileLoc;
use crate::fog::Fog;
use crate::lights::punctual::{Shape as LightShape, EXPOSURE};
use crate::mesh::extra::{AlphaMode, Emissive, Extra};
use crate::mesh::{Mesh, Raw, Shading};
use crate::object::Object;
use crate::scene::ext::{ExtItem, ExtLight, ExtObject, Extension, LightKind, Modifiers};
use crate::scene::{ObjectSpec, Scene, ShapeSpec};
use crate::shapes::{MeshRef, Shape, Transform};
use crate::texture::{MapKind, Texture};
use glam::DVec3;
use std::path::Path;
use std::sync::Arc;

impl Model {
    /// The scene at `t` seconds with the clips `playing` and the values `puts` over
    /// them.
    pub fn scene_at(&self, t: f64, playing: &[usize], puts: &[Put]) -> Result<Scene, GltfError> {
        let pose = Pose::at(&self.rig, t, playing, puts);
        let mut scene = scene(&self.rig, &pose, &self.options)?;
        scene.model = Some(Model {
            posed: Some((t, playing.to_vec(), puts.to_vec())),
            ..self.clone()
        });
        Ok(scene)
    }
}

/// The scene of a glTF file as a still shows it: every animation at t = 0.
pub fn load(path: &Path, bytes: &[u8], options: Options) -> Result<Scene, GltfError> {
    let model = Model::read(path, bytes, options)?;
    model.scene_at(0.0, &model.all_clips(), &[])
}

/// The scene of `rig` at `pose`.
pub fn scene(rig: &Arc<Rig>, pose: &Pose, options: &Options) -> Result<Scene, GltfError> {
    let order = rig.order();
    let loc = FileLoc {
        file: rig.file.clone(),
        line: 1,
        column: 1,
    };
    let mut scene = Scene {
        width: view::WIDTH,
        height: view::HEIGHT,
        eye: DVec3::new(0.0, 0.0, 1.0),
        look_at: DVec3::ZERO,
        fog: Fog::None,
        objects: Vec::new(),
        specs: Vec::new(),
        lights: Vec::new(),
        background: Color::ZERO,
        t_min: 0.01,
        lens: Default::default(),
        ext: Extension::default(),
        meshes: Vec::new(),
        pbr: rig.pbr.clone(),
        parallel: None,
        linear: true,
        model: None,
    };
    let mut names: Vec<String> = Vec::new();
    let mut warnings = rig.warnings.clone();
    let (mut lo, mut hi) = (DVec3::INFINITY, DVec3::NEG_INFINITY);
    for &n in &order {
        let node = &rig.nodes[n];
        if let Some(skin) = node.skin {
            if let Some(j) = rig.skins[skin].joints.iter().find(|j| !order.contains(j)) {
                return Err(at(
                    &rig.file,
                    format!("skins[{skin}].joints"),
                    format!("the joint node {j} is not in the scene"),
                ));
            }
        }
        let Some(m) = node.mesh else { continue };
        let base = node.name.clone().filter(|name| !names.contains(name));
        match (&base, &node.name) {
            (Some(b), _) => names.push(b.clone()),
            (None, Some(dup)) => warnings.push(format!(
                "{}: the node name `{dup}` is used twice; node {n}'s primitives are known by their numbers",
                rig.file
            )),
            (None, None) => {}
        }
        for (k, prim) in rig.meshes[m].iter().enumerate() {
            if prim.triangles.is_empty() {
                continue;
            }
            if let Some(skin) = node.skin {
                let joints = rig.skins[skin].joints.len();
                if !prim.joints.is_empty() && prim.max_joint as usize >= joints {
                    return Err(at(
                        &rig.file,
                        format!("meshes[{m}].primitives[{k}].attributes.JOINTS_0"),
                        format!(
                            "joint {} is past the {joints} joints of skins[{skin}]",
                            prim.max_joint
                        ),
                    ));
                }
            }
            let (positions, normals, mirrored) = pose::place(rig, pose, n, prim);
            let mut triangles = prim.triangles.clone();
            if mirrored {
                triangles.iter_mut().for_each(|t| t.swap(1, 2));
            }
            // A zero or non-finite normal (an exporter's degenerate vertex, a skin whose
            // weights sum to zero) would make `Mesh::from_raw` drop every normal and then
            // smooth the faces at 30 degrees, as for an OBJ without normals: a glTF
            // primitive without usable normals is flat instead (SPEC §18), with a warning.
            let unusable = normals.iter().any(|v| !v.is_finite() || *v == DVec3::ZERO);
            if unusable {
                warnings.push(format!(
                    "{}: meshes[{m}].primitives[{k}] has a zero or non-finite normal; it is drawn flat",
                    rig.file
                ));
            }
            let flat = normals.is_empty() || unusable;
            let looks = &rig.extras[prim.look];
            let raw = Raw {
                positions,
                normals,
                uvs: prim.uvs[looks.base_set].clone(),
                colors: prim.colors.clone(),
                triangles,
                ..Raw::default()
            };
            let shading = if flat { Some(Shading::Flat) } else { None };
            let Some(mesh) = Mesh::from_raw(raw, &Transform::IDENTITY, shading) else {
                continue;
            };
            let mut look = rig.looks[prim.look].clone();
            if matches!(&look.texture, Texture::Image(i) if i.map == MapKind::Uv)
                && mesh.uvs.is_empty()
            {
                look.texture = Texture::Uniform(Color::ONE);
            }
            let (mlo, mhi) = mesh.extent();
            (lo, hi) = (lo.min(mlo), hi.max(mhi));
            let id = scene.meshes.len() as u32;
            let handle = MeshRef {
                id,
                lo: mlo,
                hi: mhi,
            };
            let single_sided = !rig.double_sided[prim.look];
            let extra = extra_of(looks, &look.texture, prim, mesh.vertices.len());
            scene.meshes.push(Arc::new(Mesh {
                source: rig.source,
                single_sided,
                extra,
                ..mesh
            }));
            let name = base.as_ref().map(|b| {
                if k == 0 {
                    b.clone()
                } else {
                    format!("{b}#{}", k + 1)
                }
            });
            let item = scene.ext.objects.len() as u32;
            scene.ext.objects.push(ExtItem::Shape(ExtObject {
                shape: ShapeSpec::Gltf {
                    node: n as u32,
                    primitive: k as u32,
                },
                texture: look.texture.clone(),
                material: look.material,
                mods: Modifiers {
                    name,
                    ..Modifiers::default()
                },
                loc: loc.clone(),
            }));
            let shape = Shape::Mesh(handle);
            scene.specs.push(ObjectSpec::Ext {
                item,
                kind: "gltf",
                anchor: 0.5 * (mlo + mhi),
            });
            scene.objects.push(Object {
                shape,
                texture: look.texture,
                material: look.material,
            });
        }
    }
    let picked = view::find(rig, &order, options.camera.as_deref()).map_err(|names| {
        at(
            &rig.file,
            "cameras",
            format!(
                "no camera is named `{}`; the file's cameras: {}",
                options.camera.as_deref().unwrap_or(""),
                if names.is_empty() {
                    "none".to_string()
                } else {
                    names.join(", ")
                }
            ),
        )
    })?;
    let view: View = match picked {
        Some((n, c)) => view::placed(
            &pose.world[n],
            rig.cameras[c].projection,
            rig.cameras[c].name.clone(),
        ),
        None => view::framing(lo, hi),
    };
    for &n in &order {
        let Some(l) = rig.nodes[n].light else {
            continue;
        };
        let def = &rig.lights[l];
        let w = &pose.world[n];
        let position = w.w_axis.truncate();
        let axis = (-w.z_axis.truncate()).normalize_or(-DVec3::Z);
        let shape = match def.kind {
            LightType::Point => LightShape::Point { position },
            LightType::Directional => LightShape::Directional { direction: axis },
            LightType::Spot { inner, outer } => LightShape::Spot {
                position,
                axis,
                cos_inner: inner.cos(),
                cos_outer: outer.cos(),
            },
        };
        scene.ext.lights.push(ExtLight {
            kind: LightKind::Punctual(shape, def.range),
            color: def.color,
            intensity: def.intensity * EXPOSURE,
            mods: Modifiers {
                name: def.name.clone().or_else(|| rig.nodes[n].name.clone()),
                ..Modifiers::default()
            },
            loc: loc.clone(),
        });
    }
    if let Some(first) = scene.meshes.first_mut() {
        let mut mesh = (**first).clone();
        mesh.warnings = warnings;
        *first = Arc::new(mesh);
    }
    if scene.ext.lights.is_empty() {
        let (shape, color, intensity) = view::default_light(&view);
        scene.ext.lights.push(ExtLight {
            kind: LightKind::Punctual(shape, None),
            color,
            intensity,
            mods: Modifiers {
                name: Some("default light".into()),
                ..Modifiers::default()
            },
            loc,
        });
    }
    scene.eye = view.eye;
    scene.look_at = view.look_at;
    scene.lens = view.lens;
    scene.parallel = view.parallel;
    (scene.width, scene.height) = view.size;
    scene.t_min = crate::scene::nff::epsilon(scene.eye, &scene.objects);
    Ok(scene)
}

/// What a primitive of `vertices` vertices drawn with the material `x` (its base colour
/// `texture`) carries beyond its look: the coverage of a MASK or BLEND material (the
/// texture's alpha channel, COLOR_0's alpha) and an emissive texture on its coordinate
/// set; `None` for an opaque material without one.
fn extra_of(x: &LookExtra, texture: &Texture, prim: &Prim, vertices: usize) -> Option<Arc<Extra>> {
    let coverage = x.mode != AlphaMode::Opaque;
    if !coverage && x.emissive.is_none() {
        return None;
    }
    let texture = match texture {
        Texture::Image(image) if coverage && image.pixels.has_alpha() => Some(Arc::clone(image)),
        _ => None,
    };
    let vertex = if coverage && prim.alphas.len() == vertices {
        prim.alphas.clone()
    } else {
        Vec::new()
    };
    let emissive = x.emissive.as_ref().map(|(texture, factor, set)| Emissive {
        texture: Arc::clone(texture),
        factor: *factor,
        uvs: prim.uvs[*set].clone(),
    });
    Some(Arc::new(Extra {
        mode: x.mode,
        factor: x.factor,
        texture,
        vertex,
        emissive,
    }))
}
