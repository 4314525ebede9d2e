//! A bounding volume hierarchy over bounded primitives (`Bounded`: the spheres of `Prim`,
//! any other bounded shape or a mesh's triangle in `ShapePrim`), built once per scene
//! (binned SAH, `build`, in parallel to the same tree on any thread count),
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
//! cones, a mesh's triangles) lie inside their boxes exactly, and their tests' rounding
//! moves a hit point by a few ulps of its coordinates, far inside the same margin.

mod build;
mod holder;
mod lanes;
mod node8;
mod raybox;
mod sah;
mod shaft;
mod walk;

use crate::optics::Ray;
use crate::shapes::Sphere;
use glam::{DVec3, Vec3, Vec3A};
use lanes::Choice;
use node8::{down, up, WideNode, LEAF, WIDTH};
pub use shaft::Shaft;

/// The build splits every node of more primitives than this (unless it runs out of
/// depth) ...
const LEAF_MAX: usize = 2;
/// ... except one of at most this many that the SAH finds cheaper as a leaf: so leaves
/// hold at most `LEAF_SAH_MAX` primitives.
const LEAF_SAH_MAX: usize = 4;
/// A node's traversal cost in the SAH, in primitive tests (0.25, 1 and 2 counted more
/// instructions on the SPD; docs/performance.md).
const TRAVERSE_COST: f64 = 0.5;
/// Up to this many spheres there is no tree: every query tests them all, in order (fewer
/// instructions than box tests for so few; see docs/performance.md).
pub const FLAT_MAX: usize = 12;
/// SAH bins per split.
const BINS: usize = 16;
/// Deepest level the build creates (10,000 spheres need about 15). The wide tree is no
/// deeper, and its traversal stacks at most `WIDTH - 1` children per level.
const MAX_DEPTH: usize = 32;
const STACK: usize = (WIDTH - 1) * (MAX_DEPTH + 2);
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

/// One primitive of the shapes' tree: a bounded shape of an object (a triangle, a
/// smooth triangle, a cone, an extension shape: `part` indexes the accelerator's table
/// of them) or one triangle of a mesh object (`part` is the triangle's index in mesh
/// `mesh`). Small, so that a million triangles fit.
#[derive(Clone, Copy, Debug)]
pub struct ShapePrim {
    /// Its object's index in the scene's object list (file order), which breaks ties.
    pub index: u32,
    /// The slot of its shape, or its triangle in the mesh.
    pub part: u32,
    /// `SOLO` for a shape of its own, `TRI` for a triangle of its own (`part` then
    /// indexes the accelerator's compact triangles), `SPHERE` for a sphere (`part`
    /// indexes the accelerator's spheres), else the slot of its mesh.
    pub mesh: u32,
    /// For a mesh's triangle, its corner and edges' slot in the accelerator's copy of
    /// them in the tree's order (0 elsewhere).
    pub slot: u32,
    /// Kt > 0: shadow rays cross it.
    pub glass: bool,
    /// Kt ≤ 0: shadow rays stop at it. (Neither, for a NaN Kt.)
    pub opaque: bool,
}

impl ShapePrim {
    /// `mesh` of a primitive that is a shape of its own.
    pub const SOLO: u32 = u32::MAX;
    /// `mesh` of a primitive that is a triangle of its own (an NFF polygon's).
    pub const TRI: u32 = u32::MAX - 1;
    /// `mesh` of a primitive that is a sphere (when the spheres share this tree).
    pub const SPHERE: u32 = u32::MAX - 2;

    /// Whether it is a shape of its own (no mesh's triangle).
    #[inline(always)]
    pub fn is_own(&self) -> bool {
        self.mesh >= ShapePrim::SPHERE
    }
}

/// What the tree needs of a primitive besides its box: whether it is glass.
pub trait Bounded: Copy {
    /// Kt > 0 (a flat list keeps the others first).
    fn is_glass(&self) -> bool;
}

impl Bounded for Prim {
    fn is_glass(&self) -> bool {
        self.glass
    }
}

impl Bounded for ShapePrim {
    fn is_glass(&self) -> bool {
        self.glass
    }
}

