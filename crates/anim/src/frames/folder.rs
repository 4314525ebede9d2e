//! What a frame folder holds besides the frames a manifest now asks for, found by the
//! manifest's name pattern (`frame_####.png`):
//!
//! - `beyond`: files of frames past the end of the sequence (the manifest's `frames` was
//!   lowered after they were rendered), which a `frame_%04d.png` glob would mix into a
//!   video;
//! - `temporaries`: hidden `.frame_0007.png.XXXXXX.tmp` files (and those of RAW records)
//!   that a killed run left; a run alone in the folder removes them as it takes it
//!   (`take`), before another run may join and write its own;
//! - `clean` (`animate clean`): removes both, the records of removed RAW frames and the
//!   claim files of the manifest's frames that no run holds (`claim`); files past the end
//!   that are not this manifest's (`owner`) only when forced.

use super::lock::FolderLock;
use super::owner::{owner, Owner};
use super::provenance::{raw_record_path, RAW_RECORDS};
use crate::error::AnimError;
use crate::project::Animation;
use std::path::{Path, PathBuf};
use whitted::output::temporary_target;

/// The frame number a file name `name` stands for under `anim`'s name pattern, whatever
/// its zero padding (a longer sequence padded more), if it is one.
fn frame_of(anim: &Animation, name: &str) -> Option<u32> {
    let out = &anim.manifest.output;
    let stem = name.strip_suffix(&format!(".{}", out.format.extension()))?;
    let (head, base, tail) = out.parts();
    let digits = stem.strip_prefix(head.as_str())?.strip_suffix(tail)?;
    if digits.len() < base || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    // Zero-padded as a sequence of some length pads it: `0015` or `00015`, never `+15`.
    let frame: u32 = digits.parse().ok()?;
    (format!("{frame:0width$}", width = digits.len()) == digits).then_some(frame)
}

/// The files of `dir` that hold frames past the end of `anim`'s sequence, by frame. A
/// folder under a frame's name is no frame's file: it is not listed (nor removed).
pub fn beyond(anim: &Animation, dir: &Path) -> Vec<(u32, PathBuf)> {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return Vec::new();
    };
    let mut found: Vec<(u32, PathBuf)> = entries
        .filter_map(Result::ok)
        .filter(|e| e.file_type().is_ok_and(|t| !t.is_dir()))
        .filter_map(|e| {
            let name = e.file_name().into_string().ok()?;
            let frame = frame_of(anim, &name)?;
            (frame >= anim.manifest.frames).then(|| (frame, e.path()))
        })
        .collect();
    found.sort();
    found
}

/// The hidden temporaries of frames (and RAW records) in `dir` that a run left.
pub fn temporaries(anim: &Animation, dir: &Path) -> Vec<PathBuf> {
    let mut found = Vec::new();
    let list = |d: &Path, is_ours: &dyn Fn(&str) -> bool, found: &mut Vec<PathBuf>| {
        for e in std::fs::read_dir(d).into_iter().flatten().flatten() {
            let name = e.file_name().to_string_lossy().into_owned();
            if temporary_target(&name).is_some_and(is_ours) {
                found.push(e.path());
            }
        }
    };
    list(dir, &|t| frame_of(anim, t).is_some(), &mut found);
    let records = dir.join(RAW_RECORDS);
    let record = |t: &str| {
        let frame = t
            .strip_suffix(".txt")
            .or_else(|| t.strip_suffix(super::cost::COST_SUFFIX));
        frame.is_some_and(|f| frame_of(anim, f).is_some())
    };
    list(&records, &record, &mut found);
    found.sort();
    found
}

/// The claim files of `anim`'s frames in `dir`'s claims folder (held or not).
pub fn claim_files(anim: &Animation, dir: &Path) -> usize {
    let claims = std::fs::read_dir(dir.join(super::claim::CLAIMS));
    (claims.into_iter().flatten().flatten())
        .filter(|e| {
            let name = e.file_name().to_string_lossy().into_owned();
            (name.strip_suffix(".claim")).is_some_and(|f| frame_of(anim, f).is_some())
        })
        .count()
}

