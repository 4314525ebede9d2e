//! `animate stats`: what the frames of a folder cost, from their cost records (`frames::
//! cost`): the totals, the slowest frames, and the frames whose wall time is more than
//! twice off the pre-pass's prediction, as a table or JSON; `--plot` draws seconds per
//! frame against the prediction (`plot`).
//!
//! The prediction of a frame is its pre-pass rays (`frames::balance`) turned into seconds
//! at the run's own rate: predicted_s = prepass_rays × Σ wall_s / Σ prepass_rays over the
//! frames with costs, so that the predictions add up to the measured total. A cost is
//! used only when it names the digest the manifest now gives its frame (a cost measured
//! on another picture says nothing about this one). Exit 0 whatever the costs say; 2 on
//! bad input.

mod plot;

use super::emit;
use crate::error::AnimError;
use crate::frames::balance::predicted_costs;
use crate::frames::cost::{self, FrameCost};
use crate::frames::run;
use crate::frames::status::ranges;
use crate::project::{Animation, Project};
use crate::select::sorted;
use serde::Serialize;
use std::io::Write;
use std::path::PathBuf;
use whitted::exit::Outcome;

/// How many of the slowest frames are named.
pub const SLOWEST: usize = 5;
/// A frame is off the prediction when its time and the predicted one differ by more than
/// this factor, either way.
pub const OFF_FACTOR: f64 = 2.0;

/// What `animate stats` was asked.
#[derive(Clone, Debug, Default)]
pub struct StatsRequest {
    /// The frame list (fileseq's grammar), or every frame.
    pub frames: Option<String>,
    /// The frame folder instead of the manifest's.
    pub dir: Option<PathBuf>,
    /// JSON instead of the table.
    pub json: bool,
    /// Draw seconds per frame against the prediction into this PNG.
    pub plot: Option<PathBuf>,
}

/// One frame with its cost and prediction.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Row {
    /// The frame's number.
    pub frame: u32,
    /// Its measured wall seconds.
    pub wall_s: f64,
    /// Its share of CPU seconds.
    pub cpu_s: Option<f64>,
    /// The predicted seconds.
    pub predicted_s: f64,
    /// wall_s / predicted_s.
    pub ratio: f64,
}

/// The totals over the frames with costs.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct Totals {
    /// Frames with a cost record.
    pub frames: usize,
    /// Wall seconds, summed over frames (frames in parallel overlap).
    pub wall_s: f64,
    /// CPU seconds (null when a frame's is unknown).
    pub cpu_s: Option<f64>,
    /// The largest peak memory any frame recorded, in bytes.
    pub peak_memory_bytes: Option<u64>,
    /// Camera rays.
    pub eye: u64,
    /// Camera rays that hit.
    pub eye_hits: u64,
    /// Reflection rays.
    pub reflect: u64,
    /// Refraction rays.
    pub refract: u64,
    /// Shadow rays.
    pub shadow: u64,
    /// Rays per wall second of frame work.
    pub rays_per_second: f64,
}

/// The report of `animate stats`.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct StatsReport {
    /// The frame folder.
    pub dir: String,
    /// The totals.
    pub totals: Totals,
    /// Frames asked for with no cost record of their current picture (ranges).
    pub without_cost: String,
    /// The slowest frames, slowest first.
    pub slowest: Vec<Row>,
    /// Frames more than `OFF_FACTOR` off their prediction, in frame order.
    pub off_prediction: Vec<Row>,
    /// Every frame with a cost, in frame order.
    pub per_frame: Vec<Row>,
}

/// The totals of `costs`.
pub fn totals(costs: &[FrameCost]) -> Totals {
    let mut t = Totals {
        frames: costs.len(),
        cpu_s: Some(0.0),
        ..Totals::default()
    };
    for c in costs {
        t.wall_s += c.wall_s;
        t.cpu_s = t.cpu_s.zip(c.cpu_s).map(|(a, b)| a + b);
        t.peak_memory_bytes = t.peak_memory_bytes.max(c.peak_memory_bytes);
        t.eye += c.eye;
        t.eye_hits += c.eye_hits;
        t.reflect += c.reflect;
        t.refract += c.refract;
        t.shadow += c.shadow;
    }
    let rays = (t.eye + t.reflect + t.refract + t.shadow) as f64;
    t.rays_per_second = if t.wall_s > 0.0 { rays / t.wall_s } else { 0.0 };
    t
}

