//! The animation manifest of SPEC §5. `Manifest::parse` and `Manifest::load` read the
//! TOML (`raw`), check every value, resolve paths against the manifest's own folder and
//! build the camera (`camera`) and the tracks (`tracks`). Every refusal, syntax or meaning, is a
//! `ManifestError::Invalid` rendered `path:line:column: message` at the offending key or
//! value; unknown keys and tables are found first (`schema`), all of them in one
//! `ManifestError::Unknown`, each located with the nearest known name suggested. The user's
//! reference is docs/manifest.md. Never panics.
//!
//! ```toml
//! scene = "../scenes/orbit.txt"    # required, relative to the manifest's folder
//! frames = 250                     # required, 1..=1000000
//! fps = 25                         # 0.01 to 1000; default 25
//! loop = false                     # true: the end leads into the start (see `timeline`)
//!
//! [camera]                         # optional: path = "circle" | "spline" (see `camera`)
//! path = "circle"                  #   no path (or no [camera]): the scene's eye holds still
//! center = [0.0, 1.0, 0.0]
//! radius = 12.0
//! height = 3.0
//! look_at = "sphere 2"             # optional: a point [x, y, z] or an object to follow
//! fov = 30.0                       # optional: vertical field of view, degrees, 0 < fov < 180
//! roll = 0.0                       # optional: degrees, positive banks the camera right
//!
//! [[track]]                        # any number; see `tracks`
//! target = "light 1 intensity"
//! keys = [{ frame = 0, value = 0.2 }, { frame = 249, value = 1.0 }]
//!
//! [output]                         # optional
//! dir = "../out/orbit"             # default: the manifest's name without .toml + "-frames"
//! name = "frame_####"              # default; #### = zero-padded frame number; no / or \
//! format = "png"                   # png | jpeg (or jpg) | ppm | raw; default png
//! jpeg_quality = 90                # 1..=100; default 90
//!
//! [render]                         # optional overrides of the scene file
//! width = 1280                     # 1..=16384, and width·height <= 2^26 when both given
//! height = 960
//! samples = 2                      # n×n per pixel, 1..=16; default 1
//! motion_blur = { shutter = 0.5, samples = 8 }   # optional; shutter in (0, 1] frames
//!
//! [check]                          # optional; frames and references required
//! frames = [0, 62, 125, 187, 249]  # each < frames, no repeats
//! references = "../tests/golden/orbit"
//! fail = 2                         # 0..=255; default 2
//! fail_percent = 0.1               # 0..=100; default 0.1
//! hard_fail = 64                   # 0..=255; default 64
//! flip = 0.05                      # optional: also fail when the mean FLIP error is above
//! ```

mod antialias;
mod camera;
mod gltf;
mod locate;
mod pattern;
mod raw;
mod schema;
mod sections;
mod source;
mod tracks;
mod when;

use source::{CameraParts, Source};

pub use crate::refusal::ManifestError;
pub use crate::timeline::LookAt;

use crate::timeline::{CameraPath, MotionBlur, Sequence, TrackSpec};
use raw::{Probe, RawCircle, RawManifest, RawSpline, RawStill};
use std::path::{Path, PathBuf};
use whitted::camera::Lens;
use whitted::fileloc::FileLoc;
use whitted::output::ImageFormat;

/// `fps` when not given.
pub const DEFAULT_FPS: f64 = 25.0;

/// `[output]`, paths resolved.
#[derive(Clone, Debug, PartialEq)]
pub struct OutputSpec {
    /// The frame folder, resolved against the manifest's folder.
    pub dir: PathBuf,
    /// The name pattern, `####` standing for the zero-padded frame number.
    pub name: String,
    /// The frame files' format (JPEG with its quality).
    pub format: ImageFormat,
}

impl OutputSpec {
    /// The file name (no folder) of frame `frame` of a `frames`-frame sequence, with the
    /// format's extension. The first run of `#` becomes the frame number, zero-padded to
    /// the run's length or to the digits of `frames - 1` if more, so that names sort;
    /// without a `#` the name gets `_` and the number padded to at least 4 digits.
    pub fn file_name(&self, frame: u32, frames: u32) -> String {
        format!("{}.{}", self.stem(frame, frames), self.format.extension())
    }

    /// Where frame `frame` of a `frames`-frame sequence goes in `dir`: its `file_name`
    /// there. Every frame's path is made here (a run's, its hooks', `status`'s).
    pub fn path(&self, dir: &Path, frame: u32, frames: u32) -> PathBuf {
        self.path_as(dir, frame, frames, self.format.extension())
    }

    /// `path` with another extension (a check's references: `.png`, or `.exr`).
    pub fn path_as(&self, dir: &Path, frame: u32, frames: u32, ext: &str) -> PathBuf {
        dir.join(format!("{}.{ext}", self.stem(frame, frames)))
    }

    /// `file_name` without the extension.
    pub fn stem(&self, frame: u32, frames: u32) -> String {
        let needed = frames.saturating_sub(1).to_string().len();
        let (head, fewest, tail) = self.parts();
        let width = fewest.max(needed);
        format!("{head}{frame:0width$}{tail}")
    }

