//! `animate bless` and `animate check`: regression on selected frames.
//!
//! `bless` renders the chosen frames and writes them as lossless PNG references into the
//! references folder (atomically). `check` loads every reference first (a missing,
//! unreadable or wrongly sized one stops the check before anything renders), renders the
//! frames in parallel, compares each (`diff.rs`), and for every failing frame writes the
//! rendered frame and a diff heat map into a report folder; stale report images of frames
//! that now pass are removed, so the folder shows failures only. References are named by
//! the manifest's `[output] name` pattern with `.png`.

use super::diff::{compare, heat_map, Comparison, Tolerance};
use super::error::AnimError;
use super::manifest::Manifest;
use super::project::Animation;
use super::select::parse_frames;
use crate::output::{write_atomic, ImageFormat};
use crate::render::Frame;
use rayon::prelude::*;
use serde::Serialize;
use std::path::{Path, PathBuf};

/// The outcome for one checked frame.
#[derive(Clone, Debug, Serialize)]
pub struct FrameResult {
    pub frame: u32,
    #[serde(flatten)]
    pub comparison: Comparison,
    /// The rendered frame and the heat map, written for failing frames.
    pub rendered_image: Option<PathBuf>,
    pub diff_image: Option<PathBuf>,
}

/// The frames and the references folder of a check or bless: `--frames` / `--references`
/// when given, else the manifest's `[check]`.
pub fn targets(
    manifest: &Manifest,
    frames: Option<&str>,
    references: Option<&Path>,
) -> Result<(Vec<u32>, PathBuf), AnimError> {
    let missing = |what: &str| {
        AnimError::Usage(format!(
            "{}: no [check] section; name the {what}",
            manifest.path.display()
        ))
    };
    let check = manifest.check.as_ref();
    let frames = match (frames, check) {
        (Some(spec), _) => parse_frames(spec, manifest.frames)?,
        (None, Some(c)) => c.frames.clone(),
        (None, None) => return Err(missing("frames with --frames")),
    };
    let refs = match (references, check) {
        (Some(dir), _) => dir.to_path_buf(),
        (None, Some(c)) => c.references.clone(),
        (None, None) => return Err(missing("folder with --references")),
    };
    Ok((frames, refs))
}

/// The manifest's tolerance (or the SPEC's defaults without `[check]`), with the
/// command line's overrides.
pub fn tolerance(
    manifest: &Manifest,
    fail: Option<u8>,
    fail_percent: Option<f64>,
    hard_fail: Option<u8>,
) -> Result<Tolerance, AnimError> {
    let base = manifest
        .check
        .as_ref()
        .map_or(Tolerance::DEFAULT, |c| Tolerance {
            fail: c.fail,
            fail_percent: c.fail_percent,
            hard_fail: c.hard_fail,
        });
    let tol = Tolerance {
        fail: fail.unwrap_or(base.fail),
        fail_percent: fail_percent.unwrap_or(base.fail_percent),
        hard_fail: hard_fail.unwrap_or(base.hard_fail),
    };
    if !(0.0..=100.0).contains(&tol.fail_percent) {
        return Err(AnimError::Usage(
            "--fail-percent must be from 0 to 100".into(),
        ));
    }
    Ok(tol)
}

/// The default report folder: the frame folder's name + `-check`.
pub fn default_report(manifest: &Manifest) -> PathBuf {
    let mut name = manifest.output.dir.clone().into_os_string();
    name.push("-check");
    PathBuf::from(name)
}

/// The file name stem of frame `frame` (the name pattern, no extension).
fn stem(anim: &Animation, frame: u32) -> String {
    let name = anim.manifest.output.file_name(frame, anim.manifest.frames);
    match name.rsplit_once('.') {
        Some((stem, _)) => stem.to_string(),
        None => name,
    }
}

/// Where the reference of `frame` lives.
pub fn reference_path(anim: &Animation, refs: &Path, frame: u32) -> PathBuf {
    refs.join(format!("{}.png", stem(anim, frame)))
}

