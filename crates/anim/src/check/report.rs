//! The value `animate check` produces, [`CheckReport`]: what was checked against what,
//! with which tolerance, and per frame its figures, the limits it broke, how long it took
//! and where its images are. Every exporter (`export/`) reads this value and nothing else.

use super::diff::{Comparison, Limit, Tolerance};
use serde::Serialize;
use std::path::PathBuf;

/// The outcome for one checked frame.
#[derive(Clone, Debug, Serialize)]
pub struct FrameReport {
    /// The frame's number in the sequence.
    pub frame: u32,
    /// The frame's file name stem (the manifest's name pattern), e.g. `frame_0005`.
    pub name: String,
    /// Its figures against the reference.
    #[serde(flatten)]
    pub comparison: Comparison,
    /// The mean FLIP error, when the tolerance has a FLIP limit.
    pub flip: Option<f64>,
    /// The limits the frame broke, in the order fail_percent, hard_fail, flip.
    pub failed: Vec<Limit>,
    /// True when `failed` is empty.
    pub pass: bool,
    /// Seconds to render and compare the frame.
    pub seconds: f64,
    /// The reference it was compared with.
    pub reference_image: PathBuf,
    /// The rendered frame as written into the report folder (failing frames only).
    pub rendered_image: Option<PathBuf>,
    /// The diff heat map (failing frames only).
    pub diff_image: Option<PathBuf>,
    /// The FLIP error map (failing frames with a FLIP limit only).
    pub flip_image: Option<PathBuf>,
}

/// A whole check.
#[derive(Clone, Debug, Serialize)]
pub struct CheckReport {
    /// The manifest checked.
    pub manifest: PathBuf,
    /// The folder of reference PNGs.
    pub references: PathBuf,
    /// The folder of images of failing frames.
    pub report: PathBuf,
    /// The frames' width in pixels.
    pub width: u32,
    /// The frames' height in pixels.
    pub height: u32,
    /// The limits every frame was held to.
    pub tolerance: Tolerance,
    /// True when every frame passed.
    pub pass: bool,
    /// One report per checked frame, in frame order.
    pub frames: Vec<FrameReport>,
}

impl CheckReport {
    /// The frames that failed.
    pub fn failures(&self) -> impl Iterator<Item = &FrameReport> {
        self.frames.iter().filter(|f| !f.pass)
    }

    /// The one-line verdict: `PASS: …` or `FAIL: …`.
    pub fn verdict(&self) -> String {
        let failed = self.failures().count();
        if failed == 0 {
            format!("PASS: {} frame(s) within tolerance", self.frames.len())
        } else {
            format!(
                "FAIL: {failed} of {} frame(s); rendered frames and diff images in {}",
                self.frames.len(),
                self.report.display()
            )
        }
    }
}

impl FrameReport {
    /// The broken limits by name, `fail_percent, hard_fail`; `-` when none.
    pub fn failed_names(&self) -> String {
        if self.failed.is_empty() {
            return "-".into();
        }
        let names: Vec<&str> = self.failed.iter().map(|l| l.name()).collect();
        names.join(", ")
    }

    /// Where the largest difference is: `(x, y) G`, or `-` for identical frames.
    pub fn max_at(&self) -> String {
        self.comparison
            .max_at
            .map_or("-".to_string(), |(x, y, ch)| {
                format!("({x}, {y}) {}", ["R", "G", "B"][ch])
            })
    }

    /// The PSNR in dB with two decimals, `inf` for identical frames.
    pub fn psnr(&self) -> String {
        self.comparison
            .psnr
            .map_or("inf".to_string(), |p| format!("{p:.2}"))
    }

    /// The figures in one sentence, as a failure message names them.
    pub fn figures(&self) -> String {
        let c = &self.comparison;
        let mut text = format!(
            "max difference {} at {}, {:.3} % of pixels failing, mean error {:.4}, PSNR {} dB",
            c.max_diff,
            self.max_at(),
            c.failing_percent,
            c.mean_error,
            self.psnr()
        );
        if let Some(f) = self.flip {
            text += &format!(", mean FLIP {f:.4}");
        }
        text
    }
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    /// A two-frame report: frame 0 passes (identical), frame 5 fails on both idiff limits.
    pub(crate) fn sample(flip: bool) -> CheckReport {
        let tolerance = Tolerance {
            flip: flip.then_some(0.05),
            ..Tolerance::DEFAULT
        };
        let same = Comparison {
            max_diff: 0,
            max_at: None,
            failing_pixels: 0,
            failing_percent: 0.0,
            mean_error: 0.0,
            psnr: None,
        };
        let changed = Comparison {
            max_diff: 255,
            max_at: Some((10, 12, 1)),
            failing_pixels: 100,
            failing_percent: 3.2552083333,
            mean_error: 4.5,
            psnr: Some(21.456),
        };
        let frame = |n: u32, c: Comparison, fl: f64, failed: Vec<Limit>| FrameReport {
            frame: n,
            name: format!("frame_{n:04}"),
            comparison: c,
            flip: flip.then_some(fl),
            pass: failed.is_empty(),
            failed,
            seconds: 0.25,
            reference_image: format!("refs/frame_{n:04}.png").into(),
            rendered_image: None,
            diff_image: None,
            flip_image: None,
        };
        let mut fail = vec![Limit::FailPercent, Limit::HardFail];
        if flip {
            fail.push(Limit::Flip);
        }
        CheckReport {
            manifest: "anim.toml".into(),
            references: "refs".into(),
            report: "frames-check".into(),
            width: 64,
            height: 48,
            tolerance,
            pass: false,
            frames: vec![frame(0, same, 0.0, vec![]), frame(5, changed, 0.0712, fail)],
        }
    }

    #[test]
    fn verdict_counts_failures() {
        let mut r = sample(false);
        assert_eq!(
            r.verdict(),
            "FAIL: 1 of 2 frame(s); rendered frames and diff images in frames-check"
        );
        r.frames.truncate(1);
        assert_eq!(r.verdict(), "PASS: 1 frame(s) within tolerance");
    }

    #[test]
    fn figures_name_every_number() {
        let r = sample(true);
        assert_eq!(
            r.frames[1].figures(),
            "max difference 255 at (10, 12) G, 3.255 % of pixels failing, mean error 4.5000, \
             PSNR 21.46 dB, mean FLIP 0.0712"
        );
        assert_eq!(r.frames[1].failed_names(), "fail_percent, hard_fail, flip");
        assert_eq!(r.frames[0].failed_names(), "-");
        assert_eq!(r.frames[0].psnr(), "inf");
    }
}
