//! Adaptive anti-aliasing (SPEC §15), after POV-Ray's `+AM2 +A T +R D`: every pixel
//! corner is traced once and shared by the four pixels around it; a pixel (or a quarter
//! of one) whose four corners differ by more than T is split into four, down to depth D;
//! the pixel is the mean of its leaves weighted by their areas, a leaf being the mean of
//! its four clamped corner samples.
//!
//! ```toml
//! [render]
//! antialias = { mode = "adaptive", threshold = 0.5, depth = 2 }   # raytrace --aa adaptive:0.5:2
//! ```
//!
//! Determinism. Every sample sits on the lattice of pitch 2^−D and is named by its
//! integer lattice coordinates (X, Y); its colour is a function of (X, Y) alone (the ray
//! through the point X·2^−D, Y·2^−D, exact in binary). The pixel corners (the multiples
//! of 2^D) are traced first, in parallel over lattice rows, into one array. The finer
//! samples are traced on demand and kept in a map per pixel row, each counted once
//! whichever tile or thread asks first, so the pixels' colours, and the ray
//! counts, do not depend on the thread count, the shard or the tile size. Tiles of
//! `tile`×`tile` pixels are the parallel work units.
//!
//! The difference measure (docs/decisions.md, "adaptive anti-aliasing"): over the six
//! pairs of a square's corners, POV-Ray's sum of the three channels' absolute
//! differences (`Measure::Sum`) or the largest single-channel difference
//! (`Measure::Max`), both on the clamped output values (our output has no gamma).

use super::{render, render_add, to_byte, Frame};
use crate::accel::TileView;
use crate::camera::Camera;
use crate::texture::Color;
use crate::trace::{RayCount, Tracer};
use rayon::prelude::*;
use serde::Serialize;
use std::collections::hash_map::Entry;
use std::collections::HashMap;
use std::sync::Mutex;

mod parse;
#[cfg(test)]
mod tests;

pub use parse::AntialiasError;

/// The deepest subdivision accepted (4096 leaves per pixel at most).
pub const MAX_DEPTH: u32 = 6;
/// The largest threshold accepted: the sum measure's largest difference (three channels).
pub const MAX_THRESHOLD: f64 = 3.0;
/// Pixels a side of a parallel work unit.
pub const TILE: u32 = 32;

/// How two corner samples' difference is measured.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Measure {
    /// |Δr| + |Δg| + |Δb|, POV-Ray's `Colour_Distance`.
    Sum,
    /// max(|Δr|, |Δg|, |Δb|).
    Max,
}

/// `antialias = { mode = "adaptive", threshold = T, depth = D }`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Adaptive {
    /// A square splits when two of its corners differ by more than this.
    pub threshold: f64,
    /// The most times a pixel is split (leaves of 2^−depth pixel a side).
    pub depth: u32,
    /// The difference measure.
    pub measure: Measure,
}

impl Adaptive {
    /// The defaults: the threshold whose images are as close to a 16×16 reference as
    /// POV-Ray's `+AM2 +A0.3 +R3` are to its own (benches/pov/adaptive.sh).
    pub const DEFAULT: Adaptive = Adaptive {
        threshold: 0.5,
        depth: 2,
        measure: Measure::Sum,
    };

    /// Whether the corners `c` (clamped) differ by more than the threshold.
    pub fn differ(&self, c: &[Color; 4]) -> bool {
        let distance = |a: Color, b: Color| {
            let d = (a - b).abs();
            match self.measure {
                Measure::Sum => d.x + d.y + d.z,
                Measure::Max => d.x.max(d.y).max(d.z),
            }
        };
        (0..4).any(|a| (a + 1..4).any(|b| distance(c[a], c[b]) > self.threshold))
    }
}

/// How a frame is anti-aliased: the n×n grid of `samples`, or adaptively.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub enum Antialias {
    /// n×n stratified samples per pixel (1: the pixel centre, the report's).
    Grid(u32),
    /// Corners shared, squares split where they differ.
    Adaptive(Adaptive),
}

/// A frame drawn adaptively, before rounding.
#[derive(Clone, Debug)]
pub struct Adaptively {
    /// Each pixel's colour in 0..1, rows top to bottom.
    pub colors: Vec<Color>,
    /// Each pixel's leaf count (1 when its corners agree).
    pub leaves: Vec<u32>,
    /// Each pixel's deepest split (0 when its corners agree).
    pub deepest: Vec<u32>,
    /// The rays cast.
    pub rays: RayCount,
}

