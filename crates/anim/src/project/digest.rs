//! A frame's digest (SPEC §8): SHA-256 over the pixel version and the settings
//! (`Settings`, serialized as JSON), a draft's label, and for each time the frame samples
//! the scene's values after tracks (not the file's bytes: comments and layout count for
//! nothing; the extension's shapes, lights and focus included), the eye and the look-at
//! point, every number by its exact bits. The hash takes the times one after another
//! (`Hashing`), so a frame's plan can hash each sub-frame's state as it is drawn and then
//! let it go (`FramePlan::samples`).

use super::Animation;
use crate::timeline::Snapshot;
use glam::DVec3;
use sha2::{Digest, Sha256};
use whitted::camera::Lens;
use whitted::fog::Fog;
use whitted::object::Highlight;
use whitted::object::Object;
use whitted::optics::T_MIN;
use whitted::scene::{ObjectSpec, Scene, ShapeSpec};
use whitted::shapes::csg::{Csg, Node};
use whitted::shapes::Shape;
use whitted::texture::Texture;

/// A digest being made: the settings taken, the states of the frame's times added in
/// order, then `finish`.
pub(super) struct Hashing(Sha256);

impl Hashing {
    /// The digest of a frame of `anim`, before its states.
    pub(super) fn new(anim: &Animation) -> Hashing {
        let mut h = Sha256::new();
        h.update(b"whitted frame\0");
        h.update(serde_json::to_vec(&anim.settings()).unwrap_or_default());
        // A draft's label (none for a final, whose digests stay what they were).
        if let Some(draft) = &anim.manifest.draft {
            h.update(b"\0draft\0");
            h.update(draft.as_bytes());
        }
        Hashing(h)
    }

    /// Adds the state of the frame's next time: its scene's values and its camera.
    pub(super) fn add(&mut self, state: &Snapshot) {
        let mut bytes = Vec::new();
        scene_bytes(&state.scene, &mut bytes);
        for p in [state.eye, state.look_at] {
            for x in p.to_array() {
                bytes.extend_from_slice(&x.to_bits().to_le_bytes());
            }
        }
        self.0.update(&bytes);
    }

    /// The digest, lower-case hex.
    pub(super) fn finish(self) -> String {
        hex(&self.0.finalize())
    }
}

/// Bytes as lower-case hex.
pub fn hex(bytes: &[u8]) -> String {
    bytes.iter().map(|b| format!("{b:02x}")).collect()
}

