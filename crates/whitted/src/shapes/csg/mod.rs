//! Constructive solid geometry (SPEC §16's `union`, `intersection`, `difference` blocks):
//! a tree whose leaves are solid objects (sphere, plane as the half-space behind its
//! normal, box, capped cylinder and cone, torus), each with its own texture and material,
//! and whose inner nodes are operations. The whole tree is one object of the scene.
//!
//! POV-Ray's rules decide which surface points of a leaf belong to the block, walking up
//! from the leaf: in a union every surface is kept; in an intersection a point of child k
//! is kept where it lies inside every other child; in a difference a point of the first
//! child is kept where it lies outside every other child, and a point of a subtracted
//! child where it lies inside the first child and outside the other subtracted ones, its
//! normal reversed (a cut surface). Along a ray, the candidates are every leaf's roots;
//! the hit is the smallest kept one, ties going to the leaf that comes first in the file.
//!
//! Inside tests are strict (`inside`): a point on a leaf's own surface is not inside it.
//! A block is bounded where its children allow: a union by all of its children, an
//! intersection by any bounded one, a difference by its first child.

mod inside;

use super::{Roots, Shape};
use crate::object::Object;
use crate::optics::Ray;
use glam::DVec3;

/// A CSG operation (POV-Ray's rules): the record's (`scene::ext::Csg`, a block as the
/// file writes it) and the built tree's.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Op {
    /// Every child's surface.
    Union,
    /// The surface points of each child inside every other child.
    Intersection,
    /// The first child minus the others.
    Difference,
}

impl Op {
    /// The block's keyword in a Scene.txt.
    pub fn keyword(self) -> &'static str {
        match self {
            Op::Union => "union",
            Op::Intersection => "intersection",
            Op::Difference => "difference",
        }
    }
}

/// A child of a block: a solid with its texture and material, or a nested block. Leaves
/// are the common case and are kept inline (no pointer to chase in the inside tests).
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Debug, PartialEq)]
pub enum Node {
    /// A solid object (its shape a sphere, plane or `Placed` solid).
    Leaf(Object),
    /// A nested block.
    Csg(Csg),
}

impl Node {
    /// True when `p` lies strictly inside the node's solid.
    pub fn inside(&self, p: DVec3) -> bool {
        match self {
            Node::Leaf(o) => inside::shape(&o.shape, p),
            Node::Csg(c) => c.inside(p),
        }
    }

    fn bounds(&self) -> Option<(DVec3, DVec3)> {
        match self {
            Node::Leaf(o) => o.shape.bounds(),
            Node::Csg(c) => c.bounds,
        }
    }

    fn first_leaf(&self) -> &Object {
        match self {
            Node::Leaf(o) => o,
            Node::Csg(c) => c.first_leaf(),
        }
    }
}

/// The surface a ray meets on a block: where, which leaf, and its outward normal there
/// (reversed on a difference's cut surface).
#[derive(Clone, Copy, Debug)]
pub struct Surface<'a> {
    /// The ray parameter.
    pub t: f64,
    /// The leaf hit: its texture and material shade the point.
    pub leaf: &'a Object,
    /// The block's outward unit normal at the point.
    pub normal: DVec3,
}

/// A CSG block as the tracer draws it, an operation over two or more built children: the
/// built form of a block's record (`scene::ext::Csg`, from which `scene::ext::build`
/// makes it; nested blocks of one operation flattened into one node).
#[derive(Clone, Debug, PartialEq)]
pub struct Csg {
    op: Op,
    children: Vec<Node>,
    bounds: Option<(DVec3, DVec3)>,
}

