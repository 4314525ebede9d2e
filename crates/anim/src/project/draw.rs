//! Drawing a frame from its plan (`FramePlan`): the tracer's one door
//! (`whitted::render::render`) on the scene of each time the frame samples, with that
//! time's camera; with motion blur the sub-frames are summed into one picture or one
//! frame of layers. The observer (`--display tev`) is told of every finished frame.

use super::{Animation, FramePlan};
use crate::error::AnimError;
use std::sync::Arc;
use whitted::base::{Color, Frame};
use whitted::passes::record::{finish, Sums};
use whitted::passes::{Layers, PassSet};
use whitted::pick::Pick;
use whitted::render::layers::camera_matrices;
use whitted::render::{control, render, Antialias, LayeredSum, Options, Picture, Sum};
use whitted::scene::Scene;
use whitted::trace::{RayCount, Tracer};

impl<'p> Animation<'p> {
    fn tracer<'s>(&self, scene: &'s Scene) -> Tracer<'s> {
        match &self.shared {
            Some(accel) => Tracer::with_accel(scene, Arc::clone(accel)),
            None => Tracer::new(scene),
        }
    }

    /// Draws the plan's frame: exactly what `raytrace` draws of the scene of that frame
    /// with its camera; with motion blur the mean of its sub-frames (each sample clamped,
    /// all averaged, then rounded).
    pub fn render(&self, plan: &FramePlan) -> Result<(Frame, RayCount), AnimError> {
        let _drawing = control::frame_in_progress();
        let drawn = self.draw(plan)?;
        // A signal stopped the row loops: the frame is incomplete and must not be kept.
        if let Some(sig) = control::cancelled() {
            return Err(AnimError::Interrupted(sig));
        }
        self.tell(plan.frame(), || &drawn.0);
        Ok(drawn)
    }

    /// Tells the observer (if any) of finished frame `frame`, whose picture `picture`
    /// makes: the one place `render` and `render_layers` (an EXR's frames) both end in.
    fn tell<F: std::borrow::Borrow<Frame>>(&self, frame: u32, picture: impl FnOnce() -> F) {
        if let Some(observe) = &self.observer {
            observe(frame, picture().borrow());
        }
    }

    fn draw(&self, plan: &FramePlan) -> Result<(Frame, RayCount), AnimError> {
        let (w, h) = (self.width, self.height);
        let aa = self
            .antialias
            .map_or(Antialias::Grid(self.samples), Antialias::Adaptive);
        let options = Options::new(w, h, aa);
        let frame = plan.frame();
        let count = plan.times().len() as u32;
        if count == 1 {
            let state = plan.own();
            let camera = self.camera(state).ok_or_else(|| self.camera_error(frame))?;
            let tracer = self.tracer(&state.scene);
            return Ok(render(&tracer, &camera, &options, Picture::new()));
        }
        let mut sum = vec![Color::ZERO; w as usize * h as usize];
        let mut rays = RayCount::default();
        for state in plan.samples() {
            if control::cancelled().is_some() {
                break; // the frame is discarded: no need to set up further sub-frames
            }
            let camera = self
                .camera(&state)
                .ok_or_else(|| self.camera_error(frame))?;
            let tracer = self.tracer(&state.scene);
            rays = rays + render(&tracer, &camera, &options, Sum(&mut sum));
        }
        Ok((Frame::from_sum(&sum, count, w, h), rays))
    }

    /// What the camera ray through the centre of pixel (x, y) of frame `frame` hits
    /// (`whitted::pick`), with this animation's camera (its size, `fov` and `roll`) at the
    /// frame's own time (motion blur's sub-frames are around it) and its shared tracer.
    pub fn pick(&self, frame: u32, x: u32, y: u32) -> Result<Option<Pick>, AnimError> {
        let plan = self.plan(frame);
        let state = plan.own();
        let camera = self.camera(state).ok_or_else(|| self.camera_error(frame))?;
        Ok(whitted::pick::pick(
            &self.tracer(&state.scene),
            &camera,
            x,
            y,
        ))
    }

    /// Draws the plan's frame as a frame of layers: the unclamped beauty (the mean of
    /// every sample of every sub-frame) and `passes`, from one trace per sample. The
    /// header's camera is the one at the frame's own time.
    pub fn render_layers(
        &self,
        plan: &FramePlan,
        passes: PassSet,
    ) -> Result<(Layers, RayCount), AnimError> {
        let _drawing = control::frame_in_progress();
        let (w, h, n) = (self.width, self.height, self.samples);
        let options = Options::grid(w, h, n);
        let frame = plan.frame();
        let mut sums = Sums::new(w as usize * h as usize, passes);
        let mut rays = RayCount::default();
        for state in plan.samples() {
            let camera = self
                .camera(&state)
                .ok_or_else(|| self.camera_error(frame))?;
            let tracer = self.tracer(&state.scene);
            rays = rays + render(&tracer, &camera, &options, LayeredSum(passes, &mut sums));
        }
        // A signal stopped the row loops: the frame is incomplete and must not be kept.
        if let Some(sig) = control::cancelled() {
            return Err(AnimError::Interrupted(sig));
        }
        let state = plan.own();
        let matrices = self.camera(state).map(|c| camera_matrices(&c));
        // Each camera sample is its lens rays when the scene has a `focus` record.
        let lens = whitted::render::rays_per_sample(&state.scene);
        let count = n * n * plan.times().len() as u32 * lens;
        let layers = finish(&sums, count, w, h, passes, &state.scene, matrices);
        self.tell(frame, || layers.to_frame());
        Ok((layers, rays))
    }

    /// The 8-bit picture of the plan's frame as its files hold it: `render`, or for a
    /// layered format (EXR) its beauty through the clamp-and-round of SPEC §2 (what a
    /// preview or a video shows of an EXR frame).
    pub fn render_picture(&self, plan: &FramePlan) -> Result<(Frame, RayCount), AnimError> {
        if self.format().is_layered() {
            let (layers, rays) = self.render_layers(plan, PassSet::NONE)?;
            return Ok((layers.to_frame(), rays));
        }
        self.render(plan)
    }
}
