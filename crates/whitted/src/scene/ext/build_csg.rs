//! CSG blocks drawn from the extension's `union` / `intersection` / `difference` records
//! (SPEC §16): each block becomes one object whose shape is a `shapes::Csg` tree. A
//! child's frame is its own modifiers followed by those after the `end` of every block
//! around it, innermost first; each child keeps its own TEXTURE and MATERIAL, and the
//! block's object carries its first solid's (what shadow rays through it see).

use super::{anchor, frame, place, refused, shape_in};
use crate::object::Object;
use crate::scene::ext::{Csg as Block, ExtItem};
use crate::scene::SceneError;
use crate::shapes::csg::{self, Csg, Node, Op};
use crate::shapes::{Shape, Transform};
use glam::DVec3;
use std::sync::Arc;

/// The object of a block and the point a camera looks at for it (the centre of its
/// bounding box, or where its first solid's anchor went for an unbounded block).
pub fn object(block: &Block) -> Result<(Object, DVec3), SceneError> {
    let (tree, first) = build(block)?;
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

/// A block being walked: the block, its frame in the world, its next child, and whether
/// it opened a node of its own (false when its children join its parent's node).
struct Walk<'b> {
    block: &'b Block,
    frame: Transform,
    next: usize,
    opens: bool,
}

/// A node being built: its operation and the children gathered so far.
type Gather = (Op, Vec<Node>);

/// The tree of `block`, with its first solid's anchor. The blocks are walked with a
/// stack of their own (depth first, in file order), and a chain of one operation is
/// flattened: a block whose operation is its parent's joins its parent's node (for a
/// difference, only as the node's first child), so a union of unions is one union of
/// all their solids. The surface, the inside and the bounds of the tree are the nested
/// blocks' own (the operations are associative; a difference's first child is what the
/// others are taken from), and the solids keep their order, so ties go to the same one.
fn build(block: &Block) -> Result<(Csg, DVec3), SceneError> {
    let mut walk = vec![Walk {
        block,
        frame: block_frame(block, &Transform::IDENTITY)?,
        next: 0,
        opens: true,
    }];
    let mut nodes: Vec<Gather> = vec![(block.op, Vec::new())];
    let mut first = None;
    while let Some(top) = walk.last_mut() {
        let Some(child) = top.block.children.get(top.next) else {
            let done = walk.pop().expect("a block is walked");
            if !done.opens {
                continue;
            }
            let (op, children) = nodes.pop().expect("a node is open");
            let word = done.block.op.keyword();
            let tree = Csg::new(op, children).ok_or_else(|| {
                refused(
                    &done.block.loc,
                    word,
                    "a CSG block needs two or more solids",
                )
            })?;
            match nodes.last_mut() {
                Some((_, siblings)) => siblings.push(Node::Csg(tree)),
                None => return Ok((tree, first.unwrap_or(DVec3::ZERO))),
            }
            continue;
        };
        top.next += 1;
        let outer = top.frame;
        let (node_op, gathered) = nodes.last_mut().expect("a node is open");
        match child {
            ExtItem::Shape(o) => {
                let shape = shape_in(o, &outer)?;
                if !csg::is_solid(&shape) {
                    let why = "a CSG block takes solids only (sphere, plane, box, capped cylinder or cone, torus)";
                    return Err(refused(&o.loc, o.shape.kind(), why));
                }
                first.get_or_insert_with(|| outer.point_to_world(anchor(o)));
                gathered.push(Node::Leaf(Object {
                    shape,
                    texture: o.texture.clone(),
                    material: o.material,
                }));
            }
            ExtItem::Csg(inner) => {
                let inner_op = inner.op;
                let joins =
                    inner_op == *node_op && (inner_op != Op::Difference || gathered.is_empty());
                if !joins {
                    nodes.push((inner_op, Vec::new()));
                }
                walk.push(Walk {
                    block: inner,
                    frame: block_frame(inner, &outer)?,
                    next: 0,
                    opens: !joins,
                });
            }
        }
    }
    unreachable!("the outermost block returns its tree when its walk ends")
}

/// The frame of `block` inside frames `outer`: its own modifiers, then `outer`'s.
fn block_frame(block: &Block, outer: &Transform) -> Result<Transform, SceneError> {
    let singular = || {
        refused(
            &block.loc,
            block.op.keyword(),
            "the scale, rotate and translate make a singular frame",
        )
    };
    let mut own = frame(&block.mods).ok_or_else(singular)?;
    if block.mods.placing != crate::mesh::Placing::default() {
        // The block as written (no frame, no placing) measures the box its placing needs.
        let written = Block {
            mods: place::unplaced(&block.mods),
            ..block.clone()
        };
        let bounds = build(&written)?.0.bounds();
        let word = block.op.keyword();
        let before = place::prefix(&block.mods.placing, bounds, &block.loc, word)?;
        own = before.then(&own).ok_or_else(singular)?;
    }
    own.then(outer).ok_or_else(singular)
}