    /// The name pattern cut around its frame number: the text before it, the fewest
    /// digits it takes, the text after (`f_###x` → `f_`, 3, `x`; `frame` → `frame_`, 4, ``).
    pub fn parts(&self) -> (String, usize, &str) {
        let name = &self.name;
        match name.find('#') {
            Some(start) => {
                let run = name[start..].bytes().take_while(|&b| b == b'#').count();
                (name[..start].to_string(), run, &name[start + run..])
            }
            None => (format!("{name}_"), 4, ""),
        }
    }
}

/// `[render]`: optional overrides of the scene file, and motion blur.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct RenderSpec {
    /// The frames' width in pixels instead of the scene's, 1 to `MAX_SIDE`.
    pub width: Option<u32>,
    /// The frames' height in pixels instead of the scene's, 1 to `MAX_SIDE`.
    pub height: Option<u32>,
    /// n for an n×n grid per pixel; 1 when not given.
    pub samples: u32,
    /// Sub-frames averaged over the shutter, when `[render] motion_blur` is set.
    pub motion_blur: Option<MotionBlur>,
    /// Adaptive anti-aliasing instead of the grid, when `antialias` is set (SPEC §15).
    pub antialias: Option<whitted::render::Adaptive>,
}

/// `[check]`, paths resolved.
#[derive(Clone, Debug, PartialEq)]
pub struct CheckSpec {
    /// The frames `animate check` compares, ascending, without repeats.
    pub frames: Vec<u32>,
    /// The folder of reference PNGs, resolved against the manifest's folder.
    pub references: PathBuf,
    /// A pixel fails when a channel differs by more than this, 0..255.
    pub fail: u8,
    /// A frame fails when more than this percentage of pixels fail, 0..100.
    pub fail_percent: f64,
    /// A frame fails when any channel differs by more than this, 0..255.
    pub hard_fail: u8,
    /// The FLIP limit, when the manifest sets one.
    pub flip: Option<f64>,
}

/// A parsed and validated manifest.
#[derive(Clone, Debug, PartialEq)]
pub struct Manifest {
    /// The manifest file itself.
    pub path: PathBuf,
    /// The base scene, resolved against the manifest's folder.
    pub scene: PathBuf,
    /// Where `scene = ...` is written, for errors about the scene file.
    pub scene_loc: FileLoc,
    /// Where `[camera]` is written (the manifest's start without one), for errors about
    /// the camera found when frames are drawn.
    pub camera_loc: FileLoc,
    /// The number of frames of the sequence, 1 to `MAX_FRAMES`; frames are numbered from 0.
    pub frames: u32,
    /// Frames per second, > 0: the time base of the camera and the video.
    pub fps: f64,
    /// `loop = true`: the end leads into the start with no doubled frame (frame `frames`
    /// would be frame 0): a spline camera path is closed, tracks run back to their first
    /// key, a circle makes whole turns.
    pub looped: bool,
    /// The camera path; `None` keeps the scene file's eye.
    pub camera: Option<CameraPath>,
    /// An object the camera follows (`look_at = "sphere 2"`), or, without a path, a
    /// fixed point.
    pub look_at: Option<LookAt>,
    /// `[camera] fov` and `roll`: the framing of every frame (the report's by default).
    pub lens: Lens,
    /// The `[[track]]` tables, in file order.
    pub tracks: Vec<TrackSpec>,
    /// `[output]`: where and how frames are written.
    pub output: OutputSpec,
    /// `[render]`: size overrides, supersampling, motion blur.
    pub render: RenderSpec,
    /// `[check]`, when the manifest has one.
    pub check: Option<CheckSpec>,
    /// What a draft's command-line overrides changed (`project::draft`), `None` for the
    /// manifest as written: recorded in each frame, so a draft is told from a final.
    pub draft: Option<String>,
    /// `[animation] name`: the glTF animations that play (every one without it), and
    /// where the table is.
    pub animation: Option<(Vec<String>, FileLoc)>,
    /// `[camera] name`: the glTF scene's camera to look through.
    pub camera_name: Option<String>,
}

impl Manifest {
    /// Reads and validates the manifest at `path`; relative paths inside it are resolved
    /// against its folder.
    pub fn load(path: &Path) -> Result<Manifest, ManifestError> {
        let resolved = through_descriptor(path);
        let path = resolved.as_deref().unwrap_or(path);
        let limit = whitted::limits::MAX_MANIFEST_BYTES;
        let read = whitted::input::read_regular(path, limit, "manifest");
        let bytes = read.map_err(|source| ManifestError::Io {
            path: path.display().to_string(),
            source,
        })?;
        // Not UTF-8: say where the first byte that cannot be read is, as for scenes.
        let src = std::str::from_utf8(&bytes).map_err(|e| {
            let good = std::str::from_utf8(&bytes[..e.valid_up_to()]).unwrap_or_default();
            let message = "the manifest is not UTF-8 text: this byte cannot be read";
            let fps = DEFAULT_FPS;
            Source {
                text: good,
                path,
                fps,
            }
            .error(good.len()..good.len(), message)
        })?;
        Manifest::parse(src, path)
    }

