//! The sample lattice of one adaptive frame: every sample sits on the lattice of pitch
//! 2^−D pixel and is named by its integer coordinates (X, Y), its colour a function of
//! (X, Y) alone (the camera ray through X·2^−D, Y·2^−D, exact in binary).
//!
//! Three stores, so that each point is traced once whichever band or thread asks first:
//! - the pixel corners (the multiples of 2^D), traced first in parallel over lattice rows;
//!   from them alone each pixel's first split is decided, before any finer sample;
//! - the finer points on a pixel's border, shared with the neighbour across it: a cell per
//!   point of every edge next to a pixel that splits (`edges.rs`);
//! - the points inside a pixel, which no other pixel asks for: the worker's own scratch,
//!   no lock, no hashing.
//!
//! The first two live in a `Store`, kept between frames (`store.rs`).

use super::store::Store;
use super::{Adaptive, BAND};
use crate::accel::TileView;
use crate::base::Color;
use crate::render::Shot;
use crate::trace::{RayCount, Tracer};
use rayon::prelude::*;

/// What traces a lattice point: the tracer, the camera and the lattice's size.
pub(super) struct Probe<'a> {
    pub tracer: &'a Tracer<'a>,
    pub view: Option<&'a TileView>,
    /// The camera and its lens (a lens point's colour is already clamped).
    pub shot: &'a Shot<'a>,
    pub width: u32,
    pub height: u32,
    pub depth: u32,
}

impl Probe<'_> {
    /// The clamped colour of the camera ray through lattice point (x, y).
    fn trace(&self, x: u32, y: u32, count: &mut RayCount) -> Color {
        let step = 1.0 / f64::from(1u32 << self.depth);
        let (i, j) = (
            (x >> self.depth).min(self.width - 1),
            (y >> self.depth).min(self.height - 1),
        );
        let hint = self.view.map(|v| v.hint(i, j));
        let (px, py) = (f64::from(x) * step, f64::from(y) * step);
        self.shot
            .color(self.tracer, hint, px, py, count)
            .clamp(Color::ZERO, Color::ONE)
    }
}

/// One traced lattice: the pixel corners and first splits (rows top to bottom), and the
/// shared border samples.
pub(super) struct Lattice<'a> {
    probe: Probe<'a>,
    store: Store,
}

impl Drop for Lattice<'_> {
    fn drop(&mut self) {
        std::mem::take(&mut self.store).give_back();
    }
}

