//! The four-wide tree the queries walk: the binary SAH tree of `build`, collapsed so
//! that each node holds up to four children whose boxes are tested together in f32
//! lanes (`raybox`). Each box is the binary tree's f64 box rounded outward to f32 (its
//! low corner down, its high corner up), so it still contains everything the f64 box
//! did; the traversal's δ margin does the rest (see `RayBox::new`).
//!
//! Collapsing: starting from a binary node's two children, the interior child with the
//! largest surface area is replaced by its own two children until there are four (or
//! only leaves are left); leaves keep the binary tree's primitive ranges.

use super::Node;

/// A child slot's reference: an interior node's index, or a leaf's first primitive
/// with `LEAF` set (its count is in `WideNode::count`).
pub(super) const LEAF: u32 = 1 << 31;

/// Up to four children, their boxes laid out by axis for the lanes.
#[derive(Clone, Copy, Debug)]
pub(super) struct WideNode {
    /// `lo[axis][slot]`, rounded down to f32; empty slots hold +∞.
    pub lo: [[f32; 4]; 3],
    /// `hi[axis][slot]`, rounded up to f32; empty slots hold −∞.
    pub hi: [[f32; 4]; 3],
    /// Per slot: an interior node's index, or `LEAF | first primitive`.
    pub child: [u32; 4],
    /// Per slot: the leaf's primitive count (0 for an interior child or an empty slot).
    pub count: [u32; 4],
}

const EMPTY: WideNode = WideNode {
    lo: [[f32::INFINITY; 4]; 3],
    hi: [[f32::NEG_INFINITY; 4]; 3],
    child: [0; 4],
    count: [0; 4],
};

/// `x` rounded to an f32 no larger than it (−∞ below f32's range).
pub(super) fn down(x: f64) -> f32 {
    let f = x as f32;
    if f as f64 > x {
        f.next_down()
    } else {
        f
    }
}

/// `x` rounded to an f32 no smaller than it (+∞ above f32's range).
pub(super) fn up(x: f64) -> f32 {
    let f = x as f32;
    if (f as f64) < x {
        f.next_up()
    } else {
        f
    }
}

fn area(n: &Node) -> f64 {
    let d = [0, 1, 2].map(|i| (n.b[1][i] - n.b[0][i]).max(0.0));
    d[0] * d[1] + d[1] * d[2] + d[2] * d[0]
}

/// The wide tree of binary tree `nodes` (root at 0, at least one node). A binary tree
/// that is a single leaf becomes one wide node with that leaf in slot 0.
pub(super) fn collapse(nodes: &[Node]) -> Vec<WideNode> {
    let mut wide = vec![EMPTY];
    fill(nodes, &mut wide, 0, &[0]);
    wide
}

/// Fills `wide[slot]` with the binary nodes `kids` (expanded to up to four), then
/// appends their interior children's wide nodes, depth first.
fn fill(nodes: &[Node], wide: &mut Vec<WideNode>, slot: usize, kids: &[usize]) {
    let mut kids: Vec<usize> = kids.to_vec();
    while kids.len() < 4 {
        // The interior child of largest area (the first of equals) opens up.
        let open = kids
            .iter()
            .enumerate()
            .filter(|(_, &k)| nodes[k].count == 0)
            .fold(None::<(usize, f64)>, |best, (i, &k)| match best {
                Some((_, a)) if a >= area(&nodes[k]) => best,
                _ => Some((i, area(&nodes[k]))),
            });
        let Some((i, _)) = open else { break };
        let first = nodes[kids[i]].first as usize;
        kids.splice(i..=i, [first, first + 1]);
    }
    let mut w = EMPTY;
    for (s, &k) in kids.iter().enumerate() {
        let n = &nodes[k];
        for axis in 0..3 {
            w.lo[axis][s] = down(n.b[0][axis]);
            w.hi[axis][s] = up(n.b[1][axis]);
        }
        if n.count > 0 {
            w.child[s] = LEAF | n.first;
            w.count[s] = n.count;
        }
    }
    wide[slot] = w;
    for (s, &k) in kids.iter().enumerate() {
        let n = &nodes[k];
        if n.count == 0 {
            let at = wide.len();
            wide.push(EMPTY);
            wide[slot].child[s] = at as u32;
            let l = n.first as usize;
            fill(nodes, wide, at, &[l, l + 1]);
        }
    }
}
