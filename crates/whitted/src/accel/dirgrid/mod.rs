//! Direction grids: for one point (a light), the directions around it cut into the cells
//! of an octahedral map — direction d ↦ (u, v) = (dx, dy)/(|dx| + |dy| + |dz|), an
//! N × N square per hemisphere (dz ≥ 0, dz < 0) — each cell listing the objects a ray
//! from that point along one of its directions may meet: the light buffer of Haines and
//! Greenberg (1986) for shadow rays. A query looks up its direction's cell (one division,
//! two truncations, no branch on the face) and tests only that cell's objects. The cone
//! tests (`may_hit`, `Cone`) also serve the screen tiles of camera rays (`tiles`).
//!
//! Exactness. A cell lists every object whose (widened) cone of directions seen from the
//! point overlaps the cell's (widened) cone; an object left out cannot be hit by a ray
//! in that cell, because the shape tests' rounding is far smaller than the widening:
//! - a sphere of radius r at distance D subtends asin((r + δ)/D); closer than r + δ, it
//!   is in every cell. δ = `PAD`·(4B + 1), B bounding every coordinate involved (queries
//!   from points beyond B are not answered: the caller falls back to the full scan); the
//!   sphere test's error is about 1e-8·B, a few thousand times less;
//! - a plane is left out of the cells whose directions all point away from it (by more
//!   than the margin), from a point more than δ away from it: a ray between the point and
//!   the plane's far side never crosses it;
//! - a cylinder (a quadric made by `Quadric::cylinder`) is left out of the cells whose
//!   directions, seen along its axis, all pass further than its radius + δ from it; any
//!   other quadric is in every cell;
//! - cell cones are bounded by their corners: N is even, so a cell lies within one
//!   quadrant of (u, v), where the map is affine; its directions are the conic hull of
//!   its corners', and the widest angle from the cell's centre direction is at a corner.
//!   They are widened by `ANGLE_PAD`, which covers the rounding of the lookup and of the
//!   cone tests at build time.
//!
//! Cells list their objects in object order, in two groups chosen by the builder (shadow
//! rays: opaque, then transparent), so that a caller looping over a cell's list meets the
//! objects in the order of the linear scan.

use crate::object::Object;
use crate::shapes::{Quadric, Shape};
use glam::DVec3;
use std::sync::OnceLock;

/// Cells per side of each hemisphere's octahedral square (even: no cell straddles a
/// quadrant).
const N: usize = 16;
/// Relative distance margin, as in the BVH (`bvh::PAD`).
const PAD: f64 = 1e-5;
/// Angular margin of every cell cone, in radians.
const ANGLE_PAD: f64 = 1e-6;
/// Objects beyond which no grid is built (its build would cost more than it saves; the
/// BVH answers instead).
pub const GRID_MAX_OBJECTS: usize = 64;

/// Which group of a cell an object goes into: `None` leaves it out altogether.
pub type Group = Option<bool>;

/// The cells around one point.
#[derive(Clone, Debug)]
pub struct DirGrid {
    /// Queries from points with a coordinate beyond this are not answered.
    bound: f64,
    /// Per cell: the objects of the first group and of the second, as bit sets (bit k:
    /// object k; at most 64 objects).
    cells: Vec<[u64; 2]>,
}

/// A set of object indices below 64, iterated in increasing order (object order).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Objects(pub u64);

impl Iterator for Objects {
    type Item = usize;
    #[inline(always)]
    fn next(&mut self) -> Option<usize> {
        if self.0 == 0 {
            return None;
        }
        let k = self.0.trailing_zeros() as usize;
        self.0 &= self.0 - 1;
        Some(k)
    }
}

/// A cell's cone: unit axis, sine and cosine of its widened half-angle.
pub(super) struct Cone {
    axis: DVec3,
    sin: f64,
    cos: f64,
}

/// The direction of octahedral coordinates (u, v) in −1..1 of hemisphere `h` (0: z ≥ 0,
/// 1: z < 0): the point (u, v, ±(1 − |u| − |v|)), not normalised. Outside the diamond
/// |u| + |v| ≤ 1 it continues the same plane (within a quadrant), below the equator.
fn octa_dir(h: usize, u: f64, v: f64) -> DVec3 {
    let z = 1.0 - u.abs() - v.abs();
    DVec3::new(u, v, if h == 0 { z } else { -z })
}

impl Cone {
    /// The cone around the unit `axis` that holds every direction of the conic hull of
    /// `corners` (directions of the corners of a planar convex region, any length),
    /// widened by `ANGLE_PAD`.
    pub(super) fn around(axis: DVec3, corners: &[DVec3]) -> Cone {
        let half = corners
            .iter()
            .map(|c| axis.dot(c.normalize()).clamp(-1.0, 1.0).acos())
            .fold(0.0f64, f64::max)
            + ANGLE_PAD;
        Cone {
            axis,
            sin: half.sin(),
            cos: half.cos(),
        }
    }

