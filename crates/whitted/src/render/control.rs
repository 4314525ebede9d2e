//! Process-wide control of the render loops, read between rows: a cancel flag (the
//! signal that stopped the run) and two counters, rows finished and frames in progress,
//! that a progress display reads while a frame draws.
//!
//! ```text
//! control::cancel(2)          // SIGINT: every row loop stops before its next row
//! control::cancelled()        // Some(2): the frame drawn is incomplete, do not write it
//! control::rows_done()        // rows finished by every frame since the process began
//! control::frames_in_progress()
//! ```
//!
//! A row is one row of pixels of one (sub-)frame: a motion-blurred frame of `s` samples
//! is `s × height` rows. The counters only go up (progress is their difference between
//! two readings), and a row loop pays one relaxed load and one relaxed add per row, which
//! leaves the default path's speed and bytes as they were.

use std::sync::atomic::{AtomicU64, AtomicUsize, Ordering};

/// The number of the signal that cancelled the run, 0 while none has.
static CANCEL: AtomicUsize = AtomicUsize::new(0);
/// Rows finished, all frames together.
static ROWS: AtomicU64 = AtomicU64::new(0);
/// Frames being drawn now.
static FRAMES: AtomicUsize = AtomicUsize::new(0);

/// Stops every row loop before its next row; `sig` is the signal's number (nonzero).
pub fn cancel(sig: usize) {
    let _ = CANCEL.compare_exchange(0, sig.max(1), Ordering::SeqCst, Ordering::SeqCst);
}

/// The signal that cancelled the run, if one has: the frames drawn since are incomplete.
pub fn cancelled() -> Option<i32> {
    match CANCEL.load(Ordering::Relaxed) {
        0 => None,
        sig => Some(sig as i32),
    }
}

/// Rows finished since the process began.
pub fn rows_done() -> u64 {
    ROWS.load(Ordering::Relaxed)
}

/// Frames being drawn now.
pub fn frames_in_progress() -> usize {
    FRAMES.load(Ordering::Relaxed)
}

/// True when the row loop must stop before the row it is about to draw.
#[inline]
pub(crate) fn stop_row() -> bool {
    CANCEL.load(Ordering::Relaxed) != 0
}

/// Counts one finished row.
#[inline]
pub(crate) fn row_done() {
    ROWS.fetch_add(1, Ordering::Relaxed);
}

/// Counts `n` finished rows at once (a band of rows, as a tile's last column ends it).
#[inline]
pub(crate) fn rows_done_by(n: u64) {
    ROWS.fetch_add(n, Ordering::Relaxed);
}

/// Counts a frame in progress until the guard is dropped.
pub fn frame_in_progress() -> FrameGuard {
    FRAMES.fetch_add(1, Ordering::Relaxed);
    FrameGuard(())
}

/// Held while a frame draws (`frame_in_progress`).
pub struct FrameGuard(());

impl Drop for FrameGuard {
    fn drop(&mut self) {
        FRAMES.fetch_sub(1, Ordering::Relaxed);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn guards_count_frames_and_rows_only_go_up() {
        let before = frames_in_progress();
        let g = frame_in_progress();
        let h = frame_in_progress();
        assert!(frames_in_progress() >= before + 2);
        drop((g, h));
        let rows = rows_done();
        row_done();
        row_done();
        assert!(rows_done() >= rows + 2);
    }
}
