//! The command line's spelling of adaptive anti-aliasing, `adaptive[:T[:D[:MEASURE]]]`
//! (`raytrace --aa adaptive:0.4:2`; MEASURE `edge`, the default, or `sum` or `max`, for
//! the measurements of benches/pov/adaptive.sh), and the bounds every spelling obeys:
//! 0 ≤ T ≤ 3, 0 ≤ D ≤ `MAX_DEPTH`.

use super::{Adaptive, Measure, MAX_DEPTH, MAX_THRESHOLD};
use std::str::FromStr;
use thiserror::Error;

/// A bad anti-aliasing setting.
#[derive(Debug, Error, PartialEq)]
pub enum AntialiasError {
    /// Not `adaptive[:T[:D]]`.
    #[error(
        "expected adaptive[:THRESHOLD[:DEPTH[:edge|sum|max]]], e.g. adaptive:0.4:2, found {0:?}"
    )]
    Syntax(String),
    /// A threshold out of 0..=3 (or not a number).
    #[error("the threshold must be a number from 0 to 3, found {0}")]
    Threshold(String),
    /// A depth out of 0..=MAX_DEPTH.
    #[error("the depth must be a whole number from 0 to 6, found {0}")]
    Depth(String),
    /// A depth and size whose worst case needs more than `limits::MAX_ADAPTIVE_BYTES`.
    #[error(
        "adaptive anti-aliasing at depth {depth} on {width}×{height} may need {} MiB for its \
         samples, more than the limit of {} MiB a frame: lower the depth or the size",
        bytes >> 20, crate::limits::MAX_ADAPTIVE_BYTES >> 20
    )]
    TooLarge {
        /// The frame's width.
        width: u32,
        /// The frame's height.
        height: u32,
        /// The depth asked for.
        depth: u32,
        /// The worst case (`worst_bytes`).
        bytes: u64,
    },
}

impl Adaptive {
    /// Whether a `width`×`height` frame at this depth stays within
    /// `limits::MAX_ADAPTIVE_BYTES` whatever it shows; checked before anything is allocated.
    pub fn fits(&self, width: u32, height: u32) -> Result<(), AntialiasError> {
        let bytes = super::worst_bytes(width.into(), height.into(), self.depth);
        if bytes <= crate::limits::MAX_ADAPTIVE_BYTES {
            return Ok(());
        }
        Err(AntialiasError::TooLarge {
            width,
            height,
            depth: self.depth,
            bytes,
        })
    }
}

impl Adaptive {
    /// The defaults with `threshold` and `depth` where given, each checked.
    pub fn with(threshold: Option<f64>, depth: Option<i64>) -> Result<Adaptive, AntialiasError> {
        let mut aa = Adaptive::DEFAULT;
        if let Some(t) = threshold {
            if !(0.0..=MAX_THRESHOLD).contains(&t) {
                return Err(AntialiasError::Threshold(t.to_string()));
            }
            aa.threshold = t;
        }
        if let Some(d) = depth {
            if !(0..=i64::from(MAX_DEPTH)).contains(&d) {
                return Err(AntialiasError::Depth(d.to_string()));
            }
            aa.depth = d as u32;
        }
        Ok(aa)
    }
}

impl FromStr for Adaptive {
    type Err = AntialiasError;

    fn from_str(s: &str) -> Result<Adaptive, AntialiasError> {
        let mut parts = s.split(':');
        if parts.next() != Some("adaptive") {
            return Err(AntialiasError::Syntax(s.to_string()));
        }
        let threshold = match parts.next() {
            Some(t) => Some(
                t.parse::<f64>()
                    .map_err(|_| AntialiasError::Threshold(format!("{t:?}")))?,
            ),
            None => None,
        };
        let depth = match parts.next() {
            Some(d) => Some(
                d.parse::<i64>()
                    .map_err(|_| AntialiasError::Depth(format!("{d:?}")))?,
            ),
            None => None,
        };
        let measure = match parts.next() {
            None => Adaptive::DEFAULT.measure,
            Some(name) => Measure::ALL
                .into_iter()
                .find(|m| m.name() == name)
                .ok_or_else(|| AntialiasError::Syntax(s.to_string()))?,
        };
        if parts.next().is_some() {
            return Err(AntialiasError::Syntax(s.to_string()));
        }
        Ok(Adaptive {
            measure,
            ..Adaptive::with(threshold, depth)?
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spellings() {
        assert_eq!("adaptive".parse(), Ok(Adaptive::DEFAULT));
        let a: Adaptive = "adaptive:0.3".parse().unwrap();
        assert_eq!((a.threshold, a.depth), (0.3, Adaptive::DEFAULT.depth));
        let a: Adaptive = "adaptive:0:5".parse().unwrap();
        assert_eq!((a.threshold, a.depth, a.measure), (0.0, 5, Measure::Edge));
        let a: Adaptive = "adaptive:0.2:2:max".parse().unwrap();
        assert_eq!((a.threshold, a.depth, a.measure), (0.2, 2, Measure::Max));
        let a: Adaptive = "adaptive:0.2:2:sum".parse().unwrap();
        assert_eq!(a.measure, Measure::Sum);
        let a: Adaptive = "adaptive:0.2:2:edge".parse().unwrap();
        assert_eq!(a.measure, Measure::Edge);
    }

    #[test]
    fn refusals() {
        let bad = |s: &str| s.parse::<Adaptive>().unwrap_err();
        assert!(matches!(bad("grid"), AntialiasError::Syntax(_)));
        assert!(matches!(bad("adaptive:0.1:3:1"), AntialiasError::Syntax(_)));
        assert!(matches!(
            bad("adaptive:0.1:3:Edge"),
            AntialiasError::Syntax(_)
        ));
        assert!(matches!(
            bad("adaptive:0.1:3:max:1"),
            AntialiasError::Syntax(_)
        ));
        assert!(matches!(bad("adaptive:x"), AntialiasError::Threshold(_)));
        assert!(matches!(bad("adaptive:-0.1"), AntialiasError::Threshold(_)));
        assert!(matches!(bad("adaptive:3.5"), AntialiasError::Threshold(_)));
        assert!(matches!(bad("adaptive:NaN"), AntialiasError::Threshold(_)));
        assert!(matches!(bad("adaptive:0.1:7"), AntialiasError::Depth(_)));
        assert!(matches!(bad("adaptive:0.1:1.5"), AntialiasError::Depth(_)));
    }
}
