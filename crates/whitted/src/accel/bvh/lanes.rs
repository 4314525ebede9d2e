//! The lanes that test a node's eight boxes against a ray (`enter`) or an area light's
//! shaft (`misses`, `ShaftBox`): two SSE registers of four (`Narrow`, `wide::f32x4`, on
//! every x86-64 and elsewhere through `wide`'s fallback), or one AVX2 register of eight
//! (`Avx2`, `pulp`'s safe intrinsics, chosen when the program starts on a processor that
//! has AVX2, behind the default feature `avx2`).
//!
//! Both run the same IEEE operations in the same order on each lane: per axis a
//! subtraction and a product, then `max` into the entry and `min` into the exit parameter
//! (the SSE and AVX `max`/`min` instructions, with the same operand order, so a NaN lane
//! resolves the same way), and the same three comparisons; for a shaft, six
//! comparisons with its box and per plane a sum of three products, left to right, and
//! one comparison; no fused multiply-add. So the masks and entry parameters are the
//! same bits, and so is every picture
//! (`WHITTED_LANES=narrow` forces the narrow lanes; tests compare the two).

use super::node8::{WideNode, WIDTH};
use super::raybox::RayBox;
use std::sync::OnceLock;
use wide::{f32x4, CmpGe, CmpGt, CmpLe, CmpLt};

/// Which lanes a tree's queries use (`Choice::chosen`).
#[derive(Clone, Copy, Debug)]
pub(super) enum Choice {
    Narrow,
    #[cfg(all(feature = "avx2", target_arch = "x86_64"))]
    Avx2(pulp::x86::V3),
}

impl Choice {
    /// AVX2 where the processor has it and `WHITTED_LANES` is not `narrow`, decided once.
    pub(super) fn chosen() -> Choice {
        static CHOICE: OnceLock<Choice> = OnceLock::new();
        *CHOICE.get_or_init(|| Choice::from_setting(std::env::var("WHITTED_LANES").ok().as_deref()))
    }

    /// The lanes a `WHITTED_LANES` setting asks for: `narrow`, or the widest this
    /// processor has (anything else, or no setting).
    pub(super) fn from_setting(setting: Option<&str>) -> Choice {
        #[cfg(all(feature = "avx2", target_arch = "x86_64"))]
        if setting != Some("narrow") {
            if let Some(v3) = pulp::x86::V3::try_new() {
                return Choice::Avx2(v3);
            }
        }
        let _ = setting;
        Choice::Narrow
    }
}

/// The ray box with each value splatted across a register of lanes `V`, once per query.
#[derive(Clone, Copy, Debug)]
pub(super) struct Splat<V> {
    inv: [V; 3],
    /// Per axis, whether the ray enters by the high corner.
    neg: [bool; 3],
    o_near: [V; 3],
    o_far: [V; 3],
}

/// A way to test a node's boxes: a value splatted across the lanes (`splat`), then per
/// node the mask of slots whose widened box the ray's line meets at some t in
/// [0, t_max] (bit k for slot k) and the entry parameters.
pub(super) trait Lanes: Copy {
    type V: Copy;
    fn splat(self, x: f32) -> Self::V;
    fn enter(self, r: &Splat<Self::V>, n: &WideNode, t_max: f32) -> (u32, [f32; WIDTH]);

    /// The ray box in these lanes.
    #[inline(always)]
    fn ray(self, rb: &RayBox) -> Splat<Self::V> {
        Splat {
            inv: rb.inv.map(|x| self.splat(x)),
            neg: rb.neg,
            o_near: rb.o_near.map(|x| self.splat(x)),
            o_far: rb.o_far.map(|x| self.splat(x)),
        }
    }

    /// The mask of slots whose box lies beyond the shaft `s` (bit k for slot k; an
    /// empty slot's box, from +∞ to −∞, always does): beyond its box, or past one of
    /// its planes.
    fn misses(self, s: &ShaftSplat<Self::V>, n: &WideNode) -> u32;

