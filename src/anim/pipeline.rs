//! Rendering a frame sequence: one `Animation` per manifest (the scene parsed and its
//! `Tracer` built once, shared by every frame), frames rendered in parallel with rayon,
//! then either written into a folder or streamed in frame order.
//!
//! - Folder: frames render in windows of four per thread; each is encoded and written to
//!   a temporary name in the folder, then renamed, so a file under a final name is always
//!   complete; `resume` skips frames whose file exists.
//! - Stream (`--stdout`, `--video`): frames render in windows of twice the thread count
//!   and are written in order.
//!
//! A window never holds more than `FRAME_MEMORY` of frames, so memory stays bounded whatever
//! the frame count, the frame size or the thread count.
//!
//! Both stop between frames when `stop` holds a signal number, and after the first
//! failure; the frames already finished stay finished.

use super::error::AnimError;
use super::manifest::{FrameFormat, Manifest};
use super::record::Record;
use crate::camera::Camera;
use crate::output::{encode, write_atomic, ImageFormat};
use crate::render::{render, Frame};
use crate::scene::{Scene, MAX_PIXELS};
use crate::trace::{RayCount, Tracer};
use indicatif::ProgressBar;
use rayon::prelude::*;
use std::io::Write;
use std::path::Path;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;

/// A manifest with its scene loaded, and the scene file's bytes (for the record).
pub struct Project {
    pub manifest: Manifest,
    pub scene: Scene,
    pub scene_bytes: Vec<u8>,
}

impl Project {
    /// Loads a manifest and the scene it names.
    pub fn load(path: &Path) -> Result<Project, AnimError> {
        let manifest = Manifest::load(path)?;
        let (scene, scene_bytes) = Scene::load_with_bytes(&manifest.scene)?;
        Ok(Project {
            manifest,
            scene,
            scene_bytes,
        })
    }

    /// The record a frame folder of this project keeps.
    pub fn record(&self, anim: &Animation) -> Record {
        let m = &self.manifest;
        Record::new(&m.path, &m.scene, &self.scene_bytes, &anim.settings())
    }
}

/// The memory frames in flight may take (pixels and their encoded copy): 1 GiB.
pub const FRAME_MEMORY: usize = 1 << 30;

/// A manifest bound to its scene: everything needed to draw any of its frames.
pub struct Animation<'a> {
    pub manifest: &'a Manifest,
    tracer: Tracer<'a>,
    pub width: u32,
    pub height: u32,
    pub samples: u32,
}

/// What a run did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Summary {
    pub rendered: usize,
    pub skipped: usize,
    pub rays: RayCount,
}

impl<'a> Animation<'a> {
    /// Binds `manifest` to `scene`, applying `[render]` overrides.
    pub fn new(manifest: &'a Manifest, scene: &'a Scene) -> Result<Animation<'a>, AnimError> {
        let width = manifest.render.width.unwrap_or(scene.width);
        let height = manifest.render.height.unwrap_or(scene.height);
        if width as u64 * height as u64 > MAX_PIXELS {
            return Err(AnimError::Usage(format!(
                "{}: {width}×{height} frames are past the limit of {MAX_PIXELS} pixels",
                manifest.path.display()
            )));
        }
        Ok(Animation {
            manifest,
            tracer: Tracer::new(scene),
            width,
            height,
            samples: manifest.render.samples.max(1),
        })
    }

    /// The camera of frame `frame`.
    pub fn camera(&self, frame: u32) -> Result<Camera, AnimError> {
        let scene = self.tracer.scene();
        let (eye, look_at) = self
            .manifest
            .camera
            .at(frame, self.manifest.frames, scene.look_at);
        Camera::new(eye, look_at, self.width, self.height).ok_or(AnimError::Camera { frame })
    }

    /// Draws frame `frame`: exactly what `raytrace` draws of the scene with that camera.
    pub fn render(&self, frame: u32) -> Result<(Frame, RayCount), AnimError> {
        let camera = self.camera(frame)?;
        Ok(render(
            &self.tracer,
            &camera,
            self.width,
            self.height,
            self.samples,
        ))
    }

    /// The image format of the frame files.
    pub fn format(&self) -> ImageFormat {
        let out = &self.manifest.output;
        match out.format {
            FrameFormat::Png => ImageFormat::Png,
            FrameFormat::Jpeg => ImageFormat::Jpeg {
                quality: out.jpeg_quality,
            },
            FrameFormat::Ppm => ImageFormat::Ppm,
            FrameFormat::Raw => ImageFormat::Raw,
        }
    }

    /// A canonical text of every setting that decides the frames' bytes (for the record).
    pub fn settings(&self) -> String {
        format!(
            "frames={} size={}x{} samples={} format={:?} camera={:?}",
            self.manifest.frames,
            self.width,
            self.height,
            self.samples,
            self.format(),
            self.manifest.camera
        )
    }

    /// How many frames may be in flight at once: `per_thread` per worker thread, but no
    /// more than fit in `FRAME_MEMORY` (at least one), whatever `--threads` says.
    pub fn window(&self, per_thread: usize) -> usize {
        let frame_bytes = (self.width as usize * self.height as usize * 3).max(1);
        let fit = (FRAME_MEMORY / (2 * frame_bytes)).max(1);
        (per_thread * rayon::current_num_threads().max(1)).min(fit)
    }

    /// The final path of frame `frame` inside `dir`.
    pub fn frame_path(&self, dir: &Path, frame: u32) -> std::path::PathBuf {
        dir.join(self.manifest.output.file_name(frame, self.manifest.frames))
    }
}

