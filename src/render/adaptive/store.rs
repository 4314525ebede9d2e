//! The buffers of one adaptive frame's lattice (its corners, its pixels' first splits and
//! its border cells), kept between frames. An animation draws frame after frame of the same
//! size, several at a time; allocating these anew for each frame cost more than ten
//! megabytes of fresh pages a frame at 640×480, and the kernel's time to zero them. A
//! frame takes a store from the spares (or makes one), sizes it, and gives it back when
//! its lattice is dropped; at most `spare_limit()` stores wait, so memory stays bounded by
//! the frames that were once in flight together.
//!
//! Nothing a store held survives into the next frame's colours: every corner is written
//! before it is read, the splits are recomputed, and the cells are laid out anew, empty.

use super::edges::Edges;
use crate::texture::Color;
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

/// The most stores kept waiting: one per frame in flight, which the renderers bound by a
/// small multiple of the thread count.
fn spare_limit() -> usize {
    4 * rayon::current_num_threads()
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
            if spare.len() < spare_limit() {
                spare.push(self);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
}
