//! A scene as Scene.txt describes it (report III.1, SPEC §1) or an NFF file does (SPEC
//! §17, `nff`), and parsing one. `Scene::load` (in `crate::load`, above this module and
//! the glTF reader) picks the reader by the file's extension. Every reader produces the
//! same `Scene`; the tracer never learns which format it came from.
//!
//! ```text
//! 640 480                 # ResX ResY
//! 0 2 10                  # camera position
//! 0 1 0                   # point looked at
//! 0 20                    # FogType FogDistance (0 none, 1 linear, 2 exp, 3 exp²)
//! 1 1 0 1                 # NSpheres NPlanes NCylinders NLights
//! 1 0 1 0   1 1 0 0   0.7 0.3 0 1 0 0            # sphere: R Cx Cy Cz TEXTURE MATERIAL
//! 0 0 0  0 1 0   2 1 1 1 1 0 0 0 0 0 0   1 0 0 1 0 0   # plane: P N TEXTURE MATERIAL
//! 5 10 5  1 1 1  1        # light: position, colour, intensity
//! ```
//!
//! TEXTURE is `1 R G B` or `2 Type C1 C2 C3` (Type 1 checker, 2 Perlin, 3 wood,
//! 4 marble); MATERIAL is `Kd Kr Kt Ior BumpType BumpValue`. Cylinders are
//! `Ax Ay Az Px Py Pz Radius TEXTURE MATERIAL`, infinite, with an axis of any direction.

pub(crate) mod decode;
mod error;
pub mod ext;
mod lexer;
pub mod nff;
mod parser;
mod spec;

pub use error::{FileLoc, SceneError};

use crate::base::Color;
use crate::camera::{Camera, Lens};
use crate::fog::Fog;
use crate::lights::PointLight;
use crate::object::Object;
use glam::DVec3;

pub use crate::limits::{MAX_COUNT, MAX_INTENSITY, MAX_PIXELS, MAX_SIDE};
pub use spec::{direction, ObjectSpec, ShapeSpec};

/// Everything one Scene.txt (or NFF file) holds.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    /// The image's width in pixels, 1 to `MAX_SIDE`.
    pub width: u32,
    /// The image's height in pixels, 1 to `MAX_SIDE`.
    pub height: u32,
    /// The camera's position (the eye).
    pub eye: DVec3,
    /// The point the camera looks at; never equal to `eye`.
    pub look_at: DVec3,
    /// The fog on primary rays (none when its distance is 0).
    pub fog: Fog,
    /// Spheres, then planes, then cylinders, in file order.
    pub objects: Vec<Object>,
    /// Each object's record: the report's or NFF's own (`objects[i].shape` is its
    /// `build()`), or where it is in `ext.objects`: what an animation track changes
    /// before rebuilding the shape.
    pub specs: Vec<ObjectSpec>,
    /// The point lights, in file order.
    pub lights: Vec<PointLight>,
    /// What a ray that hits nothing sees: black for a Scene.txt, NFF's `b`.
    pub background: Color,
    /// A hit counts only past this distance: the report's 0.01 for a Scene.txt, a
    /// length scaled to the scene for an NFF (`nff::epsilon`) and for a small scene of
    /// meshes (`ext::epsilon`).
    pub t_min: f64,
    /// The scene's own framing: the report's for a Scene.txt; an NFF view's angle
    /// (between the outer pixel centres) and up.
    pub lens: Lens,
    /// The extension records after the last light (SPEC §16): empty for a report file
    /// and an NFF.
    pub ext: ext::Extension,
    /// The meshes of the extension's `mesh` records, in file order (`Shape::Mesh`'s `id`
    /// indexes this): shared, so that copies of a scene (an animation's frames) share
    /// their triangles.
    pub meshes: Vec<std::sync::Arc<crate::mesh::Mesh>>,
    /// What glTF materials add besides their highlight (`Highlight::Gltf`'s `look`
    /// indexes it): empty for every other scene.
    pub pbr: Vec<crate::object::Pbr>,
    /// An orthographic view's height in the world (a glTF orthographic camera's 2·ymag):
    /// parallel camera rays instead of the pinhole's. `None` for every other scene.
    pub parallel: Option<f64>,
    /// Shaded in linear light (a glTF scene, SPEC §18): the tracer's values are linear
    /// and the frame is sRGB-encoded for display. False for Scene.txt and NFF.
    pub linear: bool,
    /// The glTF file this scene was posed from, if any (what an animation poses again
    /// at every frame).
    pub model: Option<crate::gltf::model::Model>,
}

impl Scene {
    /// Parses Scene.txt source; `file` is the name errors carry.
    pub fn parse(src: &str, file: &str) -> Result<Scene, SceneError> {
        parser::parse(src, file)
    }

    /// The objects' names, in order: `KIND N`, N counted from 1 per kind in file order
    /// (`sphere 3`: the file's third sphere; an extension record continues its kind's
    /// count after the report's), or the record's `name` when it has one (the count still
    /// advances past it), the names tracks target
    /// (`anim::timeline::target::objects_of` is the inverse), picking answers and
    /// Cryptomatte hashes.
    pub fn object_names(&self) -> impl Iterator<Item = String> + '_ {
        let mut seen: Vec<(&str, u32)> = Vec::new();
        self.specs.iter().map(move |spec| {
            let kind = spec.kind();
            let n = match seen.iter_mut().find(|(k, _)| *k == kind) {
                Some((_, n)) => {
                    *n += 1;
                    *n
                }
                None => {
                    seen.push((kind, 1));
                    1
                }
            };
            match self.ext_name(spec) {
                Some(name) => name.to_string(),
                None => format!("{kind} {n}"),
            }
        })
    }

    /// The `name` an extension record gives its object, if any.
    fn ext_name(&self, spec: &ObjectSpec) -> Option<&str> {
        match self.ext.objects.get(spec.item()?)? {
            ext::ExtItem::Shape(o) => o.mods.name.as_deref(),
            ext::ExtItem::Csg(c) => c.mods.name.as_deref(),
        }
    }

    /// The lights' names, in the order the tracer lights with them (the report's, then
    /// the extension's records in file order): `KIND N` counted per kind, where a `point`
    /// record is a `light` numbered after the report's (`light 3` after two report
    /// lights), and `spot 1`, `area 1`, `directional 1` count their own records; a
    /// record's `name` replaces it (the count still advances), as for objects.
    pub fn light_names(&self) -> Vec<String> {
        let mut names: Vec<String> = (1..=self.lights.len())
            .map(|n| format!("light {n}"))
            .collect();
        let mut seen: Vec<(&str, usize)> = vec![("light", self.lights.len())];
        for l in &self.ext.lights {
            let kind = match l.kind.keyword() {
                "point" => "light",
                k => k,
            };
            let n = match seen.iter_mut().find(|(k, _)| *k == kind) {
                Some((_, n)) => {
                    *n += 1;
                    *n
                }
                None => {
                    seen.push((kind, 1));
                    1
                }
            };
            names.push(match &l.mods.name {
                Some(name) => name.clone(),
                None => format!("{kind} {n}"),
            });
        }
        names
    }

    /// The name of object `index` (see `object_names`); `None` past the last object.
    pub fn object_name(&self, index: usize) -> Option<String> {
        self.object_names().nth(index)
    }

    /// The scene's own camera, at its resolution.
    pub fn camera(&self) -> Camera {
        let size = (self.width, self.height);
        Camera::framed(self.eye, self.look_at, size, size, &self.lens)
            .expect("the parser refuses an eye placed on its look-at point")
    }
}
