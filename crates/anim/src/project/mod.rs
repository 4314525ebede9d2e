//! One loader for everything a manifest names (`Project`: the manifest, its scene and the
//! timeline built from both), and `Animation`, which draws any frame of a project from
//! the frame's plan (`plan`: its states, digest and path, built once): the tracer run on
//! the scene of frame t with the camera of frame t, or, with motion blur, the mean of the
//! sub-frames at the frame's sample times (`draw`).
//!
//! A timeline whose tracks leave geometry alone (colours, lights, fog, coefficients other
//! than Kt) shares one acceleration structure, built once, across all frames; otherwise
//! each sample builds its own from its scene.

mod digest;
mod draw;
mod plan;
mod settings;
pub(crate) use digest::hex;
pub use plan::{FramePlan, Samples};
pub use settings::Settings;

use super::error::AnimError;
use super::manifest::Manifest;
use super::timeline::{Field, Snapshot, Timeline};
use std::path::{Path, PathBuf};
use std::sync::{Arc, OnceLock};
use whitted::accel::Accel;
use whitted::base::Frame;
use whitted::camera::{Camera, Lens, NonSquare, VIEW_HEIGHT, VIEW_WIDTH};
use whitted::limits::size_ok;
use whitted::output::ImageFormat;
use whitted::render::Adaptive;
use whitted::scene::{Scene, SceneError};

/// Bumped whenever an intended change of the library moves pixels: frames recorded under
/// another version are stale (SPEC §8).
pub const PIXEL_VERSION: u32 = 1;

pub use cost::FRAME_MEMORY;

/// A manifest with its scene and timeline.
pub struct Project {
    /// The validated manifest.
    pub manifest: Manifest,
    /// The base scene and everything that changes over time.
    pub timeline: Timeline,
    /// The acceleration structure of the base scene's objects, built at the first
    /// `Animation` that shares one and kept for every later one (a view's requests).
    accel: OnceLock<Arc<Accel>>,
}

impl Project {
    /// The frames' size: the manifest's `[render]` width and height, else the scene's.
    pub fn size(&self) -> (u32, u32) {
        let (r, scene) = (&self.manifest.render, &self.timeline.base);
        (
            r.width.unwrap_or(scene.width),
            r.height.unwrap_or(scene.height),
        )
    }

    /// Loads a manifest, the scene it names and their timeline. A scene file that cannot
    /// be read is reported at the manifest's `scene =` line.
    pub fn load(path: &Path) -> Result<Project, AnimError> {
        let manifest = Manifest::load(path)?;
        let scene = Scene::load(&manifest.scene).map_err(|e| match e {
            SceneError::Io { path, source } => AnimError::SceneFile {
                loc: manifest.scene_loc.clone(),
                path,
                source,
            },
            other => AnimError::Scene(other),
        })?;
        // `[camera] name`: the glTF scene seen through that camera.
        let scene = match &manifest.camera_name {
            Some(name) => scene.through_camera(name).map_err(|message| {
                AnimError::Manifest(crate::refusal::ManifestError::Invalid {
                    loc: manifest.camera_loc.clone(),
                    message: format!("[camera] name: {message}"),
                })
            })?,
            None => scene,
        };
        let timeline = Timeline::new(scene, &manifest)?;
        Ok(Project {
            manifest,
            timeline,
            accel: OnceLock::new(),
        })
    }

    /// The acceleration structure every frame shares, when no track moves geometry:
    /// built once per project, whatever the number of animations drawn from it.
    fn shared_accel(&self) -> Option<Arc<Accel>> {
        let base = &self.timeline.base;
        (!self.timeline.moves_geometry())
            .then(|| Arc::clone(self.accel.get_or_init(|| Arc::new(Accel::for_scene(base)))))
    }
}

/// A project ready to draw any of its frames at a size.
pub struct Animation<'p> {
    /// The project's manifest.
    pub manifest: &'p Manifest,
    /// The project's timeline.
    pub timeline: &'p Timeline,
    /// The frames' width in pixels (the manifest's, the scene's, or a preview's).
    pub width: u32,
    /// The frames' height in pixels.
    pub height: u32,
    /// n of the n×n supersampling grid.
    pub samples: u32,
    /// Adaptive anti-aliasing instead of the grid, when the manifest asks for it.
    pub antialias: Option<Adaptive>,
    /// The acceleration structure every frame shares, when no track moves geometry.
    shared: Option<Arc<Accel>>,
    /// Told of every frame drawn (a live display such as tev), if any.
    observer: Option<FrameObserver>,
}

/// A callback told of each frame as it is drawn: its number and pixels.
pub type FrameObserver = Arc<dyn Fn(u32, &Frame) + Send + Sync>;

