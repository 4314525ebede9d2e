//! What both binaries' progress bars move by: a thread that reads the process-wide rows
//! counter (`render::control::rows_done`) every `PERIOD` and hands the rows done since a
//! base to a callback, until the poller is stopped or dropped.
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