/// `render` with either anti-aliasing; `Antialias::Grid(n)` is `render(…, n)`, byte for byte.
pub fn render_with(
    tracer: &Tracer,
    camera: &Camera,
    width: u32,
    height: u32,
    aa: Antialias,
) -> (Frame, RayCount) {
    match aa {
        Antialias::Grid(n) => render(tracer, camera, width, height, n),
        Antialias::Adaptive(a) => {
            let out = trace(tracer, camera, width, height, a, TILE);
            let pixels = out
                .colors
                .iter()
                .flat_map(|c| [to_byte(c.x), to_byte(c.y), to_byte(c.z)])
                .collect();
            let frame = Frame {
                width,
                height,
                pixels,
            };
            (frame, out.rays)
        }
    }
}

/// `render_add` with either anti-aliasing (motion blur: each sub-frame adaptive).
pub fn render_add_with(
    tracer: &Tracer,
    camera: &Camera,
    width: u32,
    height: u32,
    aa: Antialias,
    sum: &mut [Color],
) -> RayCount {
    match aa {
        Antialias::Grid(n) => render_add(tracer, camera, width, height, n, sum),
        Antialias::Adaptive(a) => {
            let out = trace(tracer, camera, width, height, a, TILE);
            for (acc, c) in sum.iter_mut().zip(&out.colors) {
                *acc += *c;
            }
            out.rays
        }
    }
}

/// The hash of a lattice point for the sample maps: the two coordinates packed and
/// multiplied by an odd constant (Fibonacci hashing), high half folded in. The keys are small distinct integer
/// pairs chosen by the render, not by an adversary, so SipHash's resistance buys nothing
/// and its cost was paid on every finer sample.
#[derive(Default)]
struct PointHasher(u64);

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

type BuildPointHasher = std::hash::BuildHasherDefault<PointHasher>;

/// The finer samples of one pixel row, by lattice point.
type SampleMap = HashMap<(u32, u32), Color, BuildPointHasher>;

/// One traced lattice: the pixel corners, and the finer samples traced once on demand.
struct Lattice<'a> {
    tracer: &'a Tracer<'a>,
    view: Option<&'a TileView>,
    camera: &'a Camera,
    width: u32,
    height: u32,
    depth: u32,
    /// The pixel corners, (width+1)·(height+1), rows top to bottom.
    corners: Vec<Color>,
    /// The finer samples, one map per pixel row (its inside and its bottom edge).
    memo: Vec<Mutex<SampleMap>>,
}

impl Lattice<'_> {
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

    /// The sample at lattice point (x, y), traced if no one has yet.
    fn sample(&self, x: u32, y: u32, count: &mut RayCount) -> Color {
        let mask = (1u32 << self.depth) - 1;
        if x & mask == 0 && y & mask == 0 {
            let k = (y >> self.depth) as usize * (self.width as usize + 1);
            return self.corners[k + (x >> self.depth) as usize];
        }
        let row = if y & mask == 0 && y > 0 {
            (y >> self.depth) - 1
        } else {
            (y >> self.depth).min(self.height - 1)
        };
        let lock = || {
            self.memo[row as usize]
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
        let c = self.trace(x, y, &mut own);
        match lock().entry((x, y)) {
            Entry::Occupied(first) => *first.get(),
            Entry::Vacant(slot) => {
                *count = *count + own;
                *slot.insert(c)
            }
        }
    }
}

/// The statistics of one square's subdivision.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Split {
    /// Leaves.
    pub leaves: u32,
    /// The deepest level reached (0: the square itself is a leaf).
    pub deepest: u32,
}

/// The colour of the square of side `size` lattice steps at (x, y) whose corners are `c`
/// (top-left, top-right, bottom-left, bottom-right), `level` splits below its pixel,
/// with `sample` giving the colour at any lattice point: the mean of its four corners
/// when they agree or at the deepest level, else the mean of its four quarters.
pub fn square<F>(
    aa: &Adaptive,
    (x, y): (u32, u32),
    size: u32,
    level: u32,
    c: [Color; 4],
    sample: &mut F,
) -> (Color, Split)
where
    F: FnMut(u32, u32) -> Color,
{
    if level >= aa.depth || size < 2 || !aa.differ(&c) {
        let leaf = Split {
            leaves: 1,
            deepest: level,
        };
        return ((c[0] + c[1] + c[2] + c[3]) / 4.0, leaf);
    }
    let h = size / 2;
    let top = sample(x + h, y);
    let left = sample(x, y + h);
    let mid = sample(x + h, y + h);
    let right = sample(x + size, y + h);
    let bottom = sample(x + h, y + size);
    let quarters = [
        ((x, y), [c[0], top, left, mid]),
        ((x + h, y), [top, c[1], mid, right]),
        ((x, y + h), [left, mid, c[2], bottom]),
        ((x + h, y + h), [mid, right, bottom, c[3]]),
    ];
    let mut sum = Color::ZERO;
    let mut split = Split::default();
    for (at, corners) in quarters {
        let (q, s) = square(aa, at, h, level + 1, corners, sample);
        sum += q;
        split.leaves += s.leaves;
        split.deepest = split.deepest.max(s.deepest);
    }
    (sum / 4.0, split)
}