/// What a crossing visitor is told: t, the point, the leaf, and whether its normal is
/// reversed; it answers false to stop.
type Visit<'v, 'a> = dyn FnMut(f64, DVec3, &'a Object, bool) -> bool + 'v;

impl Csg {
    /// The block `op` over `children`; `None` with fewer than two children.
    pub fn new(op: Op, children: Vec<Node>) -> Option<Csg> {
        if children.len() < 2 {
            return None;
        }
        let boxes: Vec<_> = children.iter().map(Node::bounds).collect();
        let bounds = match op {
            Op::Union => boxes
                .iter()
                .copied()
                .collect::<Option<Vec<_>>>()
                .map(|b| b.into_iter().reduce(|a, b| (a.0.min(b.0), a.1.max(b.1))))
                .and_then(|b| b),
            Op::Intersection => boxes
                .iter()
                .flatten()
                .copied()
                .reduce(|a, b| (a.0.max(b.0), a.1.min(b.1)))
                .map(|(lo, hi)| (lo, hi.max(lo))),
            Op::Difference => boxes[0],
        };
        Some(Csg {
            op,
            children,
            bounds,
        })
    }

    /// The operation.
    pub fn op(&self) -> Op {
        self.op
    }

    /// The children, in file order.
    pub fn children(&self) -> &[Node] {
        &self.children
    }

    /// A box around the block, where its children bound it.
    pub fn bounds(&self) -> Option<(DVec3, DVec3)> {
        self.bounds
    }

    /// The first leaf in file order (the block's texture and material for shadow rays).
    pub fn first_leaf(&self) -> &Object {
        self.children[0].first_leaf()
    }

    /// True when `p` lies strictly inside the block's solid.
    pub fn inside(&self, p: DVec3) -> bool {
        let mut kids = self.children.iter();
        match self.op {
            Op::Union => kids.any(|c| c.inside(p)),
            Op::Intersection => kids.all(|c| c.inside(p)),
            Op::Difference => {
                kids.next().is_some_and(|c| c.inside(p)) && !kids.any(|c| c.inside(p))
            }
        }
    }

    /// Whether a surface point `p` of child `k` belongs to this block, and if so whether
    /// its normal is reversed here.
    fn keeps(&self, k: usize, p: DVec3) -> Option<bool> {
        let others = || {
            self.children
                .iter()
                .enumerate()
                .filter(move |&(j, _)| j != k)
                .map(|(_, c)| c)
        };
        match self.op {
            Op::Union => Some(false),
            Op::Intersection => others().all(|c| c.inside(p)).then_some(false),
            Op::Difference if k == 0 => others().all(|c| !c.inside(p)).then_some(false),
            Op::Difference => {
                let rest = self.children[1..].iter().enumerate();
                let cut = self.children[0].inside(p)
                    && rest.filter(|&(j, _)| j + 1 != k).all(|(_, c)| !c.inside(p));
                cut.then_some(true)
            }
        }
    }

    /// Calls `f` for every kept crossing with lo < t < hi, leaf by leaf in file order and
    /// along each leaf in ascending t; returns false when `f` stopped it.
    fn visit<'a>(&'a self, ray: &Ray, lo: f64, hi: f64, f: &mut Visit<'_, 'a>) -> bool {
        for (k, child) in self.children.iter().enumerate() {
            let go = match child {
                Node::Leaf(o) => o.shape.roots(ray).crossings(lo, hi).all(|t| {
                    let p = ray.at(t);
                    match self.keeps(k, p) {
                        Some(flip) => f(t, p, o, flip),
                        None => true,
                    }
                }),
                Node::Csg(c) => c.visit(ray, lo, hi, &mut |t, p, o, flip| match self.keeps(k, p) {
                    Some(here) => f(t, p, o, flip ^ here),
                    None => true,
                }),
            };
            if !go {
                return false;
            }
        }
        true
    }

    /// The nearest kept crossing with ray.t_min < t < t_max: t, the leaf, the reversal.
    fn nearest(&self, ray: &Ray, t_max: f64) -> Option<(f64, &Object, bool)> {
        let mut best: Option<(f64, &Object, bool)> = None;
        self.visit(ray, ray.t_min, t_max, &mut |t, _, o, flip| {
            if best.is_none_or(|b| t < b.0) {
                best = Some((t, o, flip));
            }
            true
        });
        best
    }

    /// The nearest hit with ray.t_min < t < t_max, if any.
    pub fn hit(&self, ray: &Ray, t_max: f64) -> Option<f64> {
        self.nearest(ray, t_max).map(|b| b.0)
    }

    /// The nearest hit with its leaf and the block's outward normal there.
    pub fn surface(&self, ray: &Ray, t_max: f64) -> Option<Surface<'_>> {
        self.nearest(ray, t_max).map(|(t, leaf, flip)| {
            let n = leaf.shape.normal(ray.at(t));
            Surface {
                t,
                leaf,
                normal: if flip { -n } else { n },
            }
        })
    }

    /// The four nearest kept crossings past ray.t_min, ascending (a block may have more;
    /// a shadow ray through a transparent block sees these four).
    pub fn roots(&self, ray: &Ray) -> Roots {
        let mut ts = [f64::INFINITY; 4];
        self.visit(ray, ray.t_min, f64::INFINITY, &mut |t, _, _, _| {
            if t < ts[3] {
                ts[3] = t;
                ts.sort_by(f64::total_cmp);
            }
            true
        });
        let n = ts.iter().take_while(|t| t.is_finite()).count();
        Roots::from_slice(&ts[..n])
    }

    /// The outward normal at a surface point `p` seen without its ray (a block's normal
    /// depends on which leaf the ray met; `surface` knows it): the first leaf, in file
    /// order, that `p` is on (a step along its normal leaves it, one against enters it)
    /// and that the block keeps there; the first leaf's normal otherwise.
    pub fn normal(&self, p: DVec3) -> DVec3 {
        let eps = 1e-7 * (1.0 + p.abs().max_element());
        let mut found = None;
        self.visit_point(p, eps, &mut |n| {
            found = Some(n);
        });
        found.unwrap_or_else(|| self.first_leaf().shape.normal(p))
    }

    fn visit_point(&self, p: DVec3, eps: f64, f: &mut dyn FnMut(DVec3)) -> bool {
        for (k, child) in self.children.iter().enumerate() {
            let found = match child {
                Node::Leaf(o) => {
                    let n = o.shape.normal(p);
                    let on = inside::shape(&o.shape, p - eps * n)
                        && !inside::shape(&o.shape, p + eps * n);
                    match self.keeps(k, p).filter(|_| on) {
                        Some(flip) => {
                            f(if flip { -n } else { n });
                            true
                        }
                        None => false,
                    }
                }
                Node::Csg(c) => match self.keeps(k, p) {
                    Some(flip) => c.visit_point(p, eps, &mut |n| f(if flip { -n } else { n })),
                    None => false,
                },
            };
            if found {
                return true;
            }
        }
        false
    }
}

/// True for the shapes a block takes as leaves (solids with an inside test).
pub fn is_solid(shape: &Shape) -> bool {
    inside::is_solid(shape)
}

#[cfg(test)]
mod tests;
