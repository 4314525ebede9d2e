//! The record a frame folder keeps of what produced it, so that `--resume` never mixes
//! frames of different scenes: the SHA-256 of the scene file's bytes and of the settings
//! that decide the pixels (frame count, camera path, resolution, samples, format).
//!
//! It is a small TOML file, `.animate-record.toml`, written atomically at the start of a
//! run:
//!
//! ```toml
//! manifest = "animations/orbit.toml"
//! scene = "scenes/orbit.txt"
//! scene_sha256 = "3f1c…"
//! settings_sha256 = "9a07…"
//! ```

use super::error::AnimError;
use serde::{Deserialize, Serialize};
use sha2::{Digest, Sha256};
use std::io::Write;
use std::path::Path;

/// The record's file name inside the frame folder.
pub const RECORD_FILE: &str = ".animate-record.toml";

/// What produced a frame folder.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Record {
    pub manifest: String,
    pub scene: String,
    pub scene_sha256: String,
    pub settings_sha256: String,
}

/// Lower-case hex SHA-256 of `bytes`.
pub fn sha256_hex(bytes: &[u8]) -> String {
    Sha256::digest(bytes)
        .iter()
        .map(|b| format!("{b:02x}"))
        .collect()
}

impl Record {
    /// A record from the manifest and scene paths, the scene file's bytes and a canonical
    /// description of the pixel-deciding settings.
    pub fn new(manifest: &Path, scene: &Path, scene_bytes: &[u8], settings: &str) -> Record {
        Record {
            manifest: manifest.display().to_string(),
            scene: scene.display().to_string(),
            scene_sha256: sha256_hex(scene_bytes),
            settings_sha256: sha256_hex(settings.as_bytes()),
        }
    }

    /// True when frames made under `self` and under `other` can share a folder.
    pub fn compatible(&self, other: &Record) -> bool {
        self.scene_sha256 == other.scene_sha256 && self.settings_sha256 == other.settings_sha256
    }

    /// Makes `dir` the home of frames made under this record: creates the folder and writes
    /// the record. With `refuse_foreign` (a `--resume` without `--force`), a folder whose
    /// record differs is refused, naming the digest that differs.
    pub fn claim(&self, dir: &Path, refuse_foreign: bool) -> Result<(), AnimError> {
        let folder = |source| AnimError::Folder {
            dir: dir.to_path_buf(),
            source,
        };
        std::fs::create_dir_all(dir).map_err(folder)?;
        if refuse_foreign {
            if let Some(old) = Record::read(dir).map_err(folder)? {
                if old.scene_sha256 != self.scene_sha256 {
                    let (dir, record) = (dir.to_path_buf(), "scene digest");
                    return Err(AnimError::ForeignFrames { dir, record });
                }
                if old.settings_sha256 != self.settings_sha256 {
                    let (dir, record) = (dir.to_path_buf(), "settings digest");
                    return Err(AnimError::ForeignFrames { dir, record });
                }
            }
        }
        self.write(dir).map_err(folder)
    }

    /// The record in `dir`, if there is a readable one.
    pub fn read(dir: &Path) -> std::io::Result<Option<Record>> {
        match std::fs::read_to_string(dir.join(RECORD_FILE)) {
            Ok(text) => Ok(toml::from_str(&text).ok()),
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => Ok(None),
            Err(e) => Err(e),
        }
    }

    /// Writes the record into `dir` atomically.
    pub fn write(&self, dir: &Path) -> std::io::Result<()> {
        let text = toml::to_string(self).map_err(std::io::Error::other)?;
        let path = dir.join(RECORD_FILE);
        let mut tmp = crate::output::temp_beside(&path)?;
        tmp.write_all(b"# What produced these frames; `animate --resume` compares it.\n")?;
        tmp.write_all(text.as_bytes())?;
        tmp.persist(path).map_err(|e| e.error)?;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sha256_of_abc() {
        // FIPS 180-2's example.
        assert_eq!(
            sha256_hex(b"abc"),
            "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad"
        );
    }

    #[test]
    fn round_trip_and_compatibility() {
        let dir = tempfile::tempdir().unwrap();
        let a = Record::new(
            Path::new("m.toml"),
            Path::new("s.txt"),
            b"scene",
            "frames=3",
        );
        a.write(dir.path()).unwrap();
        assert_eq!(Record::read(dir.path()).unwrap(), Some(a.clone()));
        let moved = Record::new(
            Path::new("other/m.toml"),
            Path::new("s.txt"),
            b"scene",
            "frames=3",
        );
        assert!(a.compatible(&moved));
        let edited = Record::new(
            Path::new("m.toml"),
            Path::new("s.txt"),
            b"scene!",
            "frames=3",
        );
        assert!(!a.compatible(&edited));
        let longer = Record::new(
            Path::new("m.toml"),
            Path::new("s.txt"),
            b"scene",
            "frames=4",
        );
        assert!(!a.compatible(&longer));
    }

    #[test]
    fn claim_refuses_a_foreign_folder_only_when_asked() {
        let dir = tempfile::tempdir().unwrap();
        let sub = dir.path().join("frames");
        let a = Record::new(
            Path::new("m.toml"),
            Path::new("s.txt"),
            b"scene",
            "frames=3",
        );
        a.claim(&sub, true).unwrap();
        let b = Record::new(
            Path::new("m.toml"),
            Path::new("s.txt"),
            b"other",
            "frames=3",
        );
        let err = b.claim(&sub, true).unwrap_err().to_string();
        assert!(err.contains("scene digest"), "{err}");
        let c = Record::new(
            Path::new("m.toml"),
            Path::new("s.txt"),
            b"scene",
            "frames=4",
        );
        let err = c.claim(&sub, true).unwrap_err().to_string();
        assert!(err.contains("settings digest"), "{err}");
        b.claim(&sub, false).unwrap();
        assert_eq!(Record::read(&sub).unwrap(), Some(b));
    }

    #[test]
    fn no_record_is_none() {
        let dir = tempfile::tempdir().unwrap();
        assert_eq!(Record::read(dir.path()).unwrap(), None);
    }
}
