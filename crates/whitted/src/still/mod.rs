//! One picture of a scene, `raytrace`'s run: the scene's camera at a size and lens, the
//! warning before an enormous request (`estimate::Enormous`), and the drawing, through
//! the renderer's one door with any of its sinks (a picture, streamed to a live display
//! as it goes if asked, or layers).
//!
//! ```text
//! let still = Still::new(&scene, native, (w, h), &lens, aa)?;   // None: eye on look_at
//! still.enormous()                → Enormous { rays, seconds, .. } (past camera_rays' 2^28)
//! still.render(Picture::observed(STREAM_BAND, &send)) → (Frame, RayCount)
//! still.render(Layered(passes))   → (Layers, RayCount)
//! ```

mod request;
pub use request::{Done, Job, Request, StillError};

use crate::camera::{Camera, Lens};
use crate::render::estimate::{self, Enormous};
use crate::render::{render, Antialias, Options, Picture, Sink};
use crate::scene::Scene;
use crate::spd::Rules;
use crate::trace::Tracer;

/// Rows per band streamed to tev: a band is a few milliseconds of work at the report's
/// sizes, so the picture fills in smoothly.
pub const STREAM_BAND: u32 = 16;

/// A scene ready to draw at a size.
pub struct Still<'s> {
    scene: &'s Scene,
    native: (u32, u32),
    lens: Lens,
    /// The picture's width in pixels.
    pub width: u32,
    /// Its height.
    pub height: u32,
    /// Its anti-aliasing.
    pub aa: Antialias,
    camera: Camera,
    tracer: Tracer<'s>,
    /// The SPD's testing procedure: a camera through the pixel corners.
    corners: Option<Camera>,
}

/// The camera rays a picture of `size` drawn with `aa` casts: samples² a pixel, times the
/// lens rays a `focus` record traces for every camera sample.
pub fn camera_rays(scene: &Scene, size: (u32, u32), aa: Antialias) -> u64 {
    let n = Options::new(size.0, size.1, aa).grid_side();
    let lens = u64::from(crate::render::rays_per_sample(scene));
    estimate::camera_rays(size.0, size.1, n, 1, 1).saturating_mul(lens)
}

impl<'s> Still<'s> {
    /// `scene` (whose own resolution is `native`) drawn at `size` through `lens`; `None`
    /// when its eye is on the point it looks at.
    pub fn new(
        scene: &'s Scene,
        native: (u32, u32),
        size: (u32, u32),
        lens: &Lens,
        aa: Antialias,
    ) -> Option<Still<'s>> {
        let camera = Camera::framed(scene.eye, scene.look_at, native, size, lens)?;
        Some(Still {
            scene,
            native,
            lens: *lens,
            width: size.0,
            height: size.1,
            aa,
            camera,
            tracer: Tracer::new(scene),
            corners: None,
        })
    }

    /// This picture drawn by the SPD's testing procedure (`crate::spd`): the
    /// (w + 1) × (h + 1) rays through the pixel corners averaged, the SPD's depth and
    /// spawning. `None` when the eye is on its look-at point.
    pub fn spd(mut self) -> Option<Still<'s>> {
        let size = (self.width + 1, self.height + 1);
        let s = self.scene;
        self.corners = Some(Camera::framed(
            s.eye,
            s.look_at,
            self.native,
            size,
            &self.lens,
        )?);
        self.tracer = self.tracer.with_rules(Rules::spd());
        Some(self)
    }

    /// How the picture is sampled: its size, its anti-aliasing, and the corners under
    /// the SPD's procedure.
    fn options(&self) -> Options<'_> {
        Options {
            corners: self.corners.as_ref(),
            ..Options::new(self.width, self.height, self.aa)
        }
    }

    /// The warning before this picture's camera rays (`camera_rays`, which the caller
    /// compares with `estimate::ENORMOUS` before it makes a `Still`): with the seconds a
    /// 1/8-size sample, drawn as the picture will be (its anti-aliasing), predicts on the
    /// current pool.
    pub fn enormous(&self) -> Enormous {
        let (w, h, n) = (self.width, self.height, self.options().grid_side());
        let rays = camera_rays(self.scene, (w, h), self.aa);
        let lens = u64::from(crate::render::rays_per_sample(self.scene));
        let k = estimate::SAMPLE_DIVISOR;
        let small = ((w / k).max(1), (h / k).max(1));
        let seconds = Camera::framed(
            self.scene.eye,
            self.scene.look_at,
            self.native,
            small,
            &self.lens,
        )
        .map(|cam| {
            let t = std::time::Instant::now();
            let sampled = Options::new(small.0, small.1, self.aa);
            render(&self.tracer, &cam, &sampled, Picture::new());
            let sample = camera_rays(self.scene, small, self.aa);
            estimate::predict(rays, sample, t.elapsed().as_secs_f64())
        });
        Enormous {
            rays,
            frames: None,
            width: w,
            height: h,
            per_pixel: u64::from(n) * u64::from(n) * lens,
            seconds,
            threads: rayon::current_num_threads(),
        }
    }

    /// The picture (`Picture`, observed or not) or its layers (`Layered`), drawn as the
    /// still's options say (a picture through the pixel corners under the SPD's
    /// procedure).
    pub fn render<S: Sink>(&self, sink: S) -> S::Made {
        render(&self.tracer, &self.camera, &self.options(), sink)
    }
}

#[cfg(test)]
#[path = "tests.rs"]
mod tests;
