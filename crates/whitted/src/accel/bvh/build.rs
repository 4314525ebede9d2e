//! Building the tree: binned SAH splits over the three axes of the primitives'
//! centres, down to leaves of `LEAF_MAX` (or `MAX_DEPTH` levels), a node of up to
//! `LEAF_SAH_MAX` kept whole where the SAH prefers a leaf; big subtrees in parallel
//! (`build_tree`), to the same tree on any thread count. The items' boxes and centres
//! are f32 (`Item`: the boxes already rounded outward as the wide nodes keep them), a
//! centre's three bins are found in one lane operation (`bins3`), and the SAH's costs
//! are summed in f64.

use super::{Item, Node, BINS, BLANK, LEAF_SAH_MAX, MAX_DEPTH, TRAVERSE_COST};

/// Subtrees over more primitives than this are built in parallel (below it a task costs
/// more than it saves).
const PAR_MIN: usize = 8192;
use glam::{DVec3, Vec3, Vec3A};
use wide::{f32x4, i32x4};

/// The surface area of the box of f32 corners `lo`, `hi`, in f64.
fn surface_area(lo: Vec3A, hi: Vec3A) -> f64 {
    let d = (hi.as_dvec3() - lo.as_dvec3()).max(DVec3::ZERO);
    2.0 * (d.x * d.y + d.y * d.z + d.z * d.x)
}

/// Fills node `index` with the bounds of `items` (which start at `offset` in the final
/// primitive order) and splits it, recursively.
pub(super) fn build_node(
    nodes: &mut Vec<Node>,
    items: &mut [Item],
    offset: usize,
    index: usize,
    depth: usize,
    leaf_max: usize,
) {
    let Some(mid) = split(nodes, items, offset, index, depth, leaf_max) else {
        return;
    };
    let left = nodes.len();
    nodes.push(BLANK);
    nodes.push(BLANK);
    nodes[index].first = left as u32;
    nodes[index].count = 0;
    let (a, b) = items.split_at_mut(mid);
    build_node(nodes, a, offset, left, depth + 1, leaf_max);
    build_node(nodes, b, offset + mid, left + 1, depth + 1, leaf_max);
}

/// A subtree built apart: its nodes with the root at 0 and children's indices local to
/// the vector, or a split whose two halves were built in parallel.
enum Sub {
    Nodes(Vec<Node>),
    Split(Node, Box<(Sub, Sub)>),
}

/// The nodes of the tree over `items` (at least one), in the order `build_node` alone
/// would not give but always the same: subtrees of more than `PAR_MIN` primitives are
/// split in this thread and their halves built by rayon's `join`, which changes where
/// the work runs, never what it computes. So the tree is the same on any thread count.
pub(super) fn build_tree(items: &mut [Item], leaf_max: usize) -> Vec<Node> {
    let sub = build_sub(items, 0, 0, leaf_max);
    let mut nodes = vec![BLANK];
    place(&mut nodes, sub, 0);
    nodes
}

fn build_sub(items: &mut [Item], offset: usize, depth: usize, leaf_max: usize) -> Sub {
    let mut root = [BLANK];
    if items.len() <= PAR_MIN {
        let mut nodes = vec![BLANK];
        build_node(&mut nodes, items, offset, 0, depth, leaf_max);
        return Sub::Nodes(nodes);
    }
    let Some(mid) = split(&mut root, items, offset, 0, depth, leaf_max) else {
        return Sub::Nodes(root.to_vec());
    };
    let (a, b) = items.split_at_mut(mid);
    // In a pool (the renderer's, sized by --threads) the halves are built side by side;
    // outside one, in turn: rayon's global pool would start a thread per core regardless.
    let halves = if rayon::current_thread_index().is_some() {
        rayon::join(
            || build_sub(a, offset, depth + 1, leaf_max),
            || build_sub(b, offset + mid, depth + 1, leaf_max),
        )
    } else {
        (
            build_sub(a, offset, depth + 1, leaf_max),
            build_sub(b, offset + mid, depth + 1, leaf_max),
        )
    };
    Sub::Split(root[0], Box::new(halves))
}

