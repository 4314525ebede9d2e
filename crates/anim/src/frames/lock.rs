//! One folder, one manifest: a run that writes frames into a folder holds an advisory
//! lock (`flock`, through std's `File::try_lock`) that the system releases when the
//! process ends however it ends (kill -9 included), so no stale lock is ever left.
//!
//! Runs of the same manifest (the file name its frames record) may share the folder, as
//! the shards of a render-farm array job do: each holds a *shared* lock on
//! `.whitted-lock-KEY` (KEY from the manifest's file name). A run of another manifest
//! finds that lock held and refuses, naming the holder from the file:
//!
//! ```text
//! pid 4242
//! manifest /home/me/animations/orbit.toml
//! started 1767225600 (seconds since 1970)
//! shared since 1767225581.250918112
//! ```
//!
//! `shared since` is when the first of the runs now sharing the folder took it (a run
//! alone starts the sharing; a run that joins keeps the time it finds): a frame written
//! since then records the work of those runs, which a joining run does not do again
//! (`claim`).
//!
//! The look at the other manifests' locks and the taking of one's own happen under an
//! exclusive lock on `.whitted-lock` (held for milliseconds), so two runs cannot both
//! find the folder free. A run that finds itself alone (no other run of its manifest)
//! is told so: only then may it remove the temporaries that killed runs left, and it does
//! so still holding the gate (`lock_with`), since a run let in meanwhile would be writing
//! temporaries of its own. The lock files stay (removing a held one would let a second
//! run lock a new file). Taking the lock is also the check, before anything renders, that
//! the folder can be written.

use crate::error::AnimError;
use sha2::{Digest, Sha256};
use std::fs::{File, OpenOptions, TryLockError};
use std::io::{Read, Seek, Write};
use std::path::Path;
use std::time::{Duration, SystemTime, UNIX_EPOCH};

/// The gate's name inside a frame folder; manifests' locks are named after it.
pub const LOCK_FILE: &str = ".whitted-lock";

/// A held lock on a frame folder, released when dropped or when the process ends.
#[derive(Debug)]
pub struct FolderLock {
    _file: File,
    alone: bool,
    shared_with: Option<u32>,
    since: SystemTime,
}

impl FolderLock {
    /// Whether no other run of the same manifest held the folder when this one took it.
    pub fn alone(&self) -> bool {
        self.alone
    }

    /// The process id of the latest run of the same manifest that held the folder when
    /// this one took it (each run writes its own into the lock file), if any.
    pub fn shared_with(&self) -> Option<u32> {
        self.shared_with
    }

    /// When the first of the runs sharing the folder with this one took it (this run's
    /// own start when it was alone).
    pub fn since(&self) -> SystemTime {
        self.since
    }
}

/// The `shared since` time of a lock file's text (seconds and nanoseconds since 1970).
fn shared_since(text: &str) -> Option<SystemTime> {
    let value = text.lines().find_map(|l| l.strip_prefix("shared since "))?;
    let (secs, nanos) = value.trim().split_once('.')?;
    let nanos: u32 = nanos.parse().ok().filter(|&n| n < 1_000_000_000)?;
    let since = Duration::new(secs.parse().ok()?, nanos);
    UNIX_EPOCH.checked_add(since)
}

fn open(path: &Path) -> std::io::Result<File> {
    OpenOptions::new()
        .read(true)
        .write(true)
        .create(true)
        .truncate(false)
        .open(path)
}

/// A lock file's text (its first 4 KiB).
fn text_of(mut file: &File) -> String {
    let mut text = String::new();
    let _ = file.rewind();
    let _ = file.take(4096).read_to_string(&mut text);
    text
}

/// Who holds a lock file, from its text.
fn holder(file: &File) -> String {
    let text = text_of(file).lines().collect::<Vec<_>>().join(", ");
    if text.is_empty() {
        "a run that has not yet said who it is".into()
    } else {
        text
    }
}

/// Takes the lock on `dir` (which exists) for a run of `manifest`; refuses, naming the
/// holder, when a run of another manifest holds it.
pub fn lock(dir: &Path, manifest: &Path) -> Result<FolderLock, AnimError> {
    lock_with(dir, manifest, |_| Ok(())).map(|(held, ())| held)
}

