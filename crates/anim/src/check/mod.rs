//! `animate bless` and `animate check`: regression on selected frames.
//!
//! `bless` renders the chosen frames and writes them as lossless PNG references into the
//! references folder (atomically). `check` looks at every reference's header first (a
//! missing, unreadable or wrongly sized one stops the check before anything renders),
//! then renders the frames in parallel windows, reading each reference only when its
//! frame is compared (memory bounded by the window, as in rendering), compares each (`diff.rs`, and `flip.rs` when the tolerance has a
//! FLIP limit), and for every failing frame writes the rendered frame, a diff heat map and
//! the FLIP map into a report folder; stale report images of frames that now pass are
//! removed, so the folder shows failures only. The result is one [`CheckReport`]
//! (`report.rs`) that the exporters of `export/` turn into a table, JSON, JUnit XML or an
//! HTML page. References are named by the manifest's `[output] name` pattern with `.png`;
//! for EXR frames (`format = "exr"`) with `.exr`, holding the float beauty, which check
//! compares as floats (`diff::compare_float`); its report images are the beauty's
//! clamp-and-round.
//!
//! Options come from the manifest's `[check]` (frames, references, fail, fail_percent,
//! hard_fail, flip), each overridden by the caller's [`Overrides`].

pub mod diff;
pub mod export;
pub mod flip;
mod reference;
pub mod report;

pub use diff::{Comparison, Limit, Tolerance};
pub use reference::reference_path;
pub use report::{CheckReport, FrameReport};

use super::error::AnimError;
use super::manifest::Manifest;
use super::project::Animation;
use super::select::{parse_frames, SelectError};
use diff::{compare, heat_map};
use rayon::prelude::*;
use reference::{draw, load_reference, probe_reference, stem, Reference};
use std::path::{Path, PathBuf};
use std::time::Instant;
use whitted::base::Frame;
use whitted::output::{write_atomic, ImageFormat};

/// Why the options of a check cannot be settled. The messages name manifest keys, never
/// command-line flags: the binary says which flag to use.
#[derive(Debug, thiserror::Error)]
pub enum CheckError {
    /// The manifest has no `[check]` and the caller did not give the frames or the
    /// references folder either.
    #[error("{manifest}: no [check] section names the {what}")]
    NoCheckSection {
        /// The manifest's path.
        manifest: PathBuf,
        /// What is left unnamed.
        what: Missing,
    },
    /// The caller's frame list is bad.
    #[error(transparent)]
    Frames(#[from] SelectError),
    /// The caller's fail percentage is outside 0..=100 (the value given).
    #[error("fail_percent must be from 0 to 100, found {0}")]
    FailPercent(f64),
    /// The caller's FLIP limit is outside 0..=1 (the value given).
    #[error("the FLIP limit must be from 0 to 1, found {0}")]
    Flip(f64),
}

/// What a manifest without `[check]` leaves unnamed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Missing {
    /// Which frames to check.
    Frames,
    /// Where the reference images are.
    References,
}

impl std::fmt::Display for Missing {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Missing::Frames => "frames to check",
            Missing::References => "references folder",
        })
    }
}

/// The caller's choices, each replacing the manifest's `[check]` value when given.
#[derive(Clone, Debug, Default)]
pub struct Overrides<'a> {
    /// A frame list (`0-3,9`) instead of `[check] frames`.
    pub frames: Option<&'a str>,
    /// The references folder instead of `[check] references`.
    pub references: Option<&'a Path>,
    /// The folder for images of failing frames instead of the default (`default_report`).
    pub report: Option<&'a Path>,
    /// The per-pixel channel difference limit, 0..255.
    pub fail: Option<u8>,
    /// The percentage of failing pixels a frame may have, 0..100.
    pub fail_percent: Option<f64>,
    /// The channel difference no pixel may exceed, 0..255.
    pub hard_fail: Option<u8>,
    /// The mean FLIP error limit, 0..1.
    pub flip: Option<f64>,
}

/// A check's settled options.
#[derive(Clone, Debug, PartialEq)]
pub struct CheckOptions {
    /// The frames to check, ascending, without repeats.
    pub frames: Vec<u32>,
    /// The folder holding the reference PNGs.
    pub references: PathBuf,
    /// The folder for the images of failing frames.
    pub report: PathBuf,
    /// The limits a frame must stay within.
    pub tolerance: Tolerance,
}

