//! Ear clipping (Meisters, 1975) that cuts the smallest ear first: the cuts
//! `polygon::triangulate` makes of a polygon already projected to 2-D and turned
//! counter-clockwise.
//!
//! An ear is a corner turning left whose triangle holds no other remaining vertex. Of all
//! the ears, the one whose triangle has the smallest box (half its perimeter: width plus
//! height, ties to the lowest vertex index) is cut next, and only its two neighbours are
//! asked again. On a round outline, such as the gears' 144-vertex faces, this cuts the
//! rim's corners first, then every other corner of what is left, round after round, so
//! that the triangles grow towards the middle; cutting the first ear met instead made a
//! fan of slivers from one vertex, each with a box across the whole face, and the tree
//! over such boxes is a poor one (the gears' faces: 7.96 times their area in boxes by the
//! first-ear walk, 3.13 times by this one). Corners without area (a repeated or collinear
//! vertex) go first, without a triangle. A convex polygon needs no vertex tests (every
//! left turn is an ear), so it is cut in O(n log n); others take O(n²). Should no ear be
//! left in a polygon that is not simple, the rest is cut as a fan from its lowest vertex.

use glam::DVec2;
use std::cmp::Reverse;
use std::collections::BinaryHeap;

/// Twice the signed area of the 2-D triangle a, b, c (positive counter-clockwise).
pub(super) fn cross(a: DVec2, b: DVec2, c: DVec2) -> f64 {
    (b - a).perp_dot(c - a)
}

/// Whether p lies inside or on the counter-clockwise triangle a, b, c.
fn inside(p: DVec2, a: DVec2, b: DVec2, c: DVec2) -> bool {
    cross(a, b, p) >= 0.0 && cross(b, c, p) >= 0.0 && cross(c, a, p) >= 0.0
}

/// The corners' ring as it is cut: each alive vertex's neighbours, and the ears waiting
/// in a heap keyed (box size's bits, vertex, the vertex's version when it was asked).
struct Ring<'a> {
    flat: &'a [DVec2],
    convex: bool,
    prev: Vec<usize>,
    next: Vec<usize>,
    version: Vec<u32>,
    heap: BinaryHeap<Reverse<(u64, usize, u32)>>,
}

impl Ring<'_> {
    /// The corner `i`'s neighbours.
    fn corner(&self, i: usize) -> (usize, usize) {
        (self.prev[i], self.next[i])
    }

    /// Corner `i`'s place in the heap: 0 for a corner without area, its box's width plus
    /// height for an ear (positive, so its bits order as the numbers do), none otherwise.
    fn key(&self, i: usize) -> Option<u64> {
        let (a, c) = self.corner(i);
        let (pa, pb, pc) = (self.flat[a], self.flat[i], self.flat[c]);
        let turn = cross(pa, pb, pc);
        if turn == 0.0 {
            return Some(0);
        }
        if turn < 0.0 {
            return None;
        }
        if !self.convex {
            let mut k = self.next[c];
            while k != a {
                let q = self.flat[k];
                if q != pa && q != pb && q != pc && inside(q, pa, pb, pc) {
                    return None;
                }
                k = self.next[k];
            }
        }
        let size = pa.max(pb).max(pc) - pa.min(pb).min(pc);
        Some((size.x + size.y).to_bits())
    }

    /// Asks corner `i` again, forgetting what the heap held for it.
    fn ask(&mut self, i: usize) {
        self.version[i] += 1;
        if let Some(key) = self.key(i) {
            self.heap.push(Reverse((key, i, self.version[i])));
        }
    }
}

/// The triangles of the counter-clockwise polygon `flat` (index triples, each in the
/// polygon's winding); `convex` says every corner turns left and the outline winds once.
pub(super) fn clip(flat: &[DVec2], convex: bool) -> Vec<[usize; 3]> {
    let n = flat.len();
    let mut ring = Ring {
        flat,
        convex,
        prev: (0..n).map(|i| (i + n - 1) % n).collect(),
        next: (0..n).map(|i| (i + 1) % n).collect(),
        version: vec![0; n],
        heap: BinaryHeap::with_capacity(n),
    };
    (0..n).for_each(|i| ring.ask(i));
    let mut alive = vec![true; n];
    let mut left = n;
    let mut out = Vec::with_capacity(n.saturating_sub(2));
    let mut asked_all = false;
    while left > 3 {
        let Some(Reverse((key, i, version))) = ring.heap.pop() else {
            // Only neighbours are asked again after a cut; once, before giving up on a
            // polygon that is not simple, ask every corner.
            if asked_all {
                break;
            }
            asked_all = true;
            (0..n).filter(|&i| alive[i]).for_each(|i| ring.ask(i));
            continue;
        };
        if !alive[i] || version != ring.version[i] {
            continue;
        }
        let (a, c) = ring.corner(i);
        if key != 0 {
            out.push([a, i, c]);
        }
        alive[i] = false;
        left -= 1;
        ring.next[a] = c;
        ring.prev[c] = a;
        ring.ask(a);
        ring.ask(c);
    }
    // What is left, from its lowest vertex: the last triangle, or a fan of a polygon that
    // is not simple.
    let Some(first) = alive.iter().position(|&x| x) else {
        return out;
    };
    let mut k = ring.next[first];
    while ring.next[k] != first {
        let c = ring.next[k];
        if left > 3 || cross(flat[first], flat[k], flat[c]) != 0.0 {
            out.push([first, k, c]);
        }
        k = c;
    }
    out
}
