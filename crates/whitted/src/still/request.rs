//! `raytrace`'s run as a library call: a `Request` (what the command line asked: the
//! scene, the image to write and how to draw it) is checked and its scene loaded by
//! `Job::prepare`, before any pixel is drawn; `Job::run` draws the picture (or its passes)
//! and writes it atomically, and returns what it cost (`Done`).
//!
//! ```text
//! let job = Job::prepare(&request)?;          // bad scene, bad OUT: StillError, nothing drawn
//! job.enormous()                              // the warning before a huge request
//! let done = pool.install(|| job.run())?;     // the image is written under OUT
//! eprintln!("raytrace: {}", done.summary());  // "wrote out.png (640×480, 1 sample(s)/px) in …"
//! ```

use super::{Still, STREAM_BAND};
use crate::base::{Frame, Transfer};
use crate::camera::{Lens, NonSquare};
use crate::display::{Display, Tev};
use crate::exit::Outcome;
use crate::output::{check_target, write_atomic, ExrDepth, ImageFormat, OutputError};
use crate::passes::{visible::picture, Pass, PassSet};
use crate::render::adaptive::AntialiasError;
use crate::render::estimate::{self, Enormous};
use crate::render::{Adaptive, Antialias, Layered, Picture};
use crate::scene::{Scene, SceneError};
use crate::trace::RayCount;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// What `raytrace` is asked to draw, as its command line says it.
#[derive(Clone, Debug, Default)]
pub struct Request {
    /// The Scene.txt to read.
    pub scene: PathBuf,
    /// The image to write; `None`: the scene's path with `.png`.
    pub out: Option<PathBuf>,
    /// The picture's size; `None`: the scene's own.
    pub size: Option<(u32, u32)>,
    /// The field of view and roll.
    pub lens: Lens,
    /// n of the n×n grid of samples a pixel.
    pub samples: u32,
    /// Adaptive anti-aliasing instead of the grid.
    pub aa: Option<Adaptive>,
    /// The passes an `.exr` carries.
    pub passes: Option<PassSet>,
    /// One pass drawn as the picture.
    pub pass: Option<Pass>,
    /// The EXR's float depth.
    pub exr_depth: Option<ExrDepth>,
    /// How the EXR stores colours (`srgb`: display values decoded to linear light).
    pub colour: Option<Transfer>,
    /// A live viewer the picture streams to while it is drawn.
    pub display: Option<Display>,
    /// The SPD's testing procedure (`--spd`): 512 × 512 from 513 × 513 corner rays.
    pub spd: bool,
    /// A glTF scene's camera, by name (`--camera`).
    pub camera: Option<String>,
}

