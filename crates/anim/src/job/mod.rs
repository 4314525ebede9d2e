//! `animate job MANIFEST --openjd`: an Open Job Description template (the job format of
//! AWS Deadline Cloud, specification 2023-09 with the TASK_CHUNKING extension) that renders
//! the manifest on a farm: a `Render` step whose one task parameter, `Frame`, is a
//! `CHUNK[INT]` range, each chunk running
//!
//! ```text
//! {{Param.Animate}} {{Param.Manifest}} -o {{Param.OutDir}} --frames {{Task.Param.Frame}} --resume --quiet
//! ```
//!
//! (a chunk arrives as an OpenJD range such as `0-3`, which the frame grammar reads), and,
//! when the job renders the whole sequence, a `Video` step that depends on it and encodes
//! the finished frames as `animate encode` does (its readiness check, options and
//! temporary-and-rename):
//!
//! ```text
//! {{Param.Animate}} encode {{Param.Manifest}} --dir {{Param.OutDir}} -o {{Param.Video}} --force --quiet
//! ```
//!
//! followed by the `--codec`, `--crf` and `--pix-fmt` the job was given (`Video`); a job
//! of some frames has no video step, and is refused them.
//!
//! The chunk
//! size is `--chunk N` frames, or comes from `--chunk-seconds S` and the cost estimate
//! (`frames::estimate`), which also becomes the chunks' `targetRuntimeSeconds` so that a
//! scheduler that adapts chunk sizes aims at the same duration.

use crate::frames::status::ranges;
use crate::manifest::Manifest;
use serde_json::{json, Value};
use std::path::Path;

/// The video step of a job of every frame: the extra arguments of its `animate encode`.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Video {
    /// `--codec C`, `--crf N`, `--pix-fmt F`, as given.
    pub args: Vec<String>,
}

impl Video {
    /// The video step of `frames` of `m` with `encoding`: `None` for a job of some frames
    /// (refused when an encoding was asked), or why the encoding cannot be written into
    /// a template.
    pub fn new(
        m: &Manifest,
        frames: &[u32],
        encoding: &crate::frames::run::Encoding,
    ) -> Result<Option<Video>, String> {
        let mut args = Vec::new();
        let options = [
            ("--codec", encoding.codec.clone()),
            ("--crf", encoding.crf.map(|n| n.to_string())),
            ("--pix-fmt", encoding.pix_fmt.clone()),
        ];
        for (flag, value) in options {
            let Some(value) = value else { continue };
            if !plain(&value) || value.trim().is_empty() {
                return Err(format!(
                    "{flag} {value:?} cannot go into a job template: no control characters, braces or empty values"
                ));
            }
            args.extend([flag.to_string(), value]);
        }
        if !frames.iter().copied().eq(0..m.frames) {
            return match args.first() {
                Some(flag) => Err(format!(
                    "{flag} applies to the job's video step, and a job of some frames (--frames) has none: `animate encode` needs every frame"
                )),
                None => Ok(None),
            };
        }
        Ok(Some(Video { args }))
    }
}

/// How the frames are cut into tasks.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Chunking {
    /// N frames a task.
    Frames(u32),
    /// About this many seconds a task, with the expected seconds of one frame.
    Seconds {
        /// The target duration of a task.
        target: u32,
        /// The expected seconds of a mean frame on this machine.
        per_frame: f64,
    },
}

impl Chunking {
    /// Frames a task: at least 1.
    pub fn size(&self) -> u32 {
        match *self {
            Chunking::Frames(n) => n.max(1),
            Chunking::Seconds { target, per_frame } => {
                let n = f64::from(target) / per_frame.max(1e-9);
                n.round().clamp(1.0, f64::from(u32::MAX)) as u32
            }
        }
    }
}

/// `path` relative to the folder `base` (both absolute): OpenJD joins a PATH parameter's
/// default to the template's folder, and refuses absolute defaults.
pub fn relative_to(path: &Path, base: &Path) -> std::path::PathBuf {
    let (p, b): (Vec<_>, Vec<_>) = (path.components().collect(), base.components().collect());
    let common = p.iter().zip(&b).take_while(|(x, y)| x == y).count();
    let mut out = std::path::PathBuf::new();
    for _ in common..b.len() {
        out.push("..");
    }
    for c in &p[common..] {
        out.push(c);
    }
    if out.as_os_str().is_empty() {
        out.push(".");
    }
    out
}

