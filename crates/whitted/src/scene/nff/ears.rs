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
//!
//! A corner enters the heap by its shape alone, and its vertex test runs when it reaches
//! the top, against the vertices that were alive when it was asked (`Ring::blocked`):
//! the cuts of testing every corner as it is asked, with most tests never run (a corner
//! is usually asked again before it reaches the top).

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

/// The corners' ring as it is cut: each alive vertex's neighbours, the alive vertices'
/// points packed in one array (what an ear's test reads), and the ears waiting in a heap
/// keyed (box size's bits, vertex, the vertex's version when it was asked).
struct Ring<'a> {
    flat: &'a [DVec2],
    convex: bool,
    prev: Vec<usize>,
    next: Vec<usize>,
    version: Vec<u32>,
    heap: BinaryHeap<Reverse<(u64, usize, u32)>>,
    /// The alive vertices' points, in no particular order, and which vertex each is
    /// (none for a convex outline).
    alive_points: Vec<DVec2>,
    alive_ids: Vec<usize>,
    /// Each vertex's place in `alive_points`.
    place: Vec<usize>,
    /// The points cut so far, in turn, and how many had been cut when each vertex was
    /// last asked: the vertices alive then are those alive now and those cut since.
    killed: Vec<DVec2>,
    asked_at: Vec<usize>,
    /// Whether an ear's vertex test runs when it is asked, else when it leaves the heap
    /// (`clip`'s way; the other is the tests' reference).
    eager: bool,
}