/// The signal number held in `stop`, if any.
fn stopped(stop: &AtomicUsize) -> Option<i32> {
    match stop.load(Ordering::SeqCst) {
        0 => None,
        sig => Some(sig as i32),
    }
}

/// Renders `frames` into `dir` (created if missing), in parallel. With `resume`, frames
/// whose file exists are skipped and counted as done on `progress`.
pub fn render_to_folder(
    anim: &Animation,
    frames: &[u32],
    dir: &Path,
    resume: bool,
    progress: &ProgressBar,
    stop: &AtomicUsize,
) -> Result<Summary, AnimError> {
    let todo: Vec<u32> = frames
        .iter()
        .copied()
        .filter(|&f| !(resume && anim.frame_path(dir, f).exists()))
        .collect();
    let skipped = frames.len() - todo.len();
    progress.set_position(skipped as u64);
    progress.reset_eta();

    let format = anim.format();
    let failure: Mutex<Option<AnimError>> = Mutex::new(None);
    let failed = || failure.lock().map(|f| f.is_some()).unwrap_or(true);
    // One frame: rendered, encoded and written on its worker; the first failure is kept.
    let work = |frame: u32| -> RayCount {
        if stopped(stop).is_some() || failed() {
            return RayCount::default();
        }
        let result = anim.render(frame).and_then(|(image, rays)| {
            write_atomic(&anim.frame_path(dir, frame), &image, format)
                .map_err(|source| AnimError::Write { frame, source })?;
            Ok(rays)
        });
        match result {
            Ok(rays) => {
                progress.inc(1);
                rays
            }
            Err(e) => {
                if let Ok(mut slot) = failure.lock() {
                    slot.get_or_insert(e);
                }
                RayCount::default()
            }
        }
    };
    let rays = todo
        .chunks(anim.window(4))
        .map(|chunk| {
            let sum = |a, b| a + b;
            chunk
                .par_iter()
                .map(|&f| work(f))
                .reduce(RayCount::default, sum)
        })
        .fold(RayCount::default(), |a, b| a + b);

    if let Some(e) = failure.into_inner().unwrap_or(None) {
        return Err(e);
    }
    if let Some(sig) = stopped(stop) {
        return Err(AnimError::Interrupted(sig));
    }
    Ok(Summary {
        rendered: todo.len(),
        skipped,
        rays,
    })
}

/// Renders `frames` and writes them, encoded in `format`, one after another in frame order
/// into `out`. Frames render in parallel windows; memory is bounded by the window.
pub fn render_to_stream(
    anim: &Animation,
    frames: &[u32],
    out: &mut dyn Write,
    format: ImageFormat,
    progress: &ProgressBar,
    stop: &AtomicUsize,
) -> Result<Summary, AnimError> {
    let window = anim.window(2);
    let mut rays = RayCount::default();
    for chunk in frames.chunks(window) {
        if let Some(sig) = stopped(stop) {
            return Err(AnimError::Interrupted(sig));
        }
        let encoded: Vec<Result<(Vec<u8>, RayCount), AnimError>> = chunk
            .par_iter()
            .map(|&frame| {
                let (image, rays) = anim.render(frame)?;
                let mut bytes = Vec::with_capacity(image.pixels.len() + 32);
                encode(&image, format, &mut bytes)
                    .map_err(|source| AnimError::Write { frame, source })?;
                Ok((bytes, rays))
            })
            .collect();
        for item in encoded {
            let (bytes, r) = item?;
            out.write_all(&bytes).map_err(AnimError::Stream)?;
            rays = rays + r;
            progress.inc(1);
        }
    }
    out.flush().map_err(AnimError::Stream)?;
    Ok(Summary {
        rendered: frames.len(),
        skipped: 0,
        rays,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::Path;

    fn window_for(width: u32, height: u32, threads: usize, per_thread: usize) -> usize {
        let scene = Scene::parse(
            &format!("{width} {height} 0 0 5 0 0 0 0 1 0 0 0 0"),
            "s.txt",
        )
        .unwrap();
        let manifest = Manifest::parse(
            "scene = \"s.txt\"\nframes = 10\n[camera]\npath = \"circle\"\n\
             center = [0.0, 0.0, 0.0]\nradius = 5.0\nheight = 1.0\n",
            Path::new("m.toml"),
        )
        .unwrap();
        let anim = Animation::new(&manifest, &scene).unwrap();
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        pool.install(|| anim.window(per_thread))
    }

    #[test]
    fn window_is_per_thread_for_small_frames() {
        assert_eq!(window_for(640, 480, 2, 4), 8);
        assert_eq!(window_for(640, 480, 3, 2), 6);
    }

    #[test]
    fn window_is_capped_by_memory_for_huge_frames() {
        // The largest frame, 2^26 pixels: 192 MiB, twice with its encoded copy, so two fit
        // in 1 GiB however many threads there are.
        assert_eq!(window_for(16384, 4096, 64, 4), 2);
        assert_eq!(window_for(8192, 8192, 64, 2), 2);
        assert_eq!(window_for(8192, 8192, 1, 1), 1);
    }
}
