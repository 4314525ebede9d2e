//! `animate status`: which frames of the folder are up to date, stale, missing or past the
//! end, as a table or JSON (with the predicted rays of each frame); exit 0 when all are up
//! to date, 1 when not, whatever became of the text.

use super::emit;
use crate::error::AnimError;
use crate::frames::balance;
use crate::frames::run;
use crate::frames::status::status as folder_status;
use crate::project::{Animation, Project};
use crate::select::sorted;
use std::io::Write;
use std::path::PathBuf;
use whitted::exit::Outcome;

/// What `animate status` was asked.
#[derive(Clone, Debug, Default)]
pub struct StatusRequest {
    /// The frame list (fileseq's grammar), or every frame.
    pub frames: Option<String>,
    /// The frame folder instead of the manifest's.
    pub dir: Option<PathBuf>,
    /// JSON instead of the table.
    pub json: bool,
    /// Decode every frame too.
    pub verify: bool,
}

/// Runs `animate status` on `project` (on the current rayon pool), writing to `out`.
pub fn status(
    project: &Project,
    request: &StatusRequest,
    out: &mut dyn Write,
) -> Result<Outcome, AnimError> {
    let anim = Animation::new(project)?;
    let frames = sorted(&run::frames_of(&anim, request.frames.as_deref(), None)?);
    let dir = (request.dir.clone()).unwrap_or_else(|| project.manifest.output.dir.clone());
    let report = folder_status(&anim, &dir, &frames, request.verify);
    let text = match request.json {
        true => {
            let mut doc = report.json(&dir);
            let costs = balance::predicted_costs(&anim, &frames)?;
            let per_frame: serde_json::Map<String, serde_json::Value> = frames
                .iter()
                .zip(costs)
                .map(|(f, c)| (f.to_string(), c.into()))
                .collect();
            doc["predicted_rays"] = per_frame.into();
            doc["draft"] = project.manifest.draft.clone().into();
            serde_json::to_string_pretty(&doc).unwrap_or_default() + "\n"
        }
        false => report.table(&dir),
    };
    // The verdict stands whether or not the reader took the text.
    emit(out, text.as_bytes())?;
    Ok(match report.complete() {
        true => Outcome::Success,
        false => Outcome::Failed,
    })
}
