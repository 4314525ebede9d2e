//! How `animate` shows a run: a progress bar on a terminal (indicatif: frames done to a
//! tenth, moving with the rows of the frames in progress; frames/s, or seconds per frame
//! when frames are slow; ETA, from the frames' predicted costs on a render), or JSON lines on standard error (`--events`), or nothing;
//! then the one-line summary. Also the hints that name command-line flags, which the library's messages
//! leave out.

use std::time::Instant;
use whitted::exit::Outcome;
use whitted_anim::check::{CheckError, Missing};
use whitted_anim::frames::pipeline::Summary;
use whitted_anim::frames::run::ffmpeg_raw_input;
use whitted_anim::preview::{PreviewError, PreviewSummary};
use whitted_anim::select::SelectError;
use whitted_anim::{AnimError, Animation, Event, Reporter};

pub mod bar;

/// One JSON object a line on standard error, per event.
pub struct JsonLines;

impl Reporter for JsonLines {
    fn event(&self, event: Event) {
        let line = match event {
            Event::Started { total, skipped } => {
                serde_json::json!({"event": "started", "total": total, "skipped": skipped})
            }
            Event::Finished {
                frame,
                seconds,
                rays,
            } => serde_json::json!({"event": "finished", "frame": frame,
                                    "seconds": seconds, "rays": rays.total()}),
            Event::Skipped { frame } => serde_json::json!({"event": "skipped", "frame": frame}),
            Event::Failed { frame } => serde_json::json!({"event": "failed", "frame": frame}),
            Event::Elsewhere { frame } => {
                serde_json::json!({"event": "elsewhere", "frame": frame})
            }
            Event::Sharing { pid } => serde_json::json!({"event": "sharing", "pid": pid}),
        };
        eprintln!("{line}");
    }
}

/// What a run says before it starts: that a selection is empty, and the ffmpeg input
/// options that read raw frames.
pub fn announce(anim: &Animation, frames: usize, raw: bool) {
    if frames == 0 {
        let all = anim.manifest.frames;
        eprintln!("animate: this selection has no frames ({all} in all): nothing to do");
    }
    if raw {
        eprintln!(
            "animate: raw RGB frames; for ffmpeg: {}",
            ffmpeg_raw_input(anim)
        );
    }
}

/// Before frames whose pixels are not square, that warning (`Animation::non_square`), and
/// before frames of another shape than a glTF camera's `aspectRatio` that one; and the
/// scene's mesh warnings (`Animation::mesh_warnings`), as `raytrace` prints them.
pub fn warn_if_non_square(anim: &Animation) {
    if let Some(w) = anim.non_square() {
        eprintln!("animate: warning: {w}");
    }
    let base = &anim.timeline.base;
    if let Some(w) = base.aspect_warning((anim.width, anim.height)) {
        eprintln!("animate: warning: {w}");
    }
    for w in anim.mesh_warnings() {
        eprintln!("animate: warning: {w}");
    }
}

/// A run's reporter that, when the run starts (it then knows which frames it renders:
/// not those `--resume` found up to date), says the library's warning before more than
/// `ENORMOUS` camera rays (`Animation::enormous_of`), with what the command line can do.
pub struct WarnEnormous<'a> {
    /// The reporter the events go on to.
    pub inner: &'a dyn Reporter,
    /// The animation and the run's frames (the first is the timed sample).
    pub anim: &'a Animation<'a>,
    pub frames: &'a [u32],
}

impl Reporter for WarnEnormous<'_> {
    fn event(&self, event: Event) {
        if let (Event::Started { total, skipped }, Some(&first)) = (&event, self.frames.first()) {
            if let Some(e) = self.anim.enormous_of(total.saturating_sub(*skipped), first) {
                eprintln!("animate: warning: {e} (Ctrl-C stops, --resume continues)");
            }
        }
        self.inner.event(event)
    }
}

/// The view's first lines: where it listens (standard error, with a warning when it
/// listens on every interface) and its URL alone on standard output, for scripts.
pub fn view_ready(manifest: &std::path::Path, url: &str, bind: std::net::IpAddr) {
    eprintln!(
        "animate: view of {} at {url} (Ctrl-C to stop)",
        manifest.display()
    );
    if bind.is_unspecified() {
        eprintln!(
            "animate: warning: listening on every interface ({bind}): whoever can reach this \
             machine can see the scene and make it render"
        );
    }
    whitted_anim::view::print_url(url);
}

/// What a run says when it finds another run of its manifest in its folder.
pub fn sharing(pid: u32) {
    eprintln!(
        "animate: sharing the folder with pid {pid}, another run of this manifest: each frame \
         is rendered once, by the run that claims it first"
    );
}

/// The one-line summary: frames, wall time, frames/s, rays/s, where they went.
pub fn summary(s: &Summary, start: Instant, place: &str) {
    let secs = start.elapsed().as_secs_f64().max(1e-9);
    let frames = |n: usize| if n == 1 { "frame" } else { "frames" };
    let elsewhere = match s.elsewhere {
        0 => String::new(),
        n => format!(", {n} by another run"),
    };
    eprintln!(
        "animate: {} {} rendered, {} up to date{elsewhere} in {:.2} s: {:.2} frames/s, {:.1} Mrays/s -> {place}",
        s.rendered,
        frames(s.rendered),
        s.skipped,
        secs,
        s.rendered as f64 / secs,
        s.rays.total() as f64 / secs / 1e6,
    );
}

