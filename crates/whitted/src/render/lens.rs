//! A camera sample's rays: its pinhole ray, or, when the scene has a `focus` record
//! (SPEC §16), the Samples × Samples lens rays of the thin lens (`camera::thin_lens`)
//! through the point where the pinhole ray meets the plane in focus. Every loop behind
//! `render`'s sinks but the SPD's corners (the grid's picture and sum, the streamed
//! picture, adaptive anti-aliasing, the layered one) takes its camera samples here, so
//! the lens multiplies `samples`, the adaptive lattice's points and motion blur's
//! sub-frames alike.
//!
//! The colour of a sample with a lens is the mean of its lens rays' colours, each clamped
//! to 0..1 first, as §7 clamps every ray before a mean; without a lens it is the pinhole
//! ray's colour as it was (a scene without `focus` keeps its bytes).

use crate::accel::Hint;
use crate::base::Color;
use crate::camera::thin_lens::ThinLens;
use crate::camera::Camera;
use crate::optics::Ray;
use crate::trace::{RayCount, Tracer};

/// The camera of a frame and the lens the scene puts on it, if any.
pub struct Shot<'a> {
    camera: &'a Camera,
    lens: Option<ThinLens>,
    /// An orthographic view's height in the world (a glTF camera's), if the scene has one.
    parallel: Option<f64>,
}

impl<'a> Shot<'a> {
    /// The shot of `camera` with the tracer's scene's `focus`, if it has one.
    pub fn new(tracer: &Tracer, camera: &'a Camera) -> Shot<'a> {
        let focus = tracer.scene().ext.focus.as_ref();
        Shot {
            camera,
            lens: focus.map(|f| ThinLens::new(camera, f)),
            parallel: tracer.scene().parallel,
        }
    }

    /// The camera.
    pub fn camera(&self) -> &Camera {
        self.camera
    }

    /// The camera when the shot has no lens (each camera sample is one pinhole ray).
    #[inline]
    pub fn pinhole(&self) -> Option<&Camera> {
        match (&self.lens, self.parallel) {
            (None, None) => Some(self.camera),
            _ => None,
        }
    }

    /// The camera ray through image point (x, y): the pinhole's, or an orthographic
    /// view's parallel ray.
    #[inline(always)]
    fn ray(&self, x: f64, y: f64) -> Ray {
        match self.parallel {
            None => self.camera.ray(x, y),
            Some(height) => self.camera.parallel_ray(x, y, height),
        }
    }

    /// The rays traced for one camera sample: 1 without a lens, Samples² with one.
    pub fn rays_per_sample(&self) -> u32 {
        self.lens.as_ref().map_or(1, |l| l.points().len() as u32)
    }

    /// The colour of the camera sample at image point (x, y) (pixels from the top left):
    /// the pinhole ray's (not clamped), or the mean of the clamped lens rays'. `hint`,
    /// the sample's screen tile, answers for rays that leave the eye.
    #[inline(always)]
    pub fn color(
        &self,
        tracer: &Tracer,
        hint: Option<Hint>,
        x: f64,
        y: f64,
        count: &mut RayCount,
    ) -> Color {
        let ray = self.ray(x, y);
        // The tiles' lists answer for rays that leave the eye: not a parallel view's.
        let hint = hint.filter(|_| self.parallel.is_none());
        match &self.lens {
            None => tracer.primary_in(hint, &ray, count),
            Some(lens) => lens_color(lens, tracer, hint, &ray, count),
        }
    }

    /// Every ray of the camera sample at (x, y), in lens-point order: `each(ray)`.
    #[inline]
    pub fn each_ray(&self, x: f64, y: f64, mut each: impl FnMut(&Ray)) {
        let ray = self.ray(x, y);
        match &self.lens {
            None => each(&ray),
            Some(lens) => lens.rays(&ray).for_each(|r| each(&r)),
        }
    }
}

/// The mean of the clamped colours of the lens rays through `ray`'s focal point. Out of
/// line: the pinhole path of `Shot::color` stays the row loop's own code.
#[inline(never)]
fn lens_color(
    lens: &ThinLens,
    tracer: &Tracer,
    hint: Option<Hint>,
    ray: &Ray,
    count: &mut RayCount,
) -> Color {
    let mut sum = Color::ZERO;
    for r in lens.rays(ray) {
        sum += tracer
            .primary_in(hint, &r, count)
            .clamp(Color::ZERO, Color::ONE);
    }
    sum / lens.points().len() as f64
}

/// The rays traced per camera sample of `scene`: Samples² with a `focus` record, else 1
/// (what a sum of layered samples is divided by, times the samples and sub-frames).
pub fn rays_per_sample(scene: &crate::Scene) -> u32 {
    scene.ext.focus.map_or(1, |f| f.samples.max(1).pow(2))
}