/// Why `raytrace` drew nothing, or could not write what it drew.
#[derive(Debug, thiserror::Error)]
pub enum StillError {
    /// The scene file cannot be read or is not a valid scene.
    #[error(transparent)]
    Scene(#[from] SceneError),
    /// OUT cannot be used, or the image could not be written.
    #[error(transparent)]
    Output(#[from] OutputError),
    /// A TOML file was given where a Scene.txt was expected.
    #[error(
        "{0} looks like an animation manifest (TOML), not a Scene.txt: render it with `animate {0}` \
         (or one frame: `animate {0} --frames 0`)"
    )]
    NotAScene(String),
    /// Adaptive anti-aliasing asked for more than its bounds allow at this size.
    #[error(transparent)]
    Antialias(#[from] AntialiasError),
    /// The pass asked for has no picture (it was not recorded).
    #[error("the pass was not drawn")]
    PassNotDrawn,
}

impl StillError {
    /// The row of the exit-status table this error belongs to.
    pub fn outcome(&self) -> Outcome {
        match self {
            StillError::Scene(_) | StillError::NotAScene(_) | StillError::Antialias(_) => {
                Outcome::BadInput
            }
            StillError::Output(o) => o.outcome(),
            StillError::PassNotDrawn => Outcome::Failed,
        }
    }
}

/// A request whose scene is loaded and whose output is known to be usable.
pub struct Job {
    scene: Scene,
    native: (u32, u32),
    out: PathBuf,
    format: ImageFormat,
    request: Request,
}

/// What a finished run drew and cost.
#[derive(Clone, Debug)]
pub struct Done {
    /// The image written.
    pub out: PathBuf,
    /// Its size.
    pub size: (u32, u32),
    /// How it was sampled.
    pub aa: Antialias,
    /// The rays cast.
    pub rays: RayCount,
    /// Seconds spent drawing (not writing).
    pub seconds: f64,
}

/// The format of OUT with the EXR options, refusing options its format cannot carry.
fn out_format(request: &Request, out: &Path) -> Result<ImageFormat, OutputError> {
    let refuse = |reason: &str| OutputError::Target {
        path: out.to_path_buf(),
        reason: reason.into(),
    };
    let format = ImageFormat::from_path(out)?;
    if request.aa.is_some() && (format.is_layered() || request.pass.is_some()) {
        return Err(refuse(
            "--aa adaptive draws 8-bit pictures only; an .exr or a --pass takes --samples",
        ));
    }
    match format {
        ImageFormat::Exr(mut o) => {
            if request.pass.is_some() {
                return Err(refuse("--pass writes an 8-bit picture (.png, .jpg, .ppm, .raw); an .exr takes --passes"));
            }
            o.passes = request.passes.unwrap_or_default();
            o.depth = request.exr_depth.unwrap_or_default();
            o.colour = request.colour.unwrap_or_default();
            Ok(ImageFormat::Exr(o))
        }
        _ if request.colour.is_some() => Err(refuse("--colour needs an .exr image")),
        _ if request.passes.is_some() => Err(refuse("--passes needs an .exr image")),
        _ if request.exr_depth.is_some() => Err(refuse("--exr-depth needs an .exr image")),
        other => Ok(other),
    }
}

/// Whether two paths name one existing file.
fn same_file(a: &Path, b: &Path) -> bool {
    matches!((a.canonicalize(), b.canonicalize()), (Ok(x), Ok(y)) if x == y)
}

impl Job {
    /// Checks OUT and its options, loads the scene, and refuses an OUT that is the scene.
    pub fn prepare(request: &Request) -> Result<Job, StillError> {
        let out = (request.out.clone()).unwrap_or_else(|| request.scene.with_extension("png"));
        let format = out_format(request, &out)?;
        if request.scene.extension().is_some_and(|e| e == "toml") {
            return Err(StillError::NotAScene(request.scene.display().to_string()));
        }
        let mut scene = Scene::load(&request.scene)?;
        if let Some(name) = &request.camera {
            scene = scene.through_camera(name).map_err(|message| {
                StillError::Scene(SceneError::Syntax {
                    loc: crate::fileloc::FileLoc {
                        file: request.scene.display().to_string(),
                        line: 1,
                        column: 1,
                    },
                    message,
                    context: "--camera".into(),
                })
            })?;
        }
        check_target(&out)?;
        if same_file(&request.scene, &out) {
            let reason = "it is the scene file being read (name another image with -o)";
            let path = out;
            return Err(OutputError::Target {
                path,
                reason: reason.into(),
            }
            .into());
        }
        let native = (scene.width, scene.height);
        let spd_size = (crate::spd::SPD_SIZE, crate::spd::SPD_SIZE);
        let size = if request.spd {
            Some(spd_size)
        } else {
            request.size
        };
        (scene.width, scene.height) = size.unwrap_or(native);
        if let Some(adaptive) = &request.aa {
            adaptive.fits(scene.width, scene.height)?;
        }
        let request = request.clone();
        Ok(Job {
            scene,
            native,
            out,
            format,
            request,
        })
    }

    /// The picture's height in rows (what a progress bar counts).
    pub fn height(&self) -> u32 {
        self.scene.height
    }

    fn aa(&self) -> Antialias {
        (self.request.aa).map_or(Antialias::Grid(self.request.samples), Antialias::Adaptive)
    }

    /// The scene's own lens (an NFF's view angle) with the command line's overrides.
    fn lens(&self) -> Lens {
        let Lens { fov, roll, .. } = self.request.lens;
        self.scene.lens.overridden(fov, roll)
    }

    fn still(&self) -> Still<'_> {
        let size = (self.scene.width, self.scene.height);
        let spd = self.request.spd;
        Still::new(&self.scene, self.native, size, &self.lens(), self.aa())
            .and_then(|s| if spd { s.spd() } else { Some(s) })
            .expect("the parser refuses an eye placed on its look-at point")
    }

