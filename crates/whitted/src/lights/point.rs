//! The report's point light (`Lx Ly Lz R G B Intensity`, SPEC §1): light from one point
//! in every direction, its shadow ray bounded by the distance to it. The extension's
//! `point` record is the same light with an optional `fade` (`Faded`).

use super::Occluders;
use super::{Incident, LightSource};
use crate::base::Color;
use glam::DVec3;

/// An omnidirectional point light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointLight {
    /// Where the light is.
    pub position: DVec3,
    /// Its colour, each component in 0..1.
    pub color: Color,
    /// Its intensity, a factor on the colour (0..1000).
    pub intensity: f64,
}

/// The incident light of a point light at `position` on `p`: the unit direction to it
/// and its distance; none when `p` is the light's own position (it lights nothing there).
#[inline(always)]
pub fn towards(position: DVec3, p: DVec3, intensity: f64) -> Option<Incident> {
    let to = position - p;
    let dist = to.length();
    if dist == 0.0 {
        return None;
    }
    Some(Incident {
        l: to / dist,
        to,
        dist,
        intensity,
    })
}

impl LightSource for PointLight {
    #[inline(always)]
    fn color(&self) -> Color {
        self.color
    }

    #[inline(always)]
    fn incident(&self, p: DVec3) -> Option<Incident> {
        towards(self.position, p, self.intensity)
    }

    /// One shadow ray, through the tracer's per-light structures (light number `k`).
    #[inline(always)]
    fn shadow<O: Occluders + ?Sized>(
        &self,
        k: usize,
        occluders: &O,
        p: DVec3,
        inc: &Incident,
        rays: &mut u64,
    ) -> Color {
        *rays += 1;
        occluders.transmission_to(k, p, inc.to, inc.l, inc.dist)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn direction_and_distance_by_hand() {
        let l = PointLight {
            position: DVec3::new(3.0, 4.0, 0.0),
            color: Color::ONE,
            intensity: 2.0,
        };
        let inc = l.incident(DVec3::ZERO).unwrap();
        assert_eq!(inc.dist, 5.0);
        assert!((inc.l - DVec3::new(0.6, 0.8, 0.0)).length() < 1e-15);
        assert_eq!(inc.intensity, 2.0);
        assert!(l.incident(l.position).is_none());
    }
}
