//! The progress bars of `animate` (indicatif): `RowBar` for a render, moving with the rows
//! of the frames in progress and, when the frames' predicted costs are given, weighted by
//! them so that the ETA holds when later frames cost more; `Bar` for work counted in
//! frames (encode, preview).

use indicatif::{ProgressBar, ProgressState, ProgressStyle};
use std::io::IsTerminal;
use std::sync::Arc;
use whitted::render::control;
use whitted_anim::{Event, Reporter};
use whitted_cmd::progress::{RowPoller, Weighted};

/// The progress bar: frames done (skipped ones count as done), frames/s, ETA.
pub struct Bar(ProgressBar);

/// A render's progress bar, counted in rows (`whitted::render::control`) so that it
/// moves within a frame: frames done to a tenth, frames/s or s/frame, ETA.
pub struct RowBar {
    bar: ProgressBar,
    /// The frames' predicted costs, when the bar moves by them.
    weighted: Option<Arc<Weighted>>,
    rows_per_frame: u64,
    /// What moves the bar (none when it is hidden); it counts from the rows done before
    /// the run (the counter is process-wide), minus skipped frames.
    poll: Option<RowPoller>,
    /// No lines besides the bar (`--quiet`).
    quiet: bool,
}

impl RowBar {
    /// Whether a bar would show (standard error a terminal, not `quiet`).
    pub fn shown(quiet: bool) -> bool {
        !quiet && std::io::stderr().is_terminal()
    }

    /// A bar for `total` frames of `rows_per_frame` rows each, hidden with `quiet` or when
    /// standard error is not a terminal; moving by the frames' predicted costs when
    /// `weighted` is given, so that its ETA holds when later frames cost more.
    pub fn weighted(
        total: usize,
        rows_per_frame: u64,
        quiet: bool,
        weighted: Option<Arc<Weighted>>,
    ) -> RowBar {
        let rows = rows_per_frame.max(1);
        let hidden = !RowBar::shown(quiet);
        let bar = if hidden {
            ProgressBar::hidden()
        } else {
            let length = weighted.as_ref().map(|w| w.length());
            ProgressBar::new(length.unwrap_or(total as u64 * rows))
        };
        let (frames_of, rate_of) = (weighted.clone(), weighted.clone());
        let style = ProgressStyle::with_template(
            "{elapsed_precise} [{wide_bar}] {frames}/{total} frames  {rate}  ETA {eta}",
        )
        .unwrap_or_else(|_| ProgressStyle::default_bar())
        .with_key(
            "frames",
            move |s: &ProgressState, w: &mut dyn std::fmt::Write| {
                let _ = match &frames_of {
                    Some(weights) => write!(w, "{}", weights.frames_done()),
                    None => write!(w, "{:.1}", s.pos() as f64 / rows as f64),
                };
            },
        )
        .with_key(
            "total",
            move |_: &ProgressState, w: &mut dyn std::fmt::Write| {
                let _ = write!(w, "{total}");
            },
        )
        .with_key(
            "rate",
            move |s: &ProgressState, w: &mut dyn std::fmt::Write| {
                let per_sec = match &rate_of {
                    Some(weights) => weights.frames_done() as f64 / s.elapsed().as_secs_f64(),
                    None => s.per_sec() / rows as f64,
                };
                let _ = write!(w, "{}", rate(per_sec));
            },
        );
        bar.set_style(style.progress_chars("=> "));
        let poll = (!hidden).then(|| {
            let (bar, weights) = (bar.clone(), weighted.clone());
            RowPoller::start(move |rows| match &weights {
                Some(w) => bar.set_position(w.position(rows)),
                None => bar.set_position(rows),
            })
        });
        RowBar {
            bar,
            weighted,
            rows_per_frame: rows,
            poll,
            quiet,
        }
    }

    pub fn finish(&self) {
        if let Some(poll) = &self.poll {
            poll.stop();
        }
        self.bar.finish_and_clear();
    }
}

impl Reporter for RowBar {
    fn event(&self, event: Event) {
        if let (
            Some(w),
            Event::Finished { frame, .. } | Event::Skipped { frame } | Event::Elsewhere { frame },
        ) = (&self.weighted, event)
        {
            w.done(frame);
        }
        if let (Event::Sharing { pid }, false) = (event, self.quiet) {
            self.bar.suspend(|| super::sharing(pid));
        }
        if let Event::Started { skipped, .. } = event {
            // Skipped frames count as done: move the base back by their rows.
            let rows = skipped as u64 * self.rows_per_frame;
            if let Some(poll) = &self.poll {
                poll.set_base(control::rows_done().saturating_sub(rows));
            }
            if self.weighted.is_none() {
                self.bar.set_position(rows);
            }
            self.bar.reset_eta();
        }
    }
}

/// A rate in words: frames/s, or seconds per frame below one frame a second.
pub fn rate(frames_per_second: f64) -> String {
    if frames_per_second >= 1.0 {
        format!("{frames_per_second:.1} frames/s")
    } else if frames_per_second > 0.0 {
        format!("{:.1} s/frame", 1.0 / frames_per_second)
    } else {
        "… s/frame".into()
    }
}

impl Bar {
    /// A bar for `total` frames, hidden with `quiet` or when standard error is not a
    /// terminal.
    pub fn new(total: usize, quiet: bool) -> Bar {
        if quiet || !std::io::stderr().is_terminal() {
            return Bar(ProgressBar::hidden());
        }
        let bar = ProgressBar::new(total as u64);
        let style = ProgressStyle::with_template(
            "{elapsed_precise} [{wide_bar}] {pos}/{len} frames  {fps}  ETA {eta}",
        )
        .unwrap_or_else(|_| ProgressStyle::default_bar())
        .with_key(
            "fps",
            |state: &ProgressState, w: &mut dyn std::fmt::Write| {
                let _ = write!(w, "{:.1} frames/s", state.per_sec());
            },
        );
        bar.set_style(style.progress_chars("=> "));
        Bar(bar)
    }

    /// Shows `done` of `total` (for work counted outside the render pipeline).
    pub fn set(&self, done: usize, total: usize) {
        self.0.set_length(total as u64);
        self.0.set_position(done as u64);
    }

    pub fn finish(&self) {
        self.0.finish_and_clear();
    }
}

impl Reporter for Bar {
    fn event(&self, event: Event) {
        match event {
            Event::Started { skipped, .. } => {
                self.0.set_position(skipped as u64);
                self.0.reset_eta();
            }
            Event::Finished { .. } | Event::Elsewhere { .. } => self.0.inc(1),
            Event::Skipped { .. } | Event::Failed { .. } | Event::Sharing { .. } => {}
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn slow_frames_are_shown_in_seconds_per_frame() {
        assert_eq!(rate(12.34), "12.3 frames/s");
        assert_eq!(rate(1.0), "1.0 frames/s");
        // 0.08 frames/s is 12.5 s a frame.
        assert_eq!(rate(0.08), "12.5 s/frame");
        assert_eq!(rate(0.0), "… s/frame");
    }
}
