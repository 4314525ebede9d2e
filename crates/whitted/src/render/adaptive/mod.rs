//! Adaptive anti-aliasing (SPEC §15), after POV-Ray's `+AM2 +A T +R D`: every pixel
//! corner is traced once and shared by the four pixels around it; a pixel (or a quarter
//! of one) whose four corners differ by more than T is split into four, down to depth D;
//! the pixel is the mean of its leaves weighted by their areas, a leaf being the mean of
//! its four clamped corner samples.
//!
//! ```toml
//! [render]
//! antialias = { mode = "adaptive", threshold = 0.4, depth = 2 }   # raytrace --aa adaptive:0.4:2
//! ```
//!
//! Determinism. Every sample is named by its integer coordinates on the lattice of pitch
//! 2^−D and its colour is a function of them alone; each pixel's first split is decided
//! from the corner pass alone, and every finer sample is traced and counted once, whichever
//! band or thread asks first (`lattice.rs`), so the pixels' colours and the ray counts do
//! not depend on the thread count, the shard or the band height. Bands of `band` rows are
//! the parallel work units, each drawn straight into the caller's buffer (the frame's
//! bytes, a motion-blur sum, or the statistics below). When a square splits is
//! `measure.rs`'s; the lattice's buffers are kept between frames (`store.rs`).

use crate::accel::TileView;
use crate::base::Color;
use crate::base::{to_rgb, Frame};
use crate::camera::Camera;
use crate::trace::{RayCount, Tracer};
use lattice::{Lattice, Probe, Scratch};
use rayon::prelude::*;
use serde::Serialize;

mod edges;
mod lattice;
mod measure;
mod parse;
mod store;
#[cfg(test)]
mod tests;

pub use measure::Measure;
pub use parse::AntialiasError;
pub use store::worst_bytes;

/// The deepest subdivision accepted (4096 leaves per pixel at most).
pub const MAX_DEPTH: u32 = 6;
/// The largest threshold accepted: the sum measure's largest difference (three channels).
pub const MAX_THRESHOLD: f64 = 3.0;
/// Pixel rows in a parallel work unit.
pub const BAND: u32 = 16;

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
    /// The defaults: the fewest rays whose images are as close to a 16×16 reference as
    /// POV-Ray's `+AM2 +A0.3 +R3` are to its own (benches/pov/adaptive.sh).
    pub const DEFAULT: Adaptive = Adaptive {
        threshold: 0.4,
        depth: 2,
        measure: Measure::Edge,
    };
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

/// A fresh 8-bit picture drawn adaptively (`Picture` under `Antialias::Adaptive`).
pub(super) fn picture(
    tracer: &Tracer,
    camera: &Camera,
    width: u32,
    height: u32,
    a: Adaptive,
) -> (Frame, RayCount) {
    let mut pixels = vec![0; width as usize * height as usize * 3];
    let (rgb, _) = pixels.as_chunks_mut::<3>();
    let rays = draw(tracer, camera, (width, height), a, BAND, rgb, |p, c, _| {
        *p = to_rgb(c)
    });
    let frame = Frame {
        width,
        height,
        pixels,
    };
    (frame, rays)
}

/// Every pixel drawn adaptively, added into `sum` (`Sum` under `Antialias::Adaptive`;
/// motion blur: each sub-frame adaptive).
pub(super) fn add(
    tracer: &Tracer,
    camera: &Camera,
    width: u32,
    height: u32,
    a: Adaptive,
    sum: &mut [Color],
) -> RayCount {
    let size = (width, height);
    draw(tracer, camera, size, a, BAND, sum, |acc, c, _| *acc += c)
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
    let split = level < aa.depth && size >= 2 && aa.measure.differ(aa.threshold, &c, level);
    let at = (x, y);
    resolve(aa, Square { at, size, level, c }, sample, split)
}

/// A square of the lattice: its top-left point, its side in lattice steps, how many
/// splits below its pixel it is, and its corners.
struct Square {
    at: (u32, u32),
    size: u32,
    level: u32,
    c: [Color; 4],
}