    /// The same cone reflected in a plane of unit normal `n` (angles are kept).
    pub(super) fn mirrored(&self, n: DVec3) -> Cone {
        Cone {
            axis: (self.axis - 2.0 * self.axis.dot(n) * n).normalize(),
            sin: self.sin,
            cos: self.cos,
        }
    }
}

/// The cones of every cell, in cell order: the same for every grid, computed once.
fn cones() -> &'static [Cone] {
    static CONES: OnceLock<Vec<Cone>> = OnceLock::new();
    CONES.get_or_init(|| {
        (0..2)
            .flat_map(|h| (0..N).flat_map(move |i| (0..N).map(move |j| cell_cone(h, i, j))))
            .collect()
    })
}

/// A cell lies within one quadrant of (u, v) (N is even), where the map is affine: its
/// directions are the conic hull of its four corners' directions, and the widest angle
/// from the cell's centre direction is at a corner.
fn cell_cone(h: usize, i: usize, j: usize) -> Cone {
    let at = |k: usize| -1.0 + 2.0 * k as f64 / N as f64;
    let (u0, u1, v0, v1) = (at(i), at(i + 1), at(j), at(j + 1));
    let axis = octa_dir(h, 0.5 * (u0 + u1), 0.5 * (v0 + v1)).normalize();
    let corners = [(u0, v0), (u0, v1), (u1, v0), (u1, v1)].map(|(u, v)| octa_dir(h, u, v));
    Cone::around(axis, &corners)
}

/// The largest coordinate, in absolute value, of the point and of every shape's defining
/// points (the far side of spheres included); `None` when something is not finite.
fn bound(center: DVec3, objects: &[Object]) -> Option<f64> {
    let mut b = center.abs().max_element();
    for o in objects {
        let r = match o.shape {
            Shape::Sphere(s) => s.center.abs().max_element() + s.radius,
            Shape::Plane(p) => p.point.abs().max_element(),
            Shape::Quadric(q) => q.origin.abs().max_element(),
            // An NFF's shapes: no grid (`LightBuffer` answers nothing, the BVH does).
            Shape::Triangle(_)
            | Shape::Smooth(_)
            | Shape::Cone(_)
            | Shape::Placed(_)
            | Shape::Mesh(_)
            | Shape::Csg(_) => return None,
        };
        b = b.max(r);
        if !r.is_finite() {
            return None;
        }
    }
    b.is_finite().then_some(b)
}

/// May a ray from `from` along a direction of `cone` meet `shape`? (False only when it
/// cannot, widened by `delta`.)
pub(super) fn may_hit(shape: &Shape, from: DVec3, cone: &Cone, delta: f64) -> bool {
    match shape {
        Shape::Sphere(s) => {
            let to = s.center - from;
            let d = to.length();
            let r = s.radius + delta;
            if d <= r {
                return true;
            }
            let sin = r / d;
            let cos = (1.0 - sin * sin).sqrt();
            // angle(axis, to) ≤ cell half-angle + sphere half-angle, in cosines.
            cone.axis.dot(to / d) >= cone.cos * cos - cone.sin * sin - 1e-12
        }
        Shape::Plane(p) => {
            let h = p.normal().dot(from - p.point);
            if h.abs() <= delta {
                return true;
            }
            let away = if h > 0.0 { p.normal() } else { -p.normal() };
            // Every direction of the cone points away from the plane: it is never met.
            cone.axis.dot(away) <= cone.sin + 1e-9
        }
        Shape::Quadric(q) => match cylinder_of(q) {
            Some((axis, point, radius)) => {
                cylinder_may_hit(axis, point, radius + delta, from, cone)
            }
            None => true,
        },
        Shape::Triangle(_)
        | Shape::Smooth(_)
        | Shape::Cone(_)
        | Shape::Placed(_)
        | Shape::Mesh(_)
        | Shape::Csg(_) => true,
    }
}

/// The axis, a point of the axis and the radius of a quadric made by
/// `Quadric::cylinder`, recovered from its coefficients (and checked: rebuilt, they must
/// agree to 1e-9); `None` for any other quadric.
fn cylinder_of(q: &Quadric) -> Option<(DVec3, DVec3, f64)> {
    let c = &q.coef;
    let (xx, yy, zz) = (1.0 - c[0], 1.0 - c[1], 1.0 - c[2]);
    let a = if xx >= yy && xx >= zz {
        let x = xx.sqrt();
        DVec3::new(x, -c[3] / (2.0 * x), -c[4] / (2.0 * x))
    } else if yy >= zz {
        let y = yy.sqrt();
        DVec3::new(-c[3] / (2.0 * y), y, -c[5] / (2.0 * y))
    } else {
        let z = zz.sqrt();
        DVec3::new(-c[4] / (2.0 * z), -c[5] / (2.0 * z), z)
    };
    let radius = (-c[9]).sqrt();
    if !(a.is_finite() && radius.is_finite() && (a.length() - 1.0).abs() < 1e-9) {
        return None;
    }
    let back = Quadric::cylinder(a, q.origin, radius);
    let same = back.coef.iter().zip(c).all(|(x, y)| (x - y).abs() <= 1e-9);
    same.then_some((a, q.origin, radius))
}

