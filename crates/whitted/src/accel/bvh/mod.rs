//! A bounding volume hierarchy over bounded primitives (`Bounded`: the spheres of `Prim`,
//! any bounded shape of `ShapePrim`), built once per scene (binned SAH, `build`),
//! queried without allocation (a fixed stack on the call's own stack frame; the box test
//! is `raybox`'s).
//!
//! Exactness. The tree only prunes: a sphere whose box the ray misses is never tested.
//! For that never to lose a hit the sphere test would have found, the box test is made
//! conservative against the rounding of both tests (see `RayBox::new`): boxes are widened
//! by a margin δ that grows with the coordinates involved, far larger than the error of
//! the geometric sphere test. A sphere the ray really meets is then always visited, and
//! the caller chooses among the hits it finds with the same rule as the linear scan, so
//! the result is the linear scan's, bit for bit. The other bounded shapes (triangles,
//! cones) lie inside their boxes exactly, and their tests' rounding moves a hit point by
//! a few ulps of its coordinates, far inside the same margin.

mod build;
mod raybox;

use crate::optics::Ray;
use crate::shapes::{Shape, Sphere};
use glam::DVec3;
use raybox::RayBox;

/// Leaves hold at most this many spheres (unless the build runs out of depth).
const LEAF_MAX: usize = 4;
/// Up to this many spheres there is no tree: every query tests them all, in order (fewer
/// instructions than box tests for so few; see docs/performance.md).
pub const FLAT_MAX: usize = 12;
/// SAH bins per split.
const BINS: usize = 16;
/// Deepest level the build creates (10,000 spheres need about 15); the traversal stack
/// holds one entry per level.
const MAX_DEPTH: usize = 32;
const STACK: usize = MAX_DEPTH + 2;
/// Relative box margin: δ = PAD · (|origin|∞ + scale + 1), see `RayBox::new`.
const PAD: f64 = 1e-5;

/// One sphere of the tree with the index of its object in the scene.
#[derive(Clone, Copy, Debug)]
pub struct Prim {
    /// The sphere itself (a copy, so a leaf test needs no indirection).
    pub sphere: Sphere,
    /// Its index in the scene's object list (file order), which breaks ties.
    pub index: u32,
    /// Kt > 0: shadow rays cross it.
    pub glass: bool,
    /// Kt ≤ 0: shadow rays stop at it. (Neither, for a NaN Kt.)
    pub opaque: bool,
}

/// One bounded shape of the tree (a triangle, a smooth triangle, a cone ...) with the
/// index of its object in the scene.
#[derive(Clone, Debug)]
pub struct ShapePrim {
    /// The shape (a copy, so a leaf test needs no indirection).
    pub shape: Shape,
    /// Its index in the scene's object list (file order), which breaks ties.
    pub index: u32,
    /// Kt > 0: shadow rays cross it.
    pub glass: bool,
    /// Kt ≤ 0: shadow rays stop at it. (Neither, for a NaN Kt.)
    pub opaque: bool,
}

/// What the tree needs of a primitive: its box and centre, and whether it is glass.
pub trait Bounded: Clone {
    /// The low corner, the high corner and the centre of its box.
    fn bounds(&self) -> (DVec3, DVec3, DVec3);
    /// Kt > 0 (a flat list keeps the others first).
    fn is_glass(&self) -> bool;
}

impl Bounded for Prim {
    #[inline]
    fn bounds(&self) -> (DVec3, DVec3, DVec3) {
        let s: Sphere = self.sphere;
        let r = DVec3::splat(s.radius);
        (s.center - r, s.center + r, s.center)
    }
    fn is_glass(&self) -> bool {
        self.glass
    }
}

impl Bounded for ShapePrim {
    fn bounds(&self) -> (DVec3, DVec3, DVec3) {
        let (lo, hi) = self
            .shape
            .bounds()
            .expect("only bounded shapes go into the tree");
        (lo, hi, 0.5 * (lo + hi))
    }
    fn is_glass(&self) -> bool {
        self.glass
    }
}

#[derive(Clone, Copy, Debug)]
struct Node {
    /// The low and high corners.
    b: [[f64; 3]; 2],
    /// Leaf: first primitive; interior: the left child (the right one follows it).
    first: u32,
    /// Primitives in a leaf; 0 for an interior node.
    count: u32,
}

const BLANK: Node = Node {
    b: [[0.0; 3]; 2],
    first: 0,
    count: 0,
};

/// The tree: nodes in depth-first order, leaves pointing into `prims`. With at most
/// `FLAT_MAX` primitives there are no nodes, only the primitives, opaque ones first.
#[derive(Clone, Debug)]
pub struct Bvh<P = Prim> {
    nodes: Vec<Node>,
    prims: Vec<P>,
    /// The largest coordinate magnitude of the boxes.
    scale: f64,
    /// In a flat list, how many opaque primitives come first.
    flat_opaque: usize,
}

struct Item<P> {
    lo: DVec3,
    hi: DVec3,
    centre: DVec3,
    prim: P,
}

