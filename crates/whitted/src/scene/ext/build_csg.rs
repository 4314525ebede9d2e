//! CSG blocks drawn from the extension's `union` / `intersection` / `difference` records
//! (SPEC §16): each block becomes one object whose shape is a `shapes::Csg` tree. A
//! child's frame is its own modifiers followed by those after the `end` of every block
//! around it, innermost first; each child keeps its own TEXTURE and MATERIAL, and the
//! block's object carries its first solid's (what shadow rays through it see).

use super::{anchor, frame, refused, shape_in};
use crate::object::Object;
use crate::scene::ext::{Csg as Block, CsgOp, ExtItem};
use crate::scene::SceneError;
use crate::shapes::csg::{self, Csg, Node, Op};
use crate::shapes::{Frame, Shape};
use glam::DVec3;
use std::sync::Arc;

/// The object of a block and the point a camera looks at for it (the centre of its
/// bounding box, or where its first solid's anchor went for an unbounded block).
pub fn object(block: &Block) -> Result<(Object, DVec3), SceneError> {
    let (tree, first) = build(block, &Frame::IDENTITY)?;
    let lead = tree.first_leaf();
    let (texture, material) = (lead.texture.clone(), lead.material);
    let look = tree.bounds().map_or(first, |(lo, hi)| 0.5 * (lo + hi));
    let object = Object {
        shape: Shape::Csg(Arc::new(tree)),
        texture,
        material,
    };
    Ok((object, look))
}

/// The tree of `block` inside frames `outer`, with its first solid's anchor.
fn build(block: &Block, outer: &Frame) -> Result<(Csg, DVec3), SceneError> {
    let word = block.op.keyword();
    let singular = || {
        refused(
            &block.loc,
            word,
            "the scale, rotate and translate make a singular frame",
        )
    };
    let own = frame(&block.mods).ok_or_else(singular)?;
    let f = own.then(outer).ok_or_else(singular)?;
    let mut children = Vec::with_capacity(block.children.len());
    let mut first = None;
    for child in &block.children {
        let (node, look) = match child {
            ExtItem::Shape(o) => {
                let shape = shape_in(o, &f)?;
                if !csg::is_solid(&shape) {
                    let why = "a CSG block takes solids only (sphere, plane, box, capped cylinder or cone, torus)";
                    return Err(refused(&o.loc, o.shape.keyword(), why));
                }
                let look = f.point_to_world(anchor(&o.shape, &o.mods));
                let leaf = Object {
                    shape,
                    texture: o.texture.clone(),
                    material: o.material,
                };
                (Node::Leaf(leaf), look)
            }
            ExtItem::Csg(inner) => {
                let (tree, look) = build(inner, &f)?;
                (Node::Csg(tree), look)
            }
        };
        first.get_or_insert(look);
        children.push(node);
    }
    let op = match block.op {
        CsgOp::Union => Op::Union,
        CsgOp::Intersection => Op::Intersection,
        CsgOp::Difference => Op::Difference,
    };
    let tree = Csg::new(op, children)
        .ok_or_else(|| refused(&block.loc, word, "a CSG block needs two or more solids"))?;
    Ok((tree, first.unwrap_or(DVec3::ZERO)))
}