/// Takes `dir` (which exists) for a run of `anim`'s manifest (`lock::lock_with`). Alone
/// in it, the run first removes the temporaries killed runs left, still holding the
/// folder's gate: a run let in before that could be writing a temporary of its own, which
/// the listing would take for a killed run's (one of the two runs then failed).
pub(crate) fn take(anim: &Animation, dir: &Path) -> Result<FolderLock, AnimError> {
    let clear = |alone: bool| match alone {
        true => remove(&temporaries(anim, dir))
            .map(|_| ())
            .map_err(|source| AnimError::Folder {
                dir: dir.to_path_buf(),
                source,
            }),
        false => Ok(()),
    };
    super::lock::lock_with(dir, &anim.manifest.path, clear).map(|(held, ())| held)
}

/// Removes `paths`, and the RAW records of frames among them; returns how many files went
/// (a file already gone is not an error, nor counted).
pub(crate) fn remove(paths: &[PathBuf]) -> std::io::Result<usize> {
    let mut n = 0;
    for p in paths {
        match std::fs::remove_file(p) {
            Ok(()) => n += 1,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => continue,
            Err(e) => return Err(e),
        }
        // A removed frame's cost record goes with it (not counted: it is not a frame).
        let spent = super::cost::cost_path(p);
        if spent.is_file() {
            std::fs::remove_file(spent)?;
        }
        let record = raw_record_path(p);
        if p.extension().is_some_and(|e| e == "raw") && record.is_file() {
            std::fs::remove_file(record)?;
            n += 1;
        }
    }
    Ok(n)
}

/// What `clean` removed.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Cleaned {
    /// Frames past the end of the sequence whose files were removed.
    pub beyond: Vec<u32>,
    /// Temporaries of killed runs removed.
    pub temporaries: usize,
    /// Claim files of this manifest's frames removed (`claim::remove_free`).
    pub claims: usize,
}

/// The files among `beyond(anim, dir)` that are not `anim`'s manifest's (another
/// manifest's frames, files with no record), with their owners.
pub fn not_ours(anim: &Animation, dir: &Path) -> Vec<(PathBuf, Owner)> {
    beyond(anim, dir)
        .into_iter()
        .map(|(_, p)| {
            let whose = owner(anim, &p);
            (p, whose)
        })
        .filter(|(_, whose)| matches!(whose, Owner::Other(_) | Owner::Nobody))
        .collect()
}

/// Removes from `dir` the files of frames past the end of `anim`'s sequence (with their
/// RAW records), the temporaries of killed runs and the claim files of the manifest's
/// frames that no one holds, alone in the folder and holding its gate throughout (no run
/// can join before it is done): refused while any other run writes into it
/// (`AnimError::Busy`, `AnimError::InUse`), and when a file to remove is not this
/// manifest's (`AnimError::NotOurs`) unless `force`.
pub fn clean(anim: &Animation, dir: &Path, force: bool) -> Result<Cleaned, AnimError> {
    let folder = |source| AnimError::Folder {
        dir: dir.to_path_buf(),
        source,
    };
    let gated = |alone: bool| {
        if !alone {
            return Err(AnimError::InUse {
                dir: dir.to_path_buf(),
            });
        }
        if !force {
            if let Some(refusal) = super::owner::refusal("removed", &not_ours(anim, dir)) {
                return Err(refusal);
            }
        }
        // Each part is done however the one before it ended; the first error is said.
        let past = beyond(anim, dir);
        let paths: Vec<PathBuf> = past.iter().map(|(_, p)| p.clone()).collect();
        let removed = remove(&paths);
        let temps = remove(&temporaries(anim, dir));
        let claims = super::claim::remove_free(dir, |name| frame_of(anim, name).is_some());
        let (_, temps, claims) = (
            removed.map_err(folder)?,
            temps.map_err(folder)?,
            claims.map_err(folder)?,
        );
        Ok(Cleaned {
            beyond: past.into_iter().map(|(f, _)| f).collect(),
            temporaries: temps,
            claims,
        })
    };
    let (_held, cleaned) = super::lock::lock_with(dir, &anim.manifest.path, gated)?;
    Ok(cleaned)
}

