//! The buffers of one adaptive frame's lattice (its corners, its pixels' first splits and
//! its border cells), kept between frames. An animation draws frame after frame of the same
//! size, several at a time; allocating these anew for each frame cost more than ten
//! megabytes of fresh pages a frame at 640×480, and the kernel's time to zero them. A
//! frame takes a store from the spares (or makes one), sizes it, and gives it back when
//! its lattice is dropped. The spares are as many as the frames once in flight together,
//! and hold at most `SPARE_BYTES` in all, so that a long-lived process (the live view)
//! that once drew large frames side by side does not keep them all.
//!
//! Nothing a store held survives into the next frame's colours: every corner is written
//! before it is read, the splits are recomputed, and the cells are laid out anew, empty.

use super::edges::Edges;
use crate::base::Color;
use std::sync::Mutex;

/// One lattice's buffers.
#[derive(Default)]
pub(super) struct Store {
    /// The pixel corners, (width+1)·(height+1).
    pub corners: Vec<Color>,
    /// Whether each pixel's own corners differ.
    pub own: Vec<bool>,
    /// Whether each pixel splits at all.
    pub split: Vec<bool>,
    /// The finer border samples (laid out by the lattice once the splits are known).
    pub edges: Edges,
}

/// Stores given back and not yet taken again.
static SPARE: Mutex<Vec<Store>> = Mutex::new(Vec::new());

/// The most memory the waiting stores may hold: a few 1080p frames' worth (one takes
/// about 75 MB there, about 12 MB at 640×480 and depth 2).
const SPARE_BYTES: usize = 256 << 20;

/// Whether a store of `bytes` is kept when the waiting ones hold `waiting` bytes.
fn keeps(waiting: usize, bytes: usize) -> bool {
    waiting.saturating_add(bytes) <= SPARE_BYTES
}

/// The most memory a `width`×`height` frame's store can need at `depth`: when every pixel
/// splits, every edge of the frame gets its 2^depth − 1 cells (saturating, never wrapping).
pub fn worst_bytes(width: u64, height: u64, depth: u32) -> u64 {
    let edges = (height + 1)
        .saturating_mul(width)
        .saturating_add(height.saturating_mul(width + 1));
    let per_edge = (1u64 << depth.min(63)) - 1;
    let cells = edges.saturating_mul(per_edge);
    let corners = (width + 1).saturating_mul(height + 1);
    cells
        .saturating_mul(std::mem::size_of::<std::sync::OnceLock<Color>>() as u64)
        .saturating_add(edges.saturating_mul(4))
        .saturating_add(corners.saturating_mul(std::mem::size_of::<Color>() as u64))
        .saturating_add(width.saturating_mul(height).saturating_mul(2))
}

impl Store {
    /// A store for a `width`×`height` frame: a spare one when there is one, its corners
    /// zero and its splits false.
    pub fn take(width: usize, height: usize) -> Store {
        let spare = SPARE.lock().ok().and_then(|mut s| s.pop());
        let mut store = spare.unwrap_or_default();
        store.corners.clear();
        store
            .corners
            .resize((width + 1) * (height + 1), Color::ZERO);
        for flags in [&mut store.own, &mut store.split] {
            flags.clear();
            flags.resize(width * height, false);
        }
        store
    }

    /// Gives the buffers back for the next frame (dropped when enough wait already).
    pub fn give_back(self) {
        if let Ok(mut spare) = SPARE.lock() {
            let waiting = spare.iter().map(Store::bytes).sum();
            if keeps(waiting, self.bytes()) {
                spare.push(self);
            }
        }
    }

    /// The memory the store's buffers hold.
    fn bytes(&self) -> usize {
        self.corners.capacity() * std::mem::size_of::<Color>()
            + self.own.capacity()
            + self.split.capacity()
            + self.edges.bytes()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_worst_case_by_hand() {
        // 2×1 pixels at depth 1: (1+1)·2 = 4 horizontal and 1·(2+1) = 3 vertical edges,
        // each 1 cell (32 bytes) and 4 bytes of index; 3·2 corners of 24 bytes; 2 pixels
        // of 2 flags.
        assert_eq!(std::mem::size_of::<std::sync::OnceLock<Color>>(), 32);
        assert_eq!(worst_bytes(2, 1, 1), 7 * 32 + 7 * 4 + 6 * 24 + 2 * 2);
        // 4096×2048 at depth 6, the attack's request: 33.8 GB.
        assert!(worst_bytes(4096, 2048, 6) > 33_000_000_000);
        assert_eq!(worst_bytes(u64::MAX, u64::MAX, 6), u64::MAX);
    }

    #[test]
    fn a_taken_store_is_sized_and_empty_whatever_it_held() {
        // Fill a store as a 3×2 frame would, give it back, and take one for 2×4: every
        // buffer has the new frame's size and holds nothing of the old one.
        let mut old = Store::take(3, 2);
        old.corners.iter_mut().for_each(|c| *c = Color::ONE);
        old.split.iter_mut().for_each(|s| *s = true);
        old.own.iter_mut().for_each(|s| *s = true);
        old.give_back();
        let new = Store::take(2, 4);
        assert_eq!(new.corners, vec![Color::ZERO; 3 * 5]);
        assert_eq!(new.split, vec![false; 8]);
        assert_eq!(new.own, vec![false; 8]);
    }

    #[test]
    fn the_spares_hold_at_most_the_budget() {
        // 256 MiB = 268,435,456 bytes: a store that fits beside the waiting ones is kept,
        // one byte more is not.
        assert!(keeps(0, 12 << 20));
        assert!(keeps(200 << 20, 56 << 20));
        assert!(!keeps(200 << 20, (56 << 20) + 1));
        assert!(!keeps(usize::MAX, 1));
        // A 3×2 frame's buffers: 12 corners of 24 bytes and two flags of 6 bytes each, and
        // no edge cells laid out.
        let store = Store {
            corners: vec![Color::ZERO; 12],
            own: vec![false; 6],
            split: vec![false; 6],
            edges: Edges::default(),
        };
        assert_eq!(store.bytes(), 12 * 24 + 2 * 6);
    }
}
