//! Many runs, one folder: a run claims each frame before it renders it, so that runs of
//! the same manifest started into one folder (two terminals, two machines on a shared
//! disk) share the frames instead of each rendering all of them, as Blender's placeholders
//! do, but with no placeholder left behind by a killed run.
//!
//! A claim is an exclusive advisory lock (`flock`, as the folder's lock in `lock`) on
//! `.whitted-claims/NAME.claim`, NAME the frame's file name: the system releases it when
//! the run ends however it ends (kill -9 included), so a dead run's claims are free for the
//! next run to take. The claim files stay while runs come and go (removing a held one
//! would let two runs lock two files of one name); they are empty.
//!
//! A run takes a free claim at once (`try_claim`) and skips, for now, a frame another live
//! run holds; once through its frames it comes back to those and waits for each claim
//! (`claim`): the other run has finished the frame (then it is written since the runs
//! began sharing the folder, and records what the manifest gives it: `done_elsewhere`), or
//! has died (then this run renders it). A frame another run wrote before this one joined
//! it is found the same way, so no frame is rendered twice (`lock`'s `shared since`). `animate clean` removes the claim files no one holds
//! (`remove_free`).

use super::provenance::{self, Inspection};
use crate::error::AnimError;
use crate::project::FramePlan;
use std::fs::{File, OpenOptions, TryLockError};
use std::path::{Path, PathBuf};
use std::time::SystemTime;

/// The folder of claims inside a frame folder.
pub const CLAIMS: &str = ".whitted-claims";

/// A frame claimed by this run, released when dropped.
#[derive(Debug)]
pub struct Claim {
    _file: File,
}

/// The claims of one run in one folder.
pub struct Claims {
    dir: PathBuf,
    since: SystemTime,
}

impl Claims {
    /// The claims of a run into `dir` that shares it with runs of its manifest since
    /// `since` (creating the claims folder).
    pub fn new(dir: &Path, since: SystemTime) -> Result<Claims, AnimError> {
        let claims = dir.join(CLAIMS);
        std::fs::create_dir_all(&claims).map_err(|source| AnimError::Folder {
            dir: claims.clone(),
            source,
        })?;
        Ok(Claims { dir: claims, since })
    }

    fn open(&self, frame_path: &Path) -> std::io::Result<File> {
        let name = frame_path.file_name().unwrap_or_default().to_string_lossy();
        OpenOptions::new()
            .write(true)
            .create(true)
            .truncate(false)
            .open(self.dir.join(format!("{name}.claim")))
    }

    /// Claims the frame whose file is `frame_path` if no live run holds it: `None` when
    /// one does.
    pub fn try_claim(&self, frame_path: &Path) -> std::io::Result<Option<Claim>> {
        let file = self.open(frame_path)?;
        match file.try_lock() {
            Ok(()) => Ok(Some(Claim { _file: file })),
            Err(TryLockError::WouldBlock) => Ok(None),
            Err(TryLockError::Error(e)) => Err(e),
        }
    }

    /// Claims the frame, waiting while a live run holds it.
    pub fn claim(&self, frame_path: &Path) -> std::io::Result<Claim> {
        let file = self.open(frame_path)?;
        file.lock()?;
        Ok(Claim { _file: file })
    }

    /// Whether another run sharing the folder wrote the plan's frame: its file is newer
    /// than the sharing's start and records the digest the manifest now gives it.
    pub fn done_elsewhere(&self, plan: &FramePlan) -> bool {
        let (anim, path) = (plan.anim(), plan.path());
        let newer = std::fs::metadata(path)
            .and_then(|m| m.modified())
            .is_ok_and(|t| t >= self.since);
        if !newer {
            return false;
        }
        let (format, w, h) = (anim.format(), anim.width, anim.height);
        match provenance::inspect(path, format, w, h, false) {
            Inspection::Sound(record) => record.digest.as_deref() == Some(plan.digest()),
            _ => false,
        }
    }
}

/// Removes the claim files in `dir`'s claims folder whose frame file name `ours` accepts,
/// each only if no one holds it: locked first, removed while locked. Called by `clean`
/// alone in the folder and holding its gate (`lock::lock_with`), when no run of the
/// manifest can be between taking the folder and claiming a frame, so none can open a
/// claim file that is then unlinked under it and lock it while a later run locks a new
/// file of the same name. The folder goes too once empty. Returns how many files went.
pub fn remove_free(dir: &Path, ours: impl Fn(&str) -> bool) -> std::io::Result<usize> {
    let claims = dir.join(CLAIMS);
    let entries = match std::fs::read_dir(&claims) {
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(0),
        entries => entries?,
    };
    let mut removed = 0;
    for entry in entries {
        let entry = entry?;
        let name = entry.file_name().to_string_lossy().into_owned();
        if !name.strip_suffix(".claim").is_some_and(&ours) {
            continue;
        }
        // Opened without creating: a file gone meanwhile is not made again.
        let file = match OpenOptions::new().write(true).open(entry.path()) {
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => continue,
            file => file?,
        };
        match file.try_lock() {
            Ok(()) => match std::fs::remove_file(entry.path()) {
                Ok(()) => removed += 1,
                Err(e) if e.kind() == std::io::ErrorKind::NotFound => {}
                Err(e) => return Err(e),
            },
            Err(TryLockError::WouldBlock) => {}
            Err(TryLockError::Error(e)) => return Err(e),
        }
    }
    // Still holding others' claims (or another manifest's): it stays.
    let _ = std::fs::remove_dir(&claims);
    Ok(removed)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_claim_is_held_until_dropped() {
        let dir = tempfile::tempdir().unwrap();
        let (one, two) = (
            Claims::new(dir.path(), SystemTime::now()).unwrap(),
            Claims::new(dir.path(), SystemTime::now()).unwrap(),
        );
        let frame = dir.path().join("frame_0003.png");
        let held = one.try_claim(&frame).unwrap().expect("free");
        // Another holder (flock locks belong to the open file) finds it taken.
        assert!(two.try_claim(&frame).unwrap().is_none());
        assert!(two
            .try_claim(&dir.path().join("frame_0004.png"))
            .unwrap()
            .is_some());
        drop(held);
        assert!(two.try_claim(&frame).unwrap().is_some());
        assert!(dir
            .path()
            .join(CLAIMS)
            .join("frame_0003.png.claim")
            .is_file());
    }

    #[test]
    fn only_free_claims_of_the_manifest_are_removed() {
        let dir = tempfile::tempdir().unwrap();
        let claims = Claims::new(dir.path(), SystemTime::now()).unwrap();
        let frame = |n: u32| dir.path().join(format!("frame_{n:04}.png"));
        let held = claims.try_claim(&frame(1)).unwrap().unwrap();
        drop(claims.try_claim(&frame(2)).unwrap().unwrap());
        drop(claims.try_claim(&frame(3)).unwrap().unwrap());
        drop(
            claims
                .try_claim(&dir.path().join("other_0002.png"))
                .unwrap(),
        );
        let ours = |name: &str| name.starts_with("frame_");
        assert_eq!(remove_free(dir.path(), ours).unwrap(), 2);
        let mut left: Vec<String> = std::fs::read_dir(dir.path().join(CLAIMS))
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        left.sort();
        assert_eq!(left, ["frame_0001.png.claim", "other_0002.png.claim"]);
        drop(held);
        assert_eq!(remove_free(dir.path(), |_| true).unwrap(), 2);
        assert!(!dir.path().join(CLAIMS).exists());
        assert_eq!(remove_free(dir.path(), |_| true).unwrap(), 0);
    }
}
