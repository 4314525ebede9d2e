//! What a scene holds besides geometry: materials (`Kd Kr Kt Ior BumpType BumpValue`, or
//! an NFF's `Kd Ks Shine T index` with its Phong highlight), objects (a shape with a
//! texture and a material) and point lights (`Lx Ly Lz R G B Intensity`).

use crate::base::Color;
use crate::bump::Bump;
use crate::shapes::Shape;
use crate::texture::Texture;
use glam::DVec3;

/// The optical coefficients of an object (report III.1, "MATERIAU").
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material {
    /// Diffuse coefficient; the specular term is weighted 1 − Kd.
    pub kd: f64,
    /// Reflection coefficient.
    pub kr: f64,
    /// Refraction (transmission) coefficient.
    pub kt: f64,
    /// Refraction index of the object (the outside is always air, 1.0).
    pub ior: f64,
    /// How the normal is perturbed (bump type and amplitude).
    pub bump: Bump,
    /// The specular highlight: the report's, or an NFF's Phong term.
    pub highlight: Highlight,
}

/// The specular highlight of a material (SPEC §2 and §17).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum Highlight {
    /// The report's: `(1 − Kd)·I·max(0, V·R)^20·Lc`.
    #[default]
    Report,
    /// NFF's Phong term: `Ks·I·max(0, V·R)^Shine·Lc`.
    Phong {
        /// The highlight's weight, NFF's Ks.
        ks: f64,
        /// The Phong exponent, NFF's Shine.
        shine: f64,
    },
    /// A glTF material's (SPEC §18, `gltf::material`): a Phong highlight from its
    /// roughness, and the index of the rest of it in the scene's `Scene::pbr` (the tint
    /// its mirror reflection takes, the light it emits). Kept as small as `Phong`: a
    /// larger highlight made every object larger and cost the orbit 1 % of its
    /// instructions (callgrind), though it never takes this arm.
    Gltf {
        /// The highlight's weight, as NFF's Ks.
        ks: f32,
        /// The Phong exponent.
        shine: f32,
        /// Its entry of `Scene::pbr`.
        look: u32,
    },
}

impl Highlight {
    /// The Phong term's (Ks, Shine): NFF's as written, a glTF material's widened to f64;
    /// none (0, 0) for the report's, whose weight is 1 − Kd.
    #[inline(always)]
    pub fn phong(self) -> (f64, f64) {
        match self {
            Highlight::Report => (0.0, 0.0),
            Highlight::Phong { ks, shine } => (ks, shine),
            Highlight::Gltf { ks, shine, .. } => (f64::from(ks), f64::from(shine)),
        }
    }
}

/// What a glTF material adds to §2's terms besides its highlight (`Highlight::Gltf`'s
/// entry of `Scene::pbr`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pbr {
    /// The colour the reflected ray's term is multiplied by (white for a dielectric).
    pub tint: Color,
    /// Unlit colour added at every hit (`emissiveFactor` × `emissiveStrength`).
    pub emission: Color,
}

/// One renderable object (not `Copy`: its shape may be a shared CSG block).
#[derive(Clone, Debug, PartialEq)]
pub struct Object {
    /// The surface.
    pub shape: Shape,
    /// Its colour pattern.
    pub texture: Texture,
    /// Its lighting coefficients, index and bump.
    pub material: Material,
}

impl Object {
    /// The texture's colour at the world point `p` of the surface (an image texture reads
    /// its map frame from the shape).
    #[inline]
    pub fn color_at(&self, p: DVec3) -> Color {
        if let Texture::Image(image) = &self.texture {
            return image.color_at(&self.shape, p);
        }
        self.texture.color_at(p)
    }
}
