//! What a render makes of its samples (`render`'s last argument): a fresh 8-bit picture,
//! told to an observer band by band if it has one (`Picture`); a float sum to add into
//! (`Sum`, motion blur's sub-frames); a frame of layers with passes (`Layered`), or their
//! sums (`LayeredSum`). Each goes to its own loop as the options' sampling says.

use super::{adaptive, corners, grid, layers, stream, Antialias, Options};
use crate::base::{Color, Frame};
use crate::camera::Camera;
use crate::passes::record::Sums;
use crate::passes::{Layers, PassSet};
use crate::trace::{RayCount, Tracer};

mod sealed {
    /// Only this module's sinks: each names loops that are the crate's own.
    pub trait Sealed {}
}

/// What `render` makes of the samples, and returns.
pub trait Sink: sealed::Sealed {
    /// What the render returns: the thing made and its rays, or the rays alone.
    type Made;

    /// Draws the tracer's scene through `camera` as `options` say, into this sink.
    fn draw(self, tracer: &Tracer, camera: &Camera, options: &Options) -> Self::Made;
}

/// Told of each finished band of rows of a picture: `observe(first_row, band_pixels)`.
type Observer<'o> = (u32, &'o dyn Fn(u32, &[u8]));

/// A fresh 8-bit picture (the beauty through the clamp-and-round of each sample).
#[derive(Clone, Copy, Default)]
pub struct Picture<'o> {
    observer: Option<Observer<'o>>,
}

impl<'o> Picture<'o> {
    /// The picture, returned whole.
    pub fn new() -> Picture<'o> {
        Picture { observer: None }
    }

    /// The picture, each band of `band` rows (at least 1) told to `observe(first_row,
    /// band_pixels)` as it finishes, top to bottom, before the next starts (a live
    /// display). On the grid the bands are drawn as the whole picture draws its rows, so
    /// every band is exactly the picture's bytes; an adaptive or corners picture is told
    /// once, whole, when drawn.
    pub fn observed(band: u32, observe: &'o dyn Fn(u32, &[u8])) -> Picture<'o> {
        Picture {
            observer: Some((band, observe)),
        }
    }
}

impl sealed::Sealed for Picture<'_> {}

impl Sink for Picture<'_> {
    type Made = (Frame, RayCount);

    fn draw(self, tracer: &Tracer, camera: &Camera, o: &Options) -> (Frame, RayCount) {
        let (w, h) = (o.width, o.height);
        let drawn = match (o.corners, o.aa, self.observer) {
            (Some(corners), _, _) => corners::picture(tracer, corners, w, h),
            (None, Antialias::Grid(n), None) => grid::picture(tracer, camera, w, h, n),
            (None, Antialias::Grid(n), Some((band, observe))) => {
                return stream::picture(tracer, camera, w, h, n, band, observe);
            }
            (None, Antialias::Adaptive(a), _) => adaptive::picture(tracer, camera, w, h, a),
        };
        if let Some((_, observe)) = self.observer {
            observe(0, &drawn.0.pixels);
        }
        drawn
    }
}

/// Every pixel's colour clamped to 0..1 (the mean of its clamped samples), added into
/// the slice (width·height colours, rows top to bottom). Motion blur sums its sub-frames
/// this way and then divides (`Frame::from_sum`), so each sample is clamped, all are
/// averaged, then rounded, as anti-aliasing does. Returns the rays.
pub struct Sum<'b>(pub &'b mut [Color]);

impl sealed::Sealed for Sum<'_> {}

impl Sink for Sum<'_> {
    type Made = RayCount;

    fn draw(self, tracer: &Tracer, camera: &Camera, o: &Options) -> RayCount {
        match o.aa {
            Antialias::Grid(n) => grid::add(tracer, camera, o.width, o.height, n, self.0),
            Antialias::Adaptive(a) => adaptive::add(tracer, camera, o.width, o.height, a, self.0),
        }
    }
}

/// A fresh frame of layers: the beauty (the mean of the unclamped samples) and these
/// passes, from one trace per sample, on the options' grid (`Options::grid_side`).
pub struct Layered(pub PassSet);

impl sealed::Sealed for Layered {}

impl Sink for Layered {
    type Made = (Layers, RayCount);

    fn draw(self, tracer: &Tracer, camera: &Camera, o: &Options) -> (Layers, RayCount) {
        layers::layers(tracer, camera, o.width, o.height, o.grid_side(), self.0)
    }
}

/// Every pixel's samples of the beauty and these passes added into the sums (made by
/// `Sums::new` for the same passes): one sub-frame of a frame of layers, on the options'
/// grid. Returns the rays.
pub struct LayeredSum<'b>(pub PassSet, pub &'b mut Sums);

impl sealed::Sealed for LayeredSum<'_> {}

impl Sink for LayeredSum<'_> {
    type Made = RayCount;

    fn draw(self, tracer: &Tracer, camera: &Camera, o: &Options) -> RayCount {
        let LayeredSum(passes, sums) = self;
        layers::add(
            tracer,
            camera,
            o.width,
            o.height,
            o.grid_side(),
            passes,
            sums,
        )
    }
}
