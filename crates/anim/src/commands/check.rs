//! `animate check` as one call: the outputs guarded first (reports must not overwrite the
//! run's inputs or others' files), then the check, then every exporter; exit 0 when every
//! frame passed, 1 when one failed, whatever became of standard output's text.

use crate::check::export::Exporter;
use crate::check::{check as run_check, CheckOptions};
use crate::error::AnimError;
use crate::guard::{self, Mark};
use crate::project::{Animation, Project};
use std::path::PathBuf;
use whitted::exit::Outcome;

/// What `animate check` was asked, its options resolved.
pub struct CheckRequest {
    /// The frames, references, limits and report folder.
    pub options: CheckOptions,
    /// Where the results go (a table or JSON on standard output, JUnit, HTML).
    pub exporters: Vec<Box<dyn Exporter + Send + Sync>>,
    /// The files the exporters write, each with the mark of its kind.
    pub outputs: Vec<(PathBuf, Mark)>,
    /// Write the outputs over files animate did not write.
    pub force: bool,
}

/// Runs `animate check` on the current rayon pool.
pub fn check(project: &Project, request: &CheckRequest) -> Result<Outcome, AnimError> {
    let anim = Animation::new(project)?;
    let inputs = guard::inputs(project);
    for (path, mark) in &request.outputs {
        guard::output(path, &inputs, *mark, request.force)?;
        // Every report's folder before the render, not after it: an HTML page's is made.
        guard::folder(path, mark.0 == guard::HTML.0)?;
    }
    let report = run_check(&anim, &request.options)?;
    for exporter in &request.exporters {
        exporter.export(&report)?;
    }
    Ok(match report.pass {
        true => Outcome::Success,
        false => Outcome::Failed,
    })
}