impl Prim {
    /// The box of its sphere, and its centre.
    #[inline]
    pub fn bounds(&self) -> (DVec3, DVec3, DVec3) {
        let (lo, hi) = self.sphere.bounds();
        (lo, hi, self.sphere.center)
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
    /// The wide nodes (`node8`), root at 0.
    nodes: Vec<WideNode>,
    /// The lanes its queries test the nodes' boxes with.
    lanes: Choice,
    prims: Vec<P>,
    /// The largest coordinate magnitude of the boxes.
    scale: f64,
    /// In a flat list, how many opaque primitives come first.
    flat_opaque: usize,
    /// For each primitive (in the tree's order), the node whose slot holds its leaf.
    holder: Vec<u32>,
}

/// A primitive while the tree is built: its box rounded outward to f32, as the wide
/// nodes keep it (so a node's box is the one the f64 boxes round to: rounding outward
/// and taking the union commute), its centre rounded to f32, and its place in the list
/// given to the build. 48 bytes: a million triangles' items were 96 each, and the
/// build's passes over them were a quarter of that scene's set-up.
#[derive(Clone, Copy, Debug)]
struct Item {
    lo: Vec3A,
    hi: Vec3A,
    centre: Vec3,
    prim: u32,
}

impl Item {
    fn new(prim: usize, (lo, hi, centre): (DVec3, DVec3, DVec3)) -> Item {
        Item {
            lo: Vec3A::new(down(lo.x), down(lo.y), down(lo.z)),
            hi: Vec3A::new(up(hi.x), up(hi.y), up(hi.z)),
            centre: centre.as_vec3(),
            prim: prim as u32,
        }
    }
}

impl<P> Default for Bvh<P> {
    fn default() -> Bvh<P> {
        Bvh {
            nodes: Vec::new(),
            lanes: Choice::chosen(),
            prims: Vec::new(),
            scale: 0.0,
            flat_opaque: 0,
            holder: Vec::new(),
        }
    }
}

impl<P: Bounded + Send + Sync> Bvh<P> {
    /// Builds the tree over `prims` (any order; each keeps its object index), each with
    /// the low and high corners of its box and the point that sorts it (its centre), from
    /// `bounds`, computed in parallel.
    pub fn build(prims: Vec<P>, bounds: impl Fn(&P) -> (DVec3, DVec3, DVec3) + Sync) -> Bvh<P> {
        Bvh::build_leaves(prims, bounds, LEAF_MAX)
    }

    /// `build` splitting only nodes of more than `leaf_max` primitives (leaves of
    /// triangles, tested four at a time, take up to four: `accel::packet`).
    pub fn build_leaves(
        prims: Vec<P>,
        bounds: impl Fn(&P) -> (DVec3, DVec3, DVec3) + Sync,
        leaf_max: usize,
    ) -> Bvh<P> {
        use rayon::prelude::*;
        let item = |(i, prim): (usize, &P)| Item::new(i, bounds(prim));
        // Outside a pool (one sized by --threads), no rayon: its global pool would start.
        let mut items: Vec<Item> = if rayon::current_thread_index().is_some() {
            prims.par_iter().enumerate().map(item).collect()
        } else {
            prims.iter().enumerate().map(item).collect()
        };
        // From the rounded boxes: no smaller than from the f64 ones (each box's farthest
        // corner rounds away from zero), so the box margin is still wide enough.
        let mut bvh = Bvh {
            scale: items
                .iter()
                .map(|it| it.lo.abs().max(it.hi.abs()).max_element())
                .fold(0.0, f32::max) as f64,
            ..Bvh::default()
        };
        if items.len() <= FLAT_MAX {
            // Opaque first, so that shadow rays can run through those alone.
            bvh.prims = prims;
            bvh.prims.sort_by_key(|p| p.is_glass());
            bvh.flat_opaque = bvh.prims.iter().filter(|p| !p.is_glass()).count();
            return bvh;
        }
        bvh.nodes = node8::collapse(&build::build_tree(&mut items, leaf_max));
        // The items go before the primitives are copied into the tree's order.
        let order: Vec<u32> = items.iter().map(|it| it.prim).collect();
        drop(items);
        bvh.prims = order.iter().map(|&i| prims[i as usize]).collect();
        bvh.holder = holder::table(&bvh.nodes, bvh.prims.len());
        bvh
    }

