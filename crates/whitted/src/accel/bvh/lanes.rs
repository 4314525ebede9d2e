//! The lanes that test a node's eight boxes against a ray: two SSE registers of four
//! (`Narrow`, `wide::f32x4`, on every x86-64 and elsewhere through `wide`'s fallback),
//! or one AVX2 register of eight (`Avx2`, `pulp`'s safe intrinsics, chosen when the
//! program starts on a processor that has AVX2, behind the default feature `avx2`).
//!
//! Both run the same IEEE operations in the same order on each lane: per axis a
//! subtraction and a product, then `max` into the entry and `min` into the exit parameter
//! (the SSE and AVX `max`/`min` instructions, with the same operand order, so a NaN lane
//! resolves the same way), and the same three comparisons; no fused multiply-add. So
//! the masks and entry parameters are the same bits, and so is every picture
//! (`WHITTED_LANES=narrow` forces the narrow lanes; tests compare the two).

use super::node8::{WideNode, WIDTH};
use super::raybox::RayBox;
use std::sync::OnceLock;
use wide::{f32x4, CmpGe, CmpLe};

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
                let half = |v: &[f32; WIDTH]| {
                    f32x4::from([v[4 * h], v[4 * h + 1], v[4 * h + 2], v[4 * h + 3]])
                };
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
}

#[cfg(all(feature = "avx2", target_arch = "x86_64"))]
pub(super) use avx2::Avx2;

#[cfg(all(feature = "avx2", target_arch = "x86_64"))]
mod avx2 {
    use super::{Lanes, Splat, WideNode, WIDTH};
    use core::arch::x86_64::{__m256, _CMP_GE_OQ, _CMP_LE_OQ};
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
    }
}