/// Writes `sub` with its root at `nodes[slot]` and the rest appended.
fn place(nodes: &mut Vec<Node>, sub: Sub, slot: usize) {
    match sub {
        Sub::Nodes(local) => {
            // Local index i ≥ 1 lands at base + i − 1.
            let base = nodes.len();
            let at = |i: u32| (base + i as usize - 1) as u32;
            let fix = |mut n: Node| {
                if n.count == 0 {
                    n.first = at(n.first);
                }
                n
            };
            nodes[slot] = fix(local[0]);
            nodes.extend(local[1..].iter().map(|&n| fix(n)));
        }
        Sub::Split(mut root, halves) => {
            let left = nodes.len();
            nodes.push(BLANK);
            nodes.push(BLANK);
            root.first = left as u32;
            root.count = 0;
            nodes[slot] = root;
            let (a, b) = *halves;
            place(nodes, a, left);
            place(nodes, b, left + 1);
        }
    }
}

/// Fills node `index` with the bounds of `items` and, unless it stays a leaf (which it
/// then also fills), partitions the items and says how many go left.
fn split(
    nodes: &mut [Node],
    items: &mut [Item],
    offset: usize,
    index: usize,
    depth: usize,
    leaf_max: usize,
) -> Option<usize> {
    let (mut lo, mut hi) = (Vec3A::INFINITY, Vec3A::NEG_INFINITY);
    let (mut clo, mut chi) = (Vec3A::INFINITY, Vec3A::NEG_INFINITY);
    for it in items.iter() {
        lo = lo.min(it.lo);
        hi = hi.max(it.hi);
        clo = clo.min(it.centre.into());
        chi = chi.max(it.centre.into());
    }
    let (clo, chi) = (Vec3::from(clo), Vec3::from(chi));
    nodes[index].b = [lo.as_dvec3().to_array(), hi.as_dvec3().to_array()];
    let n = items.len();
    if n <= leaf_max || depth >= MAX_DEPTH {
        nodes[index].first = offset as u32;
        nodes[index].count = n as u32;
        return None;
    }
    let extent = chi - clo;
    let widest = if extent.x >= extent.y && extent.x >= extent.z {
        0
    } else if extent.y >= extent.z {
        1
    } else {
        2
    };
    // Binned SAH over the three axes of the centres: the cheapest split, the lower axis
    // on a tie.
    let best = sah(items, clo, extent);
    if let Some((cost, _, _)) = best {
        let area = surface_area(lo, hi);
        if n <= LEAF_SAH_MAX.max(leaf_max) && n as f64 * area <= TRAVERSE_COST * area + cost {
            nodes[index].first = offset as u32;
            nodes[index].count = n as u32;
            return None;
        }
    }
    let axis = best.map_or(widest, |b| b.1);
    let mid = match best {
        Some((_, axis, split)) => {
            let k = BINS as f32 / extent[axis];
            partition(items, |it| bin(it.centre[axis], clo[axis], k) <= split)
        }
        None => n / 2,
    };
    if mid == 0 || mid == n {
        // All centres in one bin (or all equal): split at the median.
        items.select_nth_unstable_by(n / 2, |a, b| a.centre[axis].total_cmp(&b.centre[axis]));
        return Some(n / 2);
    }
    Some(mid)
}

/// The bin of a centre coordinate `c`: bins of width 1/k from `c0`, the last one closed.
/// The same bin as `(((c - c0) * k) as usize).min(BINS - 1)` for every `c` (NaN and
/// negatives to bin 0), without that conversion's saturating steps for the whole of
/// `usize`: the comparison leaves `as u32` values in [0, BINS).
#[inline]
fn bin(c: f32, c0: f32, k: f32) -> usize {
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
fn sah(items: &[Item], c0: Vec3, extent: Vec3) -> Option<(f64, usize, usize)> {
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

/// Moves the items satisfying `pred` to the front; returns how many there are.
fn partition(items: &mut [Item], pred: impl Fn(&Item) -> bool) -> usize {
    let mut i = 0;
    for j in 0..items.len() {
        if pred(&items[j]) {
            items.swap(i, j);
            i += 1;
        }
    }
    i
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
