//! When a square of the lattice splits: how two corner samples' difference is measured
//! (`adaptive:T:D:MEASURE` on the command line; manifests take the default, `edge`).
//!
//! ```text
//! sum   |Δr| + |Δg| + |Δb| > T                      POV-Ray's Colour_Distance
//! max   max(|Δr|, |Δg|, |Δb|) > T
//! edge  (|Δr| + |Δg| + |Δb|) · s > T, s = 2^−level  the square's side in pixels; and a
//!       pixel whose corners agree splits once when two or more of its four neighbours do
//! ```
//!
//! Every pair of a square's four corners is measured (the sides and the diagonals), on the
//! clamped output values (our output has no gamma). Why `edge` is the default, with the
//! figures that chose it: docs/decisions.md and docs/performance.md.

use crate::base::Color;
use serde::Serialize;

/// How two corner samples' difference is measured.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Measure {
    /// |Δr| + |Δg| + |Δb|, POV-Ray's `Colour_Distance`, the same at every level.
    Sum,
    /// max(|Δr|, |Δg|, |Δb|), the same at every level.
    Max,
    /// The sum times the square's side in pixels (2^−level): a difference across a
    /// quarter of a pixel moves the pixel about half as much as one across the whole pixel,
    /// since an edge crosses a square along its side. With it, a pixel whose corners agree
    /// while two or more of its four neighbours split is split once too: corners that
    /// agree amid splitting neighbours are most often an alias of detail finer than the
    /// lattice (a far checker), not a flat patch.
    Edge,
}

impl Measure {
    /// Every measure, the default first.
    pub const ALL: [Measure; 3] = [Measure::Edge, Measure::Sum, Measure::Max];

    /// The measure's name, as `adaptive:T:D:NAME` spells it.
    pub fn name(self) -> &'static str {
        match self {
            Measure::Sum => "sum",
            Measure::Max => "max",
            Measure::Edge => "edge",
        }
    }

    /// Whether a pixel whose own corners agree splits amid splitting neighbours.
    pub fn splits_amid_neighbours(self) -> bool {
        self == Measure::Edge
    }

    /// Whether the corners `c` (clamped; top-left, top-right, bottom-left, bottom-right)
    /// of a square `level` splits below its pixel differ by more than `threshold`.
    pub fn differ(self, threshold: f64, c: &[Color; 4], level: u32) -> bool {
        // Scaling by a power of two is exact: `edge` at level L is the sum against T·2^L.
        let t = match self {
            Measure::Edge => threshold * f64::from(1u32 << level.min(31)),
            Measure::Sum | Measure::Max => threshold,
        };
        // Each channel's range over the four corners bounds every pair's difference in
        // that channel, and the largest pair difference of one channel is its range: the
        // ranges decide most squares (flat ones) without the six pairs.
        let lo = c[0].min(c[1]).min(c[2].min(c[3]));
        let hi = c[0].max(c[1]).max(c[2].max(c[3]));
        let range = hi - lo;
        match self {
            Measure::Max => range.max_element() > t,
            Measure::Sum | Measure::Edge => {
                if range.x + range.y + range.z <= t {
                    return false;
                }
                let sum = |a: Color, b: Color| {
                    let d = (a - b).abs();
                    d.x + d.y + d.z
                };
                sum(c[0], c[1]) > t
                    || sum(c[0], c[2]) > t
                    || sum(c[0], c[3]) > t
                    || sum(c[1], c[2]) > t
                    || sum(c[1], c[3]) > t
                    || sum(c[2], c[3]) > t
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const BLACK: Color = Color::ZERO;

    #[test]
    fn the_measures_by_hand() {
        // Δ = (0.1, 0.1, 0.1) between two corners: sum 0.3, max 0.1.
        let c = [BLACK, Color::splat(0.1), BLACK, BLACK];
        assert!(Measure::Sum.differ(0.25, &c, 0));
        assert!(!Measure::Sum.differ(0.3 + 1e-9, &c, 0));
        assert!(!Measure::Max.differ(0.25, &c, 0));
        assert!(Measure::Max.differ(0.09, &c, 0));
        // `edge` at level 0 is the sum; at level 1 the difference counts half (0.15), at
        // level 2 a quarter (0.075).
        assert!(Measure::Edge.differ(0.25, &c, 0));
        assert!(!Measure::Edge.differ(0.25, &c, 1));
        assert!(Measure::Edge.differ(0.14, &c, 1));
        assert!(!Measure::Edge.differ(0.08, &c, 2));
        assert!(Measure::Edge.differ(0.07, &c, 2));
        // sum and max are the same at every level.
        assert!(Measure::Sum.differ(0.25, &c, 3));
        assert!(Measure::Max.differ(0.09, &c, 3));
    }

    #[test]
    fn a_diagonal_pair_counts_and_the_ranges_alone_do_not_split() {
        let diagonal = [
            BLACK,
            Color::splat(0.05),
            Color::splat(0.05),
            Color::splat(0.1),
        ];
        assert!(Measure::Sum.differ(0.25, &diagonal, 0));
        assert!(!Measure::Sum.differ(0.31, &diagonal, 0));
        // Ranges of 0.2 in red and 0.2 in green (their sum 0.4 > T = 0.3), but every pair
        // differs by 0.2: the six pairs decide, not the ranges.
        let spread = [
            Color::new(0.2, 0.1, 0.0),
            Color::new(0.0, 0.1, 0.0),
            Color::new(0.1, 0.2, 0.0),
            Color::new(0.1, 0.0, 0.0),
        ];
        assert!(!Measure::Sum.differ(0.3, &spread, 0));
        assert!(Measure::Sum.differ(0.19, &spread, 0));
    }

    #[test]
    fn names() {
        let names: Vec<_> = Measure::ALL.iter().map(|m| m.name()).collect();
        assert_eq!(names, ["edge", "sum", "max"]);
        assert!(Measure::Edge.splits_amid_neighbours());
        // The settings' JSON, which the frame digest hashes, names the measure.
        let json = serde_json::to_string(&super::super::Adaptive::DEFAULT).unwrap();
        assert!(json.contains(r#""measure":"edge""#), "{json}");
        assert!(!Measure::Sum.splits_amid_neighbours());
    }
}
