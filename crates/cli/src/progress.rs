//! What both binaries' progress bars move by: a thread that reads the process-wide rows
//! counter (`render::control::rows_done`) every `PERIOD` and hands the rows done since a
//! base to a callback, until the poller is stopped or dropped; and `Weighted`, which turns
//! rows into a position weighted by each frame's predicted cost, for an ETA that holds
//! when frames differ in cost.
//!
//! ```text
//! let poll = RowPoller::start(move |rows| bar.set_position(rows));  // every 200 ms
//! poll.set_base(control::rows_done() - skipped_rows);               // count from there
//! ```

use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::Arc;
use std::time::Duration;
use whitted::render::control;

/// How often the counter is read.
pub const PERIOD: Duration = Duration::from_millis(200);

/// A running poller.
pub struct RowPoller {
    base: Arc<AtomicU64>,
    done: Arc<AtomicBool>,
}

impl RowPoller {
    /// Starts polling; `show` is given the rows done since now.
    pub fn start(show: impl Fn(u64) + Send + 'static) -> RowPoller {
        let base = Arc::new(AtomicU64::new(control::rows_done()));
        let done = Arc::new(AtomicBool::new(false));
        let (from, stop) = (Arc::clone(&base), Arc::clone(&done));
        std::thread::spawn(move || {
            while !stop.load(Ordering::Relaxed) {
                show(control::rows_done().saturating_sub(from.load(Ordering::Relaxed)));
                std::thread::sleep(PERIOD);
            }
        });
        RowPoller { base, done }
    }

    /// Counts from `base` rows of the counter on.
    pub fn set_base(&self, base: u64) {
        self.base.store(base, Ordering::Relaxed);
    }

    /// Stops the thread (at its next reading).
    pub fn stop(&self) {
        self.done.store(true, Ordering::Relaxed);
    }
}

impl Drop for RowPoller {
    fn drop(&mut self) {
        self.stop();
    }
}

/// Progress weighted by each frame's predicted cost (the pre-pass's rays), so that an
/// ETA taken from it holds on an animation whose last frames cost ten times the first:
/// the position is the finished frames' costs plus the rows of frames in flight at the
/// mean cost of a frame still to finish, in units of cost × rows.
#[derive(Debug)]
pub struct Weighted {
    costs: std::collections::HashMap<u32, u64>,
    rows: u64,
    total: u64,
    done_cost: AtomicU64,
    done_frames: AtomicU64,
    frames: u64,
}

impl Weighted {
    /// For `frames` with predicted `costs` (same order), of `rows` rows each.
    pub fn new(frames: &[u32], costs: &[u64], rows: u64) -> Weighted {
        let costs: std::collections::HashMap<u32, u64> = frames
            .iter()
            .zip(costs)
            .map(|(&f, &c)| (f, c.max(1)))
            .collect();
        let total = costs.values().sum();
        Weighted {
            frames: costs.len() as u64,
            costs,
            rows: rows.max(1),
            total,
            done_cost: AtomicU64::new(0),
            done_frames: AtomicU64::new(0),
        }
    }

    /// The bar's length.
    pub fn length(&self) -> u64 {
        self.total * self.rows
    }

    /// Frame `frame` is done (rendered or skipped).
    pub fn done(&self, frame: u32) {
        let c = self.costs.get(&frame).copied().unwrap_or(0);
        self.done_cost.fetch_add(c, Ordering::Relaxed);
        self.done_frames.fetch_add(1, Ordering::Relaxed);
    }

    /// Frames done so far.
    pub fn frames_done(&self) -> u64 {
        self.done_frames.load(Ordering::Relaxed)
    }

    /// The position when `rows` rows of rendered frames are done (finished frames'
    /// rows included).
    pub fn position(&self, rows: u64) -> u64 {
        let (cost, frames) = (
            self.done_cost.load(Ordering::Relaxed),
            self.done_frames.load(Ordering::Relaxed),
        );
        let left = self.frames.saturating_sub(frames).max(1);
        let mean = self.total.saturating_sub(cost) / left;
        let in_flight = rows
            .saturating_sub(frames * self.rows)
            .min(self.rows * left);
        (cost * self.rows + in_flight * mean).min(self.length())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn weighted_by_hand() {
        // Costs 1, 1, 10, 10 at 4 rows a frame: length 22 × 4 = 88.
        let w = Weighted::new(&[0, 1, 2, 3], &[1, 1, 10, 10], 4);
        assert_eq!(w.length(), 88);
        w.done(0);
        w.done(1);
        // Two cheap frames done: 8 of 88, though half the frames are.
        assert_eq!(w.position(8), 8);
        // Two rows of a frame in flight at the mean remaining cost 10: 8 + 2 × 10.
        assert_eq!(w.position(10), 28);
        w.done(2);
        w.done(3);
        assert_eq!(w.position(16), 88);
    }
}
