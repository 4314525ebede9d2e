//! Drawing an image, through one door: `render(tracer, camera, &options, sink)`. The
//! options say how the pixels are sampled (the size, the anti-aliasing: the n×n grid or
//! adaptive, or the SPD's pixel corners); the sink says what is made of the samples and
//! where it goes (a fresh 8-bit picture, streamed to an observer band by band if asked;
//! a float sum to add into, for motion blur's sub-frames; a frame of layers with passes,
//! or their sums). Every render runs on the current rayon pool, in parallel over rows
//! or bands of rows, and its bytes do not depend on the thread count.
//!
//! ```text
//! let (frame, rays) = render(&tracer, &camera, &Options::grid(w, h, 1), Picture::new());
//! let rays = render(&tracer, &camera, &Options::new(w, h, aa), Sum(&mut sum));
//! let (layers, rays) = render(&tracer, &camera, &options, Layered(passes));
//! let shown = Picture::observed(16, &|y0, rows| tev.rows("img", w, y0, rows));
//! ```
//!
//! Each sink goes straight to its own loop (`grid`, `stream`, `adaptive`, `corners`,
//! `layers`): the door chooses the loop once, not per pixel.

pub mod adaptive;
pub mod control;
mod corners;
pub mod estimate;
mod grid;
pub mod layers;
pub mod lens;
mod sink;
mod stream;

pub use adaptive::{Adaptive, Antialias};
pub use lens::{rays_per_sample, Shot};
pub use sink::{Layered, LayeredSum, Picture, Sink, Sum};

use crate::camera::Camera;
use crate::trace::Tracer;

/// How a render samples its pixels.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Options<'c> {
    /// The picture's width in pixels.
    pub width: u32,
    /// Its height in pixels.
    pub height: u32,
    /// The n×n grid of samples a pixel, or adaptive anti-aliasing. Layers are drawn on
    /// the grid: n×n, or one sample a pixel under adaptive anti-aliasing.
    pub aa: Antialias,
    /// The SPD's testing procedure (`crate::spd`): a camera whose pixel centres are the
    /// picture's (width + 1) × (height + 1) pixel corners; each pixel is the mean of its
    /// four corner rays, each clamped to 0..1 first, instead of `aa`'s samples. 8-bit
    /// pictures only (`Picture`): the other sinks sample as `aa` says.
    pub corners: Option<&'c Camera>,
}

impl Options<'static> {
    /// `width` × `height`, anti-aliased as `aa` says.
    pub fn new(width: u32, height: u32, aa: Antialias) -> Options<'static> {
        Options {
            width,
            height,
            aa,
            corners: None,
        }
    }

    /// `width` × `height` with n×n samples a pixel (1: the pixel centre, the report's).
    pub fn grid(width: u32, height: u32, n: u32) -> Options<'static> {
        Options::new(width, height, Antialias::Grid(n))
    }
}

impl Options<'_> {
    /// The side of the grid layers are drawn on: n, or 1 under adaptive anti-aliasing
    /// (whose rays are counted from the one corner sample a pixel shares).
    pub fn grid_side(&self) -> u32 {
        match self.aa {
            Antialias::Grid(n) => n,
            Antialias::Adaptive(_) => 1,
        }
    }
}

/// Draws the tracer's scene through `camera` as `options` say, into `sink`: what the sink
/// makes (a picture or layers and their rays, or the rays alone for the sums). Runs on
/// the current rayon pool. The `Tracer` is built once per scene and shared by every frame
/// drawn of it.
pub fn render<S: Sink>(tracer: &Tracer, camera: &Camera, options: &Options, sink: S) -> S::Made {
    sink.draw(tracer, camera, options)
}