/// `lock`, then `gated(alone)` before any other run may take the folder: the gate is
/// held until it returns, so a run alone in the folder stays alone while it clears what
/// killed runs left (a run that joined meanwhile could be writing what it removes). Its
/// error is the lock's.
pub fn lock_with<T>(
    dir: &Path,
    manifest: &Path,
    gated: impl FnOnce(bool) -> Result<T, AnimError>,
) -> Result<(FolderLock, T), AnimError> {
    let folder = |source| AnimError::Folder {
        dir: dir.to_path_buf(),
        source,
    };
    let name = manifest.file_name().unwrap_or_default().to_string_lossy();
    let key = &super::provenance::hex(&Sha256::digest(name.as_bytes()))[..16];
    let own = format!("{LOCK_FILE}-{key}");
    let gate = open(&dir.join(LOCK_FILE)).map_err(folder)?;
    gate.lock().map_err(folder)?;
    for entry in std::fs::read_dir(dir).map_err(folder)?.flatten() {
        let other = entry.file_name().to_string_lossy().into_owned();
        if !other.starts_with(&format!("{LOCK_FILE}-")) || other == own {
            continue;
        }
        let file = open(&entry.path()).map_err(folder)?;
        match file.try_lock() {
            Ok(()) => {} // left by a run that has ended
            Err(TryLockError::WouldBlock) => {
                return Err(AnimError::Busy {
                    dir: dir.to_path_buf(),
                    holder: holder(&file),
                })
            }
            Err(TryLockError::Error(e)) => return Err(folder(e)),
        }
    }
    let mut file = open(&dir.join(&own)).map_err(folder)?;
    let alone = match file.try_lock() {
        Ok(()) => true,
        Err(TryLockError::WouldBlock) => false,
        Err(TryLockError::Error(e)) => return Err(folder(e)),
    };
    file.lock_shared().map_err(folder)?;
    let now = SystemTime::now();
    let before = text_of(&file);
    let (shared_with, since) = match alone {
        true => (None, now),
        false => (
            before
                .strip_prefix("pid ")
                .and_then(|rest| rest.lines().next())
                .and_then(|pid| pid.trim().parse().ok()),
            // A run of a version that did not say: this run's start, as before.
            shared_since(&before).map_or(now, |t| t.min(now)),
        ),
    };
    let epoch = |t: SystemTime| t.duration_since(UNIX_EPOCH).unwrap_or_default();
    let manifest = std::path::absolute(manifest).unwrap_or_else(|_| manifest.to_path_buf());
    let text = format!(
        "pid {}\nmanifest {}\nstarted {} (seconds since 1970)\nshared since {}.{:09}\n",
        std::process::id(),
        manifest.display(),
        epoch(now).as_secs(),
        epoch(since).as_secs(),
        epoch(since).subsec_nanos()
    );
    file.set_len(0).map_err(folder)?;
    file.rewind().map_err(folder)?;
    file.write_all(text.as_bytes()).map_err(folder)?;
    let value = gated(alone)?;
    drop(gate);
    let held = FolderLock {
        _file: file,
        alone,
        shared_with,
        since,
    };
    Ok((held, value))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn another_manifest_is_refused_the_same_one_shares() {
        let dir = tempfile::tempdir().unwrap();
        let first = lock(dir.path(), Path::new("/a/one.toml")).unwrap();
        assert!(first.alone());
        let shard = lock(dir.path(), Path::new("/b/one.toml")).unwrap();
        assert!(!shard.alone());
        assert_eq!(shard.shared_with(), Some(std::process::id()));
        assert_eq!(first.shared_with(), None);
        // The sharing started with the first run, to the nanosecond.
        assert_eq!(shard.since(), first.since());
        let read = shared_since("pid 1\nshared since 1767225600.000000250\n").unwrap();
        assert_eq!(read, UNIX_EPOCH + Duration::new(1_767_225_600, 250));
        assert_eq!(shared_since("pid 1\nstarted 5\n"), None);
        drop(shard);
        let e = lock(dir.path(), Path::new("/a/two.toml")).unwrap_err();
        let shown = e.to_string();
        // The latest run of the holding manifest names it.
        let me = format!("pid {}, manifest /b/one.toml, started ", std::process::id());
        assert!(shown.contains(&me), "{shown}");
        assert_eq!(e.exit_code(), 2);
        drop(first);
        lock(dir.path(), Path::new("/a/two.toml")).unwrap();
    }

    #[test]
    fn what_a_lone_run_does_at_the_gate_no_run_can_join() {
        let dir = tempfile::tempdir().unwrap();
        let manifest = Path::new("/a/one.toml");
        let gate_free = || {
            open(&dir.path().join(LOCK_FILE))
                .unwrap()
                .try_lock()
                .is_ok()
        };
        let (held, seen) = lock_with(dir.path(), manifest, |alone| {
            // A run taking the folder now would first have to take the gate.
            Ok((alone, gate_free()))
        })
        .unwrap();
        assert_eq!(seen, (true, false));
        assert!(gate_free());
        // A run that joins sees it is not alone; an error at the gate is the lock's.
        let (_shard, alone) = lock_with(dir.path(), manifest, Ok).unwrap();
        assert!(!alone);
        let refused = lock_with(dir.path(), manifest, |_| -> Result<(), AnimError> {
            Err(AnimError::InUse {
                dir: dir.path().to_path_buf(),
            })
        });
        assert!(matches!(refused, Err(AnimError::InUse { .. })));
        drop(held);
    }
}
