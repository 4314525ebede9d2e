//! The `area` light (SPEC §16, POV-Ray's `area_light` without jitter): a rectangle
//! centred at P with edges A1 and A2. Shading takes the direction to P; the shadow factor
//! is the mean transmission over the N1 × N2 points
//! P + A1·(i/(N1−1) − ½) + A2·(j/(N2−1) − ½) (an axis with N = 1 has no offset): soft
//! shadows, the same on every run. Each point costs one shadow ray.

use super::point::towards;
use super::{ext_key, Clearance, Occluders};
use super::{Incident, LightSource};
use crate::base::Color;
use glam::DVec3;

/// A rectangle of shadow points lighting as its centre.
#[derive(Clone, Debug, PartialEq)]
pub struct Area {
    /// The centre P: the direction for shading.
    pub position: DVec3,
    /// The N1 × N2 shadow points, i major.
    pub points: Vec<DVec3>,
    /// The grid's four extreme points, in order round it: every point lies in their
    /// quadrilateral (the shaft's base, `Occluders::clearance`).
    pub corners: [DVec3; 4],
    /// Its colour.
    pub color: Color,
    /// Its intensity.
    pub intensity: f64,
}

/// The offset of grid index `i` of `n` along an edge, in −½..½ (0 when n = 1).
fn offset(i: u32, n: u32) -> f64 {
    if n <= 1 {
        0.0
    } else {
        i as f64 / (n - 1) as f64 - 0.5
    }
}

impl Area {
    /// The light at `position` with edges `a1`, `a2` and an `n1` × `n2` grid (each ≥ 1).
    pub fn new(
        position: DVec3,
        a1: DVec3,
        a2: DVec3,
        n1: u32,
        n2: u32,
        color: Color,
        intensity: f64,
    ) -> Area {
        let mut points = Vec::with_capacity((n1 * n2) as usize);
        for i in 0..n1 {
            for j in 0..n2 {
                points.push(position + a1 * offset(i, n1) + a2 * offset(j, n2));
            }
        }
        let at = |i: u32, j: u32| points[(i * n2 + j) as usize];
        let corners = [at(0, 0), at(n1 - 1, 0), at(n1 - 1, n2 - 1), at(0, n2 - 1)];
        Area {
            position,
            points,
            corners,
            color,
            intensity,
        }
    }
}

impl LightSource for Area {
    fn color(&self) -> Color {
        self.color
    }

    fn incident(&self, p: DVec3) -> Option<Incident> {
        towards(self.position, p, self.intensity)
    }

    /// The mean of the transmissions towards every grid point (a point on `p` itself lets
    /// everything through). Where the shaft from `p` to the grid's corners holds nothing
    /// bounded (`Occluders::clearance`: most of a floor around a model), each ray asks
    /// only the unbounded objects, the same answer without walking a tree; where it
    /// holds nothing at all, no ray is cast (but each is counted).
    fn shadow<O: Occluders + ?Sized>(
        &self,
        k: usize,
        occluders: &O,
        p: DVec3,
        _inc: &Incident,
        rays: &mut u64,
    ) -> Color {
        let clear = if self.points.len() > 1 {
            occluders.clearance(p, &self.corners)
        } else {
            Clearance::Unknown
        };
        if clear == Clearance::Open {
            // Every ray would let everything through: the sum of ones divided by their
            // count is exactly one. The rays are still counted.
            *rays += self
                .points
                .iter()
                .filter(|&&q| (q - p).length_squared() != 0.0)
                .count() as u64;
            return Color::ONE;
        }
        let mut sum = Color::ZERO;
        for (i, &q) in self.points.iter().enumerate() {
            let to = q - p;
            let dist = to.length();
            if dist == 0.0 {
                sum += Color::ONE;
                continue;
            }
            *rays += 1;
            sum += if clear == Clearance::Unbounded {
                occluders.transmission_unbounded(p, to / dist, dist)
            } else {
                occluders.transmission_keyed(ext_key(k, i), p, to / dist, dist)
            };
        }
        sum / self.points.len() as f64
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bump::Bump;
    use crate::object::{Highlight, Material, Object};
    use crate::shapes::{Shape, Sphere};
    use crate::texture::Texture;

    #[test]
    fn grid_points_by_hand() {
        let a = Area::new(
            DVec3::new(0.0, 5.0, 0.0),
            DVec3::new(2.0, 0.0, 0.0),
            DVec3::new(0.0, 0.0, 4.0),
            2,
            3,
            Color::ONE,
            1.0,
        );
        let want = [
            (-1.0, -2.0),
            (-1.0, 0.0),
            (-1.0, 2.0),
            (1.0, -2.0),
            (1.0, 0.0),
            (1.0, 2.0),
        ];
        assert_eq!(a.points.len(), 6);
        for (q, (x, z)) in a.points.iter().zip(want) {
            assert_eq!(*q, DVec3::new(x, 5.0, z));
        }
        // A 1 × 1 grid is its centre.
        let one = Area::new(DVec3::Y, DVec3::X, DVec3::Z, 1, 1, Color::ONE, 1.0);
        assert_eq!(one.points, vec![DVec3::Y]);
    }

    #[test]
    fn a_blocker_hides_part_of_the_grid() {
        // A 2 × 1 grid at x = ±1, y = 10; a small opaque ball above x = 1 hides one of the
        // two points from the origin: half the light gets through, two rays cast.
        let a = Area::new(
            DVec3::new(0.0, 10.0, 0.0),
            DVec3::new(2.0, 0.0, 0.0),
            DVec3::Z,
            2,
            1,
            Color::ONE,
            1.0,
        );
        let ball = Object {
            shape: Shape::Sphere(Sphere::new(DVec3::new(0.5, 5.0, 0.0), 0.2)),
            texture: Texture::Uniform(Color::ONE),
            material: Material {
                kd: 1.0,
                kr: 0.0,
                kt: 0.0,
                ior: 1.0,
                bump: Bump::None,
                highlight: Highlight::Report,
            },
        };
        let objects = [ball];
        let inc = a.incident(DVec3::ZERO).unwrap();
        let mut rays = 0;
        let t = a.shadow(0, &objects[..], DVec3::ZERO, &inc, &mut rays);
        assert_eq!(t, Color::splat(0.5));
        assert_eq!(rays, 2);
    }
}
