//! What a light's shadow rays ask of the scene: `Occluders`, the interface every light
//! kind calls (`LightSource::shadow`) and that the tracer's acceleration structures
//! (`trace::Tracer`) and the reference linear scan (`shading`) implement.

use crate::base::Color;
use glam::DVec3;

/// What stands between a point and a light: answers `transmission` queries.
pub trait Occluders {
    /// What a shadow ray from `p` along the unit `to_light` lets through over a distance
    /// `dist`, as the free function `transmission` defines it.
    fn transmission(&self, p: DVec3, to_light: DVec3, dist: f64) -> Color;

    /// The same, knowing that the ray goes to light number `light` of the scene along
    /// `to` = `to_light`·`dist` before normalisation (an implementation may keep
    /// per-light structures); by default, `transmission`.
    #[inline]
    fn transmission_to(
        &self,
        light: usize,
        p: DVec3,
        to: DVec3,
        to_light: DVec3,
        dist: f64,
    ) -> Color {
        let _ = (light, to);
        self.transmission(p, to_light, dist)
    }

    /// The same for a shadow ray of an extension light: `key` names the ray's light and,
    /// for an area light, its point on the grid (`ext_key`), so that an implementation
    /// may keep what blocked the last ray of that key (a shadow cache); by default,
    /// `transmission`.
    #[inline]
    fn transmission_keyed(&self, key: usize, p: DVec3, to_light: DVec3, dist: f64) -> Color {
        let _ = key;
        self.transmission(p, to_light, dist)
    }

    /// What stands between `p` and the quadrilateral `corners` (a shaft, holding every
    /// shadow ray from `p` to a point of an area light's grid); by default, not known.
    #[inline]
    fn clearance(&self, p: DVec3, corners: &[DVec3; 4]) -> Clearance {
        let _ = (p, corners);
        Clearance::Unknown
    }

    /// What a shadow ray in a shaft with nothing bounded in it (`Clearance::Unbounded`)
    /// lets through: the same answer as `transmission`, from the unbounded objects alone;
    /// by default, `transmission`.
    #[inline]
    fn transmission_unbounded(&self, p: DVec3, to_light: DVec3, dist: f64) -> Color {
        self.transmission(p, to_light, dist)
    }
}

/// What a shaft holds (`Occluders::clearance`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Clearance {
    /// Something may stand in the way: each ray is asked as usual.
    Unknown,
    /// Nothing bounded and nothing transparent: each ray asks `transmission_unbounded`.
    Unbounded,
    /// Nothing at all: every ray lets everything through.
    Open,
}

/// The key of the shadow rays of extension light `k` towards its point `i` (0 for a
/// light of one point; an area light's grid has at most 64 × 64 points).
#[inline(always)]
pub fn ext_key(k: usize, i: usize) -> usize {
    k * 4096 + i
}
