//! The finer samples on pixel borders, each shared by the two pixels on either side of its
//! edge: one cell per lattice point of every edge next to a pixel that splits, and none
//! elsewhere. A pixel asks for finer samples only when it splits, and those on its border
//! lie on its own four edges, so every point asked for has a cell.
//!
//! A pixel edge holds 2^D − 1 lattice points between its two corners. Horizontal edges are
//! numbered by line (0 at the frame's top, `h` at its bottom) and column, vertical ones by
//! pixel row and column line (0 at the left, `w` at the right); each needed edge gets the
//! next run of cells, in that order, so the layout depends on the split flags alone. A
//! cell is a `OnceLock`: the first thread to ask traces the point and counts its rays, a
//! second one waits for that colour, so each point is traced and counted once whoever
//! asks first, without a lock per row or a hash per sample.

use crate::base::Color;
use std::sync::OnceLock;

/// An edge with no cells: neither pixel beside it splits.
const NONE: u32 = u32::MAX;

/// The border cells of one frame.
#[derive(Default)]
pub(super) struct Edges {
    depth: u32,
    width: usize,
    /// The first cell of each horizontal edge, (height+1)·width, by line then column.
    across: Vec<u32>,
    /// The first cell of each vertical edge, height·(width+1), by row then column line.
    down: Vec<u32>,
    cells: Vec<OnceLock<Color>>,
}

impl Edges {
    /// Lays out the cells of a `w`×`h` frame at depth `depth` whose pixels split as `split`
    /// says (rows top to bottom), every cell empty.
    pub fn prepare(&mut self, split: &[bool], (w, h): (usize, usize), depth: u32) {
        let per = (1u32 << depth) - 1;
        (self.depth, self.width) = (depth, w);
        let mut next = 0u32;
        let mut number = |needed: bool| {
            if needed && per > 0 {
                next += per;
                next - per
            } else {
                NONE
            }
        };
        let row = |j: usize| &split[j * w..(j + 1) * w];
        self.across.clear();
        self.across.resize((h + 1) * w, NONE);
        for (line, out) in self.across.chunks_mut(w.max(1)).enumerate() {
            let above = line.checked_sub(1).map(row);
            let below = (line < h).then(|| row(line));
            for (i, slot) in out.iter_mut().enumerate() {
                *slot = number(above.is_some_and(|r| r[i]) || below.is_some_and(|r| r[i]));
            }
        }
        self.down.clear();
        self.down.resize(h * (w + 1), NONE);
        for (j, out) in self.down.chunks_mut(w + 1).enumerate() {
            let flags = row(j);
            for (c, slot) in out.iter_mut().enumerate() {
                let left = c > 0 && flags[c - 1];
                let right = c < w && flags[c];
                *slot = number(left || right);
            }
        }
        self.cells.clear();
        self.cells.resize_with(next as usize, OnceLock::new);
    }

    /// The cell of lattice point (x, y), a point on a pixel edge (not a corner) next to a
    /// pixel that splits.
    pub fn cell(&self, x: u32, y: u32) -> &OnceLock<Color> {
        &self.cells[self.index(x, y)]
    }

    /// Where `cell(x, y)` is among the cells.
    fn index(&self, x: u32, y: u32) -> usize {
        let mask = (1u32 << self.depth) - 1;
        let (cx, cy) = ((x >> self.depth) as usize, (y >> self.depth) as usize);
        let at = if y & mask == 0 {
            self.across[cy * self.width + cx] + (x & mask) - 1
        } else {
            self.down[cy * (self.width + 1) + cx] + (y & mask) - 1
        };
        at as usize
    }

    /// The memory the layout holds.
    pub fn bytes(&self) -> usize {
        (self.across.capacity() + self.down.capacity()) * std::mem::size_of::<u32>()
            + self.cells.capacity() * std::mem::size_of::<OnceLock<Color>>()
    }

    /// The number of cells laid out.
    #[cfg(test)]
    pub fn len(&self) -> usize {
        self.cells.len()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cells_by_hand_on_three_by_two_pixels() {
        // Depth 2 (3 points an edge). Only pixel (1, 0) splits: its four edges have cells,
        // 12 in all, laid out top edge (line 0, column 1): 0..3; bottom edge (line 1,
        // column 1): 3..6; left edge (row 0, line 1): 6..9; right edge (row 0, line 2):
        // 9..12.
        let (f, t) = (false, true);
        let mut edges = Edges::default();
        edges.prepare(&[f, t, f, f, f, f], (3, 2), 2);
        assert_eq!(edges.len(), 12);
        let at = |x, y| edges.index(x, y);
        assert_eq!([at(5, 0), at(6, 0), at(7, 0)], [0, 1, 2]);
        assert_eq!([at(5, 4), at(7, 4)], [3, 5]);
        assert_eq!([at(4, 1), at(4, 3)], [6, 8]);
        assert_eq!([at(8, 1), at(8, 2), at(8, 3)], [9, 10, 11]);
        // The neighbours ask for the same points through the same cells: (8, 2) is the
        // left edge of pixel (2, 0) as well.
        edges.cell(8, 2).set(Color::ONE).unwrap();
        assert_eq!(edges.cell(8, 2).get(), Some(&Color::ONE));
        assert!(edges.cell(8, 1).get().is_none());
    }

    #[test]
    fn a_new_layout_forgets_the_old_cells_and_depth_zero_has_none() {
        let mut edges = Edges::default();
        edges.prepare(&[true], (1, 1), 1);
        assert_eq!(edges.len(), 4);
        edges.cell(1, 0).set(Color::ONE).unwrap();
        edges.prepare(&[true, true], (2, 1), 1);
        // Two pixels side by side share their middle edge: 7 edges of one point each.
        assert_eq!(edges.len(), 7);
        assert!(edges.cells.iter().all(|c| c.get().is_none()));
        edges.prepare(&[true], (1, 1), 0);
        assert_eq!(edges.len(), 0);
    }
}
