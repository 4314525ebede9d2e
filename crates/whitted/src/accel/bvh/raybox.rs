//! The ray's side of the box test, four boxes at a time in f32 lanes: 1/dir, the corner
//! each axis enters by, and the origin moved by ±δ so that every box is widened by δ at
//! no extra cost per node (see `RayBox::new` for why δ suffices, in f32 too).

use super::node4::{up, WideNode};
use super::PAD;
use crate::optics::Ray;
use wide::{f32x4, CmpGe, CmpLe};

/// Beyond this magnitude of the ray's origin plus the tree's coordinates, the lanes'
/// bound on their own rounding no longer holds (f32 overflows near 3.4e38, and a ray
/// direction's tiny components must not matter over the scene's extent): `RayBox::new`
/// declines and the caller visits every primitive.
const F32_RANGE: f64 = 1e18;

/// A ray prepared for box tests in lanes.
#[derive(Clone, Copy, Debug)]
pub(super) struct RayBox {
    inv: [f32x4; 3],
    /// Per axis, whether the ray enters by the high corner (its direction's sign bit).
    neg: [bool; 3],
    /// The origin moved so that the near planes are pushed out by δ ...
    o_near: [f32x4; 3],
    /// ... and the far planes too.
    o_far: [f32x4; 3],
}

impl RayBox {
    /// `scale`: the largest coordinate magnitude of any box in the tree queried. `None`
    /// when the ray or the tree lie beyond the lanes' range (see `F32_RANGE`).
    ///
    /// Why δ = 1e-5·(|o|∞ + scale + 1) suffices: the sphere test computes
    /// CH² = |OC|² − (OC·D)², whose absolute error is a few ε·|OC|² (ε = 2^-53); so a
    /// computed hit at t lies within r + √(44ε)·(|OC| + r) ≈ r + 1.1e-7·√3·(|o|∞ + scale)
    /// of the centre, inside the box widened by δ with a margin of ~50×; the other
    /// shapes' hits lie within a few ulps of their boxes. The lanes add their own
    /// rounding: the boxes are rounded outward, the shifted origin and 1/dir to nearest
    /// (2^-24 relative each), then one subtraction and one product (2^-24 each): the slab
    /// distances move by at most ~4·2^-24·(|o|∞ + scale + δ)/|dir_i|, under 3 % of the
    /// margin δ/|dir_i| they are widened by. A NaN lane (0·∞) needs a direction
    /// component of 0 (or below 1e-38) and a shifted origin on a box plane: the line then
    /// runs δ outside the box (or drifts from there by less than 1e-20 over the scene),
    /// so whatever the lane makes of it loses no hit.
    #[inline]
    pub(super) fn new(ray: &Ray, scale: f64) -> Option<RayBox> {
        let reach = ray.origin.abs().max_element() + scale;
        // (A NaN reach, from a NaN origin, declines too.)
        if reach.partial_cmp(&F32_RANGE) != Some(std::cmp::Ordering::Less) {
            return None;
        }
        let delta = PAD * (reach + 1.0);
        let o = ray.origin.to_array();
        let d = ray.dir.to_array();
        let lane = |x: f64| f32x4::splat(x as f32);
        let mut rb = RayBox {
            inv: [f32x4::ZERO; 3],
            neg: [false; 3],
            o_near: [f32x4::ZERO; 3],
            o_far: [f32x4::ZERO; 3],
        };
        for i in 0..3 {
            rb.inv[i] = lane(1.0 / d[i]);
            // The sign bit decides, so that −0 enters by the high corner like any
            // negative direction (1/−0 = −∞).
            let neg = d[i].is_sign_negative();
            rb.neg[i] = neg;
            let s = if neg { -delta } else { delta };
            rb.o_near[i] = lane(o[i] + s);
            rb.o_far[i] = lane(o[i] - s);
        }
        Some(rb)
    }

    /// For each of `n`'s four slots, whether the ray's line meets its widened box at
    /// some t in [0, t_max] (bit k of the mask for slot k), and the entry parameters.
    #[inline(always)]
    pub(super) fn enter4(&self, n: &WideNode, t_max: f32) -> (u32, [f32; 4]) {
        let mut near = f32x4::splat(f32::NEG_INFINITY);
        let mut far = f32x4::splat(f32::INFINITY);
        for i in 0..3 {
            let (lo, hi) = (f32x4::from(n.lo[i]), f32x4::from(n.hi[i]));
            let (a, b) = if self.neg[i] { (hi, lo) } else { (lo, hi) };
            near = near.fast_max((a - self.o_near[i]) * self.inv[i]);
            far = far.fast_min((b - self.o_far[i]) * self.inv[i]);
        }
        let hit = near.cmp_le(far) & far.cmp_ge(f32x4::ZERO) & near.cmp_le(f32x4::splat(t_max));
        (hit.move_mask() as u32, near.to_array())
    }
}

/// `t` as an f32 limit no smaller than it.
#[inline(always)]
pub(super) fn limit32(t: f64) -> f32 {
    up(t)
}