/// The rows of `costs` with their predictions from pre-pass rays `prepass` (same order):
/// seconds in proportion to the pre-pass rays, adding up to the measured total.
pub fn rows(costs: &[FrameCost], prepass: &[u64]) -> Vec<Row> {
    let wall: f64 = costs.iter().map(|c| c.wall_s).sum();
    let rays: u64 = prepass.iter().sum();
    let per_ray = if rays > 0 { wall / rays as f64 } else { 0.0 };
    costs
        .iter()
        .zip(prepass)
        .map(|(c, &p)| {
            let predicted_s = p as f64 * per_ray;
            Row {
                frame: c.frame,
                wall_s: c.wall_s,
                cpu_s: c.cpu_s,
                predicted_s,
                ratio: if predicted_s > 0.0 {
                    c.wall_s / predicted_s
                } else {
                    f64::INFINITY
                },
            }
        })
        .collect()
}

/// Whether a row is more than `OFF_FACTOR` off its prediction, either way.
pub fn off(row: &Row) -> bool {
    row.ratio > OFF_FACTOR || row.ratio < 1.0 / OFF_FACTOR
}

/// The report over `frames` of `anim` in `dir`, the pre-pass traced on the current pool.
pub fn report(
    anim: &Animation,
    dir: &std::path::Path,
    frames: &[u32],
) -> Result<StatsReport, AnimError> {
    let (mut costs, mut without) = (Vec::new(), Vec::new());
    for &f in frames {
        let plan = anim.plan_in(dir, f);
        match cost::read(plan.path()) {
            Some(c) if c.frame == f && c.digest == plan.digest() => costs.push(c),
            _ => without.push(f),
        }
    }
    let with: Vec<u32> = costs.iter().map(|c| c.frame).collect();
    let prepass = predicted_costs(anim, &with)?;
    let per_frame = rows(&costs, &prepass);
    let mut slowest = per_frame.clone();
    slowest.sort_by(|a, b| b.wall_s.total_cmp(&a.wall_s).then(a.frame.cmp(&b.frame)));
    slowest.truncate(SLOWEST);
    Ok(StatsReport {
        dir: whitted::fileloc::shown(dir),
        totals: totals(&costs),
        without_cost: ranges(&without),
        slowest,
        off_prediction: per_frame.iter().filter(|r| off(r)).cloned().collect(),
        per_frame,
    })
}

/// Bytes in words: `45.2 MB`.
fn bytes(b: Option<u64>) -> String {
    b.map_or("unknown".into(), |b| format!("{:.1} MB", b as f64 / 1e6))
}

impl StatsReport {
    /// The table for people.
    pub fn table(&self) -> String {
        let t = &self.totals;
        let cpu = t.cpu_s.map_or("unknown".into(), |c| format!("{c:.2} s"));
        let mut s = format!(
            "{}: {} frame(s) with costs; without a cost of their current picture: {}\n\
             total   wall {:.2} s   cpu {cpu}   peak memory {}\n\
             rays    eye {}   eye_hits {}   reflect {}   refract {}   shadow {}   ({:.2} Mrays/s)\n",
            self.dir,
            t.frames,
            self.without_cost,
            t.wall_s,
            bytes(t.peak_memory_bytes),
            t.eye,
            t.eye_hits,
            t.reflect,
            t.refract,
            t.shadow,
            t.rays_per_second / 1e6
        );
        let row = |r: &Row| {
            format!(
                "  frame {:<6} {:>8.3} s   predicted {:>8.3} s   ({:.1}x)\n",
                r.frame, r.wall_s, r.predicted_s, r.ratio
            )
        };
        s.push_str("slowest frames:\n");
        self.slowest.iter().for_each(|r| s.push_str(&row(r)));
        match self.off_prediction.is_empty() {
            true => s.push_str("off the prediction by more than 2x: none\n"),
            false => {
                s.push_str("off the prediction by more than 2x:\n");
                self.off_prediction.iter().for_each(|r| s.push_str(&row(r)));
            }
        }
        s
    }
}

/// Runs `animate stats` on `project` (on the current rayon pool), writing to `out`.
pub fn stats(
    project: &Project,
    request: &StatsRequest,
    out: &mut dyn Write,
) -> Result<Outcome, AnimError> {
    let anim = Animation::new(project)?;
    let frames = sorted(&run::frames_of(&anim, request.frames.as_deref(), None)?);
    let dir = (request.dir.clone()).unwrap_or_else(|| project.manifest.output.dir.clone());
    let report = report(&anim, &dir, &frames)?;
    if let Some(path) = &request.plot {
        plot::write(path, &report.per_frame)?;
    }
    let text = match request.json {
        true => serde_json::to_string_pretty(&report).unwrap_or_default() + "\n",
        false => report.table(),
    };
    emit(out, text.as_bytes())?;
    Ok(Outcome::Success)
}

#[cfg(test)]
mod tests;
