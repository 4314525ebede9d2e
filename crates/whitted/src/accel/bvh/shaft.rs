//! Shafts (Haines and Wallace, "Shaft Culling for Efficient Ray-Traced Radiosity", 1991):
//! the convex hull of a surface point and an area light's four corners, which holds every
//! shadow ray from the point to a point of the light's grid. `Bvh::shaft_clear` says
//! whether any box of the tree meets it; where none does, no primitive of the tree can
//! stop or tint one of those rays, and the light's many rays need not walk the tree.
//!
//! A box misses the shaft when it lies beyond the hull's own box, or wholly outside one
//! of the planes through the point and two neighbouring corners (each a face of the
//! hull, or a plane holding a flat hull, so the hull lies on one side). Both tests are
//! widened by the traversal's δ (see `RayBox::new`): a primitive's computed hit lies
//! within its box widened by δ, and a shadow ray's rounded direction keeps it within far
//! less than δ of the hull. The answer may be "met" where no ray meets anything (then
//! the rays walk as before), never "clear" where a ray could.

use super::lanes::{Choice, Lanes, Narrow, ShaftBox};
use super::node8::{down, up, WideNode, LEAF, WIDTH};
use super::{Bvh, PAD, STACK};
use arrayvec::ArrayVec;
use glam::DVec3;

/// Beyond this coordinate magnitude no shaft is made (as the lanes decline, `RayBox`).
const RANGE: f64 = 1e18;

/// How many nodes a shaft's walk may open, and how many primitives of its leaves it may
/// ask, before it gives up and says "met": a shaft through the middle of a model meets
/// box after box, and the rays then walk anyway.
const NODES_MAX: usize = 24;
const PRIMS_MAX: usize = 48;

/// The hull of a point and four corners, as a box and up to four planes.
#[derive(Clone, Debug)]
pub struct Shaft {
    p: DVec3,
    corners: [DVec3; 4],
    lo: DVec3,
    hi: DVec3,
    /// Unit normal n and offset d: the hull lies where n·x ≤ d.
    planes: ArrayVec<(DVec3, f64), 4>,
    /// The largest coordinate magnitude of the hull.
    reach: f64,
    /// How far a light's sample point may lie off the corners' quadrilateral, by
    /// rounding: far below δ.
    eta: f64,
    /// The farthest corner's distance from the point, plus `eta`.
    far: f64,
}

impl Shaft {
    /// The shaft from `p` to the quadrilateral `corners` (in order round it); `None`
    /// beyond the coordinates' range or for coordinates that are not finite.
    pub fn new(p: DVec3, corners: &[DVec3; 4]) -> Option<Shaft> {
        let (mut lo, mut hi) = (p, p);
        for &c in corners {
            lo = lo.min(c);
            hi = hi.max(c);
        }
        let reach = lo.abs().max(hi.abs()).max_element();
        if !p.is_finite() || !corners.iter().all(|c| c.is_finite()) || reach >= RANGE {
            return None;
        }
        // How far off its plane the hull may lie by rounding: far below δ.
        let tol = 1e-9 * (reach + 1.0);
        let mut planes = ArrayVec::new();
        for i in 0..4 {
            let (a, b) = (corners[i], corners[(i + 1) % 4]);
            let Some(n) = (a - p).cross(b - p).try_normalize() else {
                continue; // two equal corners (a grid one point wide) or p on the edge
            };
            let d = n.dot(p);
            let side = corners.map(|c| n.dot(c) - d);
            if side.iter().all(|&s| s <= tol) {
                planes.push((n, d));
            } else if side.iter().all(|&s| s >= -tol) {
                planes.push((-n, -d));
            }
            // Corners on both sides (a quadrilateral that is not convex): not a face.
        }
        let far = corners
            .iter()
            .fold(0.0, |m: f64, &c| m.max((c - p).length()))
            + tol;
        Some(Shaft {
            p,
            corners: *corners,
            lo,
            hi,
            planes,
            reach,
            eta: tol,
            far,
        })
    }