impl CheckOptions {
    /// The manifest's `[check]` (or the SPEC's default thresholds without it) merged with
    /// `over`. Frames and references must come from one or the other.
    pub fn new(manifest: &Manifest, over: &Overrides) -> Result<CheckOptions, CheckError> {
        let (frames, references) = targets(manifest, over.frames, over.references)?;
        let check = manifest.check.as_ref();
        let base = check.map_or(Tolerance::DEFAULT, |c| Tolerance {
            fail: c.fail,
            fail_percent: c.fail_percent,
            hard_fail: c.hard_fail,
            flip: c.flip,
        });
        let tolerance = Tolerance {
            fail: over.fail.unwrap_or(base.fail),
            fail_percent: over.fail_percent.unwrap_or(base.fail_percent),
            hard_fail: over.hard_fail.unwrap_or(base.hard_fail),
            flip: over.flip.or(base.flip),
        };
        if !(0.0..=100.0).contains(&tolerance.fail_percent) {
            return Err(CheckError::FailPercent(tolerance.fail_percent));
        }
        if let Some(f) = tolerance.flip.filter(|f| !(0.0..=1.0).contains(f)) {
            return Err(CheckError::Flip(f));
        }
        let report = over
            .report
            .map_or_else(|| default_report(manifest), Path::to_path_buf);
        Ok(CheckOptions {
            frames,
            references,
            report,
            tolerance,
        })
    }
}

/// The frames and the references folder of a check or bless: the caller's when given,
/// else the manifest's `[check]`.
pub fn targets(
    manifest: &Manifest,
    frames: Option<&str>,
    references: Option<&Path>,
) -> Result<(Vec<u32>, PathBuf), CheckError> {
    let missing = |what| CheckError::NoCheckSection {
        manifest: manifest.path.clone(),
        what,
    };
    let check = manifest.check.as_ref();
    let frames = match (frames, check) {
        (Some(spec), _) => parse_frames(spec, manifest.frames)?,
        (None, Some(c)) => c.frames.clone(),
        (None, None) => return Err(missing(Missing::Frames)),
    };
    let refs = match (references, check) {
        (Some(dir), _) => dir.to_path_buf(),
        (None, Some(c)) => c.references.clone(),
        (None, None) => return Err(missing(Missing::References)),
    };
    Ok((frames, refs))
}

/// The default report folder: the frame folder's name + `-check`.
pub fn default_report(manifest: &Manifest) -> PathBuf {
    let mut name = manifest.output.dir.clone().into_os_string();
    name.push("-check");
    PathBuf::from(name)
}

fn create_dir(dir: &Path) -> Result<(), AnimError> {
    std::fs::create_dir_all(dir).map_err(|source| AnimError::Folder {
        dir: dir.to_path_buf(),
        source,
    })
}

/// A reference `bless` wrote: where, and what was there before.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Blessed {
    /// The reference file.
    pub path: PathBuf,
    /// A reference was there and was replaced.
    pub replaced: bool,
    /// The replaced reference had other bytes than the new one.
    pub changed: bool,
}

/// `3 new` or `2 replaced (1 changed), 1 new`: what a bless did, for its summary line.
pub fn bless_counts(blessed: &[Blessed]) -> String {
    let replaced = blessed.iter().filter(|b| b.replaced).count();
    let changed = blessed.iter().filter(|b| b.changed).count();
    let new = blessed.len() - replaced;
    let mut parts = Vec::new();
    if replaced > 0 {
        parts.push(format!("{replaced} replaced ({changed} changed)"));
    }
    if new > 0 || blessed.is_empty() {
        parts.push(format!("{new} new"));
    }
    parts.join(", ")
}