    /// The warning for a picture whose pixels are not square (the report's view plane at
    /// a resolution of another shape), before anything is drawn.
    pub fn non_square(&self) -> Option<NonSquare> {
        let size = (self.scene.width, self.scene.height);
        NonSquare::check(&self.lens(), self.native, size)
    }

    /// The warning for a glTF camera whose `aspectRatio` is not the picture's shape.
    pub fn aspect_warning(&self) -> Option<String> {
        self.scene
            .aspect_warning((self.scene.width, self.scene.height))
    }

    /// The warnings of the scene's mesh files: what each holds and the tracer does not
    /// use, a material or image it cannot read (SPEC §18), one line per kind.
    pub fn mesh_warnings(&self) -> Vec<String> {
        let meshes = self.scene.meshes.iter();
        meshes.flat_map(|m| m.warnings.iter().cloned()).collect()
    }

    /// The warning before an enormous request (on the current thread pool).
    pub fn enormous(&self) -> Option<Enormous> {
        // Below the threshold the answer is arithmetic: the tracer, whose trees are the
        // costly part of making one, is built only to time a sample of a picture past it.
        let size = (self.scene.width, self.scene.height);
        let rays = super::camera_rays(&self.scene, size, self.aa());
        (rays > estimate::ENORMOUS).then(|| self.still().enormous())
    }

    /// Draws the picture on the current thread pool and writes it under OUT.
    pub fn run(&self) -> Result<Done, StillError> {
        let still = self.still();
        let start = Instant::now();
        let (frame, rays) = if self.format.is_layered() || self.request.pass.is_some() {
            let passes = (self.request.pass).map_or(self.format.passes(), |p| PassSet::of(&[p]));
            let (layers, rays) = still.render(Layered(passes));
            // A --pass is written as a picture below; an .exr is written here, whole.
            let frame = match self.request.pass {
                Some(p) => Some(picture(&layers, p).ok_or(StillError::PassNotDrawn)?),
                None => {
                    write_atomic(&self.out, layers, self.format, &[])?;
                    None
                }
            };
            (frame, rays)
        } else {
            let (frame, rays) = match &self.request.display {
                None => still.render(Picture::new()),
                Some(display) => self.shown(&still, display),
            };
            (Some(frame), rays)
        };
        let seconds = start.elapsed().as_secs_f64();
        if let Some(frame) = &frame {
            write_atomic(&self.out, frame, self.format, &[])?;
        }
        let size = (self.scene.width, self.scene.height);
        let (out, aa) = (self.out.clone(), self.aa());
        Ok(Done {
            out,
            size,
            aa,
            rays,
            seconds,
        })
    }

    /// The picture, shown on `display` as image `raytrace: OUT` while it is drawn: a
    /// grid's rows in bands of `STREAM_BAND` as they finish, an adaptive picture whole
    /// once drawn (its corner lattice comes first). A missing viewer: one warning,
    /// `raytrace: warning: …`.
    fn shown(&self, still: &Still, display: &Display) -> (Frame, RayCount) {
        let Display::Tev(addr) = display;
        let tev = Tev::connect_stderr(addr, "raytrace");
        let name = format!("raytrace: {}", self.out.display());
        let w = still.width;
        tev.create(&name, w, still.height);
        let send = |y0: u32, rows: &[u8]| tev.rows(&name, w, y0, rows);
        still.render(Picture::observed(STREAM_BAND, &send))
    }
}

impl Done {
    /// The line `raytrace` prints: what was written, how it was sampled, and its speed.
    pub fn summary(&self) -> String {
        let (w, h) = self.size;
        let total = self.rays.total();
        let mrays = total as f64 / self.seconds.max(1e-9) / 1e6;
        let n = match self.aa {
            Antialias::Grid(n) => format!("{} sample(s)/px", n * n),
            Antialias::Adaptive(a) => format!(
                "adaptive {} depth {} {}, {:.3} camera rays/px",
                a.threshold,
                a.depth,
                a.measure.name(),
                self.rays.primary as f64 / (f64::from(w) * f64::from(h))
            ),
        };
        let (out, traced) = (self.out.display(), self.seconds);
        format!("wrote {out} ({w}×{h}, {n}) in {traced:.3} s: {total} rays, {mrays:.2} Mrays/s")
    }
}