impl<'p> Animation<'p> {
    /// The project at the manifest's size (`[render]` overrides, else the scene's).
    pub fn new(project: &'p Project) -> Result<Animation<'p>, AnimError> {
        let (width, height) = project.size();
        Animation::with_size(project, width, height)
    }

    /// The project at `width`×`height` (a preview's smaller size, say).
    pub fn with_size(
        project: &'p Project,
        width: u32,
        height: u32,
    ) -> Result<Animation<'p>, AnimError> {
        if !size_ok(u64::from(width), u64::from(height)) {
            return Err(AnimError::Size {
                manifest: project.manifest.path.clone(),
                width,
                height,
            });
        }
        if let Some(aa) = &project.manifest.render.antialias {
            aa.fits(width, height)
                .map_err(|source| AnimError::Antialias {
                    manifest: project.manifest.path.clone(),
                    source,
                })?;
        }
        let shared = project.shared_accel();
        Ok(Animation {
            manifest: &project.manifest,
            timeline: &project.timeline,
            width,
            height,
            samples: project.manifest.render.samples.max(1),
            antialias: project.manifest.render.antialias,
            shared,
            observer: None,
        })
    }

    /// This animation, telling `observer` of every frame it draws (`--display tev`).
    pub fn observed(mut self, observer: FrameObserver) -> Animation<'p> {
        self.observer = Some(observer);
        self
    }

    /// The framing of a frame's scene: the manifest's `fov` and `roll` over the scene's
    /// own lens (an NFF view's angle and up, the report's for a Scene.txt, a `camera fov`
    /// track's value).
    pub(crate) fn lens_of(&self, scene: &Scene) -> Lens {
        let own = &self.manifest.lens;
        scene.lens.overridden(own.fov, own.roll)
    }

    /// The framing of the first frame (every frame's but with a `camera fov` track).
    fn lens(&self) -> Lens {
        let tracked = (self.timeline.tracks.iter()).any(|t| t.target.field == Field::CameraFov);
        match tracked {
            true => self.lens_of(&self.timeline.at(0.0).scene),
            false => self.lens_of(&self.timeline.base),
        }
    }

    /// The camera of a frame state, `None` when the eye is on the point it looks at.
    pub(crate) fn camera(&self, state: &Snapshot) -> Option<Camera> {
        let native = (self.timeline.base.width, self.timeline.base.height);
        let size = (self.width, self.height);
        Camera::framed(
            state.eye,
            state.look_at,
            native,
            size,
            &self.lens_of(&state.scene),
        )
    }

    /// The warnings of the scene's mesh files (what each holds and the tracer does not
    /// use, a material or image it cannot read), one line per kind, as `raytrace` prints
    /// them.
    pub fn mesh_warnings(&self) -> Vec<String> {
        let meshes = self.timeline.base.meshes.iter();
        meshes.flat_map(|m| m.warnings.iter().cloned()).collect()
    }

    /// The warning for frames whose pixels are not square (the report's view plane at
    /// a resolution of another shape, without `[camera] fov`).
    pub fn non_square(&self) -> Option<NonSquare> {
        let native = (self.timeline.base.width, self.timeline.base.height);
        NonSquare::check(&self.lens(), native, (self.width, self.height))
    }

    /// The view plane (width, height) and roll when they are not the report's 0.5 × 0.35
    /// unrolled plane (a size of another shape than the scene's, a `fov`, a `roll`).
    pub fn view(&self) -> Option<[f64; 3]> {
        let lens = &self.lens();
        let native = (self.timeline.base.width, self.timeline.base.height);
        let (w, h) = lens.plane(native, (self.width, self.height));
        let report = (w, h) == (VIEW_WIDTH, VIEW_HEIGHT) && lens.roll == 0.0;
        (!report).then_some([w, h, lens.roll])
    }

    /// Frame `frame`'s camera sits on the point it looks at: located at the object the
    /// camera follows, or the manifest's `[camera]` table.
    pub(crate) fn camera_error(&self, frame: u32) -> AnimError {
        let loc = match &self.manifest.look_at {
            Some(crate::timeline::LookAt::Object { loc, .. }) => loc.clone(),
            _ => self.manifest.camera_loc.clone(),
        };
        AnimError::Camera { frame, loc }
    }

    /// Refuses, before anything renders, a frame whose camera (at any of its sample
    /// times) sits on the point it looks at.
    pub fn check_cameras(&self, frames: &[u32]) -> Result<(), AnimError> {
        for &frame in frames {
            let plan = self.plan(frame);
            if plan.samples().any(|s| self.camera(&s).is_none()) {
                return Err(self.camera_error(frame));
            }
        }
        Ok(())
    }

    /// The image format of the frame files.
    pub fn format(&self) -> ImageFormat {
        self.manifest.output.format
    }

    /// Every setting besides scene and camera that decides the frames' bytes.
    pub fn settings(&self) -> Settings {
        Settings {
            width: self.width,
            height: self.height,
            samples: self.samples,
            motion_blur: self.timeline.blur,
            antialias: self.antialias,
            format: self.format(),
            pixel_version: PIXEL_VERSION,
            view: self.view(),
        }
    }

    /// The final path of frame `frame` inside `dir` (`OutputSpec::path`).
    pub fn frame_path(&self, dir: &Path, frame: u32) -> PathBuf {
        self.manifest.output.path(dir, frame, self.manifest.frames)
    }
}

mod cost;
mod display;
pub mod draft;
#[cfg(test)]
mod tests;