/// `square` once its split is decided: a leaf, or the mean of its four quarters.
fn resolve<F>(aa: &Adaptive, sq: Square, sample: &mut F, split: bool) -> (Color, Split)
where
    F: FnMut(u32, u32) -> Color,
{
    let Square {
        at: (x, y),
        size,
        level,
        c,
    } = sq;
    if !split {
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

/// Every pixel of a `width`×`height` frame drawn adaptively, in bands of `band` rows; the
/// result does not depend on `band` nor on the thread count.
pub fn trace(
    tracer: &Tracer,
    camera: &Camera,
    width: u32,
    height: u32,
    aa: Adaptive,
    band: u32,
) -> Adaptively {
    let n = width as usize * height as usize;
    let mut pixels = vec![(Color::ZERO, Split::default()); n];
    let rays = draw(
        tracer,
        camera,
        (width, height),
        aa,
        band,
        &mut pixels,
        |p, c, s| *p = (c, s),
    );
    Adaptively {
        colors: pixels.iter().map(|p| p.0).collect(),
        leaves: pixels.iter().map(|p| p.1.leaves).collect(),
        deepest: pixels.iter().map(|p| p.1.deepest).collect(),
        rays,
    }
}

/// Draws every pixel of a `width`×`height` frame adaptively, handing each one's colour and
/// split to `put` with its element of `out` (one per pixel, rows top to bottom), in
/// parallel bands of `band` rows; returns the rays cast. A cancelled render leaves bands
/// untouched: its caller discards the frame.
fn draw<T, P>(
    tracer: &Tracer,
    camera: &Camera,
    (width, height): (u32, u32),
    aa: Adaptive,
    band: u32,
    out: &mut [T],
    put: P,
) -> RayCount
where
    T: Send,
    P: Fn(&mut T, Color, Split) + Sync,
{
    let depth = aa.depth.min(MAX_DEPTH);
    let aa = Adaptive { depth, ..aa };
    let view = TileView::new(camera, width, height, &tracer.scene().objects);
    let shot = super::Shot::new(tracer, camera);
    let probe = Probe {
        tracer,
        view: view.as_ref(),
        shot: &shot,
        width,
        height,
        depth,
    };
    let mut rays = RayCount::default();
    let lattice = Lattice::new(probe, &aa, &mut rays);
    let (w, band) = ((width as usize).max(1), band.max(1) as usize);
    let bands = out.par_chunks_mut(band * w).enumerate();
    let drawn = bands.map(|(b, pixels)| {
        let mut count = RayCount::default();
        if super::control::stop_row() {
            return count;
        }
        let mut scratch = Scratch::new(depth);
        for (r, row) in pixels.chunks_mut(w).enumerate() {
            let j = (b * band + r) as u32;
            for (i, slot) in row.iter_mut().enumerate() {
                let (c, s) = pixel(&lattice, &aa, (i as u32, j), &mut scratch, &mut count);
                put(slot, c, s);
            }
        }
        super::control::rows_done_by((pixels.len() / w) as u64);
        count
    });
    rays + drawn.reduce(RayCount::default, |a, b| a + b)
}

/// Pixel (i, j): its square of the lattice, split as the lattice decided and then as its
/// quarters' corners ask (`aa.depth` is the lattice's).
fn pixel(
    lattice: &Lattice,
    aa: &Adaptive,
    (i, j): (u32, u32),
    scratch: &mut Scratch,
    count: &mut RayCount,
) -> (Color, Split) {
    let d = lattice.depth();
    let (c, split) = lattice.pixel(i, j);
    scratch.next_pixel();
    let mut sample = |x: u32, y: u32| lattice.sample((i, j), x, y, scratch, count);
    let at = (i << d, j << d);
    let size = 1 << d;
    resolve(
        aa,
        Square {
            at,
            size,
            level: 0,
            c,
        },
        &mut sample,
        split,
    )
}
