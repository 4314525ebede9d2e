//! Exporters of a [`CheckReport`], one small file per format behind one trait (as
//! hyperfine's `export/`): `table` (the text `animate check` prints), `json`, `junit`
//! (JUnit XML for CI servers) and `html` (a page with the pictures of failing frames).
//! Each exporter only reads the report; files appear atomically (a temporary name, then
//! a rename), so a stopped export never leaves a half-written file under its final name.

mod html;
mod json;
mod junit;
mod table;

pub use html::Html;
pub use json::Json;
pub use junit::Junit;
pub use table::Table;

use super::report::CheckReport;
use std::io::Write;
use std::path::{Path, PathBuf};
use whitted::output::temp_beside;

/// Why an export failed.
#[derive(Debug, thiserror::Error)]
pub enum ExportError {
    /// The report file (or its temporary) cannot be written or renamed into place.
    #[error("cannot write {path}: {source}")]
    Io {
        /// The report file's final name.
        path: PathBuf,
        /// The system's reason.
        #[source]
        source: std::io::Error,
    },
    /// Standard output was closed or failed.
    #[error("cannot write standard output: {0}")]
    Stdout(#[source] std::io::Error),
    /// The XML writer refused the document (the text says why).
    #[error("cannot build the JUnit XML: {0}")]
    Junit(String),
}

/// A format a check report can be written in.
pub trait Exporter {
    /// Writes `report` where this exporter was told to.
    fn export(&self, report: &CheckReport) -> Result<(), ExportError>;
}

/// Where a text export goes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Sink {
    /// Standard output.
    Stdout,
    /// This file, written atomically.
    File(PathBuf),
}

impl Sink {
    fn write(&self, bytes: &[u8]) -> Result<(), ExportError> {
        match self {
            Sink::Stdout => {
                let mut out = std::io::stdout().lock();
                match out.write_all(bytes).and_then(|()| out.flush()) {
                    // The reader went away (`animate check M | head -1`): the check's
                    // verdict stands, the other exporters still write their files.
                    Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(()),
                    other => other.map_err(ExportError::Stdout),
                }
            }
            Sink::File(path) => write_file(path, bytes),
        }
    }
}

/// Writes `bytes` to `path` through a temporary file beside it and a rename.
pub(crate) fn write_file(path: &Path, bytes: &[u8]) -> Result<(), ExportError> {
    let io = |source| ExportError::Io {
        path: path.to_path_buf(),
        source,
    };
    let mut tmp = temp_beside(path).map_err(io)?;
    tmp.write_all(bytes).map_err(io)?;
    tmp.persist(path).map_err(|e| io(e.error))?;
    Ok(())
}

/// Copies `from` to `to` atomically.
pub(crate) fn copy_file(from: &Path, to: &Path) -> Result<(), ExportError> {
    let bytes = std::fs::read(from).map_err(|source| ExportError::Io {
        path: from.to_path_buf(),
        source,
    })?;
    write_file(to, &bytes)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn write_file_replaces_and_leaves_no_temporary() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("a.xml");
        write_file(&path, b"one").unwrap();
        write_file(&path, b"two").unwrap();
        assert_eq!(std::fs::read(&path).unwrap(), b"two");
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 1);
    }

    #[test]
    fn write_file_into_a_missing_folder_is_an_error_naming_it() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("no/such/a.xml");
        let e = write_file(&path, b"x").unwrap_err().to_string();
        assert!(e.contains("no/such/a.xml"), "{e}");
    }
}
