//! The reader of CSG blocks (SPEC §16): `union`, `intersection` or `difference`, then two
//! or more solids or nested blocks, `end`, and the block's modifiers:
//!
//! ```text
//! union|intersection|difference  SOLID|BLOCK SOLID|BLOCK …  end  [name N] [scale x y z] [rotate x y z] [translate x y z]
//! ```
//!
//! Blocks nest at most `limits::MAX_CSG_DEPTH` deep (the outermost block is level 1); a
//! deeper one is refused at its keyword. The reader keeps the open blocks on a stack of
//! its own, not on the call stack, so no nesting can exhaust it. Only the outermost block
//! is numbered (`csg 3`) and named; its solids and inner blocks are `in csg 3`.

use super::super::super::ext::{Csg, ExtItem};
use super::super::super::lexer::Token;
use super::super::Result;
use super::{keywords, Ext};
use crate::input::quote;
use crate::limits::MAX_CSG_DEPTH;
use crate::shapes::csg::Op;

/// The operation a block keyword names.
pub(super) fn op(word: &str) -> Option<Op> {
    match word {
        "union" => Some(Op::Union),
        "intersection" => Some(Op::Intersection),
        "difference" => Some(Op::Difference),
        _ => None,
    }
}

/// A block being read: its keyword's token, its operation and the children read so far.
struct Open<'a> {
    tok: Token<'a>,
    op: Op,
    children: Vec<ExtItem>,
}

impl<'a> Ext<'_, 'a> {
    /// A top-level CSG block: `op` read at `tok`, its children (nested blocks included)
    /// up to its `end`, then its modifiers.
    pub(super) fn csg(&mut self, tok: Token<'a>, op: Op) -> Result<Csg> {
        let n = self.number("csg");
        let mut open = vec![Open {
            tok,
            op,
            children: Vec::new(),
        }];
        loop {
            let depth = open.len();
            let top = open.last_mut().expect("a block is open");
            // The outermost block is `union 3`; the others are `union in csg 3`.
            let (index, within) = if depth == 1 {
                (Some(n), None)
            } else {
                (None, Some(n))
            };
            let (block_tok, block_op) = (top.tok, top.op);
            self.enter(block_op.keyword(), index, within);
            let Some(child) = self.p.next() else {
                let (line, column) = self.p.lexer.position();
                let msg = format!(
                    "the {} block of line {} has no 'end' (the file ends inside it)",
                    block_op.keyword(),
                    block_tok.line
                );
                return Err(self.p.error_at(line, column, msg, ""));
            };
            if child.text == "end" {
                let done = open.pop().expect("a block is open");
                let block = self.close(done, index, within)?;
                match open.last_mut() {
                    Some(parent) => parent.children.push(ExtItem::Csg(block)),
                    None => return Ok(block),
                }
            } else if let Some(keyword) = keywords::find(keywords::SHAPES, child.text) {
                self.count_object(&child)?;
                let object = self.shape(child, keyword, Some(n))?;
                if !object.shape.is_solid(object.mods.open) {
                    let what = if object.mods.open { "an open " } else { "a " };
                    let msg = format!(
                        "{what}{} is not a solid: CSG takes spheres, planes, boxes, capped cylinders and cones, and tori",
                        child.text
                    );
                    return Err(self.p.error(&child, msg, ""));
                }
                let top = open.last_mut().expect("a block is open");
                top.children.push(ExtItem::Shape(object));
            } else if let Some(inner) = self::op(child.text) {
                if depth >= MAX_CSG_DEPTH {
                    let msg = format!(
                        "CSG blocks nest at most {MAX_CSG_DEPTH} deep: this {} block would be level {}",
                        inner.keyword(),
                        depth + 1
                    );
                    return Err(self.p.error(&child, msg, ""));
                }
                open.push(Open {
                    tok: child,
                    op: inner,
                    children: Vec::new(),
                });
            } else {
                let msg = format!(
                    "expected a solid, a CSG block or 'end' in the {} block of line {}, found '{}'",
                    block_op.keyword(),
                    block_tok.line,
                    quote(child.text)
                );
                return Err(self.p.error(&child, msg, ""));
            }
        }
    }

    /// The block `done` after its `end`: two or more children, then its modifiers (a
    /// nested block, `within` a numbered one, takes no name).
    fn close(&mut self, done: Open<'a>, index: Option<u64>, within: Option<u64>) -> Result<Csg> {
        if done.children.len() < 2 {
            let msg = format!(
                "a {} block needs two or more objects, found {}",
                done.op.keyword(),
                done.children.len()
            );
            return Err(self.p.error(&done.tok, msg, ""));
        }
        self.enter(done.op.keyword(), index, within);
        let allowed = ["name", "scale", "rotate", "translate", "fit", "pivot"];
        let mods = self.modifiers(&allowed, within.is_some())?;
        Ok(Csg {
            op: done.op,
            children: done.children,
            mods,
            loc: self.loc(&done.tok),
        })
    }
}
