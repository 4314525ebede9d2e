//! First-hit culling of camera rays (after Weghorst, Hooper and Greenberg, 1984): every
//! camera ray of a frame leaves the eye, so a direction grid around the eye (`DirGrid`)
//! lists, per cell, the objects a ray in it may meet, in object order; a camera ray tests
//! only its cell's objects. Built per frame (it depends on the eye), in microseconds.
//!
//! The answer is the linear scan's exactly: objects left out of a cell cannot be hit by
//! its rays (see `dirgrid`), and the cell's objects are scanned in file order keeping the
//! first of equal t, as the linear scan does.

use super::dirgrid::DirGrid;
use crate::object::Object;
use crate::optics::Ray;
use glam::DVec3;

/// The candidates of camera rays from one eye.
#[derive(Clone, Debug)]
pub struct ViewGrid {
    grid: DirGrid,
}

impl ViewGrid {
    /// The grid around `eye` over `objects`; `None` when there are too many objects for
    /// a grid to pay (the BVH answers) or coordinates are not finite.
    pub fn new(eye: DVec3, objects: &[Object]) -> Option<ViewGrid> {
        let grid = DirGrid::build(eye, objects, |_| Some(true))?;
        Some(ViewGrid { grid })
    }

    /// The nearest hit (t, object index) of a ray leaving the eye, as the linear scan
    /// finds it; `None` when the grid cannot answer (another origin).
    #[inline]
    pub fn nearest(&self, objects: &[Object], ray: &Ray) -> Option<Option<(f64, usize)>> {
        if ray.origin != self.grid.center() {
            return None;
        }
        let (cands, _) = self.grid.cell(ray.dir)?;
        let mut best = None;
        let mut t_max = f64::INFINITY;
        for i in cands {
            if let Some(t) = objects[i].shape.hit(ray, t_max) {
                t_max = t;
                best = Some((t, i));
            }
        }
        Some(best)
    }
}
