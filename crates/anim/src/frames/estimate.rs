//! `animate estimate`: what a render will cost before it runs. The pre-pass of `balance`
//! predicts each frame's rays; one frame (the median by predicted cost) rendered at full
//! size as a run makes it (an EXR's passes included) and encoded in memory, timed, turns
//! pre-pass rays into full-size rays and seconds on this machine.
//!
//! A frame is drawn on every thread of the pool but encoded on one, and a run keeps
//! frames in flight on every thread, so one frame's encoding overlaps the others' work: a
//! frame of the run takes about its drawing plus its encoding divided among the frames in
//! flight (`in_flight`: the threads, at most the frames). An EXR with ten passes spends
//! most of its time encoding: timed whole, its frame predicted 1.8 times what the run's
//! frames took on two threads.
//!
//! ```text
//! frames 0-249: 1.84 Grays predicted, 412 s expected (frame 118 timed: 1.62 s, drawn 0.71 s and encoded 0.91 s, 7.3 Mrays, 921600 bytes encoded)
//! frames      predicted rays   share   expected
//! 0-31        12.1 M            4.2 %   20.4 s
//! …
//! shard       frames   predicted (balanced)   share   | equal count   share
//! 0/4         0-101    …
//! ```

use super::balance::{predicted_costs, split};
use super::status::ranges;
use crate::error::AnimError;
use crate::project::Animation;
use std::fmt::Write;
use std::time::Instant;

/// The prediction for a set of frames.
#[derive(Clone, Debug)]
pub struct Estimate {
    /// The frames, in number order.
    pub frames: Vec<u32>,
    /// Each frame's pre-pass rays.
    pub costs: Vec<u64>,
    /// Seconds the pre-pass took (all frames).
    pub prepass_seconds: f64,
    /// The frame timed at full size.
    pub sample: u32,
    /// Its full-size rays.
    pub sample_rays: u64,
    /// Its seconds in a run, its encoding shared among the frames in flight.
    pub sample_seconds: f64,
    /// Its seconds drawn, then encoded (timed alone).
    pub drawn_encoded: (f64, f64),
    /// Its size, encoded as the run writes it (without its provenance).
    pub sample_bytes: usize,
    /// Full-size rays per pre-pass ray, from the timed frame.
    pub scale: f64,
}

/// How many frames a run of `frames` frames keeps in flight on `threads` threads, at least
/// one: the frames whose encodings overlap.
pub fn in_flight(threads: usize, frames: usize) -> usize {
    threads.min(frames).max(1)
}

/// The seconds a frame drawn in `render_s` and encoded in `encode_s` (timed alone) takes
/// in a run with `in_flight` frames in flight: its encoding overlaps theirs.
pub fn run_seconds(render_s: f64, encode_s: f64, in_flight: usize) -> f64 {
    render_s + encode_s / in_flight.max(1) as f64
}

impl Estimate {
    /// Predicts `frames` (any order) of `anim`; renders their pre-pass and one frame.
    pub fn new(anim: &Animation, frames: &[u32]) -> Result<Estimate, AnimError> {
        let frames = super::select::sorted(frames);
        let start = Instant::now();
        let costs = predicted_costs(anim, &frames)?;
        let prepass_seconds = start.elapsed().as_secs_f64();
        let mut by_cost: Vec<usize> = (0..frames.len()).collect();
        by_cost.sort_by_key(|&i| (costs[i], frames[i]));
        let Some(&median) = by_cost.get(by_cost.len() / 2) else {
            return Ok(Estimate {
                frames,
                costs,
                prepass_seconds,
                sample: 0,
                sample_rays: 0,
                sample_seconds: 0.0,
                drawn_encoded: (0.0, 0.0),
                sample_bytes: 0,
                scale: 0.0,
            });
        };
        let timed = anim.render_timed(frames[median])?;
        let in_flight = in_flight(rayon::current_num_threads(), frames.len());
        Ok(Estimate {
            sample: frames[median],
            sample_rays: timed.rays.total(),
            sample_seconds: run_seconds(timed.render_s, timed.encode_s, in_flight),
            drawn_encoded: (timed.render_s, timed.encode_s),
            sample_bytes: timed.bytes,
            scale: timed.rays.total() as f64 / costs[median].max(1) as f64,
            frames,
            costs,
            prepass_seconds,
        })
    }