    /// The primitives in the tree's order (a leaf's are neighbours), to be changed in
    /// place without moving them.
    pub fn prims_mut(&mut self) -> &mut [P] {
        &mut self.prims
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
    /// [0, limit], nearer subtrees first (a flat list: every primitive, in order).
    /// `visit` returns the new limit (it may shrink it, as a nearest-hit search does) or
    /// `None` to stop at once (an any-hit search).
    #[inline(always)]
    pub fn traverse(&self, ray: &Ray, limit: f64, visit: impl FnMut(&P, f64) -> Option<f64>) {
        self.query::<true>(ray, limit, visit)
    }

    /// `traverse` in whatever order the tree gives, for visitors that never shrink the
    /// limit (shadow rays: every crossing counts, or the first opaque blocker stops it),
    /// where sorting the children by distance buys nothing.
    #[inline(always)]
    pub fn traverse_any(&self, ray: &Ray, limit: f64, visit: impl FnMut(&P, f64) -> Option<f64>) {
        self.query::<false>(ray, limit, visit)
    }

    #[inline(always)]
    fn query<const ORDERED: bool>(
        &self,
        ray: &Ray,
        limit: f64,
        mut visit: impl FnMut(&P, f64) -> Option<f64>,
    ) {
        let prims = &self.prims[..];
        self.query_leaves::<ORDERED>(
            ray,
            limit,
            #[inline(always)]
            |first, count, mut limit| {
                for prim in &prims[first..first + count] {
                    limit = visit(prim, limit)?;
                }
                Some(limit)
            },
        )
    }

    /// `traverse` (`ORDERED`) or `traverse_any` a leaf at a time: `leaf(first, count,
    /// limit)` for the primitives `first..first + count` of `prims` (a flat list, or a
    /// ray beyond the lanes' range: every primitive, as one leaf), returning the new
    /// limit or `None` to stop.
    #[inline(always)]
    pub fn query_leaves<const ORDERED: bool>(
        &self,
        ray: &Ray,
        limit: f64,
        mut leaf: impl FnMut(usize, usize, f64) -> Option<f64>,
    ) {
        if self.nodes.is_empty() {
            leaf(0, self.prims.len(), limit);
            return;
        }
        let (nodes, len, scale) = (&self.nodes[..], self.prims.len(), self.scale);
        walk::walk::<ORDERED, STACK>(self.lanes, nodes, len, scale, ray, limit, leaf)
    }

    /// The primitives in the tree's order (a leaf's are neighbours).
    pub fn prims(&self) -> &[P] {
        &self.prims
    }

    /// Every leaf of the tree as (first primitive, count); none for a flat list.
    pub fn leaves(&self) -> Vec<(usize, usize)> {
        let mut out = Vec::new();
        for n in &self.nodes {
            for s in 0..WIDTH {
                if n.child[s] & LEAF != 0 {
                    out.push(((n.child[s] & !LEAF) as usize, n.count[s] as usize));
                }
            }
        }
        out
    }

    /// The depth of the wide tree (1 for a root whose children are all leaves;
    /// 0 for a flat list), for tests and statistics.
    pub fn depth(&self) -> usize {
        fn walk(nodes: &[WideNode], i: usize) -> usize {
            let n = &nodes[i];
            let below = (0..WIDTH)
                .filter(|&s| {
                    n.child[s] & LEAF == 0 && n.count[s] == 0 && n.b[0][0][s] <= n.b[1][0][s]
                })
                .map(|s| walk(nodes, n.child[s] as usize))
                .max()
                .unwrap_or(0);
            1 + below
        }
        if self.nodes.is_empty() {
            0
        } else {
            walk(&self.nodes, 0)
        }
    }
}

#[cfg(all(test, feature = "avx2", target_arch = "x86_64"))]
mod lanes_tests;
#[cfg(test)]
mod tests;
