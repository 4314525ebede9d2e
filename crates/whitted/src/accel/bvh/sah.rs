//! The binned surface area heuristic of the tree's build: a node's items are put in
//! `BINS` bins by their centres on each axis (a centre's three bins in one lane
//! operation, `bins3`), and a sweep over each axis's bins finds the split of least
//! cost, the two sides' surface areas times their counts, summed in f64.

use super::{Item, BINS};
use glam::{DVec3, Vec3, Vec3A};
use wide::{f32x4, i32x4};

/// The surface area of the box of f32 corners `lo`, `hi`, in f64.
pub(super) fn surface_area(lo: Vec3A, hi: Vec3A) -> f64 {
    let d = (hi.as_dvec3() - lo.as_dvec3()).max(DVec3::ZERO);
    2.0 * (d.x * d.y + d.y * d.z + d.z * d.x)
}

/// The bin of a centre coordinate `c`: bins of width 1/k from `c0`, the last one closed.
/// The same bin as `(((c - c0) * k) as usize).min(BINS - 1)` for every `c` (NaN and
/// negatives to bin 0), without that conversion's saturating steps for the whole of
/// `usize`: the comparison leaves `as u32` values in [0, BINS).
#[inline]
pub(super) fn bin(c: f32, c0: f32, k: f32) -> usize {
    let x = (c - c0) * k;
    if x >= (BINS - 1) as f32 {
        BINS - 1
    } else {
        x as u32 as usize
    }
}

/// A centre's bins on the three axes at once (the fourth lane unused): `bin` in each
/// lane, the same bin for every input (`as i32` truncates and saturates as `as u32`
/// does below 2³¹ and sends NaN to 0 too; the clamp then does what the comparison does).
#[inline]
fn bins3(c: Vec3, c0: f32x4, k: f32x4) -> [i32; 4] {
    let x = (f32x4::from([c.x, c.y, c.z, 0.0]) - c0) * k;
    let last = i32x4::splat(BINS as i32 - 1);
    x.trunc_int().max(i32x4::ZERO).min(last).to_array()
}

/// A bin's box and count.
type Bin = (Vec3A, Vec3A, usize);

/// The cheapest binned SAH split of `items` over the three axes of their centres (from
/// `c0` over `extent`; an axis without extent is not split): (cost, axis, last bin on
/// the left), the lower axis on a tie, if some split leaves both sides non-empty. The
/// items are binned on all three axes in one pass (an axis without extent puts them all
/// in its bin 0, unused), each bin growing in the items' order.
pub(super) fn sah(items: &[Item], c0: Vec3, extent: Vec3) -> Option<(f64, usize, usize)> {
    let k = BINS as f32 / extent;
    let (c0, k) = (
        f32x4::from([c0.x, c0.y, c0.z, 0.0]),
        f32x4::from([k.x, k.y, k.z, 0.0]),
    );
    let empty: Bin = (Vec3A::INFINITY, Vec3A::NEG_INFINITY, 0);
    let mut bins = [[empty; BINS]; 3];
    for it in items.iter() {
        let at = bins3(it.centre, c0, k);
        for (axis, bins) in bins.iter_mut().enumerate() {
            let b = &mut bins[at[axis] as usize];
            b.0 = b.0.min(it.lo);
            b.1 = b.1.max(it.hi);
            b.2 += 1;
        }
    }
    let mut best: Option<(f64, usize, usize)> = None;
    for (axis, bins) in bins.iter().enumerate() {
        if extent[axis] > 0.0 {
            if let Some((cost, bin)) = sweep(bins, items.len()) {
                if best.is_none_or(|b| cost < b.0) {
                    best = Some((cost, axis, bin));
                }
            }
        }
    }
    best
}

