//! The extension records of Scene.txt (SPEC §16) as the reader hands them over: what the
//! file says, checked against §16's bounds, before anything is built from it. Shapes,
//! CSG and meshes are built from `ExtObject`s, lights from `ExtLight`s, the lens from
//! `Focus`; animation tracks change a value here and build again, as the reader would
//! from the changed file (`check` holds the bounds both apply).
//!
//! After the last light of the report's section, a file may hold records, each a
//! lowercase keyword and its fields in a fixed order, then modifiers:
//!
//! ```text
//! box  -1 0 -1  1 2 1   1 0.8 0.2 0.2   0.7 0 0 1 0 0      # Min Max TEXTURE MATERIAL
//!   name crate  rotate 0 45 0  translate 2 0 0             # modifiers, each at most once
//! cylinder 0 0 0  0 2 0  0.5  1 1 1 1  1 0 0 1 0 0  open   # A B Radius …, no caps
//! difference                                               # CSG: two or more solids
//!   sphere 0 1 0 1  1 1 0 0  0.7 0 0 1 0 0
//!   box -2 1 -2 2 3 2  1 0 0 1  0.7 0 0 1 0 0
//! end  name bowl
//! mesh "models/teapot.obj"  1 0.9 0.9 0.9  0.8 0 0 1 0 0  scale 0.5 0.5 0.5
//! spot 0 5 0  0 0 0  1 1 1  1  20 30 1   name key  fade 10 2
//! area 0 6 0  2 0 0  0 0 2  4 4  1 1 1  1
//! focus 0.2 8 3                                            # Aperture Distance Samples
//! background 0.2 0.3 0.5                                   # R G B: what misses see
//! ```

pub mod build;
pub mod check;
pub mod epsilon;

use crate::base::Color;
use crate::fileloc::FileLoc;
use crate::object::Material;
use crate::scene::ShapeSpec;
use crate::shapes::csg::Op;
use crate::texture::Texture;
use glam::DVec3;

/// Every extension record of a file, in file order within each list.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Extension {
    /// Shape records and CSG blocks (objects), in file order.
    pub objects: Vec<ExtItem>,
    /// Light records, in file order.
    pub lights: Vec<ExtLight>,
    /// The `focus` record, if the file has one (at most one).
    pub focus: Option<Focus>,
    /// The `background R G B` record (SPEC §18), if the file has one (at most one): what
    /// a ray that hits nothing sees, instead of black.
    pub background: Option<crate::base::Color>,
}

impl Extension {
    /// True when the file had no extension record: it renders as the report's.
    pub fn is_empty(&self) -> bool {
        self.objects.is_empty()
            && self.lights.is_empty()
            && self.focus.is_none()
            && self.background.is_none()
    }
}

/// One object of the extension: a shape record or a CSG block.
// A record is read once per scene and copied by tracks; boxing it would change every
// reader of the records for no measurable gain.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Debug, PartialEq)]
pub enum ExtItem {
    /// A shape record with its texture and material.
    Shape(ExtObject),
    /// `union`/`intersection`/`difference` … `end`.
    Csg(Csg),
}

/// The modifiers an object or a light takes (each at most once; §16).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Modifiers {
    /// `name N`: unique in the file.
    pub name: Option<String>,
    /// `open`: a cylinder or cone without its caps.
    pub open: bool,
    /// `scale x y z` (no zero component).
    pub scale: Option<DVec3>,
    /// `rotate x y z`, degrees about x, then y, then z.
    pub rotate: Option<DVec3>,
    /// `translate x y z`.
    pub translate: Option<DVec3>,
    /// `fade Distance Power` (lights other than directional).
    pub fade: Option<(f64, f64)>,
    /// `smooth Angle` or `flat` (meshes; SPEC §18): none keeps the file's normals.
    pub shading: Option<crate::mesh::Shading>,
    /// `fit Size` and `pivot center | x y z` (meshes; SPEC §18).
    pub placing: crate::mesh::Placing,
}

impl Modifiers {
    /// True when the object's frame is moved (scale, rotate or translate given).
    pub fn has_transform(&self) -> bool {
        self.scale.is_some() || self.rotate.is_some() || self.translate.is_some()
    }
}

