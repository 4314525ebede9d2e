//! The sample lattice of one adaptive frame: every sample sits on the lattice of pitch
//! 2^−D pixel and is named by its integer coordinates (X, Y), its colour a function of
//! (X, Y) alone (the camera ray through X·2^−D, Y·2^−D, exact in binary).
//!
//! Three stores, so that each point is traced once whichever tile or thread asks first:
//! - the pixel corners (the multiples of 2^D), traced first in parallel over lattice rows;
//!   from them alone each pixel's first split is decided, before any finer sample;
//! - the finer points on a pixel's border, shared with the neighbour across it: one map per
//!   pixel row behind a lock (a point on a row's top edge belongs to the row above);
//! - the points inside a pixel, which no other pixel asks for: the worker's own scratch,
//!   no lock, no hashing.
//!
//! The first two live in a `Store`, kept between frames (`store.rs`).

use super::store::Store;
use super::{Adaptive, BAND};
use crate::accel::TileView;
use crate::camera::Camera;
use crate::texture::Color;
use crate::trace::{RayCount, Tracer};
use rayon::prelude::*;
use std::collections::hash_map::Entry;
use std::collections::HashMap;

/// The hash of a lattice point for the border maps: the two coordinates packed and
/// multiplied by an odd constant (Fibonacci hashing), high half folded in. The keys are
/// small distinct integer pairs chosen by the render, not by an adversary, so SipHash's
/// resistance buys nothing and its cost was paid on every finer sample.
#[derive(Default)]
pub(super) struct PointHasher(u64);

impl std::hash::Hasher for PointHasher {
    fn finish(&self) -> u64 {
        // The product's high half (which both coordinates reach) folded into its low
        // half, whose bits alone would see only y: the table indexes by the low bits.
        let h = self.0.wrapping_mul(0x9E37_79B9_7F4A_7C15);
        h ^ (h >> 32)
    }
    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.0 = self.0.rotate_left(8) ^ u64::from(b);
        }
    }
    fn write_u32(&mut self, v: u32) {
        self.0 = self.0 << 32 | u64::from(v);
    }
}

pub(super) type BuildPointHasher = std::hash::BuildHasherDefault<PointHasher>;

/// The finer border samples of one pixel row, by lattice point.
pub(super) type SampleMap = HashMap<(u32, u32), Color, BuildPointHasher>;

/// What traces a lattice point: the tracer, the camera and the lattice's size.
pub(super) struct Probe<'a> {
    pub tracer: &'a Tracer<'a>,
    pub view: Option<&'a TileView>,
    pub camera: &'a Camera,
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
        let ray = self.camera.ray(f64::from(x) * step, f64::from(y) * step);
        self.tracer
            .primary_in(hint, &ray, count)
            .clamp(Color::ZERO, Color::ONE)
    }
}

/// One traced lattice: the pixel corners and first splits, and the shared border samples
/// (rows top to bottom; one map per pixel row, for its inside and its bottom edge).
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
            ..
        } = &mut store;
        first_splits(corners, (w, h), aa, own, split);
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
    /// scratch, else traced (and shared through the row's map when it is on the border).
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

    /// A border point, traced if no one has yet.
    fn shared(&self, x: u32, y: u32, count: &mut RayCount) -> Color {
        let Probe { depth, height, .. } = self.probe;
        let mask = (1u32 << depth) - 1;
        let row = if y & mask == 0 && y > 0 {
            (y >> depth) - 1
        } else {
            (y >> depth).min(height - 1)
        };
        let lock = || {
            self.store.memo[row as usize]
                .lock()
                .unwrap_or_else(|e| e.into_inner())
        };
        if let Some(&c) = lock().get(&(x, y)) {
            return c;
        }
        // Traced outside the lock; when another thread traced the point meanwhile (only
        // on a pixel row's top or bottom edge), the colours are the same and the first
        // one's rays are the ones counted: each point counts once, whoever traced it.
        let mut own = RayCount::default();
        let c = self.probe.trace(x, y, &mut own);
        match lock().entry((x, y)) {
            Entry::Occupied(first) => *first.get(),
            Entry::Vacant(slot) => {
                *count = *count + own;
                *slot.insert(c)
            }
        }
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
    let corner = |k: usize| {
        let at = (k / w) * (w + 1) + k % w;
        [
            corners[at],
            corners[at + 1],
            corners[at + w + 1],
            corners[at + w + 2],
        ]
    };
    let rows = BAND as usize * w.max(1);
    own.par_chunks_mut(rows).enumerate().for_each(|(b, flags)| {
        for (k, flag) in flags.iter_mut().enumerate() {
            *flag = aa.measure.differ(aa.threshold, &corner(b * rows + k), 0);
        }
    });
    if !aa.measure.splits_amid_neighbours() {
        split.copy_from_slice(own);
        return;
    }
    let own = &*own;
    for (k, flag) in split.iter_mut().enumerate().take(w * h) {
        let (i, j) = (k % w, k / w);
        let near = [
            i > 0 && own[k - 1],
            i + 1 < w && own[k + 1],
            j > 0 && own[k - w],
            j + 1 < h && own[k + w],
        ];
        *flag = own[k] || near.iter().filter(|&&n| n).count() >= 2;
    }
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
