//! The eight-wide tree the queries walk: the binary SAH tree of `build`, collapsed so
//! that each node holds up to eight children whose boxes are tested together in f32
//! lanes (`raybox`: one AVX2 register or two SSE ones, the same operations either way).
//! Each box is the binary tree's box rounded outward to f32 (its low corner down, its
//! high corner up; the build's items are rounded so already, and rounding outward
//! commutes with taking the union), so it still contains everything the primitives'
//! f64 boxes did; the traversal's δ margin does the rest (see `RayBox::new`).
//!
//! Collapsing: starting from a binary node's two children, the interior child with the
//! largest surface area is replaced by its own two children until there are `WIDTH` (or
//! only leaves are left); leaves keep the binary tree's primitive ranges. The width is
//! the same on every machine, so the tree is too; only the lanes that test a node's
//! boxes are chosen when the program starts.

use super::Node;

/// A child slot's reference: an interior node's index, or a leaf's first primitive
/// with `LEAF` set (its count is in `WideNode::count`).
pub(super) const LEAF: u32 = 1 << 31;

/// Children per node.
pub(super) const WIDTH: usize = 8;

/// Up to `WIDTH` children, their boxes laid out by axis for the lanes. 256 bytes, aligned
/// to 64 so that a node is four whole cache lines.
#[derive(Clone, Copy, Debug)]
#[repr(C, align(64))]
pub(super) struct WideNode {
    /// `b[0][axis][slot]`: the low corners, rounded down to f32 (empty slots hold +∞);
    /// `b[1][axis][slot]`: the high corners, rounded up (empty slots hold −∞). A ray
    /// enters by `b[neg]` on each axis, `neg` its direction's sign bit (no branch).
    pub b: [[[f32; WIDTH]; 3]; 2],
    /// Per slot: an interior node's index, or `LEAF | first primitive`.
    pub child: [u32; WIDTH],
    /// Per slot: the leaf's primitive count (0 for an interior child or an empty slot).
    pub count: [u32; WIDTH],
}

const EMPTY: WideNode = WideNode {
    b: [[[f32::INFINITY; WIDTH]; 3], [[f32::NEG_INFINITY; WIDTH]; 3]],
    child: [0; WIDTH],
    count: [0; WIDTH],
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

/// Fills `wide[slot]` with the binary nodes `kids` (expanded to up to `WIDTH`), then
/// appends their interior children's wide nodes, depth first.
fn fill(nodes: &[Node], wide: &mut Vec<WideNode>, slot: usize, kids: &[usize]) {
    let mut kids: Vec<usize> = kids.to_vec();
    while kids.len() < WIDTH {
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
            w.b[0][axis][s] = down(n.b[0][axis]);
            w.b[1][axis][s] = up(n.b[1][axis]);
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