    /// Expected seconds for pre-pass `rays`, at the timed frame's rate.
    pub fn seconds(&self, rays: u64) -> f64 {
        let full = (rays as f64 * self.scale).round() as u64;
        whitted::render::estimate::predict(full, self.sample_rays, self.sample_seconds)
    }

    /// The whole selection's pre-pass rays.
    pub fn total(&self) -> u64 {
        self.costs.iter().sum()
    }

    /// The table: the whole render, about eight ranges of frames, and `shards` shards both
    /// balanced and by equal counts.
    pub fn table(&self, shards: u32) -> String {
        let mut out = String::new();
        let total = self.total().max(1);
        let share = |c: u64| 100.0 * c as f64 / total as f64;
        let full = |c: u64| c as f64 * self.scale / 1e6;
        let expected = self.seconds(self.total());
        let _ = writeln!(
            out,
            "frames {}: {:.1} Mrays predicted, {:.1} s expected (frame {} timed: {:.2} s, drawn {:.2} s and encoded {:.2} s, {:.2} Mrays, {} bytes encoded); pre-pass {:.2} s ({:.1} % of the expected render)",
            ranges(&self.frames),
            full(self.total()),
            expected,
            self.sample,
            self.sample_seconds,
            self.drawn_encoded.0,
            self.drawn_encoded.1,
            self.sample_rays as f64 / 1e6,
            self.sample_bytes,
            self.prepass_seconds,
            100.0 * self.prepass_seconds / expected.max(1e-9),
        );
        let _ = writeln!(
            out,
            "{:<14} {:>14} {:>8} {:>11}",
            "frames", "predicted", "share", "expected"
        );
        let n = self.frames.len();
        let parts = n.clamp(1, 8);
        for p in 0..parts {
            let (a, b) = (p * n / parts, (p + 1) * n / parts);
            self.row(&mut out, &self.frames[a..b], &self.costs[a..b], share, full);
        }
        if shards > 0 {
            let bounds = split(&self.costs, shards);
            let _ = writeln!(out, "{shards} balanced shards (--balance):");
            for k in 0..shards as usize {
                let (a, b) = (bounds[k], bounds[k + 1]);
                self.row(&mut out, &self.frames[a..b], &self.costs[a..b], share, full);
            }
            let _ = writeln!(out, "{shards} shards of equal frame counts:");
            for k in 0..shards as usize {
                let (a, b) = (k * n / shards as usize, (k + 1) * n / shards as usize);
                self.row(&mut out, &self.frames[a..b], &self.costs[a..b], share, full);
            }
        }
        out
    }

    fn row(
        &self,
        out: &mut String,
        frames: &[u32],
        costs: &[u64],
        share: impl Fn(u64) -> f64,
        full: impl Fn(u64) -> f64,
    ) {
        let c: u64 = costs.iter().sum();
        let _ = writeln!(
            out,
            "{:<14} {:>8.1} Mrays {:>6.1} % {:>9.1} s",
            ranges(frames),
            full(c),
            share(c),
            self.seconds(c)
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn encodings_overlap_among_the_frames_in_flight() {
        assert_eq!(in_flight(2, 12), 2);
        assert_eq!(in_flight(8, 3), 3);
        assert_eq!(in_flight(4, 0), 1);
        // Drawn in 0.1 s on the pool, encoded in 0.4 s on one thread: with two frames in
        // flight a frame takes 0.1 + 0.4 / 2 = 0.3 s of the run; alone, all of 0.5 s.
        assert!((run_seconds(0.1, 0.4, 2) - 0.3).abs() < 1e-12);
        assert!((run_seconds(0.1, 0.4, 1) - 0.5).abs() < 1e-12);
    }
}