impl<'a> Ring<'a> {
    /// The whole outline, nothing asked yet.
    fn new(flat: &'a [DVec2], convex: bool, eager: bool) -> Ring<'a> {
        let n = flat.len();
        // A convex outline tests no vertex: it keeps no packed points.
        let tested = if convex { 0 } else { n };
        Ring {
            flat,
            convex,
            prev: (0..n).map(|i| (i + n - 1) % n).collect(),
            next: (0..n).map(|i| (i + 1) % n).collect(),
            version: vec![0; n],
            heap: BinaryHeap::with_capacity(n),
            alive_points: flat[..tested].to_vec(),
            alive_ids: (0..tested).collect(),
            place: (0..tested).collect(),
            killed: Vec::new(),
            asked_at: vec![0; n],
            eager,
        }
    }

    /// The corner `i`'s neighbours.
    fn corner(&self, i: usize) -> (usize, usize) {
        (self.prev[i], self.next[i])
    }

    /// Corner `i`'s place in the heap by its shape alone: 0 for a corner without area, its
    /// box's width plus height for a left turn (positive, so its bits order as the numbers
    /// do), none for a right turn.
    fn shape_key(&self, i: usize) -> Option<u64> {
        let (a, c) = self.corner(i);
        let (pa, pb, pc) = (self.flat[a], self.flat[i], self.flat[c]);
        let turn = cross(pa, pb, pc);
        if turn == 0.0 {
            return Some(0);
        }
        if turn < 0.0 {
            return None;
        }
        let size = pa.max(pb).max(pc) - pa.min(pb).min(pc);
        Some((size.x + size.y).to_bits())
    }

    /// Whether a vertex alive when `since` points had been cut lies inside (or on) corner
    /// `i`'s triangle: those alive now and those cut since. The three corners themselves,
    /// and copies of them, are left out by their points; the answer is whether any such
    /// vertex exists, so the packed arrays are read in their own order.
    fn blocked(&self, i: usize, since: usize) -> bool {
        if self.convex {
            return false;
        }
        let (a, c) = self.corner(i);
        let (pa, pb, pc) = (self.flat[a], self.flat[i], self.flat[c]);
        let within = |&q: &DVec2| inside(q, pa, pb, pc) && q != pa && q != pb && q != pc;
        self.alive_points.iter().any(within) || self.killed[since..].iter().any(within)
    }

    /// Corner `i`'s place in the heap: `shape_key` for an ear, none for a left turn whose
    /// triangle holds another alive vertex.
    fn key(&self, i: usize) -> Option<u64> {
        let key = self.shape_key(i)?;
        (key == 0 || !self.blocked(i, self.killed.len())).then_some(key)
    }

    /// Takes vertex `i` out of the ring (its neighbours now meet).
    fn cut(&mut self, i: usize) {
        let (a, c) = self.corner(i);
        self.next[a] = c;
        self.prev[c] = a;
        if self.convex {
            return;
        }
        let k = self.place[i];
        self.alive_points.swap_remove(k);
        self.alive_ids.swap_remove(k);
        if let Some(&moved) = self.alive_ids.get(k) {
            self.place[moved] = k;
        }
        self.killed.push(self.flat[i]);
    }

    /// Asks corner `i` again, forgetting what the heap held for it.
    fn ask(&mut self, i: usize) {
        self.version[i] += 1;
        self.asked_at[i] = self.killed.len();
        let key = if self.eager {
            self.key(i)
        } else {
            self.shape_key(i)
        };
        if let Some(key) = key {
            self.heap.push(Reverse((key, i, self.version[i])));
        }
    }
}

/// The triangles of the counter-clockwise polygon `flat` (index triples, each in the
/// polygon's winding); `convex` says every corner turns left and the outline winds once.
pub(super) fn clip(flat: &[DVec2], convex: bool) -> Vec<[usize; 3]> {
    clip_with(flat, convex, false)
}

/// `clip`, the vertex test of an ear run when it is asked (`eager`) or when it leaves the
/// heap: the same cuts, since the heap's order is its keys' and the test at the heap's
/// top asks the vertices that were alive when it was asked. Tested last, an ear is tested
/// once; tested first, every corner asked is, and each cut asks two, most of which are
/// asked again before they reach the top.
fn clip_with(flat: &[DVec2], convex: bool, eager: bool) -> Vec<[usize; 3]> {
    let n = flat.len();
    let mut ring = Ring::new(flat, convex, eager);
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
        if !eager && key != 0 && ring.blocked(i, ring.asked_at[i]) {
            continue;
        }
        let (a, c) = ring.corner(i);
        if key != 0 {
            out.push([a, i, c]);
        }
        alive[i] = false;
        left -= 1;
        ring.cut(i);
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

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// The ear test by walking the ring from the corner's far neighbour round to its near
    /// one: every other alive vertex, one by one.
    fn key_by_walk(ring: &Ring, i: usize) -> Option<u64> {
        let (a, c) = ring.corner(i);
        let (pa, pb, pc) = (ring.flat[a], ring.flat[i], ring.flat[c]);
        let turn = cross(pa, pb, pc);
        if turn <= 0.0 {
            return (turn == 0.0).then_some(0);
        }
        let mut k = ring.next[c];
        while k != a {
            let q = ring.flat[k];
            if q != pa && q != pb && q != pc && inside(q, pa, pb, pc) {
                return None;
            }
            k = ring.next[k];
        }
        let size = pa.max(pb).max(pc) - pa.min(pb).min(pc);
        Some((size.x + size.y).to_bits())
    }

    #[test]
    fn a_vertex_on_the_ears_edge_or_a_copy_of_a_corner() {
        // The square (0,0) (2,0) (2,2) (0,2) with (1,1) after (2,2): corner 2's triangle
        // (2,0) (2,2) (1,1) holds no vertex; corner 1's, (0,0) (2,0) (2,2), has (1,1) on
        // its edge: no ear. A copy of (0,0) at the end: left out as a corner's copy.
        let p = [
            (0.0, 0.0),
            (2.0, 0.0),
            (2.0, 2.0),
            (1.0, 1.0),
            (0.0, 2.0),
            (0.0, 0.0),
        ]
        .map(|(x, y)| DVec2::new(x, y));
        let ring = Ring::new(&p, false, true);
        assert_eq!(ring.key(1), None);
        assert_eq!(ring.key(2), Some(3.0f64.to_bits()));
        assert_eq!(ring.key(5), Some(0));
        assert_eq!(ring.key(0), Some(0));
    }

    proptest! {
        /// Random outlines (not simple, with repeated points on a coarse grid): after each
        /// of a run of cuts, every alive corner's answer from the packed points is the
        /// answer of the walk round the ring.
        #[test]
        fn the_packed_points_answer_as_the_ring_walk(
            pts in proptest::collection::vec((0u8..6, 0u8..6), 3..40),
            cuts in proptest::collection::vec(any::<prop::sample::Index>(), 0..40),
        ) {
            let flat: Vec<DVec2> =
                pts.iter().map(|&(x, y)| DVec2::new(x as f64, y as f64)).collect();
            let mut ring = Ring::new(&flat, false, true);
            let mut alive: Vec<usize> = (0..flat.len()).collect();
            for cut in cuts {
                for &i in &alive {
                    prop_assert_eq!(ring.key(i), key_by_walk(&ring, i), "corner {}", i);
                }
                if alive.len() <= 3 {
                    break;
                }
                let i = alive.remove(cut.index(alive.len()));
                ring.cut(i);
            }
        }

        /// Outlines on a coarse grid (repeated and collinear points, crossing edges) and
        /// star-shaped ones: testing an ear as it leaves the heap cuts what testing it
        /// when asked does.
        #[test]
        fn ears_tested_at_the_top_cut_as_ears_tested_when_asked(
            pts in proptest::collection::vec((0u8..7, 0u8..7), 3..60),
            radii in proptest::collection::vec(0.2f64..1.0, 3..150),
        ) {
            let grid: Vec<DVec2> =
                pts.iter().map(|&(x, y)| DVec2::new(x as f64, y as f64)).collect();
            let n = radii.len();
            let star: Vec<DVec2> = radii.iter().enumerate().map(|(i, r)| {
                let a = std::f64::consts::TAU * i as f64 / n as f64;
                DVec2::new(r * a.cos(), r * a.sin())
            }).collect();
            for flat in [&grid, &star] {
                prop_assert_eq!(clip_with(flat, false, false), clip_with(flat, false, true));
            }
        }
    }
}
