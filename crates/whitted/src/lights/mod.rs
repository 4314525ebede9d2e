//! Lights (report IV.2, SPEC §1 and §16), one file per kind behind one interface,
//! `LightSource`, which the shading code (`shading::direct`) takes instead of a branch per
//! kind: for a hit point, the unit direction L to the light, the distance a shadow ray
//! runs (infinite for a directional light), the intensity after spot and fade, and what
//! the shadow rays let through (one ray, or the mean over an area light's grid).
//!
//! - `point`: the report's point light (`scene.lights`, the tracer's fast path, with its
//!   light buffer) and the extension's `point` record;
//! - `directional`, `spot`, `area`: the extension's other lights;
//! - `punctual`: glTF's lights, with their own falloff and cone;
//! - `fade`: the extension's attenuation with distance, on any of them but a directional.
//!
//! These are the built forms of lights; their records (the one record form of a light's
//! kind, `scene::ext::LightKind`) are above, in the scene, which builds `SceneLight`s
//! from them (`scene::ext::build::lights`). The report's point light is read straight
//! into its built form, `PointLight`, which holds nothing its record does not.

pub mod area;
pub mod directional;
pub mod fade;
mod occluders;
pub mod point;
pub mod punctual;
pub mod spot;

pub use area::Area;
pub use directional::Directional;
pub use fade::Fade;
pub use occluders::{ext_key, Clearance, Occluders};
pub use point::PointLight;
pub use punctual::Punctual;
pub use spot::Spot;

use crate::base::Color;
use glam::DVec3;

/// The light arriving at a point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Incident {
    /// The unit vector towards the light.
    pub l: DVec3,
    /// The vector to the light before normalisation (`l` for a directional light).
    pub to: DVec3,
    /// How far a shadow ray runs: the distance to the light, or infinity.
    pub dist: f64,
    /// The intensity after spot and fade.
    pub intensity: f64,
}

/// What the shading code asks of a light.
pub trait LightSource {
    /// Its colour Lc.
    fn color(&self) -> Color;

    /// The light at `p`, or none where it gives nothing there (on a point light, outside
    /// a spot's cone).
    fn incident(&self, p: DVec3) -> Option<Incident>;

    /// What the shadow rays from `p` towards the light let through (`k`: the light's
    /// number among its list, for an occluder's per-light structures), counting them in
    /// `rays`. By default one unbounded-or-not ray along `inc`.
    #[inline]
    fn shadow<O: Occluders + ?Sized>(
        &self,
        k: usize,
        occluders: &O,
        p: DVec3,
        inc: &Incident,
        rays: &mut u64,
    ) -> Color {
        let _ = k;
        *rays += 1;
        occluders.transmission(p, inc.l, inc.dist)
    }
}

/// An extension light as the tracer shades with it: the built form of a light record's
/// kind (`scene::ext::LightKind`).
#[derive(Clone, Debug, PartialEq)]
pub enum Kind {
    /// `point`.
    Point(PointLight),
    /// `directional`.
    Directional(Directional),
    /// `spot`.
    Spot(Spot),
    /// `area`.
    Area(Area),
    /// A glTF light (`KHR_lights_punctual`).
    Punctual(Punctual),
}

/// One light of the extension records, with its fade.
#[derive(Clone, Debug, PartialEq)]
pub struct SceneLight {
    /// The light.
    pub kind: Kind,
    /// `fade Distance Power`, if given.
    pub fade: Option<Fade>,
}

impl LightSource for SceneLight {
    fn color(&self) -> Color {
        match &self.kind {
            Kind::Point(l) => l.color,
            Kind::Directional(l) => l.color,
            Kind::Spot(l) => l.color,
            Kind::Area(l) => l.color,
            Kind::Punctual(l) => l.color,
        }
    }

    fn incident(&self, p: DVec3) -> Option<Incident> {
        let mut inc = match &self.kind {
            Kind::Point(l) => point::towards(l.position, p, l.intensity),
            Kind::Directional(l) => l.incident(p),
            Kind::Spot(l) => l.incident(p),
            Kind::Area(l) => l.incident(p),
            Kind::Punctual(l) => l.incident(p),
        }?;
        if let Some(f) = self.fade {
            inc.intensity *= f.factor(inc.dist);
        }
        Some(inc)
    }

    fn shadow<O: Occluders + ?Sized>(
        &self,
        k: usize,
        occluders: &O,
        p: DVec3,
        inc: &Incident,
        rays: &mut u64,
    ) -> Color {
        match &self.kind {
            Kind::Area(a) => a.shadow(k, occluders, p, inc, rays),
            _ => {
                *rays += 1;
                occluders.transmission_keyed(ext_key(k, 0), p, inc.l, inc.dist)
            }
        }
    }
}

#[cfg(test)]
mod tests;
