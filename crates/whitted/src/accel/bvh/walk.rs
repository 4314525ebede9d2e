//! The walk through the four-wide nodes: each node's four boxes in one lane test
//! (`raybox`), the children hit entered nearest first when `ORDERED` (nearest-hit
//! searches, whose limit shrinks as they go), the others stacked with their entry
//! parameters. Measured on the SPD (callgrind, see docs/performance.md): visiting a
//! node's leaves at once and stacking only interior nodes cost 2.5–7 % more than this.

use super::node4::{WideNode, LEAF};
use super::raybox::{limit32, RayBox};
use crate::optics::Ray;

/// Calls `visit` on the primitives of every leaf whose box the ray meets within the
/// limit, as `Bvh::traverse` says (`nodes` non-empty, root at 0). `STACK` is at least
/// three entries per level of the tree: each node stacks at most three children.
#[inline(never)]
pub(super) fn walk<P, const ORDERED: bool, const STACK: usize>(
    nodes: &[WideNode],
    prims: &[P],
    scale: f64,
    ray: &Ray,
    mut limit: f64,
    mut visit: impl FnMut(&P, f64) -> Option<f64>,
) {
    let Some(rb) = RayBox::new(ray, scale) else {
        // Beyond the lanes' range: every primitive, in the tree's order.
        for prim in prims {
            match visit(prim, limit) {
                Some(l) => limit = l,
                None => return,
            }
        }
        return;
    };
    let mut lim = limit32(limit);
    // Three plain arrays: cheaper to zero than an array of triples.
    let mut stack_ref = [0u32; STACK];
    let mut stack_count = [0u32; STACK];
    let mut stack_t = [0.0f32; STACK];
    let mut sp = 0usize;
    // The root, an interior node.
    let (mut cur, mut count) = (0u32, 0u32);
    loop {
        if cur & LEAF != 0 {
            let first = (cur & !LEAF) as usize;
            for prim in &prims[first..first + count as usize] {
                match visit(prim, limit) {
                    Some(l) => limit = l,
                    None => return,
                }
            }
            lim = limit32(limit);
        } else {
            let n = &nodes[cur as usize];
            let (mask, t) = rb.enter4(n, lim);
            if mask != 0 {
                // The slots hit; by entry parameter when ordered (insertion into four).
                let mut order = [0usize; 4];
                let mut k = 0;
                let mut bits = mask;
                while bits != 0 {
                    // The set bits, lowest first.
                    let s = bits.trailing_zeros() as usize;
                    bits &= bits - 1;
                    let mut j = k;
                    if ORDERED {
                        while j > 0 && t[order[j - 1]] > t[s] {
                            order[j] = order[j - 1];
                            j -= 1;
                        }
                    }
                    order[j] = s;
                    k += 1;
                }
                for &s in order[1..k].iter().rev() {
                    stack_ref[sp] = n.child[s];
                    stack_count[sp] = n.count[s];
                    stack_t[sp] = t[s];
                    sp += 1;
                }
                cur = n.child[order[0]];
                count = n.count[order[0]];
                continue;
            }
        }
        // Next subtree from the stack whose entry is still within the limit.
        loop {
            if sp == 0 {
                return;
            }
            sp -= 1;
            if !ORDERED || stack_t[sp] <= lim {
                cur = stack_ref[sp];
                count = stack_count[sp];
                break;
            }
        }
    }
}
