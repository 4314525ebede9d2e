//! First-hit culling of camera rays by screen tiles (after Weghorst, Hooper and
//! Greenberg, 1984), and of their mirror reflections off a polished plane.
//!
//! The image is cut into tiles of `TILE`×`TILE` pixels. The camera rays of a tile (every
//! sample of its pixels) leave the eye within a small cone — the camera is a pinhole, so
//! their directions are the conic hull of the directions through the tile's four
//! corners — and the tile lists, as a bit set in object order, the objects a ray in that
//! cone may meet (`dirgrid::may_hit`, with the same widened margins as the direction
//! grids). A camera ray tests only its tile's objects: no lookup, and lists far shorter
//! than a direction grid's cells (a 16-pixel tile is about a degree wide).
//!
//! Mirror rays. A camera ray reflected off a plane (Kr > 0, no bump) leaves the hit point
//! along the line that comes from the eye's mirror image E′ in the plane: the reflected
//! rays of a tile are the rays of the mirrored cone from E′, up to the rounding of the
//! hit point and of the reflected direction (a few ulps of the coordinates, far below the
//! margin δ). So each tile has a second list, the objects the mirrored cone from E′ may
//! meet, for the reflection ray of its camera rays that hit that plane. The floor of a
//! scene sends most of a frame's secondary rays; they test the sky and what is really
//! above them instead of every object.
//!
//! The answers are the linear scan's exactly: objects left out cannot be hit (see
//! `dirgrid`), and the lists are scanned in object order keeping the first of equal t.
//! Built per frame (it depends on the camera): about a thousand cone tests per object.

use super::dirgrid::{Cone, DirGrid, Objects};
use crate::bump::Bump;
use crate::camera::Camera;
use crate::object::Object;
use crate::optics::Ray;
use crate::shapes::Shape;
use glam::DVec3;

/// Tile side, in pixels.
const TILE: u32 = 16;

/// The mirrored lists: which plane, the bound of the hit points they may answer for, and
/// one bit set per tile.
#[derive(Clone, Debug)]
struct Mirror {
    plane: usize,
    bound: f64,
    sets: Vec<u64>,
}

/// The candidate lists of one frame's camera rays, per tile.
#[derive(Clone, Debug)]
pub struct TileView {
    eye: DVec3,
    cols: u32,
    direct: Vec<u64>,
    mirror: Option<Mirror>,
}

/// The lists of the tile of one camera ray.
#[derive(Clone, Copy, Debug)]
pub struct Hint<'a> {
    view: &'a TileView,
    tile: usize,
}

/// The first plane whose reflections the tiles can list: polished (Kr > 0), not bumped.
fn mirror_plane(objects: &[Object]) -> Option<(usize, DVec3, DVec3)> {
    objects.iter().enumerate().find_map(|(k, o)| match o.shape {
        Shape::Plane(p) if o.material.kr > 0.0 && o.material.bump == Bump::None => {
            Some((k, p.point, p.normal()))
        }
        _ => None,
    })
}

/// The bit set of the objects a ray from `from` in `cone` may meet.
fn candidates(objects: &[Object], from: DVec3, cone: &Cone, delta: f64) -> u64 {
    objects
        .iter()
        .enumerate()
        .filter(|(_, o)| super::dirgrid::may_hit(&o.shape, from, cone, delta))
        .fold(0, |set, (k, _)| set | 1 << k)
}

impl TileView {
    /// The tiles of a `width`×`height` image seen through `camera`; `None` when there are
    /// too many objects for bit sets (the BVH answers) or coordinates are not finite.
    pub fn new(camera: &Camera, width: u32, height: u32, objects: &[Object]) -> Option<TileView> {
        let eye = camera.eye();
        let (_, delta) = DirGrid::margins(eye, objects)?;
        let mirror = mirror_plane(objects).and_then(|(plane, point, n)| {
            let image = eye - 2.0 * n.dot(eye - point) * n;
            let (bound, delta) = DirGrid::margins(image, objects)?;
            Some((plane, n, image, bound, delta))
        });
        let (cols, rows) = (width.div_ceil(TILE), height.div_ceil(TILE));
        let mut direct = Vec::with_capacity((cols * rows) as usize);
        let mut sets = Vec::with_capacity(if mirror.is_some() {
            direct.capacity()
        } else {
            0
        });
        for tj in 0..rows {
            for ti in 0..cols {
                let (x0, x1) = (ti * TILE, ((ti + 1) * TILE).min(width));
                let (y0, y1) = (tj * TILE, ((tj + 1) * TILE).min(height));
                let dir = |x: u32, y: u32| camera.ray(f64::from(x), f64::from(y)).dir;
                let axis = camera
                    .ray(0.5 * f64::from(x0 + x1), 0.5 * f64::from(y0 + y1))
                    .dir;
                let cone =
                    Cone::around(axis, &[dir(x0, y0), dir(x1, y0), dir(x0, y1), dir(x1, y1)]);
                direct.push(candidates(objects, eye, &cone, delta));
                if let Some((_, n, image, _, delta)) = mirror {
                    sets.push(candidates(objects, image, &cone.mirrored(n), delta));
                }
            }
        }
        Some(TileView {
            eye,
            cols,
            direct,
            mirror: mirror.map(|(plane, _, _, bound, _)| Mirror { plane, bound, sets }),
        })
    }

    /// The lists for the camera rays of pixel (i, j).
    #[inline]
    pub fn hint(&self, i: u32, j: u32) -> Hint<'_> {
        Hint {
            view: self,
            tile: ((j / TILE) * self.cols + i / TILE) as usize,
        }
    }
}

/// The linear scan over the objects of `set`, in object order.
#[inline]
fn scan(objects: &[Object], set: u64, ray: &Ray) -> Option<(f64, usize)> {
    let mut best = None;
    let mut t_max = f64::INFINITY;
    for i in Objects(set) {
        if let Some(t) = objects[i].shape.hit(ray, t_max) {
            t_max = t;
            best = Some((t, i));
        }
    }
    best
}

impl Hint<'_> {
    /// The nearest hit (t, object index) of a camera ray of this tile, as the linear
    /// scan finds it; `None` when the lists cannot answer (the ray does not leave the eye).
    #[inline]
    pub fn nearest(&self, objects: &[Object], ray: &Ray) -> Option<Option<(f64, usize)>> {
        (ray.origin == self.view.eye).then(|| scan(objects, self.view.direct[self.tile], ray))
    }

    /// The nearest hit of the mirror reflection of a camera ray of this tile that hit
    /// `mirror_plane()` (`ray` starts at that hit point, along the reflected direction;
    /// the caller checks which object was hit); `None` when the lists cannot answer (no
    /// mirror plane, or a hit point beyond their bound).
    #[inline]
    pub fn mirrored(&self, objects: &[Object], ray: &Ray) -> Option<Option<(f64, usize)>> {
        let m = self.view.mirror.as_ref()?;
        let a = ray.origin.abs();
        if !(a.x <= m.bound && a.y <= m.bound && a.z <= m.bound) {
            return None;
        }
        Some(scan(objects, m.sets[self.tile], ray))
    }

    /// The plane whose reflections `mirrored` answers for, if any.
    #[inline]
    pub fn mirror_plane(&self) -> Option<usize> {
        self.view.mirror.as_ref().map(|m| m.plane)
    }
}
