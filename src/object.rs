//! What a scene holds besides geometry: materials (`Kd Kr Kt Ior BumpType BumpValue`),
//! objects (a shape with a texture and a material) and point lights
//! (`Lx Ly Lz R G B Intensity`).

use crate::bump::Bump;
use crate::shapes::Shape;
use crate::texture::{Color, Texture};
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
    pub bump: Bump,
}

/// One renderable object.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Object {
    pub shape: Shape,
    pub texture: Texture,
    pub material: Material,
}

/// An omnidirectional point light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Light {
    pub position: DVec3,
    pub color: Color,
    pub intensity: f64,
}