    /// Whether the box `lo`–`hi` lies beyond the shaft widened by `delta`, in f64. The
    /// lanes' test (`in_lanes`, `Lanes::misses`) calls a box missed only where this
    /// does; the tests check it against this.
    #[cfg(test)]
    pub(super) fn misses(&self, lo: DVec3, hi: DVec3, delta: f64) -> bool {
        if lo.cmpgt(self.hi + delta).any() || hi.cmplt(self.lo - delta).any() {
            return true;
        }
        self.planes.iter().any(|&(n, d)| {
            // The box's corner least far along n.
            let x = DVec3::select(n.cmpgt(DVec3::ZERO), lo, hi);
            n.dot(x) > d + delta
        })
    }

    /// The shaft widened by `delta` for the lanes' f32 test of a tree whose boxes'
    /// coordinates are at most `scale` in magnitude: the box rounded outward, each
    /// plane's normal rounded to nearest and its offset raised by the lanes' rounding.
    /// A box the lanes find past a plane then lies past it widened by `delta`, as
    /// `misses` asks: the f32 product n·x is off the exact one by at most about
    /// 4·2⁻²⁴·|n|₁·scale (three roundings of the sums and products, one of n's
    /// components), under half of the allowance 2⁻²⁰·(scale + 1).
    pub(super) fn in_lanes(&self, delta: f64, scale: f64) -> ShaftBox {
        let slack = (scale + 1.0) / (1u64 << 20) as f64;
        ShaftBox {
            lo: (self.lo - delta).to_array().map(down),
            hi: (self.hi + delta).to_array().map(up),
            planes: self
                .planes
                .iter()
                .map(|&(n, d)| {
                    // The low corner where n_i > 0 (as `misses` picks it), else the high one.
                    let corner = n.to_array().map(|x| if x > 0.0 { 0 } else { 1 });
                    (
                        n.to_array().map(|x| x as f32),
                        corner,
                        up(d + delta + slack),
                    )
                })
                .collect(),
        }
    }
}

impl Shaft {
    /// Whether no shadow ray of the shaft (from its point, t_min ≥ 0 and t_min < t) can
    /// meet the plane through `point` with unit normal `n`, as `Plane::hit` tests it.
    /// That test's numerator N·(P − O) is the same for every ray of the shaft (their
    /// origin is its point); its denominator N·D has one sign over all of them when the
    /// corners lie beyond a margin on one side of the shaft's point (N·(Q − O) is linear
    /// in Q, so its extremes are at corners, and a rounded direction is far closer than
    /// the margin). Then t = N·(P − O)/N·D is −0 or below where the signs differ, and
    /// where they agree it is at most |N·(P − O)| / (min |N·(C − O)| / max |C − O|),
    /// which below half of t_min leaves every ray's t under t_min. A point on the plane
    /// (a floor lit from above) is the case this is for: its numerator is rounding.
    pub fn misses_plane(&self, point: DVec3, n: DVec3, t_min: f64) -> bool {
        let Some((sign, least)) = self.side(n) else {
            return false;
        };
        // t ≤ 0 (or NaN) unless the numerator has the denominator's sign.
        let same = sign * n.dot(point - self.p);
        t_min >= 0.0 && (same.is_nan() || same <= 0.0 || same < 0.5 * t_min * least / self.far)
    }

    /// The one sign w·(Q − p) takes over the light's quadrilateral, its sample points up
    /// to η off it (w·(Q − p) is linear in Q, so its extremes are at corners), and the
    /// least |w·(Q − p)| there; `None` where the corners are not all beyond |w|·η on one
    /// side.
    fn side(&self, w: DVec3) -> Option<(f64, f64)> {
        let along = self.corners.map(|c| w.dot(c - self.p));
        let slack = w.length() * self.eta;
        let sign = if along.iter().all(|&x| x > slack) {
            1.0
        } else if along.iter().all(|&x| x < -slack) {
            -1.0
        } else {
            return None;
        };
        let least = along.iter().fold(f64::INFINITY, |m, &x| m.min(x.abs()));
        Some((sign, least - slack))
    }
}