#[cfg(test)]
mod tests {
    use super::*;

    const SCENE: &str = "8 6  0 1 6  0 1 0  0 0  1 0 0 1\n1.0  0 1 0   1 0.9 0.2 0.1   0.7 0.3 0 1 0 0\n5 10 5  1 1 1  0.9";

    #[test]
    fn a_lone_run_clears_temporaries_before_another_may_join() {
        use notify::event::{AccessKind, AccessMode, EventKind, RemoveKind};
        use notify::Watcher;
        let dir = tempfile::tempdir().unwrap();
        std::fs::write(dir.path().join("s.txt"), SCENE).unwrap();
        let m = dir.path().join("m.toml");
        std::fs::write(&m, "scene = \"s.txt\"\nframes = 4\n").unwrap();
        let p = crate::project::Project::load(&m).unwrap();
        let anim = Animation::new(&p).unwrap();
        let frames = dir.path().join("frames");
        std::fs::create_dir(&frames).unwrap();
        let stale = frames.join(".frame_0002.png.Ab12Cd.tmp");
        std::fs::write(&stale, "half").unwrap();
        // The folder's events, in the order the system saw them.
        let (tx, rx) = std::sync::mpsc::channel();
        let mut watcher = notify::recommended_watcher(tx).unwrap();
        watcher
            .watch(&frames, notify::RecursiveMode::NonRecursive)
            .unwrap();
        let held = take(&anim, &frames).unwrap();
        assert!(held.alone() && !stale.exists());
        let gate = frames.join(super::super::lock::LOCK_FILE);
        let (mut removed, mut released) = (None, None);
        for k in 0.. {
            // A bound on the wait for the events, not a measured time.
            let event = rx.recv_timeout(std::time::Duration::from_secs(30));
            let event = event.expect("the events came").unwrap();
            let at = |path: &Path| event.paths.iter().any(|p| p == path);
            match event.kind {
                EventKind::Remove(RemoveKind::File | RemoveKind::Any) if at(&stale) => {
                    removed = Some(k)
                }
                EventKind::Access(AccessKind::Close(AccessMode::Write)) if at(&gate) => {
                    released.get_or_insert(k);
                }
                _ => {}
            }
            if removed.is_some() && released.is_some() {
                break;
            }
        }
        // Before, the gate was let go first: a run could join and have its temporary taken
        // for a killed run's.
        assert!(removed < released, "{removed:?} {released:?}");
    }

    #[test]
    fn frame_names_under_a_pattern() {
        let dir = tempfile::tempdir().unwrap();
        std::fs::write(dir.path().join("s.txt"), SCENE).unwrap();
        let m = dir.path().join("m.toml");
        std::fs::write(
            &m,
            "scene = \"s.txt\"\nframes = 10\n[output]\nname = \"f_###x\"\n",
        )
        .unwrap();
        let p = crate::project::Project::load(&m).unwrap();
        let anim = Animation::new(&p).unwrap();
        assert_eq!(frame_of(&anim, "f_012x.png"), Some(12));
        assert_eq!(frame_of(&anim, "f_00012x.png"), Some(12));
        assert_eq!(frame_of(&anim, "f_1234x.png"), Some(1234));
        assert_eq!(frame_of(&anim, "f_12x.png"), None);
        assert_eq!(frame_of(&anim, "f_0012x.jpg"), None);
        assert_eq!(frame_of(&anim, "f_+012x.png"), None);
        assert_eq!(frame_of(&anim, "g_012x.png"), None);
    }
}