    /// Parses manifest text; `path` is where it came from (for errors and relative paths).
    pub fn parse(src: &str, path: &Path) -> Result<Manifest, ManifestError> {
        let mut source = Source {
            text: src,
            path,
            fps: DEFAULT_FPS,
        };
        let unknown = schema::unknown_keys(src);
        if !unknown.is_empty() {
            let found = unknown
                .into_iter()
                .map(|(span, message)| (source.loc(span), message))
                .collect();
            return Err(ManifestError::Unknown(found));
        }
        let probe: Probe = source.deserialize()?;
        source.fps = match &probe.fps {
            Some(toml::Value::Float(f)) => *f,
            Some(toml::Value::Integer(i)) => *i as f64,
            _ => DEFAULT_FPS,
        };
        let camera_loc = source.loc(probe.camera.as_ref().map_or(0..0, |c| c.span()));
        let kind = probe
            .camera
            .as_ref()
            .and_then(|c| c.get_ref().path.as_ref());
        let manifest = match kind.map(|k| (k.get_ref().as_str(), k.span())) {
            None => {
                let raw: RawManifest<RawStill> = source.deserialize()?;
                source.manifest(raw, |s, c, _| s.still(c))
            }
            Some(("circle", _)) => {
                let raw: RawManifest<RawCircle> = source.deserialize()?;
                source.manifest(raw, |s, c, _| s.circle(c))
            }
            Some(("spline", _)) => {
                let raw: RawManifest<RawSpline> = source.deserialize()?;
                source.manifest(raw, |s, c, frames| s.spline(c, frames))
            }
            Some((other, span)) => {
                let message = format!(
                    "unknown camera path `{other}`, expected `circle` or `spline` (or no path: the scene's camera holds still)"
                );
                Err(source.error(span, message))
            }
        };
        let camera_name = probe
            .camera
            .as_ref()
            .and_then(|c| c.get_ref().name.as_ref())
            .map(|n| n.get_ref().clone());
        manifest.map(|m| Manifest {
            camera_loc,
            camera_name,
            ..m
        })
    }
}

/// A manifest named through a descriptor link (`/dev/stdin`, `/dev/fd/N`, `/proc/…/fd/N`)
/// is the file the link leads to: its folder, not `/dev`, is where its scene and its
/// frames are found (`animate status /dev/stdin < shots/a.toml` is `shots/a.toml`'s
/// status). Other paths, symbolic links included, are taken as written.
fn through_descriptor(path: &Path) -> Option<std::path::PathBuf> {
    let under = |p: &str| path.starts_with(p);
    if !(under("/dev") || under("/proc")) {
        return None;
    }
    let real = std::fs::canonicalize(path).ok()?;
    let leaves = !(real.starts_with("/dev") || real.starts_with("/proc"));
    (leaves && real.is_file()).then_some(real)
}

#[cfg(test)]
mod descriptor_tests {
    #[test]
    fn a_descriptor_link_is_the_file_it_leads_to() {
        let dir = tempfile::tempdir().unwrap();
        let file = dir.path().join("a.toml");
        std::fs::write(&file, "").unwrap();
        let opened = std::fs::File::open(&file).unwrap();
        // This process's own descriptor of the file, as /dev/stdin would be a shell's.
        let link = std::path::PathBuf::from("/proc/self/fd").join(fd_of(&opened));
        let real = std::fs::canonicalize(&file).unwrap();
        assert_eq!(super::through_descriptor(&link), Some(real));
        assert_eq!(super::through_descriptor(&file), None);
        assert_eq!(
            super::through_descriptor(std::path::Path::new("/dev/null")),
            None
        );
    }

    /// The descriptor number of `file`, found by the link that leads to it.
    fn fd_of(file: &std::fs::File) -> String {
        let want = file.metadata().unwrap();
        for entry in std::fs::read_dir("/proc/self/fd").unwrap() {
            let entry = entry.unwrap();
            if let Ok(m) = std::fs::metadata(entry.path()) {
                use std::os::unix::fs::MetadataExt;
                if m.ino() == want.ino() && m.dev() == want.dev() {
                    return entry.file_name().to_string_lossy().into_owned();
                }
            }
        }
        panic!("no descriptor leads to the file");
    }
}

#[cfg(test)]
mod refusal_tests;
#[cfg(test)]
mod tests;

impl<'a> From<&'a Manifest> for Sequence<'a> {
    /// What the timeline binds to a scene: the frame count, camera, look-at, tracks and
    /// motion blur the manifest gives.
    fn from(m: &'a Manifest) -> Sequence<'a> {
        Sequence {
            frames: m.frames,
            camera: m.camera.as_ref(),
            look_at: m.look_at.as_ref(),
            tracks: &m.tracks,
            blur: m.render.motion_blur,
            looped: m.looped,
            fov: m.lens.fov,
            animation: m
                .animation
                .as_ref()
                .map(|(names, loc)| (names.as_slice(), loc)),
            fps: m.fps,
        }
    }
}