/// Every pixel of a `width`×`height` frame drawn adaptively, in tiles of `tile` pixels a
/// side; the result does not depend on `tile` nor on the thread count.
pub fn trace(
    tracer: &Tracer,
    camera: &Camera,
    width: u32,
    height: u32,
    aa: Adaptive,
    tile: u32,
) -> Adaptively {
    let depth = aa.depth.min(MAX_DEPTH);
    let view = TileView::new(camera, width, height, &tracer.scene().objects);
    let mut lattice = Lattice {
        tracer,
        view: view.as_ref(),
        camera,
        width,
        height,
        depth,
        corners: vec![Color::ZERO; (width as usize + 1) * (height as usize + 1)],
        memo: (0..height).map(|_| Mutex::default()).collect(),
    };
    let mut corners = std::mem::take(&mut lattice.corners);
    let mut rays = corners
        .par_chunks_mut(width as usize + 1)
        .enumerate()
        .map(|(j, row)| {
            let mut count = RayCount::default();
            if super::control::stop_row() {
                return count; // cancelled: the caller discards the frame
            }
            for (i, c) in row.iter_mut().enumerate() {
                *c = lattice.trace((i as u32) << depth, (j as u32) << depth, &mut count);
            }
            count
        })
        .reduce(RayCount::default, |a, b| a + b);
    lattice.corners = corners;
    let tile = tile.max(1);
    let (cols, rows) = (width.div_ceil(tile), height.div_ceil(tile));
    let tiles: Vec<(Vec<(Color, Split)>, RayCount)> = (0..cols * rows)
        .into_par_iter()
        .map(|t| {
            let (ti, tj) = (t % cols, t / cols);
            let mut count = RayCount::default();
            let mut out = Vec::new();
            let band = tj * tile..((tj + 1) * tile).min(height);
            if super::control::stop_row() {
                // Cancelled: the caller discards the frame; the tile keeps its shape.
                let cells = band.len() * (((ti + 1) * tile).min(width) - ti * tile) as usize;
                return (vec![(Color::ZERO, Split::default()); cells], count);
            }
            for j in band.clone() {
                for i in ti * tile..((ti + 1) * tile).min(width) {
                    out.push(pixel(&lattice, &aa, i, j, &mut count));
                }
            }
            if ti + 1 == cols {
                // Progress by bands of rows: a band counts when its last column's tile ends.
                super::control::rows_done_by(band.len() as u64);
            }
            (out, count)
        })
        .collect();
    let n = width as usize * height as usize;
    let mut result = Adaptively {
        colors: vec![Color::ZERO; n],
        leaves: vec![0; n],
        deepest: vec![0; n],
        rays: RayCount::default(),
    };
    for (t, (pixels, count)) in tiles.into_iter().enumerate() {
        let (ti, tj) = (t as u32 % cols, t as u32 / cols);
        let x0 = ti * tile;
        let w = (((ti + 1) * tile).min(width) - x0) as usize;
        for (k, (c, s)) in pixels.into_iter().enumerate() {
            let (i, j) = (x0 as usize + k % w, (tj * tile) as usize + k / w);
            let at = j * width as usize + i;
            result.colors[at] = c;
            result.leaves[at] = s.leaves;
            result.deepest[at] = s.deepest;
        }
        rays = rays + count;
    }
    result.rays = rays;
    result
}

/// Pixel (i, j): its square of the lattice, split as its corners ask.
fn pixel(lattice: &Lattice, aa: &Adaptive, i: u32, j: u32, count: &mut RayCount) -> (Color, Split) {
    let d = lattice.depth;
    let (x, y, size) = (i << d, j << d, 1u32 << d);
    let mut sample = |x: u32, y: u32| lattice.sample(x, y, count);
    let c = [
        sample(x, y),
        sample(x + size, y),
        sample(x, y + size),
        sample(x + size, y + size),
    ];
    let aa = Adaptive { depth: d, ..*aa };
    square(&aa, (x, y), size, 0, c, &mut sample)
}