impl<P> Default for Bvh<P> {
    fn default() -> Bvh<P> {
        Bvh {
            nodes: Vec::new(),
            prims: Vec::new(),
            scale: 0.0,
            flat_opaque: 0,
        }
    }
}

impl<P: Bounded> Bvh<P> {
    /// Builds the tree over `prims` (any order; each keeps its object index).
    pub fn build(prims: Vec<P>) -> Bvh<P> {
        let mut items: Vec<Item<P>> = prims
            .into_iter()
            .map(|prim| {
                let (lo, hi, centre) = prim.bounds();
                Item {
                    lo,
                    hi,
                    centre,
                    prim,
                }
            })
            .collect();
        let mut bvh = Bvh {
            scale: items
                .iter()
                .map(|it| it.lo.abs().max(it.hi.abs()).max_element())
                .fold(0.0, f64::max),
            ..Bvh::default()
        };
        if items.len() <= FLAT_MAX {
            // Opaque first, so that shadow rays can run through those alone.
            bvh.prims = items.into_iter().map(|it| it.prim).collect();
            bvh.prims.sort_by_key(|p| p.is_glass());
            bvh.flat_opaque = bvh.prims.iter().filter(|p| !p.is_glass()).count();
            return bvh;
        }
        bvh.nodes.push(BLANK);
        build::build_node(&mut bvh.nodes, &mut items, 0, 0, 0);
        bvh.prims = items.into_iter().map(|it| it.prim).collect();
        bvh
    }

    /// True when the tree holds no sphere.
    pub fn is_empty(&self) -> bool {
        self.prims.is_empty()
    }

    /// How many spheres the tree holds.
    pub fn len(&self) -> usize {
        self.prims.len()
    }

    /// True when the tree is a flat list (no box tests).
    pub fn is_flat(&self) -> bool {
        self.nodes.is_empty()
    }

    /// For a flat list, its opaque primitives.
    #[inline]
    pub fn flat_opaque(&self) -> Option<&[P]> {
        self.nodes
            .is_empty()
            .then(|| &self.prims[..self.flat_opaque])
    }

    /// Calls `visit` on every primitive whose (widened) box the ray meets at some t in
    /// [0, limit()], nearer subtrees first (a flat list: every primitive, in order). `visit` returns the new limit (it may shrink
    /// it, as a nearest-hit search does) or `None` to stop at once (an any-hit search).
    #[inline(always)]
    pub fn traverse(
        &self,
        ray: &Ray,
        mut limit: f64,
        mut visit: impl FnMut(&P, f64) -> Option<f64>,
    ) {
        if self.nodes.is_empty() {
            for prim in &self.prims {
                match visit(prim, limit) {
                    Some(l) => limit = l,
                    None => return,
                }
            }
            return;
        }
        self.traverse_tree(ray, limit, visit)
    }

    /// `traverse` through the nodes (kept out of line, so that a query on a flat list
    /// carries none of this).
    #[inline(never)]
    fn traverse_tree(
        &self,
        ray: &Ray,
        mut limit: f64,
        mut visit: impl FnMut(&P, f64) -> Option<f64>,
    ) {
        let rb = &RayBox::new(ray, self.scale);
        if rb.enter(&self.nodes[0], limit).is_none() {
            return;
        }
        // Two plain arrays: cheaper to zero than an array of pairs.
        let mut stack_node = [0u32; STACK];
        let mut stack_t = [0.0f64; STACK];
        let mut sp = 0usize;
        let mut node = 0usize;
        loop {
            let n = &self.nodes[node];
            if n.count > 0 {
                let first = n.first as usize;
                for prim in &self.prims[first..first + n.count as usize] {
                    match visit(prim, limit) {
                        Some(l) => limit = l,
                        None => return,
                    }
                }
            } else {
                let l = n.first as usize;
                let hl = rb.enter(&self.nodes[l], limit);
                let hr = rb.enter(&self.nodes[l + 1], limit);
                match (hl, hr) {
                    (Some(tl), Some(tr)) => {
                        let (near, far, tfar) = if tl <= tr {
                            (l, l + 1, tr)
                        } else {
                            (l + 1, l, tl)
                        };
                        stack_node[sp] = far as u32;
                        stack_t[sp] = tfar;
                        sp += 1;
                        node = near;
                        continue;
                    }
                    (Some(_), None) => {
                        node = l;
                        continue;
                    }
                    (None, Some(_)) => {
                        node = l + 1;
                        continue;
                    }
                    (None, None) => {}
                }
            }
            // Next subtree from the stack whose entry is still within the limit.
            loop {
                if sp == 0 {
                    return;
                }
                sp -= 1;
                if stack_t[sp] <= limit {
                    node = stack_node[sp] as usize;
                    break;
                }
            }
        }
    }

    /// The depth of the tree (1 for a single leaf), for tests and statistics.
    pub fn depth(&self) -> usize {
        fn walk(nodes: &[Node], i: usize) -> usize {
            let n = &nodes[i];
            if n.count > 0 {
                1
            } else {
                1 + walk(nodes, n.first as usize).max(walk(nodes, n.first as usize + 1))
            }
        }
        if self.nodes.is_empty() {
            0
        } else {
            walk(&self.nodes, 0)
        }
    }
}
