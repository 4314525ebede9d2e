//! The `spot` light (SPEC §16, POV-Ray 3.7's `spotlight`): a point light whose intensity
//! falls off about its axis. With c the cosine between the axis (P → Target) and the
//! direction P → point: 0 where c ≤ 0, else c^Tightness, times the smoothstep 3t² − 2t³
//! of t = (c − cos Falloff) / (cos Radius − cos Falloff) clamped to 0..1 where
//! c < cos Radius (angles in degrees, 0 < Radius < Falloff < 90).

use super::point::towards;
use super::{Incident, LightSource};
use crate::base::Color;
use glam::DVec3;

/// A spotlight (built from its record by `scene::ext::build::lights`, which adds its
/// fade, `fade::Fade`, beside it).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spot {
    /// Where the light is.
    pub position: DVec3,
    /// The unit axis, P → Target.
    pub axis: DVec3,
    /// cos Radius: full intensity inside.
    pub cos_radius: f64,
    /// cos Falloff: nothing outside.
    pub cos_falloff: f64,
    /// The exponent on c.
    pub tightness: f64,
    /// Its colour.
    pub color: Color,
    /// Its intensity.
    pub intensity: f64,
}

impl Spot {
    /// The spot at `position` aimed at `target`, angles in degrees.
    pub fn new(
        position: DVec3,
        target: DVec3,
        radius: f64,
        falloff: f64,
        tightness: f64,
        color: Color,
        intensity: f64,
    ) -> Spot {
        Spot {
            position,
            axis: (target - position).normalize(),
            cos_radius: radius.to_radians().cos(),
            cos_falloff: falloff.to_radians().cos(),
            tightness,
            color,
            intensity,
        }
    }

    /// The factor on the intensity for c, the cosine between the axis and P → point.
    pub fn factor(&self, c: f64) -> f64 {
        if c <= 0.0 {
            return 0.0;
        }
        let mut f = c.powf(self.tightness);
        if c < self.cos_radius {
            let t = ((c - self.cos_falloff) / (self.cos_radius - self.cos_falloff)).clamp(0.0, 1.0);
            f *= t * t * (3.0 - 2.0 * t);
        }
        f
    }
}

impl LightSource for Spot {
    fn color(&self) -> Color {
        self.color
    }

    fn incident(&self, p: DVec3) -> Option<Incident> {
        let mut inc = towards(self.position, p, self.intensity)?;
        let f = self.factor(-inc.l.dot(self.axis));
        if f <= 0.0 {
            return None;
        }
        inc.intensity *= f;
        Some(inc)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spot(tightness: f64) -> Spot {
        // Aimed straight down from y = 10, Radius 20°, Falloff 40°.
        Spot::new(
            DVec3::new(0.0, 10.0, 0.0),
            DVec3::ZERO,
            20.0,
            40.0,
            tightness,
            Color::ONE,
            1.0,
        )
    }

    #[test]
    fn full_inside_the_radius_none_outside_the_falloff() {
        let s = spot(0.0);
        // On the axis: c = 1, c^0 = 1, no smoothstep.
        assert_eq!(s.incident(DVec3::ZERO).unwrap().intensity, 1.0);
        // 45° off the axis: outside the falloff.
        assert!(s.incident(DVec3::new(10.0, 0.0, 0.0)).is_none());
        // Behind the light.
        assert!(s.incident(DVec3::new(0.0, 20.0, 0.0)).is_none());
    }

    #[test]
    fn smoothstep_half_way_by_hand() {
        // c half-way between cos 40° and cos 20°: t = ½, smoothstep ½; tightness 2: c².
        let s = spot(2.0);
        let c = (20f64.to_radians().cos() + 40f64.to_radians().cos()) / 2.0;
        assert!((s.factor(c) - c * c * 0.5).abs() < 1e-15);
        // At 30°, by hand: t = (cos30 − cos40)/(cos20 − cos40) = 0.5373…
        let c30 = 30f64.to_radians().cos();
        let t: f64 = (0.866_025_403_784_438_6 - 0.766_044_443_118_978)
            / (0.939_692_620_785_908_4 - 0.766_044_443_118_978);
        let want = c30 * c30 * (3.0 * t * t - 2.0 * t * t * t);
        assert!((s.factor(c30) - want).abs() < 1e-12);
        // Through incident, at 30° off the axis, 10 below.
        let p = DVec3::new(10.0 * 30f64.to_radians().tan(), 0.0, 0.0);
        assert!((s.incident(p).unwrap().intensity - want).abs() < 1e-12);
    }
}
