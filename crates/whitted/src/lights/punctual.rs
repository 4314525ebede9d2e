//! glTF's lights (`KHR_lights_punctual`, SPEC §18): point, spot and directional lights
//! with the extension's own falloff, in physical units turned into §2's intensity by one
//! stated exposure (`EXPOSURE`).
//!
//! - A point or spot light of I candela gives I/d² lux at distance d, times the window
//!   the extension recommends within its `range`: clamp(1 − (d/range)⁴, 0, 1)² (none
//!   without a range).
//! - A spot light's cone: with c the cosine between its axis and the direction to the
//!   point, the factor is clamp((c − cos outer) / (cos inner − cos outer), 0, 1)²
//!   (inner 0 and outer π/4 by default), the extension's smooth attenuation.
//! - A directional light gives its lux everywhere, travelling along its axis.

use super::{Incident, LightSource};
use crate::base::Color;
use glam::DVec3;

/// §2's intensity of one lux: a directional light of 1 lux lights a surface facing it
/// as a report light of intensity 1 does.
pub const EXPOSURE: f64 = 1.0;

/// What kind of punctual light, with its geometry.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Shape {
    /// Light from a point in every direction.
    Point {
        /// Where the light is.
        position: DVec3,
    },
    /// Light from a point within a cone about `axis`.
    Spot {
        /// Where the light is.
        position: DVec3,
        /// The unit direction the cone opens towards.
        axis: DVec3,
        /// The cosine of the inner cone's half-angle (full intensity inside).
        cos_inner: f64,
        /// The cosine of the outer cone's half-angle (nothing outside).
        cos_outer: f64,
    },
    /// Parallel light travelling along `direction` (unit).
    Directional {
        /// The unit direction the light travels in.
        direction: DVec3,
    },
}

/// One glTF light placed in the world.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Punctual {
    /// The kind and its geometry.
    pub shape: Shape,
    /// Its linear colour.
    pub color: Color,
    /// Candela (point, spot) or lux (directional), times `EXPOSURE`.
    pub intensity: f64,
    /// Where a point or spot light's window ends, if it has one.
    pub range: Option<f64>,
}

/// The range window: clamp(1 − (d/range)⁴, 0, 1)².
pub fn window(d: f64, range: Option<f64>) -> f64 {
    match range {
        Some(r) if r > 0.0 => {
            let q = d / r;
            let w = (1.0 - q * q * q * q).clamp(0.0, 1.0);
            w * w
        }
        _ => 1.0,
    }
}

/// A spot's cone factor for the cosine `c` to its axis.
pub fn cone(c: f64, cos_inner: f64, cos_outer: f64) -> f64 {
    let span = (cos_inner - cos_outer).max(1e-4);
    let t = ((c - cos_outer) / span).clamp(0.0, 1.0);
    t * t
}

impl LightSource for Punctual {
    fn color(&self) -> Color {
        self.color
    }

    fn incident(&self, p: DVec3) -> Option<Incident> {
        let (position, cone_factor) = match self.shape {
            Shape::Directional { direction } => {
                return Some(Incident {
                    l: -direction,
                    to: -direction,
                    dist: f64::INFINITY,
                    intensity: self.intensity,
                })
            }
            Shape::Point { position } => (position, None),
            Shape::Spot {
                position,
                axis,
                cos_inner,
                cos_outer,
            } => (position, Some((axis, cos_inner, cos_outer))),
        };
        let to = position - p;
        let d = to.length();
        if d.is_nan() || d <= 0.0 {
            return None;
        }
        let l = to / d;
        let mut intensity = self.intensity / (d * d) * window(d, self.range);
        if let Some((axis, inner, outer)) = cone_factor {
            intensity *= cone(-l.dot(axis), inner, outer);
        }
        (intensity > 0.0).then_some(Incident {
            l,
            to,
            dist: d,
            intensity,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inverse_square_window_and_cone_by_hand() {
        let light = Punctual {
            shape: Shape::Point {
                position: DVec3::new(0.0, 2.0, 0.0),
            },
            color: Color::ONE,
            intensity: 8.0,
            range: None,
        };
        // 8 cd at 2 m: 2 lux.
        let inc = light.incident(DVec3::ZERO).unwrap();
        assert_eq!(inc.intensity, 2.0);
        assert_eq!(inc.l, DVec3::Y);
        assert_eq!(inc.dist, 2.0);
        // range 4 at d 2: (1 − 1/16)² = 225/256.
        assert_eq!(window(2.0, Some(4.0)), (15.0f64 / 16.0).powi(2));
        assert_eq!(window(4.0, Some(4.0)), 0.0);
        assert_eq!(window(9.0, None), 1.0);
        // Half-way between the cones' cosines: ¼.
        assert_eq!(cone(0.75, 1.0, 0.5), 0.25);
        assert_eq!(cone(0.4, 1.0, 0.5), 0.0);
        assert_eq!(cone(1.0, 0.9, 0.5), 1.0);
    }

    #[test]
    fn a_directional_light_gives_its_lux_everywhere() {
        let light = Punctual {
            shape: Shape::Directional {
                direction: -DVec3::Y,
            },
            color: Color::ONE,
            intensity: 3.0,
            range: Some(1.0),
        };
        let inc = light.incident(DVec3::new(5.0, -7.0, 1.0)).unwrap();
        assert_eq!((inc.l, inc.intensity), (DVec3::Y, 3.0));
        assert!(inc.dist.is_infinite());
    }

    #[test]
    fn a_spot_lights_nothing_outside_its_outer_cone() {
        let light = Punctual {
            shape: Shape::Spot {
                position: DVec3::ZERO,
                axis: -DVec3::Y,
                cos_inner: 1.0,
                cos_outer: std::f64::consts::FRAC_PI_4.cos(),
            },
            color: Color::ONE,
            intensity: 1.0,
            range: None,
        };
        assert!(light.incident(DVec3::new(0.0, -1.0, 0.0)).is_some());
        assert!(light.incident(DVec3::new(2.0, -1.0, 0.0)).is_none());
    }
}