impl<P> Bvh<P> {
    /// Whether no shadow ray inside `shaft` can meet a primitive of the tree: every box
    /// the shaft meets (as the module says; a node's eight boxes in one lane test,
    /// `Lanes::misses`) is a leaf whose primitives `leaf` clears one by one
    /// (`Shaft::misses_triangle`; `|_| false` where it cannot tell). A flat list (no
    /// boxes) is clear only when empty.
    pub fn shaft_clear(&self, shaft: &Shaft, mut leaf: impl FnMut(&[P]) -> bool) -> bool {
        if self.nodes.is_empty() {
            return self.prims.is_empty();
        }
        let delta = PAD * (shaft.reach + self.scale + 1.0);
        let q = shaft.in_lanes(delta, self.scale);
        match self.lanes {
            Choice::Narrow => shaft_walk(Narrow, &self.nodes, &self.prims, &q, &mut leaf),
            #[cfg(all(feature = "avx2", target_arch = "x86_64"))]
            Choice::Avx2(v3) => pulp::Simd::vectorize(
                v3,
                ShaftAvx2 {
                    v3,
                    nodes: &self.nodes,
                    prims: &self.prims,
                    q: &q,
                    leaf: &mut leaf,
                },
            ),
        }
    }
}

/// `shaft_walk` in AVX2 lanes, as `pulp` runs it (see `walk::WalkAvx2`).
#[cfg(all(feature = "avx2", target_arch = "x86_64"))]
struct ShaftAvx2<'a, P, F> {
    v3: pulp::x86::V3,
    nodes: &'a [WideNode],
    prims: &'a [P],
    q: &'a ShaftBox,
    leaf: &'a mut F,
}

#[cfg(all(feature = "avx2", target_arch = "x86_64"))]
impl<P, F: FnMut(&[P]) -> bool> pulp::WithSimd for ShaftAvx2<'_, P, F> {
    type Output = bool;

    #[inline(always)]
    fn with_simd<S: pulp::Simd>(self, _: S) -> bool {
        let lanes = super::lanes::Avx2(self.v3);
        shaft_walk(lanes, self.nodes, self.prims, self.q, self.leaf)
    }
}

/// The walk of `Bvh::shaft_clear`: the boxes the shaft meets, slot by slot in each
/// node, their leaves asked as they come.
#[inline(always)]
fn shaft_walk<L: Lanes, P>(
    lanes: L,
    nodes: &[WideNode],
    prims: &[P],
    q: &ShaftBox,
    leaf: &mut impl FnMut(&[P]) -> bool,
) -> bool {
    let s = lanes.shaft(q);
    let mut stack = ArrayVec::<u32, STACK>::new();
    stack.push(0);
    let (mut opened, mut asked) = (0, 0);
    while let Some(i) = stack.pop() {
        opened += 1;
        if opened > NODES_MAX {
            return false;
        }
        let n = &nodes[i as usize];
        let mut met = !lanes.misses(&s, n) & ((1 << WIDTH) - 1);
        while met != 0 {
            let slot = met.trailing_zeros() as usize;
            met &= met - 1;
            if n.child[slot] & LEAF != 0 {
                let (first, count) = ((n.child[slot] & !LEAF) as usize, n.count[slot] as usize);
                asked += count;
                if asked > PRIMS_MAX || !leaf(&prims[first..first + count]) {
                    return false;
                }
            } else if stack.try_push(n.child[slot]).is_err() {
                return false;
            }
        }
    }
    true
}

#[path = "shaft_tri.rs"]
mod tri;

#[cfg(test)]
#[path = "shaft_tests.rs"]
mod tests;
