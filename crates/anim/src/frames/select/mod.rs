//! Which frames a run renders, and in which order: a frame list in `fileseq`'s grammar
//! (`grammar`: `1-100`, `1-100x5`, `1-100y5`, `1-100:5`, lists of those), then a shard
//! (`shard`: `K/N` or `auto` from the render farm's environment).
//!
//! ```text
//! --frames 0-249:8     every 8th frame first, then the ones x7 adds, … then the rest
//! --shard 2/4          the third quarter of those frames, by frame number
//! ```
//!
//! A shard is a contiguous run of frame numbers of the selected set (its K-th quarter, say),
//! rendered in the list's order, so shards and orders compose: every frame of a list is
//! rendered by exactly one shard whatever the order. The camera's time always comes from
//! the whole sequence, so a subset renders exactly the frames a full run would.

pub mod grammar;
pub mod shard;

pub use grammar::{FrameSpec, ListProblem, SpecError};
pub use shard::{process_env, shard, Shard, ShardError};

use std::collections::HashSet;

/// A bad frame list or shard.
#[derive(Debug, thiserror::Error, PartialEq, Eq)]
pub enum SelectError {
    /// The frame list `list` (as the user wrote it) cannot be read or names a frame the
    /// sequence does not have; `column` (from 1, in characters of `list`) says where.
    #[error("frame list {list:?}, column {column}: {problem}")]
    Frames {
        /// The list as given, e.g. `"0-3,9"`.
        list: String,
        /// Where in `list` the problem is.
        column: usize,
        /// What is wrong with it.
        problem: ListProblem,
    },
    /// The shard cannot be parsed or resolved.
    #[error(transparent)]
    Shard(#[from] ShardError),
}

impl SelectError {
    /// The list and a caret under the column of the problem, for a terminal (two lines,
    /// each indented by two spaces); `None` for a shard's error.
    pub fn caret(&self) -> Option<String> {
        let SelectError::Frames { list, column, .. } = self else {
            return None;
        };
        let pad = " ".repeat(column.saturating_sub(1));
        Some(format!("  {list}\n  {pad}^"))
    }
}

/// The frames of a run over a `total`-frame sequence, in render order: all, or the `frames`
/// list, then chunk `(index, count)` of that.
pub fn select(
    total: u32,
    frames: Option<&str>,
    shard: Option<(u32, u32)>,
) -> Result<Vec<u32>, SelectError> {
    let list = match frames {
        Some(spec) => parse_frames(spec, total)?,
        None => (0..total).collect(),
    };
    Ok(match shard {
        Some((k, n)) => in_order(&list, &self::shard(&sorted(&list), k, n)),
        None => list,
    })
}

/// Parses a frame list (`0-3,9`, `1-99:4`) against a sequence of `frames` frames: in the
/// list's order, without repeats, not empty.
pub fn parse_frames(spec: &str, frames: u32) -> Result<Vec<u32>, SelectError> {
    let err = |e: SpecError| SelectError::Frames {
        list: spec.to_string(),
        column: e.column,
        problem: e.problem,
    };
    let list = FrameSpec::parse(spec)
        .and_then(|s| s.frames(Some(frames)))
        .map_err(err)?;
    if list.is_empty() {
        let column = 1;
        return Err(err(SpecError {
            column,
            problem: ListProblem::NoFrames,
        }));
    }
    // Bounded by `frames`, so every frame fits.
    Ok(list.into_iter().map(|f| f as u32).collect())
}

/// `list` in frame-number order.
pub fn sorted(list: &[u32]) -> Vec<u32> {
    let mut s = list.to_vec();
    s.sort_unstable();
    s
}

/// The frames of `part` in the order they have in `list`.
pub fn in_order(list: &[u32], part: &[u32]) -> Vec<u32> {
    let keep: HashSet<u32> = part.iter().copied().collect();
    list.iter().copied().filter(|f| keep.contains(f)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges_and_singles_in_the_lists_order() {
        assert_eq!(
            parse_frames("0-3,10, 7", 20).unwrap(),
            vec![0, 1, 2, 3, 10, 7]
        );
        assert_eq!(parse_frames("5", 6).unwrap(), vec![5]);
        assert_eq!(parse_frames("2-4,3-5", 6).unwrap(), vec![2, 3, 4, 5]);
        assert_eq!(parse_frames("1,,2,", 6).unwrap(), vec![1, 2]);
        assert_eq!(parse_frames("3-1", 6).unwrap(), vec![3, 2, 1]);
        assert_eq!(parse_frames("0-10x3", 10).unwrap(), vec![0, 3, 6, 9]);
    }

    #[test]
    fn bad_lists_say_where() {
        let problem = |spec: &str| match parse_frames(spec, 6) {
            Err(SelectError::Frames {
                list,
                column,
                problem,
            }) if list == spec => (column, problem),
            other => panic!("{spec}: {other:?}"),
        };
        use ListProblem::*;
        assert_eq!(problem("6"), (1, PastTheEnd { frame: 6, last: 5 }));
        assert_eq!(problem("0,2-6"), (5, PastTheEnd { frame: 6, last: 5 }));
        assert_eq!(problem("1-3x0"), (5, ZeroStep));
        assert_eq!(problem("a-2"), (1, NotANumber("'a'".into())));
        assert_eq!(problem("-1"), (1, BeforeTheStart(-1)));
        assert_eq!(problem(""), (1, NoFrames));
        assert_eq!(problem(" , "), (1, NoFrames));
        let e = parse_frames("1-3x0", 6).unwrap_err();
        assert_eq!(
            e.to_string(),
            "frame list \"1-3x0\", column 5: the step must not be 0"
        );
        assert_eq!(e.caret().unwrap(), "  1-3x0\n      ^");
    }

    #[test]
    fn a_shard_is_contiguous_in_frame_numbers_and_keeps_the_order() {
        assert_eq!(select(10, None, None).unwrap(), (0..10).collect::<Vec<_>>());
        // Frames 2..=7 are six; the second of two halves is 5, 6, 7.
        assert_eq!(
            select(10, Some("2-7"), Some((1, 2))).unwrap(),
            vec![5, 6, 7]
        );
        // 0-8:4 is 0 4 8, 3 6, 2, 1 5 7; the first half of 0..=8 by number is 0..=3
        // (4 of 9), in that order.
        assert_eq!(
            select(9, Some("0-8:4"), None).unwrap(),
            [0, 4, 8, 3, 6, 2, 1, 5, 7]
        );
        assert_eq!(
            select(9, Some("0-8:4"), Some((0, 2))).unwrap(),
            [0, 3, 2, 1]
        );
        assert_eq!(
            select(9, Some("0-8:4"), Some((1, 2))).unwrap(),
            [4, 8, 6, 5, 7]
        );
    }
}