/// Whether `text` can stand in a template as it is: no control character (OpenJD refuses
/// them) and no `{{` or `}}` (a format string would read them as an expression).
fn plain(text: &str) -> bool {
    !text.chars().any(char::is_control) && !text.contains("{{") && !text.contains("}}")
}

/// `text` made plain (see [`plain`]): each control character and brace becomes `_`, and it
/// is cut to `max` characters (OpenJD's names are at most 128).
fn escaped(text: &str, max: usize) -> String {
    text.chars()
        .map(|c| match c.is_control() || c == '{' || c == '}' {
            true => '_',
            false => c,
        })
        .take(max)
        .collect()
}

/// A PATH job parameter; its default only when it stays inside the template's folder
/// (OpenJD refuses defaults that walk up) and is plain text, else the job must be given it
/// (`-p NAME=…`).
fn path_param(name: &str, kind: &str, flow: &str, path: &Path) -> Value {
    let mut p = json!({"name": name, "type": "PATH", "objectType": kind, "dataFlow": flow});
    let inside = path.components().all(|c| {
        matches!(
            c,
            std::path::Component::Normal(_) | std::path::Component::CurDir
        )
    });
    if inside && plain(&path.display().to_string()) {
        p["default"] = path.display().to_string().into();
    }
    p
}

/// The template for `frames` (in number order) of the manifest at `manifest_path`, into
/// `out_dir` (both relative to the folder the template is written into), with the video
/// step `video_step` (`Video::new`) when there is one.
pub fn openjd_template(
    manifest_path: &Path,
    out_dir: &Path,
    frames: &[u32],
    chunking: Chunking,
    video_step: Option<Video>,
) -> Value {
    let mut chunks = json!({
        "defaultTaskCount": chunking.size(),
        "rangeConstraint": "CONTIGUOUS",
    });
    if let Chunking::Seconds { target, .. } = chunking {
        chunks["targetRuntimeSeconds"] = target.into();
    }
    let name = manifest_path
        .file_stem()
        .map_or("animation".into(), |s| s.to_string_lossy().into_owned());
    let dir_name = out_dir
        .file_name()
        .map_or("frames".into(), |n| n.to_string_lossy().into_owned());
    let video = out_dir
        .with_file_name(format!("{dir_name}.mp4"))
        .display()
        .to_string();
    let render = json!({
        "name": "Render",
        "parameterSpace": {"taskParameterDefinitions": [{
            "name": "Frame",
            "type": "CHUNK[INT]",
            "range": ranges(frames),
            "chunks": chunks,
        }]},
        "script": {"actions": {"onRun": {
            "command": "{{Param.Animate}}",
            "args": ["{{Param.Manifest}}", "-o", "{{Param.OutDir}}",
                     "--frames", "{{Task.Param.Frame}}", "--resume", "--quiet"],
        }}},
    });
    let mut params = vec![
        json!({"name": "Animate", "type": "STRING", "default": "animate",
               "description": "The animate command (a path, or a name on PATH)."}),
        path_param("Manifest", "FILE", "IN", manifest_path),
        path_param("OutDir", "DIRECTORY", "OUT", out_dir),
    ];
    let mut steps = vec![render];
    // `animate encode` needs every frame of the manifest: a job of some frames makes none.
    if let Some(step) = video_step {
        let mut args: Vec<Value> = ["encode", "{{Param.Manifest}}", "--dir", "{{Param.OutDir}}"]
            .into_iter()
            .chain(["-o", "{{Param.Video}}", "--force", "--quiet"])
            .map(Value::from)
            .collect();
        args.extend(step.args.into_iter().map(Value::from));
        params.push(path_param("Video", "FILE", "OUT", Path::new(&video)));
        steps.push(json!({
            "name": "Video",
            "dependencies": [{"dependsOn": "Render"}],
            "script": {"actions": {"onRun": {
                "command": "{{Param.Animate}}",
                "args": args,
            }}},
        }));
    }
    json!({
        "specificationVersion": "jobtemplate-2023-09",
        "extensions": ["TASK_CHUNKING"],
        "name": escaped(&format!("animate {name}"), 128),
        "description": escaped(&format!("Render {} frames of {} with animate, then encode them.", frames.len(), manifest_path.display()), 2048),
        "parameterDefinitions": params,
        "steps": steps,
    })
}