fn load_reference(anim: &Animation, refs: &Path, frame: u32) -> Result<Frame, AnimError> {
    let path = reference_path(anim, refs, frame);
    if !path.exists() {
        return Err(AnimError::Reference(format!(
            "frame {frame}: the reference {} is missing (run `animate bless` first)",
            path.display()
        )));
    }
    let image = image::open(&path)
        .map_err(|e| AnimError::Reference(format!("{}: cannot read it: {e}", path.display())))?
        .to_rgb8();
    if (image.width(), image.height()) != (anim.width, anim.height) {
        return Err(AnimError::Reference(format!(
            "frame {frame}: the reference {} is {}×{}, the frame is {}×{}",
            path.display(),
            image.width(),
            image.height(),
            anim.width,
            anim.height
        )));
    }
    Ok(Frame {
        width: image.width(),
        height: image.height(),
        pixels: image.into_raw(),
    })
}

fn create_dir(dir: &Path) -> Result<(), AnimError> {
    std::fs::create_dir_all(dir).map_err(|source| AnimError::Folder {
        dir: dir.to_path_buf(),
        source,
    })
}

/// Renders `frames` and writes them as references into `refs`; returns the paths.
pub fn bless(anim: &Animation, frames: &[u32], refs: &Path) -> Result<Vec<PathBuf>, AnimError> {
    create_dir(refs)?;
    frames
        .par_iter()
        .map(|&frame| {
            let (image, _) = anim.render(frame)?;
            let path = reference_path(anim, refs, frame);
            write_atomic(&path, &image, ImageFormat::Png)
                .map_err(|source| AnimError::Write { frame, source })?;
            Ok(path)
        })
        .collect()
}

/// Checks `frames` against the references in `refs`, writing images of failing frames
/// into `report`.
pub fn check(
    anim: &Animation,
    frames: &[u32],
    refs: &Path,
    tol: Tolerance,
    report: &Path,
) -> Result<Vec<FrameResult>, AnimError> {
    let references = frames
        .iter()
        .map(|&f| load_reference(anim, refs, f))
        .collect::<Result<Vec<Frame>, AnimError>>()?;
    frames
        .par_iter()
        .zip(references.par_iter())
        .map(|(&frame, reference)| {
            let (image, _) = anim.render(frame)?;
            let comparison = compare(reference, &image, tol);
            let rendered_path = report.join(format!("{}.rendered.png", stem(anim, frame)));
            let diff_path = report.join(format!("{}.diff.png", stem(anim, frame)));
            let (mut rendered_image, mut diff_image) = (None, None);
            if comparison.pass {
                for stale in [&rendered_path, &diff_path] {
                    let _ = std::fs::remove_file(stale);
                }
            } else {
                create_dir(report)?;
                let write = |path: &PathBuf, img: &Frame| {
                    write_atomic(path, img, ImageFormat::Png)
                        .map_err(|source| AnimError::Write { frame, source })
                };
                write(&rendered_path, &image)?;
                write(&diff_path, &heat_map(reference, &image))?;
                rendered_image = Some(rendered_path);
                diff_image = Some(diff_path);
            }
            Ok(FrameResult {
                frame,
                comparison,
                rendered_image,
                diff_image,
            })
        })
        .collect()
}

/// The results as a table, one frame a row.
pub fn table(results: &[FrameResult]) -> String {
    let mut out = format!(
        "{:>6}  {:>8}  {:>16}  {:>8}  {:>9}  {:>8}  {}\n",
        "frame", "max diff", "at (x, y) ch", "fail %", "mean err", "PSNR dB", "result"
    );
    for r in results {
        let c = &r.comparison;
        let at = c.max_at.map_or("-".to_string(), |(x, y, ch)| {
            format!("({x}, {y}) {}", ["R", "G", "B"][ch])
        });
        let psnr = c.psnr.map_or("inf".to_string(), |p| format!("{p:.2}"));
        out += &format!(
            "{:>6}  {:>8}  {:>16}  {:>8.3}  {:>9.4}  {:>8}  {}\n",
            r.frame,
            c.max_diff,
            at,
            c.failing_percent,
            c.mean_error,
            psnr,
            if c.pass { "PASS" } else { "FAIL" }
        );
    }
    out
}
