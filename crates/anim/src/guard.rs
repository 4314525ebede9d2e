//! Outputs that must not destroy what they do not own: a report, a job template or a page
//! (`check --junit FILE`, `--html DIR`, `job -o FILE`) is refused when its path is one of
//! the run's inputs (the manifest, the scene), a folder, or an existing file that the tool
//! did not write (one without the mark each writer leaves in its files), unless forced.
//! The inputs are refused even when forced: nothing asked of a report is worth the
//! manifest it reads.

use crate::error::AnimError;
use crate::project::Project;
use std::io::Read;
use std::path::{Path, PathBuf};

/// The text every file of one kind the tool writes contains within its first 64 KiB.
#[derive(Clone, Copy, Debug)]
pub struct Mark(pub &'static str);

/// JUnit XML (`check --junit`): its test cases' class name.
pub const JUNIT: Mark = Mark("classname=\"animate check ");
/// The HTML report's page (`check --html`): its title.
pub const HTML: Mark = Mark("<title>animate check: ");
/// An OpenJD template (`job --openjd`): its parameter for the command.
pub const OPENJD: Mark = Mark("\"name\": \"Animate\"");

/// The files a run of `project` reads, as given.
pub fn inputs(project: &Project) -> Vec<PathBuf> {
    let m = &project.manifest;
    vec![m.path.clone(), m.scene.clone()]
}

/// Whether `a` and `b` name the same file (both existing).
fn same_file(a: &Path, b: &Path) -> bool {
    matches!((a.canonicalize(), b.canonicalize()), (Ok(x), Ok(y)) if x == y)
}

/// Whether the file `path` holds `mark` near its start.
fn marked(path: &Path, mark: Mark) -> bool {
    let mut head = Vec::new();
    let read = std::fs::File::open(path).and_then(|f| f.take(64 << 10).read_to_end(&mut head));
    read.is_ok() && String::from_utf8_lossy(&head).contains(mark.0)
}

/// Refuses, before anything is rendered, an output whose folder cannot hold it: `path`'s
/// folder missing (a file is written into an existing folder), or, when `creates` (the
/// folder is made if missing: `--html DIR`), a file where a folder on its way should be.
pub fn folder(path: &Path, creates: bool) -> Result<(), AnimError> {
    let parent = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    let refuse = |why: String| {
        Err(AnimError::Overwrite {
            path: path.to_path_buf(),
            why,
        })
    };
    if parent.is_dir() {
        return Ok(());
    }
    if !creates {
        let why = format!("its folder {} does not exist", parent.display());
        return refuse(why);
    }
    match parent.ancestors().find(|a| a.exists()) {
        Some(a) if !a.is_dir() => refuse(format!(
            "{} is a file, so the folder {} cannot be made",
            a.display(),
            parent.display()
        )),
        _ => Ok(()),
    }
}

/// Refuses to write `path` (a file of the kind `mark` marks) over one of `inputs`, over a
/// folder, or, unless `force`, over an existing file without the mark.
pub fn output(path: &Path, inputs: &[PathBuf], mark: Mark, force: bool) -> Result<(), AnimError> {
    let refuse = |why: &str| {
        Err(AnimError::Overwrite {
            path: path.to_path_buf(),
            why: why.to_string(),
        })
    };
    if path.is_dir() {
        return refuse("it is a folder, and a file is to be written");
    }
    if inputs.iter().any(|i| same_file(path, i)) {
        return refuse("it is an input of this run and would be overwritten");
    }
    if !force && path.exists() && !marked(path, mark) {
        return refuse("it exists and was not written by animate");
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inputs_folders_and_unmarked_files_are_refused() {
        let dir = tempfile::tempdir().unwrap();
        let (input, mine, theirs) = (
            dir.path().join("m.toml"),
            dir.path().join("a.xml"),
            dir.path().join("b.xml"),
        );
        std::fs::write(&input, "frames = 1").unwrap();
        std::fs::write(&mine, "<testcase classname=\"animate check m.toml\"/>").unwrap();
        std::fs::write(&theirs, "<x/>").unwrap();
        let inputs = [input.clone()];
        let why = |p: &Path, force| output(p, &inputs, JUNIT, force).map_err(|e| e.to_string());
        assert!(why(&input, true)
            .unwrap_err()
            .contains("an input of this run"));
        assert!(why(dir.path(), true).unwrap_err().contains("is a folder"));
        assert!(why(&theirs, false)
            .unwrap_err()
            .contains("not written by animate"));
        assert_eq!(why(&theirs, true), Ok(()));
        assert_eq!(why(&mine, false), Ok(()));
        assert_eq!(why(&dir.path().join("new.xml"), false), Ok(()));
    }
}
