//! The light buffer (Haines and Greenberg, 1986): per light, a direction grid
//! (`DirGrid`) whose cells list the objects that may stand between the light and a point
//! seen from it in that direction — opaque ones first, then transparent ones, each in
//! object order — so that a shadow ray tests one or two objects instead of all.
//!
//! It depends on the light positions as well as the shapes, so it is built per scene
//! (`Tracer::new` and `Tracer::with_accel` both build it; a few tens of microseconds),
//! never shared between scenes whose lights differ.
//!
//! Answers are exactly `shading::transmission`'s: a light's cell lists every object a
//! shadow ray in it may meet (see `dirgrid` for the margins), blockers end the query with
//! black whatever their order, and the transparent crossings are multiplied in object
//! order and, within an object, in t order, as the linear scan does. Opaque spheres that
//! enclose the light (a sky dome) are in no cell: a shadow ray from a point inside one,
//! or on it (within a shell thin enough that the entry is closer than ε), cannot meet it;
//! from further out it is tested (`outside2`).

use super::dirgrid::DirGrid;
use super::{is_glass, is_opaque};
use crate::base::Color;
use crate::lights::PointLight;
use crate::object::Object;
use crate::optics::Ray;
use crate::shapes::Shape;
use glam::DVec3;

/// An opaque sphere around the light: (object, centre, the squared distance from the
/// centre beyond which a shadow ray may meet it; see `outside2`).
type Enclosing = (u32, DVec3, f64);

/// For an opaque sphere (centre c, radius R) around a light at distance ℓ < R − 2δ from c:
/// the ρ² = |p − c|² up to which a shadow ray from p cannot meet the sphere. Inside
/// (ρ ≤ R) the ray leaves through the far side, beyond the light (by R − ℓ ≥ 2δ). Just
/// outside, it enters at t0 = (ρ² − R²)/(oh + √…) ≤ (ρ² − R²)/√(R² − ℓ²), because
/// oh = (c − p)·d = ρ·cos θ ≥ √(ρ² − ℓ²) in the triangle p, c, light. So for
/// ρ² ≤ R² + 0.005·√(R² − ℓ²), t0 ≤ 0.005, below the report's ε = 0.01 by far more than
/// the rounding of the test: the points that lie on the sphere (the sky dome's own
/// shading points) skip it, and the branch is the same for nearly every point.
fn outside2(radius: f64, ell: f64) -> f64 {
    radius * radius + 0.005 * ((radius - ell) * (radius + ell)).sqrt()
}

#[derive(Clone, Debug)]
struct ShadowGrid {
    grid: DirGrid,
    enclosing: Vec<Enclosing>,
}

/// One shadow grid per light (`None` where none could be built: the full query answers).
#[derive(Clone, Debug, Default)]
pub struct LightBuffer {
    lights: Vec<Option<ShadowGrid>>,
}

impl ShadowGrid {
    fn build(light: DVec3, objects: &[Object]) -> Option<ShadowGrid> {
        let (_, delta) = DirGrid::margins(light, objects)?;
        let encloses = |o: &Object| match o.shape {
            Shape::Sphere(s) => {
                is_opaque(o) && (s.center - light).length() <= s.radius - 2.0 * delta
            }
            _ => false,
        };
        let enclosing = objects
            .iter()
            .enumerate()
            .filter(|(_, o)| encloses(o))
            .map(|(i, o)| match o.shape {
                Shape::Sphere(s) => (
                    i as u32,
                    s.center,
                    outside2(s.radius, (s.center - light).length()),
                ),
                _ => unreachable!("only spheres enclose"),
            })
            .collect();
        let grid = DirGrid::build(light, objects, |o| {
            if encloses(o) {
                None
            } else if is_opaque(o) {
                Some(true)
            } else if is_glass(o) {
                Some(false)
            } else {
                None // a NaN Kt: in neither of the linear scan's loops
            }
        })?;
        Some(ShadowGrid { grid, enclosing })
    }
}

impl LightBuffer {
    /// The shadow grids of `scene`'s lights over its objects, or none (every shadow ray
    /// scans) when its rays start past another epsilon than the report's: the grids'
    /// proofs (`outside2`) assume `T_MIN`.
    pub fn for_scene(scene: &crate::scene::Scene) -> LightBuffer {
        if scene.t_min == crate::optics::T_MIN {
            LightBuffer::new(&scene.objects, &scene.lights)
        } else {
            LightBuffer::default()
        }
    }

    /// The shadow grids of `lights` over `objects`.
    pub fn new(objects: &[Object], lights: &[PointLight]) -> LightBuffer {
        LightBuffer {
            lights: lights
                .iter()
                .map(|l| ShadowGrid::build(l.position, objects))
                .collect(),
        }
    }

    /// What a shadow ray from `p` along the unit `to_light`, towards light number `light`
    /// `dist` away, lets through — exactly `shading::transmission(objects, ..)` — or
    /// `None` when the buffer cannot answer (no grid, `p` beyond its bound).
    ///
    /// `to` is the vector from `p` to the light that `to_light` normalises: the cell is
    /// looked up from it, so that the lookup need not wait for the square root and the
    /// division of the normalisation (the octahedral map ignores length, and the two
    /// directions differ by a few ulps, far inside the cells' angular margin).
    #[inline(always)]
    pub fn transmission(
        &self,
        light: usize,
        objects: &[Object],
        p: DVec3,
        to: DVec3,
        to_light: DVec3,
        dist: f64,
    ) -> Option<Color> {
        let sg = self.lights.get(light)?.as_ref()?;
        if !sg.grid.covers(p) {
            return None;
        }
        let (opaque, glass) = sg.grid.cell(-to)?;
        let ray = Ray::new(p, to_light);
        for &(i, c, outside2) in &sg.enclosing {
            if (p - c).length_squared() > outside2
                && objects[i as usize].shape.hit(&ray, dist).is_some()
            {
                return Some(Color::ZERO);
            }
        }
        for i in opaque {
            if objects[i].shape.hit(&ray, dist).is_some() {
                return Some(Color::ZERO);
            }
        }
        let mut through = Color::ONE;
        for i in glass {
            let obj = &objects[i];
            for t in obj.shape.crossings(&ray, dist) {
                through *= obj.material.kt * obj.color_at(ray.at(t));
            }
        }
        Some(through)
    }
}

#[cfg(test)]
mod tests {
    use super::outside2;

    #[test]
    fn the_shell_around_an_enclosing_sphere_by_hand() {
        // R = 1000, light at the centre: R² + 0.005·R = 1,000,005 (ρ ≈ R + 0.0025).
        assert_eq!(outside2(1000.0, 0.0), 1_000_005.0);
        // R = 5, light 3 from the centre: √(25 − 9) = 4, so 25 + 0.02.
        assert_eq!(outside2(5.0, 3.0), 25.02);
    }
}
