//! The ray's side of the box test: 1/dir, the corner each axis enters by, and the origin
//! moved by ±δ so that every box is widened by δ at no extra cost per node (see
//! `RayBox::new` for why δ suffices, in f32 too). The lanes that test a node's boxes
//! against it are `lanes`'.

use super::node8::up;
use super::PAD;
use crate::optics::Ray;

/// Beyond this magnitude of the ray's origin plus the tree's coordinates, the lanes'
/// bound on their own rounding no longer holds (f32 overflows near 3.4e38, and a ray
/// direction's tiny components must not matter over the scene's extent): `RayBox::new`
/// declines and the caller visits every primitive.
const F32_RANGE: f64 = 1e18;

/// A ray prepared for box tests in f32, per axis.
#[derive(Clone, Copy, Debug)]
pub(super) struct RayBox {
    pub inv: [f32; 3],
    /// Per axis, whether the ray enters by the high corner (its direction's sign bit).
    pub neg: [bool; 3],
    /// The origin moved so that the near planes are pushed out by δ ...
    pub o_near: [f32; 3],
    /// ... and the far planes too.
    pub o_far: [f32; 3],
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
        let mut rb = RayBox {
            inv: [0.0; 3],
            neg: [false; 3],
            o_near: [0.0; 3],
            o_far: [0.0; 3],
        };
        for i in 0..3 {
            rb.inv[i] = (1.0 / d[i]) as f32;
            // The sign bit decides, so that −0 enters by the high corner like any
            // negative direction (1/−0 = −∞).
            let neg = d[i].is_sign_negative();
            rb.neg[i] = neg;
            let s = if neg { -delta } else { delta };
            rb.o_near[i] = (o[i] + s) as f32;
            rb.o_far[i] = (o[i] - s) as f32;
        }
        Some(rb)
    }
}

/// `t` as an f32 limit no smaller than it.
#[inline(always)]
pub(super) fn limit32(t: f64) -> f32 {
    up(t)
}