/// A request on the command line that cannot be carried out, in words that name the flag
/// (exit status 2).
#[derive(Debug, thiserror::Error)]
#[error("{0}")]
pub struct Usage(pub String);

/// The exit-status row of an error from any part of the library or the command line.
pub fn outcome(e: &anyhow::Error) -> Outcome {
    if e.downcast_ref::<Usage>().is_some() {
        Outcome::BadInput
    } else if let Some(e) = e.downcast_ref::<AnimError>() {
        e.outcome()
    } else if let Some(e) = e.downcast_ref::<PreviewError>() {
        e.outcome()
    } else if let Some(e) = e.downcast_ref::<whitted_anim::view::ViewError>() {
        e.outcome()
    } else {
        Outcome::Failed
    }
}

/// The preview's one-line summary.
pub fn previewed(s: &PreviewSummary, start: Instant) {
    let (secs, w, h) = (start.elapsed().as_secs_f64(), s.width, s.height);
    let (n, dir) = (s.frames, whitted::fileloc::shown(&s.dir));
    eprintln!("animate: preview of {n} frames at {w}×{h} in {secs:.2} s -> {dir}");
}

/// The text of an error as the user sees it: the library's words, prefixed with the
/// option a value came from where the library only names the value.
pub fn message(e: &anyhow::Error) -> String {
    if let Some(e) = e.downcast_ref::<AnimError>() {
        anim_message(e)
    } else if let Some(e) = e.downcast_ref::<PreviewError>() {
        match e {
            PreviewError::ZeroScale => "--scale 0: K must be 1 or more".into(),
            PreviewError::ZeroEvery => "--every 0: N must be 1 or more".into(),
            PreviewError::SheetTooLarge { every, .. } => {
                format!("--every {every}: {e}; take a larger --every or --scale")
            }
            PreviewError::Anim(e) => anim_message(e),
            _ => e.to_string(),
        }
    } else {
        e.to_string()
    }
}

fn anim_message(e: &AnimError) -> String {
    match e {
        AnimError::Select(e) => select_message(e),
        _ => e.to_string(),
    }
}

/// A frame list's error names `--frames`, the only place a list comes from on the
/// command line, and shows the list with a caret under the column.
fn select_message(e: &SelectError) -> String {
    match e {
        SelectError::Frames {
            list,
            column,
            problem,
        } => {
            let caret = e.caret().unwrap_or_default();
            format!("--frames {list:?}, column {column}: {problem}\n{caret}")
        }
        SelectError::Shard(_) => e.to_string(),
    }
}

/// A check error, with the flag that settles it.
pub fn with_flags(e: CheckError) -> Usage {
    let hint = match &e {
        CheckError::NoCheckSection { what, .. } => match what {
            Missing::Frames => "; name them with --frames",
            Missing::References => "; name it with --references",
        },
        CheckError::FailPercent(_) => " (--fail-percent or [check] fail_percent)",
        CheckError::Flip(_) => " (--flip or [check] flip)",
        CheckError::Frames(e) => return Usage(select_message(e)),
    };
    Usage(format!("{e}{hint}"))
}

/// A hint naming the flag that helps, for errors where one does.
pub fn hint(e: &AnimError) -> Option<&'static str> {
    match e {
        AnimError::Interrupted(_) => Some("`--resume` completes the run"),
        AnimError::Reference(_) => Some("`animate bless` writes the references"),
        AnimError::FfmpegMissing => Some("or pipe `--stdout raw` into an encoder"),
        AnimError::Foreign { .. } => {
            Some("`--force` writes over them; `-o DIR` renders into another folder")
        }
        AnimError::Finals { .. } => Some(
            "`--force` writes over them; without `-o` a draft goes to a folder of its own \
             (DIR-draft-WxH)",
        ),
        AnimError::VideoExists(_) => Some("`--force` replaces it; `-o` names another file"),
        AnimError::NotOurs { .. } => Some("`--force` does it anyway"),
        AnimError::Overwrite { why, .. } if why.contains("not written") => {
            Some("`--force` writes over it")
        }
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use whitted_anim::select::parse_frames;

    #[test]
    fn usage_errors_are_bad_input() {
        let e = anyhow::Error::from(Usage("refusing".into()));
        assert_eq!(outcome(&e), Outcome::BadInput);
        assert_eq!(message(&e), "refusing");
    }

    #[test]
    fn library_errors_get_the_flag_they_came_from() {
        let e = anyhow::Error::from(PreviewError::ZeroScale);
        assert!(message(&e).starts_with("--scale 0"), "{}", message(&e));
        assert_eq!(outcome(&e), Outcome::BadInput);
        let e = anyhow::Error::from(PreviewError::ZeroEvery);
        assert!(message(&e).starts_with("--every 0"), "{}", message(&e));
        let list = || parse_frames("3-1x0", 12).unwrap_err();
        let e = anyhow::Error::from(AnimError::from(list()));
        let said = "--frames \"3-1x0\", column 5: the step must not be 0\n  3-1x0\n      ^";
        assert_eq!(message(&e), said);
        assert_eq!(outcome(&e), Outcome::BadInput);
        let e = with_flags(CheckError::Frames(list()));
        assert_eq!(e.0, said);
    }
}