    /// A shaft in these lanes.
    #[inline(always)]
    fn shaft(self, q: &ShaftBox) -> ShaftSplat<Self::V> {
        let zero = self.splat(0.0);
        let mut planes = [([zero; 3], [0; 3], zero); 4];
        for (p, &(n, corner, d)) in planes.iter_mut().zip(&q.planes) {
            *p = (n.map(|x| self.splat(x)), corner, self.splat(d));
        }
        ShaftSplat {
            lo: q.lo.map(|x| self.splat(x)),
            hi: q.hi.map(|x| self.splat(x)),
            planes,
            count: q.planes.len(),
        }
    }
}

/// A shaft's box and planes in f32, widened (`Shaft::in_lanes` says by how much): a
/// slot's box lies beyond the shaft when its low corner is above `hi` or its high
/// corner below `lo` on some axis, or when n·x > d for a plane (n, corner, d), x the
/// box's corner least far along n (`corner[axis]`: 0 the low one, 1 the high one).
#[derive(Clone, Debug)]
pub(super) struct ShaftBox {
    pub lo: [f32; 3],
    pub hi: [f32; 3],
    pub planes: arrayvec::ArrayVec<([f32; 3], [usize; 3], f32), 4>,
}

/// `ShaftBox` splatted across the lanes, once per shaft.
#[derive(Clone, Copy, Debug)]
pub(super) struct ShaftSplat<V> {
    lo: [V; 3],
    hi: [V; 3],
    planes: [([V; 3], [usize; 3], V); 4],
    count: usize,
}

/// Slots 4h to 4h + 3, one half of a node's row of eight, in one register.
#[inline(always)]
fn half_row(v: &[f32; WIDTH], h: usize) -> f32x4 {
    f32x4::from([v[4 * h], v[4 * h + 1], v[4 * h + 2], v[4 * h + 3]])
}

/// Two registers of four.
#[derive(Clone, Copy, Debug)]
pub(super) struct Narrow;

impl Lanes for Narrow {
    type V = f32x4;

    #[inline(always)]
    fn splat(self, x: f32) -> f32x4 {
        f32x4::splat(x)
    }

    #[inline(always)]
    fn enter(self, r: &Splat<f32x4>, n: &WideNode, t_max: f32) -> (u32, [f32; WIDTH]) {
        let mut mask = 0;
        let mut t = [0.0; WIDTH];
        for h in 0..WIDTH / 4 {
            let mut near = f32x4::splat(f32::NEG_INFINITY);
            let mut far = f32x4::splat(f32::INFINITY);
            for i in 0..3 {
                let half = |v: &[f32; WIDTH]| half_row(v, h);
                let neg = r.neg[i] as usize;
                let (a, b) = (half(&n.b[neg][i]), half(&n.b[1 - neg][i]));
                near = near.fast_max((a - r.o_near[i]) * r.inv[i]);
                far = far.fast_min((b - r.o_far[i]) * r.inv[i]);
            }
            let hit = near.cmp_le(far) & far.cmp_ge(f32x4::ZERO) & near.cmp_le(f32x4::splat(t_max));
            mask |= (hit.move_mask() as u32) << (4 * h);
            t[4 * h..4 * h + 4].copy_from_slice(&near.to_array());
        }
        (mask, t)
    }

    #[inline(always)]
    fn misses(self, s: &ShaftSplat<f32x4>, n: &WideNode) -> u32 {
        let mut mask = 0;
        for h in 0..WIDTH / 4 {
            let half = |v: &[f32; WIDTH]| half_row(v, h);
            let mut out = half(&n.b[0][0]).cmp_gt(s.hi[0]);
            for i in 1..3 {
                out |= half(&n.b[0][i]).cmp_gt(s.hi[i]);
            }
            for i in 0..3 {
                out |= half(&n.b[1][i]).cmp_lt(s.lo[i]);
            }
            for (w, c, d) in &s.planes[..s.count] {
                let x = |i: usize| half(&n.b[c[i]][i]);
                let along = w[0] * x(0) + w[1] * x(1) + w[2] * x(2);
                out |= along.cmp_gt(*d);
            }
            mask |= (out.move_mask() as u32) << (4 * h);
        }
        mask
    }
}

