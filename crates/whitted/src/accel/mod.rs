//! Acceleration structures, built once per scene (in `Tracer::new`) and shared by every
//! frame and thread: a BVH over the spheres, a second BVH over the other bounded shapes
//! (an NFF's triangles and cones; empty for a Scene.txt) and plain lists of the unbounded
//! ones (planes, cylinders), which every query tests. Shadow rays are `shadow`'s.
//!
//! Every query answers exactly what the linear scans over `Scene::objects` answer, bit for
//! bit (the linear versions are kept as the reference, and the tests compare them):
//! - `nearest`: the hit with the smallest t, and on equal t the object that comes first in
//!   the file, as the linear scan (which only replaces its best on a strictly smaller t)
//!   keeps it;
//! - `transmission`: black when an opaque object blocks the shadow ray, otherwise the
//!   product of `Kt·C` over the crossings of transparent objects, multiplied in object
//!   order and, within an object, in t order — the linear scan's order, so that the
//!   rounding of the product is the same.

mod bvh;
mod dirgrid;
mod lightbuf;
mod shadow;
mod tiles;

pub use bvh::{Bounded, Bvh, Prim, ShapePrim};
pub use dirgrid::DirGrid;
pub use lightbuf::LightBuffer;
pub use tiles::{Hint, TileView};

use crate::object::Object;
use crate::optics::{Ray, T_MIN};
use crate::shapes::Shape;

/// Up to this many transparent objects, shadow rays test them all in order after the
/// tree, as the linear scan does; past it they collect the crossings the tree finds.
const GLASS_LINEAR_MAX: usize = 4;
/// Crossings a shadow ray collects before it gives up and falls back to the linear loop
/// over every transparent object (no allocation either way).
const CROSSINGS_MAX: usize = 32;

/// The scene's objects sorted for fast ray queries.
#[derive(Clone, Debug, Default)]
pub struct Accel {
    /// Every bounded object: nearest hits, and shadow rays (which stop at the first
    /// opaque hit, and note the transparent crossings on the way).
    tree: Bvh,
    /// Every other bounded object (triangles, smooth triangles, cones).
    shapes: Bvh<ShapePrim>,
    /// The scene's epsilon, given to the shadow rays (`Scene::t_min`).
    t_min: f64,
    /// Unbounded objects, in object order, with their indices.
    unbounded: Vec<(u32, Shape)>,
    unbounded_opaque: Vec<Shape>,
    unbounded_glass: Vec<u32>,
    /// Every object with Kt > 0, in object order.
    glass_all: Vec<u32>,
}

/// Kt > 0: shadow rays cross it (the linear scan's second loop).
fn is_glass(o: &Object) -> bool {
    o.material.kt > 0.0
}

/// Kt ≤ 0: it stops shadow rays (the linear scan's first loop). Not simply `!is_glass`:
/// an object with a NaN Kt is in neither loop.
fn is_opaque(o: &Object) -> bool {
    o.material.kt <= 0.0
}

impl Accel {
    /// Builds the accelerator over `objects` (a BVH over the spheres from 13 spheres up, the
    /// unbounded shapes in a flat list), for rays with the report's epsilon.
    pub fn new(objects: &[Object]) -> Accel {
        Accel::with_t_min(objects, T_MIN)
    }

    /// The accelerator of `scene`'s objects, for rays with its epsilon.
    pub fn for_scene(scene: &crate::scene::Scene) -> Accel {
        Accel::with_t_min(&scene.objects, scene.t_min)
    }

    /// `new`, casting shadow rays with the epsilon `t_min` (`Scene::t_min`).
    pub fn with_t_min(objects: &[Object], t_min: f64) -> Accel {
        let shapes: Vec<ShapePrim> = objects
            .iter()
            .enumerate()
            .filter(|(_, o)| o.shape.is_bounded() && !matches!(o.shape, Shape::Sphere(_)))
            .map(|(i, o)| ShapePrim {
                shape: o.shape.clone(),
                index: i as u32,
                glass: is_glass(o),
                opaque: is_opaque(o),
            })
            .collect();
        let prims: Vec<Prim> = objects
            .iter()
            .enumerate()
            .filter_map(|(i, o)| match o.shape {
                Shape::Sphere(sphere) => Some(Prim {
                    sphere,
                    index: i as u32,
                    glass: is_glass(o),
                    opaque: is_opaque(o),
                }),
                _ => None,
            })
            .collect();
        let unbounded = |keep: &dyn Fn(&Object) -> bool| -> Vec<(u32, Shape)> {
            objects
                .iter()
                .enumerate()
                .filter(|(_, o)| !o.shape.is_bounded() && keep(o))
                .map(|(i, o)| (i as u32, o.shape.clone()))
                .collect()
        };
        Accel {
            tree: Bvh::build(prims),
            shapes: Bvh::build(shapes),
            t_min,
            unbounded: unbounded(&|_| true),
            unbounded_opaque: unbounded(&is_opaque).into_iter().map(|(_, s)| s).collect(),
            unbounded_glass: unbounded(&is_glass).into_iter().map(|(i, _)| i).collect(),
            glass_all: (0..objects.len() as u32)
                .filter(|&i| is_glass(&objects[i as usize]))
                .collect(),
        }
    }

    /// The nearest hit (t, object index), as the linear scan finds it. Kept out of line:
    /// its callers (camera and secondary rays) stay small, and the compiler's choice
    /// otherwise changed with unrelated edits (2 % of the 10,000-sphere frame either way).
    #[inline(never)]
    pub fn nearest(&self, ray: &Ray) -> Option<(f64, usize)> {
        let mut best_t = f64::INFINITY;
        let mut best_i = u32::MAX;
        for &(i, ref shape) in &self.unbounded {
            if let Some(t) = shape.hit(ray, f64::INFINITY) {
                if t < best_t || (t == best_t && i < best_i) {
                    best_t = t;
                    best_i = i;
                }
            }
        }
        self.tree.traverse(ray, best_t, |prim, limit| {
            if let Some(t) = prim.sphere.hit(ray, f64::INFINITY) {
                if t < best_t || (t == best_t && prim.index < best_i) {
                    best_t = t;
                    best_i = prim.index;
                    return Some(t);
                }
            }
            Some(limit)
        });
        if !self.shapes.is_empty() {
            self.shapes.traverse(ray, best_t, |prim, limit| {
                if let Some(t) = prim.shape.hit(ray, f64::INFINITY) {
                    if t < best_t || (t == best_t && prim.index < best_i) {
                        best_t = t;
                        best_i = prim.index;
                        return Some(t);
                    }
                }
                Some(limit)
            });
        }
        (best_i != u32::MAX).then_some((best_t, best_i as usize))
    }
}

#[cfg(test)]
mod grid_tests;

#[cfg(test)]
mod tests;
