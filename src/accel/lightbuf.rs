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
//! enclose the light (a sky dome) are in no cell: a shadow ray from a point also well
//! inside one (by 2δ) stays inside it and cannot meet it; from elsewhere it is tested.

use super::dirgrid::DirGrid;
use crate::object::{Light, Object};
use crate::optics::Ray;
use crate::shapes::Shape;
use crate::texture::Color;
use glam::DVec3;

/// An opaque sphere around the light: (object, centre, (r − 2δ)²).
type Enclosing = (u32, DVec3, f64);

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

fn is_opaque(o: &Object) -> bool {
    o.material.kt <= 0.0
}

fn is_glass(o: &Object) -> bool {
    o.material.kt > 0.0
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
                Shape::Sphere(s) => (i as u32, s.center, (s.radius - 2.0 * delta).powi(2)),
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
    /// The shadow grids of `lights` over `objects`.
    pub fn new(objects: &[Object], lights: &[Light]) -> LightBuffer {
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
    #[inline]
    pub fn transmission(
        &self,
        light: usize,
        objects: &[Object],
        p: DVec3,
        to_light: DVec3,
        dist: f64,
    ) -> Option<Color> {
        let sg = self.lights.get(light)?.as_ref()?;
        if !sg.grid.covers(p) {
            return None;
        }
        let (opaque, glass) = sg.grid.cell(-to_light)?;
        let ray = Ray::new(p, to_light);
        for &(i, c, inside2) in &sg.enclosing {
            if (p - c).length_squared() > inside2
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
                through *= obj.material.kt * obj.texture.color_at(ray.at(t));
            }
        }
        Some(through)
    }
}
