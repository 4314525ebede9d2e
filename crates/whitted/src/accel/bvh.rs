//! A bounding volume hierarchy over spheres, built once per scene (binned SAH), queried
//! without allocation (a fixed stack on the call's own stack frame).
//!
//! Exactness. The tree only prunes: a sphere whose box the ray misses is never tested.
//! For that never to lose a hit the sphere test would have found, the box test is made
//! conservative against the rounding of both tests (see `RayBox::new`): boxes are widened
//! by a margin δ that grows with the coordinates involved, far larger than the error of
//! the geometric sphere test. A sphere the ray really meets is then always visited, and
//! the caller chooses among the hits it finds with the same rule as the linear scan, so
//! the result is the linear scan's, bit for bit.

use crate::optics::Ray;
use crate::shapes::Sphere;
use glam::DVec3;

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

/// A ray prepared for box tests: 1/dir, which corner each axis enters by, and its origin
/// moved by ±δ so that every box is widened by δ at no extra cost per node.
#[derive(Clone, Copy, Debug)]
struct RayBox {
    inv: [f64; 3],
    /// Per axis, the corner (0 low, 1 high) whose plane the ray crosses first.
    near: [usize; 3],
    /// The origin moved so that the near planes are pushed out by δ ...
    o_near: [f64; 3],
    /// ... and the far planes too.
    o_far: [f64; 3],
}

#[inline(always)]
fn max(a: f64, b: f64) -> f64 {
    if a > b {
        a
    } else {
        b
    }
}

#[inline(always)]
fn min(a: f64, b: f64) -> f64 {
    if a < b {
        a
    } else {
        b
    }
}

impl RayBox {
    /// `scale`: the largest coordinate magnitude of any box in the tree queried.
    ///
    /// Why δ = 1e-5·(|o|∞ + scale + 1) suffices: the sphere test computes
    /// CH² = |OC|² − (OC·D)², whose absolute error is a few ε·|OC|² (ε = 2^-53); so a
    /// computed hit at t lies within r + √(44ε)·(|OC| + r) ≈ r + 1.1e-7·√3·(|o|∞ + scale)
    /// of the centre, inside the box widened by δ with a margin of ~50×, which also
    /// covers the rounding of the slab arithmetic (a few ε of the same magnitudes).
    #[inline]
    fn new(ray: &Ray, scale: f64) -> RayBox {
        let delta = PAD * (ray.origin.abs().max_element() + scale + 1.0);
        let o = ray.origin.to_array();
        let d = ray.dir.to_array();
        let mut rb = RayBox {
            inv: [0.0; 3],
            near: [0; 3],
            o_near: [0.0; 3],
            o_far: [0.0; 3],
        };
        for i in 0..3 {
            rb.inv[i] = 1.0 / d[i];
            // The sign bit decides, so that −0 enters by the high corner like any
            // negative direction (1/−0 = −∞).
            if d[i].is_sign_negative() {
                rb.near[i] = 1;
                rb.o_near[i] = o[i] - delta;
                rb.o_far[i] = o[i] + delta;
            } else {
                rb.near[i] = 0;
                rb.o_near[i] = o[i] + delta;
                rb.o_far[i] = o[i] - delta;
            }
        }
        rb
    }

    /// The entry parameter of the widened box if the ray's line meets it at some t in
    /// [0, t_max]; `None` otherwise.
    #[inline(always)]
    fn enter(&self, n: &Node, t_max: f64) -> Option<f64> {
        let slab = |i: usize| {
            let s = self.near[i] & 1;
            (
                (n.b[s][i] - self.o_near[i]) * self.inv[i],
                (n.b[s ^ 1][i] - self.o_far[i]) * self.inv[i],
            )
        };
        let (nx, fx) = slab(0);
        let (ny, fy) = slab(1);
        let (nz, fz) = slab(2);
        // A NaN (0·∞) only comes from a ray lying in a widened plane and parallel to it,
        // which cannot meet the sphere inside: whatever the comparisons make of it is right.
        let near = max(max(nx, ny), nz);
        let far = min(min(fx, fy), fz);
        if near <= far && far >= 0.0 && near <= t_max {
            Some(near)
        } else {
            None
        }
    }
}

/// The tree: nodes in depth-first order, leaves pointing into `prims`. With at most
/// `FLAT_MAX` primitives there are no nodes, only the primitives, opaque ones first.
#[derive(Clone, Debug, Default)]
pub struct Bvh {
    nodes: Vec<Node>,
    prims: Vec<Prim>,
    /// The largest coordinate magnitude of the boxes.
    scale: f64,
    /// In a flat list, how many opaque primitives come first.
    flat_opaque: usize,
}

struct Item {
    lo: DVec3,
    hi: DVec3,
    centre: DVec3,
    prim: Prim,
}

