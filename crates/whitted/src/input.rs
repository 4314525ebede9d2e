//! Reading input files safely: scenes, manifests and frames are read only when they are
//! regular files (a device such as `/dev/zero`, a FIFO or a folder is refused before it
//! is opened, so nothing blocks or grows without end), and only up to a size limit from
//! `limits` that the refusal states. Also `quote`, which cuts a long piece of input
//! before an error message shows it.

use std::fs::File;
use std::io::{Error, ErrorKind, Read};
use std::path::Path;

/// Why a path is not a file that can be read whole: its kind or its size, in words.
fn refusal(path: &Path, limit: u64, what: &str) -> Result<u64, Error> {
    let meta = std::fs::metadata(path)?;
    let kind = meta.file_type();
    if !kind.is_file() {
        let is = if kind.is_dir() {
            "a folder"
        } else {
            "a device, FIFO or socket"
        };
        return Err(Error::new(
            ErrorKind::InvalidInput,
            format!(
                "not a regular file ({is}); {} must be a regular file",
                a(what)
            ),
        ));
    }
    if meta.len() > limit {
        return Err(too_large(limit, what));
    }
    Ok(meta.len())
}

fn too_large(limit: u64, what: &str) -> Error {
    Error::new(
        ErrorKind::InvalidData,
        format!("larger than the limit of {} for {}", size(limit), a(what)),
    )
}

/// `what` with its article: "a scene", "an image".
fn a(what: &str) -> String {
    let vowel = what.starts_with(['a', 'e', 'i', 'o', 'u', 'A', 'E', 'I', 'O', 'U']);
    format!("{} {what}", if vowel { "an" } else { "a" })
}

/// A byte count for people: `256 MiB`, `12 KiB`, `300 bytes`.
pub fn size(bytes: u64) -> String {
    match bytes {
        b if b >= 1 << 20 && b % (1 << 20) == 0 => format!("{} MiB", b >> 20),
        b if b >= 1 << 20 => format!("{:.1} MiB", b as f64 / f64::from(1 << 20)),
        b if b >= 1 << 10 => format!("{} KiB", b >> 10),
        b => format!("{b} bytes"),
    }
}

/// Opens `path` for reading if it is a regular file of at most `limit` bytes; `what`
/// names it in a refusal ("scene", "manifest", "frame"). Returns the file and its size.
pub fn open_regular(path: &Path, limit: u64, what: &str) -> Result<(File, u64), Error> {
    let len = refusal(path, limit, what)?;
    let file = File::open(path)?;
    // The path may have been replaced between the look and the open: look again.
    let meta = file.metadata()?;
    if !meta.is_file() {
        return Err(Error::new(
            ErrorKind::InvalidInput,
            format!("not a regular file; {} must be a regular file", a(what)),
        ));
    }
    Ok((file, len.max(meta.len())))
}

/// The SHA-256 of a file's bytes: what a frame's provenance records of the mesh and
/// image files it was drawn from (their content, not their name or date).
pub fn digest(bytes: &[u8]) -> [u8; 32] {
    use sha2::{Digest, Sha256};
    Sha256::digest(bytes).into()
}

/// Reads the whole of `path` if it is a regular file of at most `limit` bytes, and
/// never more than `limit` bytes even if it grows while being read.
pub fn read_regular(path: &Path, limit: u64, what: &str) -> Result<Vec<u8>, Error> {
    let (file, len) = open_regular(path, limit, what)?;
    let mut bytes = Vec::with_capacity(len as usize);
    file.take(limit + 1).read_to_end(&mut bytes)?;
    if bytes.len() as u64 > limit {
        return Err(too_large(limit, what));
    }
    Ok(bytes)
}

/// `text` as an error message quotes it: whole when short, else its first
/// `MAX_QUOTED` characters, "…" and how long it was.
pub fn quote(text: &str) -> std::borrow::Cow<'_, str> {
    let limit = crate::limits::MAX_QUOTED;
    match text.char_indices().nth(limit) {
        None => text.into(),
        Some((end, _)) => format!("{}… ({} characters)", &text[..end], text.chars().count()).into(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn devices_fifos_and_folders_are_refused_before_opening() {
        let e = read_regular(Path::new("/dev/zero"), 100, "scene").unwrap_err();
        assert!(
            e.to_string().contains("not a regular file (a device"),
            "{e}"
        );
        let dir = tempfile::tempdir().unwrap();
        let e = read_regular(dir.path(), 100, "scene").unwrap_err();
        assert!(e.to_string().contains("(a folder)"), "{e}");
    }

    #[test]
    fn sizes_past_the_limit_are_refused_and_stated() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("big");
        std::fs::write(&path, vec![b'x'; 2048]).unwrap();
        let e = read_regular(&path, 1024, "manifest").unwrap_err();
        assert_eq!(
            e.to_string(),
            "larger than the limit of 1 KiB for a manifest"
        );
        assert_eq!(read_regular(&path, 2048, "manifest").unwrap().len(), 2048);
    }

    #[test]
    fn sizes_for_people() {
        assert_eq!(size(256 << 20), "256 MiB");
        assert_eq!(size(3 << 19), "1.5 MiB");
        assert_eq!(size(2048), "2 KiB");
        assert_eq!(size(5), "5 bytes");
    }

    #[test]
    fn long_quotes_are_cut() {
        assert_eq!(quote("short"), "short");
        let long = "é".repeat(100);
        let q = quote(&long);
        assert_eq!(q, format!("{}… (100 characters)", "é".repeat(60)));
    }
}
