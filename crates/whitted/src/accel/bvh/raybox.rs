//! The ray's side of the box test: 1/dir, the corner each axis enters by, and the origin
//! moved by ±δ so that every box is widened by δ at no extra cost per node (see
//! `RayBox::new` for why δ suffices).

use super::{Node, PAD};
use crate::optics::Ray;

/// A ray prepared for box tests: 1/dir, which corner each axis enters by, and its origin
/// moved by ±δ so that every box is widened by δ at no extra cost per node.
#[derive(Clone, Copy, Debug)]
pub(super) struct RayBox {
    inv: [f64; 3],
    /// Per axis, the corner (0 low, 1 high) whose plane the ray crosses first.
    near: [usize; 3],
    /// The origin moved so that the near planes are pushed out by δ ...
    o_near: [f64; 3],
    /// ... and the far planes too.
    o_far: [f64; 3],
}

#[inline(always)]
fn max(a: f64, b: f64) -> f64 {
    if a > b {
        a
    } else {
        b
    }
}

#[inline(always)]
fn min(a: f64, b: f64) -> f64 {
    if a < b {
        a
    } else {
        b
    }
}

impl RayBox {
    /// `scale`: the largest coordinate magnitude of any box in the tree queried.
    ///
    /// Why δ = 1e-5·(|o|∞ + scale + 1) suffices: the sphere test computes
    /// CH² = |OC|² − (OC·D)², whose absolute error is a few ε·|OC|² (ε = 2^-53); so a
    /// computed hit at t lies within r + √(44ε)·(|OC| + r) ≈ r + 1.1e-7·√3·(|o|∞ + scale)
    /// of the centre, inside the box widened by δ with a margin of ~50×, which also
    /// covers the rounding of the slab arithmetic (a few ε of the same magnitudes).
    #[inline]
    pub(super) fn new(ray: &Ray, scale: f64) -> RayBox {
        let delta = PAD * (ray.origin.abs().max_element() + scale + 1.0);
        let o = ray.origin.to_array();
        let d = ray.dir.to_array();
        let mut rb = RayBox {
            inv: [0.0; 3],
            near: [0; 3],
            o_near: [0.0; 3],
            o_far: [0.0; 3],
        };
        for i in 0..3 {
            rb.inv[i] = 1.0 / d[i];
            // The sign bit decides, so that −0 enters by the high corner like any
            // negative direction (1/−0 = −∞).
            if d[i].is_sign_negative() {
                rb.near[i] = 1;
                rb.o_near[i] = o[i] - delta;
                rb.o_far[i] = o[i] + delta;
            } else {
                rb.near[i] = 0;
                rb.o_near[i] = o[i] + delta;
                rb.o_far[i] = o[i] - delta;
            }
        }
        rb
    }

    /// The entry parameter of the widened box if the ray's line meets it at some t in
    /// [0, t_max]; `None` otherwise.
    #[inline(always)]
    pub(super) fn enter(&self, n: &Node, t_max: f64) -> Option<f64> {
        let slab = |i: usize| {
            let s = self.near[i] & 1;
            (
                (n.b[s][i] - self.o_near[i]) * self.inv[i],
                (n.b[s ^ 1][i] - self.o_far[i]) * self.inv[i],
            )
        };
        let (nx, fx) = slab(0);
        let (ny, fy) = slab(1);
        let (nz, fz) = slab(2);
        // A NaN (0·∞) only comes from a ray lying in a widened plane and parallel to it,
        // which cannot meet the sphere inside: whatever the comparisons make of it is right.
        let near = max(max(nx, ny), nz);
        let far = min(min(fx, fy), fz);
        if near <= far && far >= 0.0 && near <= t_max {
            Some(near)
        } else {
            None
        }
    }
}