impl Bvh {
    /// Builds the tree over `prims` (any order; each keeps its object index).
    pub fn build(prims: Vec<Prim>) -> Bvh {
        let mut items: Vec<Item> = prims
            .into_iter()
            .map(|prim| {
                let s = prim.sphere;
                let r = DVec3::splat(s.radius);
                Item {
                    lo: s.center - r,
                    hi: s.center + r,
                    centre: s.center,
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
            bvh.prims.sort_by_key(|p| p.glass);
            bvh.flat_opaque = bvh.prims.iter().filter(|p| !p.glass).count();
            return bvh;
        }
        bvh.nodes.push(BLANK);
        build_node(&mut bvh.nodes, &mut items, 0, 0, 0);
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
    pub fn flat_opaque(&self) -> Option<&[Prim]> {
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
        mut visit: impl FnMut(&Prim, f64) -> Option<f64>,
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
        mut visit: impl FnMut(&Prim, f64) -> Option<f64>,
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

fn surface_area(lo: DVec3, hi: DVec3) -> f64 {
    let d = (hi - lo).max(DVec3::ZERO);
    2.0 * (d.x * d.y + d.y * d.z + d.z * d.x)
}

/// Fills node `index` with the bounds of `items` (which start at `offset` in the final
/// primitive order) and splits it, recursively.
fn build_node(
    nodes: &mut Vec<Node>,
    items: &mut [Item],
    offset: usize,
    index: usize,
    depth: usize,
) {
    let (mut lo, mut hi) = (DVec3::INFINITY, DVec3::NEG_INFINITY);
    let (mut clo, mut chi) = (DVec3::INFINITY, DVec3::NEG_INFINITY);
    for it in items.iter() {
        lo = lo.min(it.lo);
        hi = hi.max(it.hi);
        clo = clo.min(it.centre);
        chi = chi.max(it.centre);
    }
    nodes[index].b = [lo.to_array(), hi.to_array()];
    let n = items.len();
    let leaf = |nodes: &mut Vec<Node>| {
        nodes[index].first = offset as u32;
        nodes[index].count = n as u32;
    };
    if n <= LEAF_MAX || depth >= MAX_DEPTH {
        return leaf(nodes);
    }
    let extent = chi - clo;
    let axis = if extent.x >= extent.y && extent.x >= extent.z {
        0
    } else if extent.y >= extent.z {
        1
    } else {
        2
    };
    let mid = if extent[axis] > 0.0 {
        // Binned SAH along the widest axis of the centres.
        let k = BINS as f64 / extent[axis];
        let bin_of = |c: f64| (((c - clo[axis]) * k) as usize).min(BINS - 1);
        let mut bins = [(DVec3::INFINITY, DVec3::NEG_INFINITY, 0usize); BINS];
        for it in items.iter() {
            let b = &mut bins[bin_of(it.centre[axis])];
            b.0 = b.0.min(it.lo);
            b.1 = b.1.max(it.hi);
            b.2 += 1;
        }
        // Costs of splitting after bin i: sweep from the right, then from the left.
        let mut right = [0.0f64; BINS];
        let (mut rlo, mut rhi, mut rn) = (DVec3::INFINITY, DVec3::NEG_INFINITY, 0usize);
        for i in (1..BINS).rev() {
            rlo = rlo.min(bins[i].0);
            rhi = rhi.max(bins[i].1);
            rn += bins[i].2;
            right[i - 1] = surface_area(rlo, rhi) * rn as f64;
        }
        let (mut llo, mut lhi, mut ln) = (DVec3::INFINITY, DVec3::NEG_INFINITY, 0usize);
        let mut best = (f64::INFINITY, 0usize);
        for i in 0..BINS - 1 {
            llo = llo.min(bins[i].0);
            lhi = lhi.max(bins[i].1);
            ln += bins[i].2;
            if ln == 0 || ln == n {
                continue;
            }
            let cost = surface_area(llo, lhi) * ln as f64 + right[i];
            if cost < best.0 {
                best = (cost, i);
            }
        }
        if best.0.is_finite() {
            let split = best.1;
            partition(items, |it| bin_of(it.centre[axis]) <= split)
        } else {
            n / 2
        }
    } else {
        n / 2
    };
    let mid = if mid == 0 || mid == n {
        // All centres in one bin (or all equal): split at the median.
        items.select_nth_unstable_by(n / 2, |a, b| a.centre[axis].total_cmp(&b.centre[axis]));
        n / 2
    } else {
        mid
    };
    let left = nodes.len();
    nodes.push(BLANK);
    nodes.push(BLANK);
    nodes[index].first = left as u32;
    nodes[index].count = 0;
    let (a, b) = items.split_at_mut(mid);
    build_node(nodes, a, offset, left, depth + 1);
    build_node(nodes, b, offset + mid, left + 1, depth + 1);
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
