//! Whose a file under a frame's name is, from the record inside it (`provenance`): this
//! manifest's, another manifest's, or nobody's (a file the tool did not write, such as a
//! photo `IMG_0042.png` in a shared folder). Runs, `clean` and `bless` replace or remove
//! only their own manifest's files unless forced. A damaged frame (cut short, a bad
//! checksum) is taken for one of the tool's only when it still looks like a frame file:
//! a regular file that starts with its format's signature (a RAW frame: whose record names
//! this manifest); a text file, a link or a FIFO under a frame's name is nobody's
//! (`looks_like_a_frame`).

use super::provenance::{inspect, raw_record_path, Inspection};
use crate::error::AnimError;
use crate::project::Animation;
use std::io::Read;
use std::path::{Path, PathBuf};
use whitted::fileloc::shown;
use whitted::output::ImageFormat;

/// Who wrote a file.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Owner {
    /// No file there.
    Missing,
    /// A frame whose record names this manifest, or a damaged frame file of its format
    /// (taken for one).
    Ours,
    /// A frame whose record names this other manifest (its file name).
    Other(String),
    /// A sound image with no record, or a file that is not a frame of its format at all
    /// (text, a link, a FIFO): not written by the tool.
    Nobody,
}

/// The file name frames record for `anim`'s manifest.
pub fn manifest_name(anim: &Animation) -> String {
    let name = anim.manifest.path.file_name().unwrap_or_default();
    name.to_string_lossy().into_owned()
}

/// Whose the file `path` (of `anim`'s format and size) is.
pub fn owner(anim: &Animation, path: &Path) -> Owner {
    owner_as(anim, path, anim.format())
}

/// `owner`, for a file of `format` (references are PNG or EXR whatever the frames are).
pub fn owner_as(anim: &Animation, path: &Path, format: ImageFormat) -> Owner {
    match inspect(path, format, anim.width, anim.height, false) {
        Inspection::Missing => Owner::Missing,
        Inspection::Damaged(_) if looks_like_a_frame(anim, path, format) => Owner::Ours,
        Inspection::Damaged(_) => Owner::Nobody,
        Inspection::Sound(record) => match record.manifest {
            Some(m) if m == manifest_name(anim) => Owner::Ours,
            Some(m) => Owner::Other(m),
            None => Owner::Nobody,
        },
    }
}

/// Whether the file at `path`, which is not a sound frame, is still a frame file of the
/// tool's gone bad: a regular file starting with `format`'s signature (PNG, JPEG, PPM,
/// OpenEXR), or a RAW frame whose record names `anim`'s manifest. A text file, an image
/// of another format, a link, a FIFO or a folder under a frame's name is not.
pub fn looks_like_a_frame(anim: &Animation, path: &Path, format: ImageFormat) -> bool {
    if !std::fs::symlink_metadata(path).is_ok_and(|m| m.is_file()) {
        return false;
    }
    let limit = whitted::limits::MAX_FRAME_BYTES;
    let Ok((file, _)) = whitted::input::open_regular(path, limit, "frame") else {
        return false;
    };
    let mut head = Vec::with_capacity(8);
    if file.take(8).read_to_end(&mut head).is_err() {
        return false;
    }
    let signature: &[u8] = match format {
        ImageFormat::Png => b"\x89PNG\r\n\x1a\n",
        ImageFormat::Jpeg { .. } => &[0xFF, 0xD8, 0xFF],
        ImageFormat::Ppm => b"P6",
        ImageFormat::Exr(_) => &[0x76, 0x2F, 0x31, 0x01],
        ImageFormat::Raw => return raw_record_names(anim, path),
    };
    head.starts_with(signature)
}

/// Whether the record of the RAW frame at `path` names `anim`'s manifest.
fn raw_record_names(anim: &Animation, path: &Path) -> bool {
    let record = raw_record_path(path);
    let Ok(bytes) = whitted::input::read_regular(&record, 64 << 10, "frame record") else {
        return false;
    };
    let key = format!("{}: ", super::provenance::MANIFEST_KEY);
    let text = String::from_utf8_lossy(&bytes);
    let name = manifest_name(anim);
    text.lines()
        .any(|l| l.strip_prefix(&key).is_some_and(|m| m.trim() == name))
}

/// The refusal of `paths` (files that are not `anim`'s, with their owners) that `what`
/// would remove or replace; `None` when there are none.
pub fn refusal(what: &str, found: &[(PathBuf, Owner)]) -> Option<AnimError> {
    let (first, owner) = found.first()?;
    let whose = match owner {
        Owner::Other(m) => format!("rendered by another manifest ({m})"),
        _ => "not written by animate (no record)".to_string(),
    };
    let more = match found.len() {
        1 => String::new(),
        n => format!(" and {} other file(s)", n - 1),
    };
    Some(AnimError::NotOurs {
        what: what.to_string(),
        files: format!("{}{more}", shown(first)),
        whose,
    })
}
