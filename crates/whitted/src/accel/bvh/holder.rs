//! The node that holds each primitive's leaf (`Bvh::holder`, a table in the tree's
//! order, read at a primitive's place, `Bvh::place`), and a query over that node's
//! leaves alone: where the shadow cache's last
//! blocker misses, the blocker of a neighbouring ray is most often in a leaf beside
//! its own (`Accel::shape_blocks`), found there without walking down from the root.

use super::lanes::{self, Lanes};
use super::node8::{WideNode, LEAF, WIDTH};
use super::raybox::{limit32, RayBox};
use super::Bvh;
use crate::optics::Ray;

/// For each of `len` primitives, the index of the node with a leaf slot that holds it.
pub(super) fn table(nodes: &[WideNode], len: usize) -> Vec<u32> {
    let mut holder = vec![0; len];
    for (i, n) in nodes.iter().enumerate() {
        for s in 0..WIDTH {
            if n.child[s] & LEAF != 0 {
                let first = (n.child[s] & !LEAF) as usize;
                holder[first..first + n.count[s] as usize].fill(i as u32);
            }
        }
    }
    holder
}

impl<P> Bvh<P> {
    /// The place in the tree's order of `prim`, a reference into `prims()` (as every walk
    /// gives); a reference from elsewhere gives a place past the end, which
    /// `holder_leaves` ignores.
    #[inline(always)]
    pub fn place(&self, prim: &P) -> u32 {
        let offset = (prim as *const P as usize).wrapping_sub(self.prims.as_ptr() as usize);
        u32::try_from(offset / std::mem::size_of::<P>().max(1)).unwrap_or(u32::MAX)
    }

    /// `query_leaves` over the leaves of one node alone: the node that holds the leaf of
    /// the primitive at `at` (in the tree's order), its boxes tested in the narrow lanes
    /// (the same bits as the walk's); its interior children are skipped. Nothing for a
    /// flat list, a place past the end or a ray beyond the lanes' range.
    pub fn holder_leaves(
        &self,
        at: usize,
        ray: &Ray,
        limit: f64,
        mut leaf: impl FnMut(usize, usize, f64) -> Option<f64>,
    ) {
        let Some(&h) = self.holder.get(at) else {
            return;
        };
        let Some(rb) = RayBox::new(ray, self.scale) else {
            return;
        };
        let n = &self.nodes[h as usize];
        let (mut mask, _) = lanes::Narrow.enter(&lanes::Narrow.ray(&rb), n, limit32(limit));
        while mask != 0 {
            let s = mask.trailing_zeros() as usize;
            mask &= mask - 1;
            if n.child[s] & LEAF != 0 {
                let first = (n.child[s] & !LEAF) as usize;
                if leaf(first, n.count[s] as usize, limit).is_none() {
                    return;
                }
            }
        }
    }
}