/// May a ray from `from` along a direction of `cone` meet the infinite cylinder of
/// radius `radius` (already widened) around the line through `point` along the unit
/// `axis`? In the plane across the axis the cylinder is a disc, seen from `from` within
/// asin(radius/ρ) of the direction to the axis; the cone's directions project within
/// asin(sin φ / sin α) of its axis' projection (α its angle to the cylinder's axis, φ
/// its half-angle), or onto every direction when α ≤ φ.
fn cylinder_may_hit(axis: DVec3, point: DVec3, radius: f64, from: DVec3, cone: &Cone) -> bool {
    let lq = from - point;
    let w = lq - lq.dot(axis) * axis;
    let rho = w.length();
    if rho <= radius || rho.is_nan() {
        return true;
    }
    let phi = cone.sin.atan2(cone.cos);
    let alpha = cone.axis.dot(axis).abs().min(1.0).acos();
    if alpha <= phi + ANGLE_PAD {
        return true;
    }
    let spread = (cone.sin / alpha.sin()).min(1.0).asin();
    let proj = cone.axis - cone.axis.dot(axis) * axis;
    let toward = -w / rho;
    let off = (proj.normalize().dot(toward)).clamp(-1.0, 1.0).acos();
    off <= spread + (radius / rho).min(1.0).asin() + ANGLE_PAD
}

impl DirGrid {
    /// The grid around `center` over `objects`, `group` sorting each object into the
    /// first or second list of a cell, or neither. `None` for too many objects or
    /// coordinates that are not finite.
    pub fn build(
        center: DVec3,
        objects: &[Object],
        group: impl Fn(&Object) -> Group,
    ) -> Option<DirGrid> {
        let (bound, delta) = Self::margins(center, objects)?;
        let mut cells = Vec::with_capacity(2 * N * N);
        for h in 0..2 {
            for i in 0..N {
                for j in 0..N {
                    let cone = &cones()[(h * N + i) * N + j];
                    let mut cell = [0u64; 2];
                    for (k, o) in objects.iter().enumerate() {
                        let Some(g) = group(o) else { continue };
                        if may_hit(&o.shape, center, cone, delta) {
                            cell[usize::from(!g)] |= 1 << k;
                        }
                    }
                    cells.push(cell);
                }
            }
        }
        Some(DirGrid { bound, cells })
    }

    /// The query bound and the distance margin δ of a grid around `center` over
    /// `objects` (`None`: no grid, too many objects or coordinates not finite).
    pub fn margins(center: DVec3, objects: &[Object]) -> Option<(f64, f64)> {
        if objects.len() > GRID_MAX_OBJECTS {
            return None;
        }
        // Queries come from points within 2B + 1; δ covers every coordinate up to there.
        let bound = 2.0 * bound(center, objects)? + 1.0;
        Some((bound, PAD * (4.0 * bound + 1.0)))
    }

    /// Whether a query from `p` may use the grid (its coordinates within the bound; not
    /// for a NaN coordinate).
    #[inline(always)]
    pub fn covers(&self, p: DVec3) -> bool {
        let a = p.abs();
        a.x <= self.bound && a.y <= self.bound && a.z <= self.bound
    }

    /// The two lists of the cell of direction `d` (from the centre; any length from 1e-300
    /// up), or `None` for a direction that is shorter, zero or not finite.
    #[inline(always)]
    pub fn cell(&self, d: DVec3) -> Option<(Objects, Objects)> {
        let a = d.abs();
        // Zero, tiny (below 1e-300, where N/2s overflows), infinite or NaN: no cell (the
        // caller falls back). The sum of absolute values is ≥ 0 or NaN, whose bits order
        // as the values do: one comparison of the bits decides.
        const LO: u64 = 1e-300f64.to_bits();
        let sum = a.x + a.y + a.z;
        if sum.to_bits().wrapping_sub(LO) > f64::MAX.to_bits() - LO {
            return None;
        }
        // Octahedral coordinates u = x/s, v = y/s; cell ⌊(u + 1)·N/2⌋ in 0..N−1: the
        // argument is within [0, N] up to rounding (|x| ≤ s), truncation makes a tiny
        // negative 0 and `min` makes N (u = 1) N − 1. Rounding may put a direction on a
        // cell boundary in its neighbour, which the cones' margin covers.
        let k = 0.5 * N as f64 / sum;
        let i = ((d.x * k + 0.5 * N as f64) as i32 as usize).min(N - 1);
        let j = ((d.y * k + 0.5 * N as f64) as i32 as usize).min(N - 1);
        let h = (d.z < 0.0) as usize;
        let [first, second] = self.cells[(h * N + i) * N + j];
        Some((Objects(first), Objects(second)))
    }
}

#[cfg(test)]
mod tests;
