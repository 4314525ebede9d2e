//! Clipping to a view's rectangle, in data coordinates, for the path plot: plotters draws
//! whatever it is given, labels and margins included, and infinite planes and cylinders
//! reach past any view. `segment` clips a line segment (Liang–Barsky), `polygon` a convex
//! or concave polygon (Sutherland–Hodgman, one rectangle edge at a time).

/// A point of a view, (horizontal, vertical).
pub type P2 = (f64, f64);

/// An axis-aligned rectangle [u0, u1] × [v0, v1].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rect {
    pub u: (f64, f64),
    pub v: (f64, f64),
}

impl Rect {
    pub fn contains(&self, p: P2) -> bool {
        (self.u.0..=self.u.1).contains(&p.0) && (self.v.0..=self.v.1).contains(&p.1)
    }

    /// The length of the diagonal.
    pub fn diagonal(&self) -> f64 {
        (self.u.1 - self.u.0).hypot(self.v.1 - self.v.0)
    }
}

/// The part of segment a–b inside `r`, if any.
pub fn segment(a: P2, b: P2, r: &Rect) -> Option<(P2, P2)> {
    let (du, dv) = (b.0 - a.0, b.1 - a.1);
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    // Each edge as p·t <= q.
    for (p, q) in [
        (-du, a.0 - r.u.0),
        (du, r.u.1 - a.0),
        (-dv, a.1 - r.v.0),
        (dv, r.v.1 - a.1),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else {
            let t = q / p;
            if p < 0.0 {
                t0 = t0.max(t);
            } else {
                t1 = t1.min(t);
            }
        }
    }
    (t0 <= t1).then(|| {
        let at = |t: f64| (a.0 + t * du, a.1 + t * dv);
        (at(t0), at(t1))
    })
}

/// The part of polygon `poly` inside `r` (empty when none).
pub fn polygon(poly: &[P2], r: &Rect) -> Vec<P2> {
    // Each edge: a test "inside" and the crossing of a segment with the edge's line.
    let edges: [(usize, f64, bool); 4] = [
        (0, r.u.0, true),
        (0, r.u.1, false),
        (1, r.v.0, true),
        (1, r.v.1, false),
    ];
    let mut out = poly.to_vec();
    for (axis, at, keep_above) in edges {
        let coord = |p: P2| if axis == 0 { p.0 } else { p.1 };
        let inside = |p: P2| (coord(p) >= at) == keep_above || coord(p) == at;
        let cross = |a: P2, b: P2| {
            let t = (at - coord(a)) / (coord(b) - coord(a));
            (a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1))
        };
        let input = std::mem::take(&mut out);
        for (i, &cur) in input.iter().enumerate() {
            let prev = input[(i + input.len() - 1) % input.len()];
            match (inside(prev), inside(cur)) {
                (true, true) => out.push(cur),
                (true, false) => out.push(cross(prev, cur)),
                (false, true) => {
                    out.push(cross(prev, cur));
                    out.push(cur);
                }
                (false, false) => {}
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    const R: Rect = Rect {
        u: (0.0, 10.0),
        v: (0.0, 5.0),
    };

    #[test]
    fn segments_are_cut_at_the_edges() {
        // Crosses the whole rectangle horizontally at v = 2.
        assert_eq!(
            segment((-5.0, 2.0), (15.0, 2.0), &R),
            Some(((0.0, 2.0), (10.0, 2.0)))
        );
        // Inside: unchanged.
        assert_eq!(
            segment((1.0, 1.0), (2.0, 3.0), &R),
            Some(((1.0, 1.0), (2.0, 3.0)))
        );
        // From (−2, −1) to (8, 4), slope 1/2: enters at u = 0, v = 0, stays to the end.
        assert_eq!(
            segment((-2.0, -1.0), (8.0, 4.0), &R),
            Some(((0.0, 0.0), (8.0, 4.0)))
        );
        // Above the rectangle: nothing.
        assert_eq!(segment((0.0, 6.0), (10.0, 7.0), &R), None);
    }

    #[test]
    fn a_polygon_overlapping_a_corner_keeps_the_overlap() {
        // The square [−2, 2]² overlaps R in [0, 2] × [0, 2].
        let sq = [(-2.0, -2.0), (2.0, -2.0), (2.0, 2.0), (-2.0, 2.0)];
        let mut got = polygon(&sq, &R);
        got.sort_by(|a, b| a.partial_cmp(b).unwrap());
        got.dedup();
        assert_eq!(got, vec![(0.0, 0.0), (0.0, 2.0), (2.0, 0.0), (2.0, 2.0)]);
        // Wholly outside: empty; wholly inside: unchanged.
        assert!(polygon(&[(20.0, 1.0), (21.0, 1.0), (21.0, 2.0)], &R).is_empty());
        let tri = [(1.0, 1.0), (2.0, 1.0), (2.0, 2.0)];
        assert_eq!(polygon(&tri, &R), tri.to_vec());
    }

    #[test]
    fn rect_helpers() {
        assert!(R.contains((10.0, 5.0)));
        assert!(!R.contains((10.1, 5.0)));
        assert_eq!(
            Rect {
                u: (0.0, 3.0),
                v: (0.0, 4.0)
            }
            .diagonal(),
            5.0
        );
    }
}