#[cfg(all(feature = "avx2", target_arch = "x86_64"))]
pub(super) use avx2::Avx2;

#[cfg(all(feature = "avx2", target_arch = "x86_64"))]
mod avx2 {
    use super::{Lanes, ShaftSplat, Splat, WideNode, WIDTH};
    use core::arch::x86_64::{__m256, _CMP_GE_OQ, _CMP_GT_OQ, _CMP_LE_OQ, _CMP_LT_OQ};
    use pulp::x86::V3;

    /// One register of eight; the token proves the processor has AVX2.
    #[derive(Clone, Copy, Debug)]
    pub(in crate::accel::bvh) struct Avx2(pub V3);

    impl Lanes for Avx2 {
        type V = __m256;

        #[inline(always)]
        fn splat(self, x: f32) -> __m256 {
            self.0.avx._mm256_set1_ps(x)
        }

        #[inline(always)]
        fn enter(self, r: &Splat<__m256>, n: &WideNode, t_max: f32) -> (u32, [f32; WIDTH]) {
            let avx = self.0.avx;
            let mut near = avx._mm256_set1_ps(f32::NEG_INFINITY);
            let mut far = avx._mm256_set1_ps(f32::INFINITY);
            for i in 0..3 {
                let neg = r.neg[i] as usize;
                let (a, b): (__m256, __m256) =
                    (pulp::cast(n.b[neg][i]), pulp::cast(n.b[1 - neg][i]));
                let sa = avx._mm256_mul_ps(avx._mm256_sub_ps(a, r.o_near[i]), r.inv[i]);
                near = avx._mm256_max_ps(near, sa);
                let sb = avx._mm256_mul_ps(avx._mm256_sub_ps(b, r.o_far[i]), r.inv[i]);
                far = avx._mm256_min_ps(far, sb);
            }
            let crossed = avx._mm256_cmp_ps::<_CMP_LE_OQ>(near, far);
            let ahead = avx._mm256_cmp_ps::<_CMP_GE_OQ>(far, avx._mm256_setzero_ps());
            let within = avx._mm256_cmp_ps::<_CMP_LE_OQ>(near, avx._mm256_set1_ps(t_max));
            let hit = avx._mm256_and_ps(avx._mm256_and_ps(crossed, ahead), within);
            (avx._mm256_movemask_ps(hit) as u32, pulp::cast(near))
        }

        #[inline(always)]
        fn misses(self, s: &ShaftSplat<__m256>, n: &WideNode) -> u32 {
            let avx = self.0.avx;
            let b = |c: usize, i: usize| -> __m256 { pulp::cast(n.b[c][i]) };
            let mut out = avx._mm256_cmp_ps::<_CMP_GT_OQ>(b(0, 0), s.hi[0]);
            for i in 1..3 {
                out = avx._mm256_or_ps(out, avx._mm256_cmp_ps::<_CMP_GT_OQ>(b(0, i), s.hi[i]));
            }
            for i in 0..3 {
                out = avx._mm256_or_ps(out, avx._mm256_cmp_ps::<_CMP_LT_OQ>(b(1, i), s.lo[i]));
            }
            for (w, c, d) in &s.planes[..s.count] {
                let along = avx._mm256_add_ps(
                    avx._mm256_add_ps(
                        avx._mm256_mul_ps(w[0], b(c[0], 0)),
                        avx._mm256_mul_ps(w[1], b(c[1], 1)),
                    ),
                    avx._mm256_mul_ps(w[2], b(c[2], 2)),
                );
                out = avx._mm256_or_ps(out, avx._mm256_cmp_ps::<_CMP_GT_OQ>(along, *d));
            }
            avx._mm256_movemask_ps(out) as u32
        }
    }
}
