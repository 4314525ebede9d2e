//! Whose a file under a frame's name is, from the record inside it (`provenance`): this
//! manifest's, another manifest's, or nobody's (a file the tool did not write, such as a
//! photo `IMG_0042.png` in a shared folder). Runs, `clean` and `bless` replace or remove
//! only their own manifest's files unless forced; a file that cannot be read as a frame
//! (damaged, cut short) is taken for a frame of a killed or broken run, as before.

use super::provenance::{inspect, Inspection};
use crate::error::AnimError;
use crate::project::Animation;
use std::path::{Path, PathBuf};
use whitted::fileloc::shown;

/// Who wrote a file.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Owner {
    /// No file there.
    Missing,
    /// A frame whose record names this manifest, or a damaged frame file (taken for one).
    Ours,
    /// A frame whose record names this other manifest (its file name).
    Other(String),
    /// A sound image with no record: not written by the tool.
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
pub fn owner_as(anim: &Animation, path: &Path, format: whitted::output::ImageFormat) -> Owner {
    match inspect(path, format, anim.width, anim.height, false) {
        Inspection::Missing => Owner::Missing,
        Inspection::Damaged(_) => Owner::Ours,
        Inspection::Sound(record) => match record.manifest {
            Some(m) if m == manifest_name(anim) => Owner::Ours,
            Some(m) => Owner::Other(m),
            None => Owner::Nobody,
        },
    }
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
