//! The walk through the eight-wide nodes: each node's boxes in one lane test (`lanes`),
//! the children hit entered nearest first when `ORDERED` (nearest-hit searches, whose
//! limit shrinks as they go), the others stacked with their entry parameters. The walk
//! is written once over `Lanes` and compiled for each: `walk` picks the tree's lanes,
//! and the AVX2 copy runs inside `pulp`'s `vectorize`, so that the whole walk, with the
//! caller's leaf visitor inlined into it, is compiled for AVX2. The narrow copy, for
//! processors without AVX2, is compiled once per order and calls the visitor through a
//! pointer: inlined into every query too, it doubled the time to link each binary
//! (`raytrace` 63 s against 34 s) and counted more instructions (gears 4,527 M against
//! 4,470 M).

use super::lanes::{Choice, Lanes, Narrow};
use super::node8::{WideNode, LEAF, WIDTH};
use super::raybox::{limit32, RayBox};
use crate::optics::Ray;
use arrayvec::ArrayVec;

/// Calls `leaf(first, count, limit)` on every leaf whose box the ray meets within the
/// limit (its primitives are `first..first + count` of the tree's `len`), as
/// `Bvh::traverse_leaves` says (`nodes` non-empty, root at 0). `STACK` is at least
/// `WIDTH - 1` entries per level of the tree: each node stacks at most that many.
#[inline(never)]
#[allow(clippy::too_many_arguments)]
pub(super) fn walk<const ORDERED: bool, const STACK: usize>(
    lanes: Choice,
    nodes: &[WideNode],
    len: usize,
    scale: f64,
    ray: &Ray,
    limit: f64,
    mut leaf: impl FnMut(usize, usize, f64) -> Option<f64>,
) {
    match lanes {
        Choice::Narrow => walk_narrow::<ORDERED, STACK>(nodes, len, scale, ray, limit, &mut leaf),
        #[cfg(all(feature = "avx2", target_arch = "x86_64"))]
        Choice::Avx2(v3) => pulp::Simd::vectorize(
            v3,
            WalkAvx2::<ORDERED, STACK, _> {
                v3,
                nodes,
                len,
                scale,
                ray,
                limit,
                leaf: &mut leaf,
            },
        ),
    }
}

/// The walk in AVX2 lanes as `pulp` runs it: `vectorize` compiles `with_simd` (and all
/// it inlines: the walk, the caller's visitor) for AVX2. Seven words, all references or
/// plain values, so that `vectorize` passes it in registers: a larger one is copied to
/// the stack on every query, and copying a freshly written ray box stalled the bunny's
/// queries on store forwarding (8 % of its time). The visitor is called directly, not
/// through `&mut F`'s `FnMut` shim, which the compiler left out of line.
#[cfg(all(feature = "avx2", target_arch = "x86_64"))]
struct WalkAvx2<'a, const ORDERED: bool, const STACK: usize, F> {
    v3: pulp::x86::V3,
    nodes: &'a [WideNode],
    len: usize,
    scale: f64,
    ray: &'a Ray,
    limit: f64,
    leaf: &'a mut F,
}

#[cfg(all(feature = "avx2", target_arch = "x86_64"))]
impl<const ORDERED: bool, const STACK: usize, F> pulp::WithSimd for WalkAvx2<'_, ORDERED, STACK, F>
where
    F: FnMut(usize, usize, f64) -> Option<f64>,
{
    type Output = ();

    #[inline(always)]
    fn with_simd<S: pulp::Simd>(self, _: S) {
        let lanes = super::lanes::Avx2(self.v3);
        let (nodes, len, scale, ray, limit) =
            (self.nodes, self.len, self.scale, self.ray, self.limit);
        walk_in::<ORDERED, STACK, _, _>(lanes, nodes, len, scale, ray, limit, self.leaf)
    }
}

/// The walk in the narrow lanes, compiled once per order, the visitor called through a
/// pointer (see the module's text).
#[inline(never)]
fn walk_narrow<const ORDERED: bool, const STACK: usize>(
    nodes: &[WideNode],
    len: usize,
    scale: f64,
    ray: &Ray,
    limit: f64,
    leaf: &mut dyn FnMut(usize, usize, f64) -> Option<f64>,
) {
    walk_in::<ORDERED, STACK, _, _>(Narrow, nodes, len, scale, ray, limit, leaf)
}

#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn walk_in<const ORDERED: bool, const STACK: usize, L: Lanes, F>(
    lanes: L,
    nodes: &[WideNode],
    len: usize,
    scale: f64,
    ray: &Ray,
    mut limit: f64,
    leaf: &mut F,
) where
    F: FnMut(usize, usize, f64) -> Option<f64> + ?Sized,
{
    let Some(rb) = RayBox::new(ray, scale) else {
        // Beyond the lanes' range: every primitive, in the tree's order, as one leaf.
        leaf(0, len, limit);
        return;
    };
    let r = lanes.ray(&rb);
    let mut lim = limit32(limit);
    // The subtrees still to visit: (reference, count, entry t). An `ArrayVec`, never
    // zeroed (zeroing plain arrays per query cost gears 1.3 % of its instructions).
    let mut stack = ArrayVec::<(u32, u32, f32), STACK>::new();
    // The root, an interior node.
    let (mut cur, mut count) = (0u32, 0u32);
    loop {
        if cur & LEAF != 0 {
            match leaf((cur & !LEAF) as usize, count as usize, limit) {
                Some(l) => limit = l,
                None => return,
            }
            lim = limit32(limit);
        } else {
            let n = &nodes[cur as usize];
            let (mask, t) = lanes.enter(&r, n, lim);
            if mask != 0 && !ORDERED {
                // Any order: the lowest slot hit next, the others stacked highest first
                // (so they come off the stack in slot order).
                let first = mask.trailing_zeros() as usize;
                let mut bits = mask & (mask - 1);
                while bits != 0 {
                    let s = 31 - bits.leading_zeros() as usize;
                    bits &= !(1 << s);
                    stack.push((n.child[s], n.count[s], 0.0));
                }
                cur = n.child[first];
                count = n.count[first];
                continue;
            }
            if mask != 0 {
                // The slots hit, by entry parameter (insertion, lowest slot first among
                // equals).
                let mut order = [0usize; WIDTH];
                let mut k = 0;
                let mut bits = mask;
                while bits != 0 {
                    // The set bits, lowest first.
                    let s = bits.trailing_zeros() as usize;
                    bits &= bits - 1;
                    let mut j = k;
                    while j > 0 && t[order[j - 1]] > t[s] {
                        order[j] = order[j - 1];
                        j -= 1;
                    }
                    order[j] = s;
                    k += 1;
                }
                for &s in order[1..k].iter().rev() {
                    stack.push((n.child[s], n.count[s], t[s]));
                }
                cur = n.child[order[0]];
                count = n.count[order[0]];
                continue;
            }
        }
        // Next subtree from the stack whose entry is still within the limit.
        loop {
            let Some((r, c, t)) = stack.pop() else {
                return;
            };
            if !ORDERED || t <= lim {
                (cur, count) = (r, c);
                break;
            }
        }
    }
}
