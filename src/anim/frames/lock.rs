//! One folder, one run: a run that writes frames into a folder holds an advisory lock on
//! its hidden `.whitted-lock` file (`flock`, through std's `File::try_lock`), which the
//! system releases when the process ends however it ends (kill -9 included), so no stale
//! lock is ever left. The file itself stays (removing it would let two runs lock two
//! different files); it holds the holder's process id, manifest and start time, which a
//! second run names when it refuses:
//!
//! ```text
//! pid 4242
//! manifest /home/me/animations/orbit.toml
//! started 1767225600 (seconds since 1970)
//! ```
//!
//! Taking the lock is also the check, before anything renders, that the folder can be
//! written.

use crate::anim::error::AnimError;
use std::fs::{File, OpenOptions, TryLockError};
use std::io::{Read, Seek, Write};
use std::path::Path;

/// The lock file's name inside a frame folder.
pub const LOCK_FILE: &str = ".whitted-lock";

/// A held lock on a frame folder, released when dropped or when the process ends.
#[derive(Debug)]
pub struct FolderLock {
    _file: File,
}

/// Takes the lock on `dir` (which exists) for a run of `manifest`; refuses, naming the
/// holder, when another run holds it.
pub fn lock(dir: &Path, manifest: &Path) -> Result<FolderLock, AnimError> {
    let path = dir.join(LOCK_FILE);
    let folder = |source| AnimError::Folder {
        dir: dir.to_path_buf(),
        source,
    };
    let mut file = OpenOptions::new()
        .read(true)
        .write(true)
        .create(true)
        .truncate(false)
        .open(&path)
        .map_err(folder)?;
    match file.try_lock() {
        Ok(()) => {}
        Err(TryLockError::WouldBlock) => {
            let mut holder = String::new();
            let _ = (&file).take(4096).read_to_string(&mut holder);
            let holder = holder.lines().collect::<Vec<_>>().join(", ");
            return Err(AnimError::Busy {
                dir: dir.to_path_buf(),
                holder: if holder.is_empty() {
                    "a run that has not yet said who it is".into()
                } else {
                    holder
                },
            });
        }
        Err(TryLockError::Error(e)) => return Err(folder(e)),
    }
    let started = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_secs());
    let manifest = std::path::absolute(manifest).unwrap_or_else(|_| manifest.to_path_buf());
    let text = format!(
        "pid {}\nmanifest {}\nstarted {started} (seconds since 1970)\n",
        std::process::id(),
        manifest.display()
    );
    file.set_len(0).map_err(folder)?;
    file.rewind().map_err(folder)?;
    file.write_all(text.as_bytes()).map_err(folder)?;
    Ok(FolderLock { _file: file })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_second_lock_names_the_first_holder_and_a_dropped_one_is_free() {
        let dir = tempfile::tempdir().unwrap();
        let first = lock(dir.path(), Path::new("/a/one.toml")).unwrap();
        let e = lock(dir.path(), Path::new("/a/two.toml")).unwrap_err();
        let shown = e.to_string();
        let me = format!("pid {}, manifest /a/one.toml, started ", std::process::id());
        assert!(shown.contains(&me), "{shown}");
        assert_eq!(e.exit_code(), 2);
        drop(first);
        lock(dir.path(), Path::new("/a/two.toml")).unwrap();
    }
}