/// Appends the exact bits of every value of `scene` that reaches a pixel.
fn scene_bytes(scene: &Scene, out: &mut Vec<u8>) {
    let mut f = |x: f64| out.extend_from_slice(&x.to_bits().to_le_bytes());
    let v = |p: DVec3, f: &mut dyn FnMut(f64)| {
        f(p.x);
        f(p.y);
        f(p.z);
    };
    f(f64::from(scene.width));
    f(f64::from(scene.height));
    let (fog_kind, fog_d) = match scene.fog {
        Fog::None => (0.0, 0.0),
        Fog::Linear(d) => (1.0, d),
        Fog::Exponential(d) => (2.0, d),
        Fog::ExponentialSquared(d) => (3.0, d),
    };
    f(fog_kind);
    f(fog_d);
    for (obj, spec) in scene.objects.iter().zip(&scene.specs) {
        match spec {
            ObjectSpec::Record(ShapeSpec::Sphere { center, radius }) => {
                let (center, radius) = (*center, *radius);
                f(1.0);
                v(center, &mut f);
                f(radius);
            }
            ObjectSpec::Record(ShapeSpec::Plane { point, normal }) => {
                let (point, normal) = (*point, *normal);
                f(2.0);
                v(point, &mut f);
                v(normal, &mut f);
            }
            ObjectSpec::Record(ShapeSpec::InfiniteCylinder {
                axis,
                point,
                radius,
            }) => {
                let (axis, point, radius) = (*axis, *point, *radius);
                f(3.0);
                v(axis, &mut f);
                v(point, &mut f);
                f(radius);
            }
            ObjectSpec::Record(ShapeSpec::Triangle { corners }) => {
                f(5.0);
                corners.iter().for_each(|&c| v(c, &mut f));
            }
            ObjectSpec::Record(ShapeSpec::Patch { corners, normals }) => {
                f(6.0);
                corners.iter().chain(normals).for_each(|&c| v(c, &mut f));
            }
            ObjectSpec::Record(ShapeSpec::OpenCone { base, apex }) => {
                let (base, apex) = (*base, *apex);
                f(7.0);
                v(base.0, &mut f);
                f(base.1);
                v(apex.0, &mut f);
                f(apex.1);
            }
            // The extension's records (the report's and an NFF's never hold these
            // kinds): where the record is, its anchor and the drawn shape's every value
            // (Debug prints each f64 exactly).
            ObjectSpec::Record(_) | ObjectSpec::Ext { .. } => {
                f(8.0);
                f(spec.item().map_or(0.0, |item| item as f64));
                v(spec.anchor(), &mut f);
                let shape = &obj.shape;
                format!("{shape:?}").bytes().for_each(|b| f(f64::from(b)));
            }
        }
        let (_, kind, colors) = obj.texture.record();
        f(f64::from(kind));
        for c in colors {
            v(c, &mut f);
        }
        // A pattern's `texture_scale` (nothing at 1, so that digests stay what they were).
        let scale = obj.texture.scale();
        if scale != 1.0 {
            f(11.0);
            f(scale);
        }
        // A texture's scale (nothing at 1, so that digests stay what they were).
        if obj.texture.scale() != 1.0 {
            f(10.0);
            f(obj.texture.scale());
        }
        let m = &obj.material;
        for x in [m.kd, m.kr, m.kt, m.ior] {
            f(x);
        }
        let (bump_kind, eps) = m.bump.record();
        f(f64::from(bump_kind));
        f(eps);
        // An NFF's Phong highlight (nothing for the report's, so that a Scene.txt's
        // digests stay what they were).
        if let Highlight::Phong { ks, shine } = m.highlight {
            f(8.0);
            f(ks);
            f(shine);
        }
    }
    for light in &scene.lights {
        f(4.0);
        v(light.position, &mut f);
        v(light.color, &mut f);
        f(light.intensity);
    }
    // The extension's records, every value as tracks left it (their modifiers included),
    // and the contents of the mesh and image files they read; nothing for a file without
    // them, so that a Scene.txt's digests stay what they were. Debug prints each f64
    // exactly.
    let ext = &scene.ext;
    if !ext.is_empty() {
        f(10.0);
        format!("{:?}{:?}{:?}", ext.objects, ext.lights, ext.focus)
            .bytes()
            .for_each(|b| f(f64::from(b)));
    }
    // A glTF scene's pose (time, animations, node values) and camera: its vertices
    // follow from them and the file, whose digest (with every file it names) its meshes
    // carry.
    if let Some(model) = &scene.model {
        f(11.0);
        format!(
            "{:?}{:?}{}{:?}{:?}",
            model.posed, model.options, scene.linear, scene.parallel, scene.pbr
        )
        .bytes()
        .for_each(|b| f(f64::from(b)));
    }
    let mut sources: Vec<[u8; 32]> = scene.meshes.iter().map(|m| m.source).collect();
    image_sources(scene.objects.iter(), &mut sources);
    for s in sources {
        s.iter().for_each(|&b| f(f64::from(b)));
    }
    // An NFF's background, epsilon and view (nothing for a Scene.txt's defaults).
    let lens = scene.lens;
    if scene.background != DVec3::ZERO || scene.t_min != T_MIN || lens != Lens::default() {
        f(9.0);
        v(scene.background, &mut f);
        f(scene.t_min);
        f(lens.fov.unwrap_or(0.0));
        f(lens.roll);
        v(lens.up, &mut f);
        f(f64::from(u8::from(lens.centres)));
    }
}

/// The SHA-256 of the file of every image texture of `objects` (CSG blocks' leaves
/// included), in order.
fn image_sources<'a>(objects: impl Iterator<Item = &'a Object>, out: &mut Vec<[u8; 32]>) {
    for obj in objects {
        if let Texture::Image(img) = &obj.texture {
            out.push(img.pixels.source());
        }
        if let Shape::Csg(csg) = &obj.shape {
            csg_sources(csg, out);
        }
    }
}

/// `image_sources` of a CSG block's leaves.
fn csg_sources(csg: &Csg, out: &mut Vec<[u8; 32]>) {
    for node in csg.children() {
        match node {
            Node::Leaf(obj) => image_sources(std::iter::once(obj), out),
            Node::Csg(inner) => csg_sources(inner, out),
        }
    }
}
