//! What frames of an animation cost before they are drawn: the camera rays they cast,
//! the rows the progress bar counts, a small timed sample (`scaled`, `predict_seconds`)
//! and the warning before an enormous request, and how many frames may be in flight
//! within `FRAME_MEMORY`.

use super::Animation;
use crate::error::AnimError;
use std::time::Instant;
use whitted::output::encode;
use whitted::passes::record::PixelSum;
use whitted::render::estimate;
use whitted::trace::RayCount;

/// A frame drawn and encoded as a run makes it, timed (`Animation::render_timed`).
#[derive(Clone, Copy, Debug, Default)]
pub struct Timed {
    /// Its rays.
    pub rays: RayCount,
    /// Its size, encoded (without its provenance).
    pub bytes: usize,
    /// Seconds to draw it.
    pub render_s: f64,
    /// Seconds to encode it.
    pub encode_s: f64,
}

/// The memory frames in flight may take (pixels and their encoded copy): 1 GiB.
pub const FRAME_MEMORY: usize = 1 << 30;

impl<'p> Animation<'p> {
    /// The camera rays `frames` frames cast (`render::estimate::camera_rays`).
    pub fn camera_rays(&self, frames: usize) -> u64 {
        let subframes = self.timeline.blur.map_or(1, |b| b.samples);
        estimate::camera_rays(
            self.width,
            self.height,
            self.samples,
            subframes,
            frames as u64,
        )
    }

    /// This animation at 1/`divisor` of each side (at least one pixel), sharing its BVH.
    /// With `samples`, that many samples a side and no adaptive anti-aliasing (the
    /// one-sample pre-pass of `balance`); without, its own sampling (the timed picture
    /// of `predict_seconds`).
    pub fn scaled(&self, divisor: u32, samples: Option<u32>) -> Animation<'p> {
        let divisor = divisor.max(1);
        let mut small = Animation {
            width: (self.width / divisor).max(1),
            height: (self.height / divisor).max(1),
            shared: self.shared.clone(),
            observer: None,
            ..*self
        };
        if let Some(n) = samples {
            small.samples = n.max(1);
            small.antialias = None;
        }
        small
    }

    /// The seconds `frames` frames are predicted to take, from frame `frame` drawn at
    /// 1/`SAMPLE_DIVISOR` of each side on the current pool.
    pub fn predict_seconds(&self, frame: u32, frames: usize) -> Result<f64, AnimError> {
        let small = self.scaled(estimate::SAMPLE_DIVISOR, None);
        let start = std::time::Instant::now();
        small.render_encoded(frame)?;
        let took = start.elapsed().as_secs_f64();
        Ok(estimate::predict(
            self.camera_rays(frames),
            small.camera_rays(1),
            took,
        ))
    }

    /// Draws frame `frame` as a run makes it (an EXR's layers with its passes) and
    /// encodes it in memory, as what a frame costs is timed: its rays and its bytes.
    pub fn render_encoded(&self, frame: u32) -> Result<(RayCount, usize), AnimError> {
        self.render_timed(frame).map(|t| (t.rays, t.bytes))
    }

    /// `render_encoded`, timing the drawing (in parallel over the pool) and the encoding
    /// (on one thread) apart.
    pub fn render_timed(&self, frame: u32) -> Result<Timed, AnimError> {
        let format = self.format();
        let plan = self.plan(frame);
        let mut bytes = Vec::new();
        let start = Instant::now();
        let (encoded, rays, render_s) = if format.is_layered() {
            let (layers, rays) = self.render_layers(&plan, format.passes())?;
            let render_s = start.elapsed().as_secs_f64();
            (encode(layers, format, &[], &mut bytes), rays, render_s)
        } else {
            let (image, rays) = self.render(&plan)?;
            let render_s = start.elapsed().as_secs_f64();
            (encode(&image, format, &[], &mut bytes), rays, render_s)
        };
        encoded.map_err(|source| AnimError::Write { frame, source })?;
        Ok(Timed {
            rays,
            bytes: bytes.len(),
            render_s,
            encode_s: start.elapsed().as_secs_f64() - render_s,
        })
    }

    /// Past `estimate::ENORMOUS` camera rays for `frames`: the warning, with the time a
    /// 1/`SAMPLE_DIVISOR` sample of the first frame predicts on the current pool.
    pub fn enormous(&self, frames: &[u32]) -> Option<estimate::Enormous> {
        self.enormous_of(frames.len(), *frames.first()?)
    }

    /// `enormous` for `count` frames, timing frame `first` (a run warns once it knows
    /// which frames it will render: not those `--resume` finds up to date).
    pub fn enormous_of(&self, count: usize, first: u32) -> Option<estimate::Enormous> {
        let rays = self.camera_rays(count);
        if rays <= estimate::ENORMOUS {
            return None;
        }
        let pixels = (u64::from(self.width) * u64::from(self.height)).max(1);
        Some(estimate::Enormous {
            rays,
            frames: Some(count),
            width: self.width,
            height: self.height,
            per_pixel: self.camera_rays(1) / pixels,
            seconds: self.predict_seconds(first, count).ok(),
            threads: rayon::current_num_threads(),
        })
    }

    /// The rows of pixels one frame draws: its height, times its motion-blur sub-frames
    /// (the unit of `render::control::rows_done`).
    pub fn rows_per_frame(&self) -> u64 {
        let subframes = self
            .timeline
            .blur
            .map_or(1, |b| u64::from(b.samples.max(1)));
        u64::from(self.height) * subframes
    }

    /// How many frames may be in flight at once: `per_thread` per worker thread, but no
    /// more than fit in `FRAME_MEMORY` (at least one), whatever `--threads` says.
    pub fn window(&self, per_thread: usize) -> usize {
        // A layered frame keeps per-pixel sums (`PixelSum`) and float channels.
        let per_pixel = if self.format().is_layered() {
            std::mem::size_of::<PixelSum>() + 4 * 64
        } else {
            3
        };
        let frame_bytes = (self.width as usize * self.height as usize * per_pixel).max(1);
        // Motion blur adds a float accumulator of 24 bytes a pixel per frame in flight.
        let blur = if self.timeline.blur.is_some() { 9 } else { 1 };
        let fit = (FRAME_MEMORY / (2 * blur * frame_bytes)).max(1);
        (per_thread * rayon::current_num_threads().max(1)).min(fit)
    }
}