/// The cheapest split of one axis's bins over `n` items: (cost, last bin on the left).
/// Empty bins are passed over: splitting after one costs what splitting after the bin
/// before it does (the same two sides, the same arithmetic), and a cost must be lower
/// to replace the best, so the answer is that of every split asked. Most of a small
/// node's bins are empty.
fn sweep(bins: &[Bin; BINS], n: usize) -> Option<(f64, usize)> {
    // Costs of splitting after bin i: sweep from the right, then from the left.
    let mut right = [0.0f64; BINS];
    let (mut rlo, mut rhi, mut rn) = (Vec3A::INFINITY, Vec3A::NEG_INFINITY, 0usize);
    // An empty right side: its box has no area.
    let mut cost = 0.0;
    for i in (1..BINS).rev() {
        if bins[i].2 > 0 {
            rlo = rlo.min(bins[i].0);
            rhi = rhi.max(bins[i].1);
            rn += bins[i].2;
            cost = surface_area(rlo, rhi) * rn as f64;
        }
        right[i - 1] = cost;
    }
    let (mut llo, mut lhi, mut ln) = (Vec3A::INFINITY, Vec3A::NEG_INFINITY, 0usize);
    let mut best: Option<(f64, usize)> = None;
    for i in 0..BINS - 1 {
        if bins[i].2 == 0 {
            continue;
        }
        llo = llo.min(bins[i].0);
        lhi = lhi.max(bins[i].1);
        ln += bins[i].2;
        if ln == n {
            break;
        }
        let cost = surface_area(llo, lhi) * ln as f64 + right[i];
        if cost.is_finite() && best.is_none_or(|b| cost < b.0) {
            best = Some((cost, i));
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::{bin, bins3, surface_area, sweep, Bin, BINS};
    use glam::{Vec3, Vec3A};
    use proptest::prelude::*;
    use wide::f32x4;

    /// Every split after bins 0 to 14 costed in turn, empty bins included.
    fn sweep_every_bin(bins: &[Bin; BINS], n: usize) -> Option<(f64, usize)> {
        let mut right = [0.0f64; BINS];
        let (mut rlo, mut rhi, mut rn) = (Vec3A::INFINITY, Vec3A::NEG_INFINITY, 0usize);
        for i in (1..BINS).rev() {
            rlo = rlo.min(bins[i].0);
            rhi = rhi.max(bins[i].1);
            rn += bins[i].2;
            right[i - 1] = surface_area(rlo, rhi) * rn as f64;
        }
        let (mut llo, mut lhi, mut ln) = (Vec3A::INFINITY, Vec3A::NEG_INFINITY, 0usize);
        let mut best: Option<(f64, usize)> = None;
        for i in 0..BINS - 1 {
            llo = llo.min(bins[i].0);
            lhi = lhi.max(bins[i].1);
            ln += bins[i].2;
            if ln == 0 || ln == n {
                continue;
            }
            let cost = surface_area(llo, lhi) * ln as f64 + right[i];
            if cost.is_finite() && best.is_none_or(|b| cost < b.0) {
                best = Some((cost, i));
            }
        }
        best
    }

    #[test]
    fn a_sweep_by_hand() {
        // Unit cubes at x = 0 (bin 2, two items) and x = 10 (bin 9, one item): every split
        // from bin 2 to bin 8 parts them alike, costing 6 · 2 + 6 · 1 = 18; bin 2 is the
        // first of them.
        let empty: Bin = (Vec3A::INFINITY, Vec3A::NEG_INFINITY, 0);
        let mut bins = [empty; BINS];
        bins[2] = (Vec3A::ZERO, Vec3A::ONE, 2);
        bins[9] = (Vec3A::new(10.0, 0.0, 0.0), Vec3A::new(11.0, 1.0, 1.0), 1);
        assert_eq!(sweep(&bins, 3), Some((18.0, 2)));
        // All items in one bin: no split.
        let mut one = [empty; BINS];
        one[5] = bins[2];
        assert_eq!(sweep(&one, 2), None);
    }

    proptest! {
        /// Bins mostly empty (as a small node's are) or full, with boxes that share
        /// faces and zeros of either sign: the same split as costing every bin.
        #[test]
        fn passing_over_empty_bins_gives_every_bins_answer(
            full in proptest::collection::vec(
                (any::<bool>(), 1usize..4, [-2i8..3, -2i8..3, -2i8..3], [0u8..3, 0u8..3, 0u8..3]), BINS),
            sparse in any::<bool>(),
        ) {
            let empty: Bin = (Vec3A::INFINITY, Vec3A::NEG_INFINITY, 0);
            let mut bins = [empty; BINS];
            for (b, (on, count, lo, size)) in bins.iter_mut().zip(&full) {
                if *on && (!sparse || count % 3 == 0) {
                    let lo = Vec3A::from_array(lo.map(|v| if v == 0 { -0.0 } else { v as f32 }));
                    *b = (lo, lo + Vec3A::from_array(size.map(|v| v as f32)), *count);
                }
            }
            let n = bins.iter().map(|b| b.2).sum();
            prop_assert_eq!(sweep(&bins, n), sweep_every_bin(&bins, n));
        }
    }

    /// `bin` against the saturating conversion it replaces, at bin edges (by hand: with
    /// c0 = 1 and k = 4, c = 1.25 is the start of bin 1 and c = 4.75 of the last, bin
    /// 15 of 16), beyond both ends, and at NaN.
    #[test]
    fn bin_is_the_saturating_conversion() {
        let old = |c: f32, c0: f32, k: f32| (((c - c0) * k) as usize).min(BINS - 1);
        assert_eq!(bin(1.25, 1.0, 4.0), 1);
        assert_eq!(bin(1.2499, 1.0, 4.0), 0);
        assert_eq!(bin(4.75, 1.0, 4.0), 15);
        assert_eq!(bin(4.7499, 1.0, 4.0), 14);
        assert_eq!(bin(5.0, 1.0, 4.0), 15);
        assert_eq!(bin(0.5, 1.0, 4.0), 0);
        assert_eq!(bin(f32::NAN, 1.0, 4.0), 0);
        let mut c = -3.0;
        while c < 9.0 {
            for k in [4.0, 3.7, 1e-30, 1e30, f32::INFINITY] {
                assert_eq!(bin(c, 1.0, k), old(c, 1.0, k), "c {c} k {k}");
            }
            c += 1.0 / 64.0 + 1e-9;
        }
        for c in [f32::INFINITY, f32::NEG_INFINITY, f32::NAN, 3e38, -3e38] {
            assert_eq!(bin(c, 1.0, 4.0), old(c, 1.0, 4.0), "c {c}");
        }
    }

    proptest! {
        /// The three lanes give `bin`'s answer, over centres and origins from every
        /// part of f32's range (negatives, zeros of either sign, infinities, NaN) and
        /// factors from 0 to ∞.
        #[test]
        fn the_lanes_bin_as_bin_does(
            c in (any::<f32>(), any::<f32>(), -40.0f32..40.0),
            c0 in (any::<f32>(), -40.0f32..40.0, any::<f32>()),
            k in (any::<f32>(), 0.0f32..8.0, 0.0f32..1e6),
        ) {
            let (c, c0) = ([c.0, c.1, c.2], [c0.0, c0.1, c0.2]);
            let k = [k.0.abs(), k.1, k.2];
            let at = bins3(
                Vec3::from_array(c),
                f32x4::from([c0[0], c0[1], c0[2], 0.0]),
                f32x4::from([k[0], k[1], k[2], 0.0]),
            );
            for axis in 0..3 {
                prop_assert_eq!(at[axis] as usize, bin(c[axis], c0[axis], k[axis]), "axis {}", axis);
            }
        }
    }
}
