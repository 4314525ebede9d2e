//! A check's references: where the reference of a frame lives (the manifest's `[output]
//! name` pattern with `.png`, or `.exr` for EXR frames), its header probed before anything
//! renders, its picture read (and an EXR reference's float beauty), and the frame drawn
//! the same way for comparison.

use super::super::error::AnimError;
use super::super::project::{Animation, FramePlan};
use std::path::{Path, PathBuf};
use whitted::base::Frame;
use whitted::fileloc::shown;
use whitted::output::ImageFormat;

/// The file name stem of frame `frame` (the name pattern, no extension).
pub(super) fn stem(anim: &Animation, frame: u32) -> String {
    anim.manifest.output.stem(frame, anim.manifest.frames)
}

/// Where the reference of `frame` lives (`OutputSpec::path_as`).
pub fn reference_path(anim: &Animation, refs: &Path, frame: u32) -> PathBuf {
    let ext = if anim.format().is_layered() {
        "exr"
    } else {
        "png"
    };
    (anim.manifest.output).path_as(refs, frame, anim.manifest.frames, ext)
}

/// A reference: its 8-bit picture and, for an EXR frame, its float beauty.
pub(super) type Reference = (Frame, Option<Vec<[f32; 3]>>);

/// A frame as check compares it: the picture, and the float beauty of an EXR frame.
pub(super) fn draw(plan: &FramePlan) -> Result<Reference, AnimError> {
    let anim = plan.anim();
    if !anim.format().is_layered() {
        return Ok((anim.render(plan)?.0, None));
    }
    let (layers, _) = anim.render_layers(plan, whitted::passes::PassSet::NONE)?;
    let floats = layers
        .beauty
        .iter()
        .map(|c| [c.x as f32, c.y as f32, c.z as f32])
        .collect();
    Ok((layers.to_frame(), Some(floats)))
}

/// Reads the reference of `frame` (that `probe_reference` accepted) with one size check:
/// an EXR reference's float beauty and its picture, or an 8-bit reference's picture.
pub(super) fn load_reference(
    anim: &Animation,
    refs: &Path,
    frame: u32,
) -> Result<Reference, AnimError> {
    let path = reference_path(anim, refs, frame);
    let (width, height) = (anim.width, anim.height);
    let read = if anim.format().is_layered() {
        whitted::output::read_beauty(&path, width, height)
            .map(|beauty| (whitted::output::beauty_bytes(&beauty), Some(beauty)))
    } else {
        whitted::output::read_rgb(&path, ImageFormat::Png, width, height).map(|p| (p, None))
    };
    let (pixels, beauty) = read.map_err(|e| unreadable(frame, &path, e))?;
    let picture = Frame {
        width,
        height,
        pixels,
    };
    Ok((picture, beauty))
}

/// Refuses a reference that is missing, unreadable or of another size, from its header
/// alone (the check's first pass, before anything renders; nothing of its pixels is
/// decoded, so an 8192² reference costs no more than a right one).
pub(super) fn probe_reference(
    anim: &Animation,
    refs: &Path,
    frame: u32,
) -> Result<PathBuf, AnimError> {
    let path = reference_path(anim, refs, frame);
    if !path.exists() {
        return Err(AnimError::Reference(format!(
            "frame {frame}: the reference {} is missing",
            shown(&path)
        )));
    }
    let unreadable = |e: &dyn std::fmt::Display| {
        AnimError::Reference(format!("{}: cannot read it: {e}", shown(&path)))
    };
    let (width, height) = if anim.format().is_layered() {
        whitted::output::exr_size(&path)
            .map_err(|e| AnimError::Reference(format!("{}: {e}", shown(&path))))?
    } else {
        let limit = whitted::limits::MAX_FRAME_BYTES;
        let (file, _) =
            whitted::input::open_regular(&path, limit, "reference").map_err(|e| unreadable(&e))?;
        let reader = image::ImageReader::new(std::io::BufReader::new(file))
            .with_guessed_format()
            .map_err(|e| unreadable(&e))?;
        reader.into_dimensions().map_err(|e| unreadable(&e))?
    };
    if (width, height) != (anim.width, anim.height) {
        return Err(AnimError::Reference(format!(
            "frame {frame}: the reference {} is {}×{}, the frame is {}×{}",
            shown(&path),
            width,
            height,
            anim.width,
            anim.height
        )));
    }
    Ok(path)
}

/// The refusal of a reference that gives no picture of the frame's size.
fn unreadable(frame: u32, path: &Path, e: whitted::output::ReadError) -> AnimError {
    AnimError::Reference(match e {
        whitted::output::ReadError::Size {
            found,
            width,
            height,
        } => format!(
            "frame {frame}: the reference {} is {found}, the frame is {width}×{height}",
            shown(path),
        ),
        e => format!("{}: {e}", shown(path)),
    })
}