/// One shape record: geometry, TEXTURE, MATERIAL, modifiers, and where it starts.
#[derive(Clone, Debug, PartialEq)]
pub struct ExtObject {
    /// The geometry (the record form every reader shares).
    pub shape: ShapeSpec,
    /// TEXTURE, as for the report's objects.
    pub texture: Texture,
    /// MATERIAL, as for the report's objects.
    pub material: Material,
    /// The modifiers after the record.
    pub mods: Modifiers,
    /// The keyword's place in the file (for errors found after reading, e.g. a mesh's).
    pub loc: FileLoc,
}

/// A CSG block, the one record form of a block: two or more solids or blocks, then `end`
/// and the whole's modifiers. `build` makes its built form, a `shapes::csg::Csg` tree.
#[derive(Clone, Debug, PartialEq)]
pub struct Csg {
    /// The operation (the built tree's own).
    pub op: Op,
    /// The children in file order (each a solid shape or a nested block).
    pub children: Vec<ExtItem>,
    /// Modifiers after `end` (name, scale, rotate, translate).
    pub mods: Modifiers,
    /// The block keyword's place in the file.
    pub loc: FileLoc,
}

/// A light record's kind and fields (§16's table): the one record form of a light's kind,
/// built into `lights::Kind` by `build::lights`.
#[derive(Clone, Debug, PartialEq)]
pub enum LightKind {
    /// `directional D(3)`: travelling along D.
    Directional {
        /// D (non-zero): the direction the light travels in.
        direction: DVec3,
    },
    /// `spot P(3) Target(3) … Radius Falloff Tightness` (angles in degrees).
    Spot {
        /// P, where the light is.
        position: DVec3,
        /// The point the axis aims at.
        target: DVec3,
        /// The full-intensity cone's half-angle in degrees, 0 < Radius < Falloff.
        radius: f64,
        /// The half-angle where the light ends, below 90 degrees.
        falloff: f64,
        /// The exponent on the cosine to the axis, ≥ 0.
        tightness: f64,
    },
    /// `point P(3)`: the report's point light as a record.
    Point {
        /// P, where the light is.
        position: DVec3,
    },
    /// `area P(3) A1(3) A2(3) N1 N2`: an N1 × N2 grid over the rectangle.
    Area {
        /// P, the rectangle's centre.
        position: DVec3,
        /// The edge A1.
        a1: DVec3,
        /// The edge A2.
        a2: DVec3,
        /// Points along A1, ≥ 1.
        n1: u32,
        /// Points along A2, ≥ 1.
        n2: u32,
    },
    /// A glTF light (SPEC §18), placed by its node, and its range if it has one: the
    /// glTF reader's, never written in a Scene.txt.
    Punctual(crate::lights::punctual::Shape, Option<f64>),
}

impl LightKind {
    /// The record's keyword; `point` lights are numbered `light N` after the report's.
    pub fn keyword(&self) -> &'static str {
        match self {
            LightKind::Directional { .. } => "directional",
            LightKind::Spot { .. } => "spot",
            LightKind::Point { .. } => "point",
            LightKind::Area { .. } => "area",
            LightKind::Punctual(..) => "gltf light",
        }
    }
}

/// One light record: kind, colour (R G B, 0..1), intensity, modifiers (name, fade).
#[derive(Clone, Debug, PartialEq)]
pub struct ExtLight {
    /// The kind and its geometry.
    pub kind: LightKind,
    /// R G B, each 0..1.
    pub color: Color,
    /// The intensity, a factor on the colour.
    pub intensity: f64,
    /// `name` and `fade`.
    pub mods: Modifiers,
    /// The keyword's place in the file.
    pub loc: FileLoc,
}

/// `focus Aperture Distance Samples`: the thin lens (§16).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Focus {
    /// The lens diameter, > 0.
    pub aperture: f64,
    /// The distance of the plane in focus along the view axis, > 0.
    pub distance: f64,
    /// Lens samples per axis (Samples × Samples per camera sample), ≥ 1.
    pub samples: u32,
}