impl<'a> Lattice<'a> {
    /// Traces the corners of every pixel and decides each pixel's first split; `rays`
    /// counts the corner rays. (A cancelled render leaves rows of zeros: its caller
    /// discards the frame.)
    pub fn new(probe: Probe<'a>, aa: &Adaptive, rays: &mut RayCount) -> Lattice<'a> {
        let (w, h, d) = (probe.width as usize, probe.height as usize, probe.depth);
        let mut store = Store::take(w, h);
        *rays = *rays
            + store
                .corners
                .par_chunks_mut(w + 1)
                .enumerate()
                .map(|(j, row)| {
                    let mut count = RayCount::default();
                    if super::super::control::stop_row() {
                        return count; // cancelled: the caller discards the frame
                    }
                    for (i, c) in row.iter_mut().enumerate() {
                        *c = probe.trace((i as u32) << d, (j as u32) << d, &mut count);
                    }
                    count
                })
                .reduce(RayCount::default, |a, b| a + b);
        let Store {
            corners,
            own,
            split,
            edges,
        } = &mut store;
        first_splits(corners, (w, h), aa, own, split);
        edges.prepare(split, (w, h), d);
        Lattice { probe, store }
    }

    /// The lattice's depth (its pitch is 2^−depth pixel).
    pub fn depth(&self) -> u32 {
        self.probe.depth
    }

    /// Pixel (i, j)'s corners (top-left, top-right, bottom-left, bottom-right) and whether
    /// it splits.
    pub fn pixel(&self, i: u32, j: u32) -> ([Color; 4], bool) {
        let w = self.probe.width as usize;
        let k = j as usize * (w + 1) + i as usize;
        let c = self.store.corners.as_slice();
        let split = self.store.split[j as usize * w + i as usize];
        ([c[k], c[k + 1], c[k + w + 1], c[k + w + 2]], split)
    }

    /// The sample at lattice point (x, y) of pixel (i, j), not one of its corners: from the
    /// scratch, else traced (and shared through its edge cell when it is on the border).
    pub fn sample(
        &self,
        (i, j): (u32, u32),
        x: u32,
        y: u32,
        s: &mut Scratch,
        count: &mut RayCount,
    ) -> Color {
        let d = self.probe.depth;
        let (lx, ly) = (x - (i << d), y - (j << d));
        let at = (ly * s.side + lx) as usize;
        if s.cells[at].0 == s.stamp {
            return s.cells[at].1;
        }
        let last = 1u32 << d;
        let c = if lx == 0 || ly == 0 || lx == last || ly == last {
            self.shared(x, y, count)
        } else {
            self.probe.trace(x, y, count)
        };
        s.cells[at] = (s.stamp, c);
        c
    }

    /// A border point, traced if no one has yet (the first to ask traces and counts it).
    fn shared(&self, x: u32, y: u32, count: &mut RayCount) -> Color {
        *self
            .store
            .edges
            .cell(x, y)
            .get_or_init(|| self.probe.trace(x, y, count))
    }
}

/// Whether each pixel of a `w`×`h` frame splits at all, into `split`, from its corners (the
/// `(w+1)·(h+1)` lattice `corners`) and, under `edge`, its neighbours': a pixel splits when
/// its corners differ, or when they agree and two or more of its four neighbours' corners
/// differ (each neighbour judged on its own corners, `own`, so nothing spreads further).
/// Both flag buffers hold `w·h` entries.
pub(super) fn first_splits(
    corners: &[Color],
    (w, h): (usize, usize),
    aa: &Adaptive,
    own: &mut [bool],
    split: &mut [bool],
) {
    if aa.depth == 0 {
        split.fill(false);
        return;
    }
    if w == 0 || h == 0 {
        return;
    }
    let rows = BAND as usize;
    let line = |j: usize| &corners[j * (w + 1)..(j + 1) * (w + 1)];
    own.par_chunks_mut(w)
        .enumerate()
        .with_min_len(rows)
        .for_each(|(j, flags)| {
            let pairs = line(j).windows(2).zip(line(j + 1).windows(2));
            for (flag, (top, bottom)) in flags.iter_mut().zip(pairs) {
                let c = [top[0], top[1], bottom[0], bottom[1]];
                *flag = aa.measure.differ(aa.threshold, &c, 0);
            }
        });
    if !aa.measure.splits_amid_neighbours() {
        split.copy_from_slice(own);
        return;
    }
    let own = &*own;
    split
        .par_chunks_mut(w)
        .enumerate()
        .with_min_len(rows)
        .for_each(|(j, flags)| {
            let row = &own[j * w..(j + 1) * w];
            let above = (j > 0).then(|| &own[(j - 1) * w..j * w]);
            let below = (j + 1 < h).then(|| &own[(j + 1) * w..(j + 2) * w]);
            for (i, flag) in flags.iter_mut().enumerate() {
                let near = usize::from(i > 0 && row[i - 1])
                    + usize::from(i + 1 < w && row[i + 1])
                    + usize::from(above.is_some_and(|r| r[i]))
                    + usize::from(below.is_some_and(|r| r[i]));
                *flag = row[i] || near >= 2;
            }
        });
}

/// One worker's samples of the pixel it is drawing, (2^D + 1)² cells stamped with the
/// pixel they belong to, so that moving to the next pixel clears nothing.
pub(super) struct Scratch {
    side: u32,
    stamp: u32,
    cells: Vec<(u32, Color)>,
}

impl Scratch {
    /// A scratch for a lattice of depth `depth`.
    pub fn new(depth: u32) -> Scratch {
        let side = (1u32 << depth) + 1;
        Scratch {
            side,
            stamp: 0,
            cells: vec![(0, Color::ZERO); (side * side) as usize],
        }
    }

    /// Forgets the last pixel's samples.
    pub fn next_pixel(&mut self) {
        self.stamp += 1;
        if self.stamp == u32::MAX {
            self.stamp = 1;
            self.cells.iter_mut().for_each(|c| c.0 = 0);
        }
    }
}
