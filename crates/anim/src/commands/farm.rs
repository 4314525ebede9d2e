//! `animate job` (an Open Job Description template of the render, written to a file or
//! standard output) and `animate estimate` (the predicted cost per frame range and shard).

use super::{emit, CUT_SHORT};
use crate::error::AnimError;
use crate::frames::estimate::Estimate;
use crate::frames::run;
use crate::guard;
use crate::job::{openjd_template, relative_to, Chunking};
use crate::project::{Animation, Project};
use crate::select::sorted;
use std::io::Write;
use std::path::{Path, PathBuf};
use whitted::exit::Outcome;

/// What `animate job` was asked.
#[derive(Clone, Debug, Default)]
pub struct JobRequest {
    /// The manifest as given (the template names it relative to its own folder).
    pub manifest: PathBuf,
    /// The frame list, or every frame.
    pub frames: Option<String>,
    /// The frame folder the job renders into, instead of the manifest's.
    pub out_dir: Option<PathBuf>,
    /// The template's file, or standard output.
    pub out: Option<PathBuf>,
    /// Frames a task.
    pub chunk: Option<u32>,
    /// About this many seconds a task (from an estimate).
    pub chunk_seconds: Option<u32>,
    /// Write over an existing file animate did not write.
    pub force: bool,
    /// The video step's `--codec`, `--crf`, `--pix-fmt` (as `animate encode`'s).
    pub encoding: crate::frames::run::Encoding,
}

/// A written template: its frame count and chunk size, for the summary line.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Job {
    /// The frames of the job.
    pub frames: usize,
    /// Frames a task.
    pub chunk: u32,
}

/// Writes the OpenJD template of `project` to `request.out`, or to `out`; `Err(outcome)`
/// ([`CUT_SHORT`]) when `out`'s reader went away before the template was whole.
pub fn job(
    project: &Project,
    request: &JobRequest,
    out: &mut dyn Write,
) -> Result<Result<Job, Outcome>, AnimError> {
    let (m, anim) = (&project.manifest, Animation::new(project)?);
    let frames = sorted(&run::frames_of(&anim, request.frames.as_deref(), None)?);
    let video = crate::job::Video::new(m, &frames, &request.encoding).map_err(AnimError::Job)?;
    if let Some(file) = &request.out {
        guard::output(file, &guard::inputs(project), guard::OPENJD, request.force)?;
    }
    let chunking = match request.chunk_seconds {
        Some(target) => {
            let e = Estimate::new(&anim, &frames)?;
            let per_frame = e.seconds(e.total()) / frames.len().max(1) as f64;
            Chunking::Seconds { target, per_frame }
        }
        None => Chunking::Frames(request.chunk.unwrap_or(10)),
    };
    let absolute = |p: &Path| std::path::absolute(p).unwrap_or(p.to_path_buf());
    let out_dir = absolute(request.out_dir.as_deref().unwrap_or(&m.output.dir));
    let manifest = absolute(&request.manifest);
    // OpenJD wants the default paths relative to the template's folder.
    let here = absolute(Path::new("."));
    let folder = match &request.out {
        Some(file) => match file.parent().filter(|p| !p.as_os_str().is_empty()) {
            Some(parent) => absolute(parent),
            None => here,
        },
        None => here,
    };
    let (manifest, out_dir) = (
        relative_to(&manifest, &folder),
        relative_to(&out_dir, &folder),
    );
    let template = openjd_template(&manifest, &out_dir, &frames, chunking, video);
    let text = serde_json::to_string_pretty(&template).unwrap_or_default() + "\n";
    match &request.out {
        Some(file) => {
            let write = || -> std::io::Result<()> {
                let mut tmp = whitted::output::temp_beside(file)?;
                tmp.write_all(text.as_bytes())?;
                tmp.persist(file).map_err(|e| e.error)?;
                Ok(())
            };
            write().map_err(|source| AnimError::Overwrite {
                path: file.clone(),
                why: format!("cannot write it ({source})"),
            })?
        }
        None if !emit(out, text.as_bytes())? => return Ok(Err(CUT_SHORT)),
        None => {}
    }
    Ok(Ok(Job {
        frames: frames.len(),
        chunk: chunking.size(),
    }))
}

/// Writes `animate estimate`'s table of `project` (with `shards` shards when given) to
/// `out`, measuring on the current rayon pool.
pub fn estimate(
    project: &Project,
    frames: Option<&str>,
    shards: Option<u32>,
    out: &mut dyn Write,
) -> Result<Outcome, AnimError> {
    let anim = Animation::new(project)?;
    let frames = run::frames_of(&anim, frames, None)?;
    let e = Estimate::new(&anim, &frames)?;
    Ok(match emit(out, e.table(shards.unwrap_or(0)).as_bytes())? {
        true => Outcome::Success,
        false => CUT_SHORT,
    })
}