/// Renders `frames` and writes them as references into `refs`, each with its record (as a
/// frame's); says what each replaced. Holds the folder's lock (`frames::lock`) as a run
/// does, and refuses to replace a reference that another manifest recorded unless
/// `force` (references with no record, as older versions blessed them, are replaced).
pub fn bless(
    anim: &Animation,
    frames: &[u32],
    refs: &Path,
    force: bool,
) -> Result<Vec<Blessed>, AnimError> {
    create_dir(refs)?;
    let _lock = crate::frames::lock::lock(refs, &anim.manifest.path)?;
    let format = match anim.format().is_layered() {
        true => ImageFormat::Exr(Default::default()),
        false => ImageFormat::Png,
    };
    if !force {
        use crate::frames::owner::{owner_as, refusal, Owner};
        let others: Vec<(PathBuf, Owner)> = frames
            .iter()
            .map(|&f| reference_path(anim, refs, f))
            .map(|p| (owner_as(anim, &p, format), p))
            .filter(|(o, _)| matches!(o, Owner::Other(_)))
            .map(|(o, p)| (p, o))
            .collect();
        if let Some(refused) = refusal("replaced", &others) {
            return Err(refused);
        }
    }
    frames
        .par_iter()
        .map(|&frame| {
            let path = reference_path(anim, refs, frame);
            let plan = anim.plan(frame).recorded();
            let before = std::fs::read(&path).ok();
            let written = if anim.format().is_layered() {
                // The tracer's float beauty, losslessly and as it is (check compares
                // it bit for bit): EXR float, ZIP, `colour = "linear"`, no alpha.
                let (mut layers, _) = anim.render_layers(&plan, whitted::passes::PassSet::NONE)?;
                let record = crate::frames::provenance::stamp(&plan);
                layers.alpha = None;
                let exr = ImageFormat::Exr(whitted::output::ExrOptions {
                    depth: whitted::output::ExrDepth::Float,
                    colour: whitted::base::Transfer::Linear,
                    ..Default::default()
                });
                whitted::output::write_atomic(&path, layers, exr, &record)
            } else {
                let (image, _) = anim.render(&plan)?;
                let record = crate::frames::provenance::stamp(&plan);
                whitted::output::write_atomic(&path, &image, ImageFormat::Png, &record)
            };
            written.map_err(|source| AnimError::Write { frame, source })?;
            let changed = before
                .as_ref()
                .is_some_and(|b| std::fs::read(&path).ok().as_ref() != Some(b));
            Ok(Blessed {
                replaced: before.is_some(),
                changed,
                path,
            })
        })
        .collect()
}

/// Checks the frames of `opts` against their references, writing images of failing
/// frames into the report folder.
pub fn check(anim: &Animation, opts: &CheckOptions) -> Result<CheckReport, AnimError> {
    let refs = &opts.references;
    for &f in &opts.frames {
        probe_reference(anim, refs, f)?;
    }
    // Frame by frame in windows, like rendering: a reference is read only when its frame
    // is compared, so memory is bounded by the window whatever the number of frames.
    let mut frames = Vec::with_capacity(opts.frames.len());
    for window in opts.frames.chunks(anim.window(1)) {
        let reports = window
            .par_iter()
            .map(|&frame| {
                let reference = load_reference(anim, refs, frame)?;
                check_frame(anim, opts, frame, &reference)
            })
            .collect::<Result<Vec<FrameReport>, AnimError>>()?;
        frames.extend(reports);
    }
    Ok(CheckReport {
        manifest: anim.manifest.path.clone(),
        references: refs.clone(),
        report: opts.report.clone(),
        width: anim.width,
        height: anim.height,
        tolerance: opts.tolerance,
        pass: frames.iter().all(|f| f.pass),
        frames,
    })
}

fn check_frame(
    anim: &Animation,
    opts: &CheckOptions,
    frame: u32,
    (reference, ref_floats): &Reference,
) -> Result<FrameReport, AnimError> {
    let start = Instant::now();
    let (image, floats) = draw(&anim.plan(frame))?;
    let tol = opts.tolerance;
    let comparison = match (ref_floats, &floats) {
        (Some(a), Some(b)) => diff::compare_float(a, b, anim.width, tol),
        _ => compare(reference, &image, tol),
    };
    let flip = tol.flip.map(|_| flip::flip(reference, &image));
    let failed = tol.failed(&comparison, flip.as_ref().map(|f| f.mean));
    let name = stem(anim, frame);
    let path = |kind: &str| opts.report.join(format!("{name}.{kind}.png"));
    let (rendered_path, diff_path, flip_path) = (path("rendered"), path("diff"), path("flip"));
    let mut images = (None, None, None);
    if failed.is_empty() {
        for stale in [&rendered_path, &diff_path, &flip_path] {
            let _ = std::fs::remove_file(stale);
        }
    } else {
        create_dir(&opts.report)?;
        let write = |path: &PathBuf, img: &Frame| {
            write_atomic(path, img, ImageFormat::Png, &[])
                .map_err(|source| AnimError::Write { frame, source })
                .map(|()| Some(path.clone()))
        };
        images.0 = write(&rendered_path, &image)?;
        images.1 = write(&diff_path, &heat_map(reference, &image))?;
        match &flip {
            Some(f) => images.2 = write(&flip_path, &f.map)?,
            None => {
                let _ = std::fs::remove_file(&flip_path);
            }
        }
    }
    Ok(FrameReport {
        frame,
        name,
        comparison,
        flip: flip.map(|f| f.mean),
        pass: failed.is_empty(),
        failed,
        seconds: start.elapsed().as_secs_f64(),
        reference_image: reference_path(anim, &opts.references, frame),
        rendered_image: images.0,
        diff_image: images.1,
        flip_image: images.2,
    })
}
