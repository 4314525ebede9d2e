//! The `directional` light (SPEC §16, POV-Ray's `parallel`): light travelling along D
//! from infinitely far. L = −D/|D| everywhere, and shadow rays are unbounded.

use super::{Incident, LightSource};
use crate::base::Color;
use glam::DVec3;

/// Light along a direction, from infinitely far.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Directional {
    /// The unit vector towards the light (−D normalised).
    pub to_light: DVec3,
    /// Its colour.
    pub color: Color,
    /// Its intensity.
    pub intensity: f64,
}

impl Directional {
    /// The light travelling along `d` (non-zero).
    pub fn new(d: DVec3, color: Color, intensity: f64) -> Directional {
        Directional {
            to_light: -d.normalize(),
            color,
            intensity,
        }
    }
}

impl LightSource for Directional {
    fn color(&self) -> Color {
        self.color
    }

    fn incident(&self, _p: DVec3) -> Option<Incident> {
        Some(Incident {
            l: self.to_light,
            to: self.to_light,
            dist: f64::INFINITY,
            intensity: self.intensity,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_same_direction_everywhere_and_no_end() {
        let d = Directional::new(DVec3::new(0.0, -2.0, 0.0), Color::ONE, 0.5);
        for p in [DVec3::ZERO, DVec3::new(100.0, -3.0, 7.0)] {
            let inc = d.incident(p).unwrap();
            assert_eq!(inc.l, DVec3::Y);
            assert_eq!(inc.dist, f64::INFINITY);
            assert_eq!(inc.intensity, 0.5);
        }
    }
}
