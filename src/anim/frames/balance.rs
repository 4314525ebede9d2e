//! Shards of equal predicted cost (`--shard K/N --balance`): each frame's cost is predicted
//! by the rays a pre-pass casts at 1/8 of the width and height with one sample per pixel
//! (1/64 of the pixels, so about 1/64 of the work at one sample); ray counts, not times,
//! so every task of an array job computes the same split with no shared state. The split
//! stays contiguous in frame numbers:
//!
//! ```text
//! costs   3 3 3 3 9 9 9 9          (a camera turning from empty sky to the glass spheres)
//! 2 equal-count shards   0-3 = 12, 4-7 = 36
//! 2 balanced shards      0-5 = 30, 6-7 = 18   (the boundary nearest half the total, 24)
//! ```

use super::select::{in_order, select, sorted};
use crate::anim::error::AnimError;
use crate::anim::project::{Animation, Project};
use rayon::prelude::*;

/// The pre-pass draws at 1/`PREPASS_DIVISOR` of the width and of the height.
pub const PREPASS_DIVISOR: u32 = 8;

/// The pre-pass of `anim`: its frames at 1/8 of each side (at least one pixel), one
/// sample per pixel.
pub fn prepass<'p>(project: &'p Project, anim: &Animation) -> Result<Animation<'p>, AnimError> {
    let side = |s: u32| (s / PREPASS_DIVISOR).max(1);
    let mut small = Animation::with_size(project, side(anim.width), side(anim.height))?;
    small.samples = 1;
    Ok(small)
}

/// The predicted cost of each of `frames` (in that order): the rays its pre-pass casts.
pub fn predicted_costs(
    project: &Project,
    anim: &Animation,
    frames: &[u32],
) -> Result<Vec<u64>, AnimError> {
    let small = prepass(project, anim)?;
    small.check_cameras(frames)?;
    frames
        .par_iter()
        .map(|&f| small.render(f).map(|(_, rays)| rays.total()))
        .collect()
}

/// The frames of a run with `--balance`: the `list` (all frames when `None`), then part
/// `(k, n)` of it by predicted cost, in the list's order.
pub fn select_balanced(
    project: &Project,
    anim: &Animation,
    list: Option<&str>,
    shard: Option<(u32, u32)>,
) -> Result<Vec<u32>, AnimError> {
    let all = select(anim.manifest.frames, list, None).map_err(AnimError::from)?;
    let Some((k, n)) = shard else {
        return Ok(all);
    };
    let by_number = sorted(&all);
    let costs = predicted_costs(project, anim, &by_number)?;
    Ok(in_order(&all, &balanced_shard(&by_number, &costs, k, n)))
}

/// The N + 1 boundaries of N contiguous parts of `costs` of about equal sums: part k is
/// `costs[b[k]..b[k + 1]]`. Each inner boundary is the index whose prefix sum is nearest
/// k/N of the total (the lower one on a tie), never before the previous boundary.
pub fn split(costs: &[u64], n: u32) -> Vec<usize> {
    let mut prefix = Vec::with_capacity(costs.len() + 1);
    prefix.push(0u128);
    for &c in costs {
        prefix.push(prefix[prefix.len() - 1] + u128::from(c));
    }
    let total = prefix[costs.len()];
    let n128 = u128::from(n.max(1));
    let mut bounds = vec![0];
    for k in 1..n.max(1) {
        let target = u128::from(k) * total;
        // The first index whose prefix·N reaches k·total.
        let hi = prefix.partition_point(|&p| p * n128 < target);
        let lo = hi.saturating_sub(1);
        let dist = |i: usize| (prefix[i] * n128).abs_diff(target);
        let best = if hi <= costs.len() && dist(hi) < dist(lo) {
            hi
        } else {
            lo
        };
        let prev = bounds[bounds.len() - 1];
        bounds.push(best.clamp(prev, costs.len()));
    }
    bounds.push(costs.len());
    bounds
}

/// Part `k` of `n` of `sorted` (frames in number order) by the costs of those frames.
pub fn balanced_shard(sorted: &[u32], costs: &[u64], k: u32, n: u32) -> Vec<u32> {
    let b = split(costs, n);
    sorted[b[k as usize]..b[k as usize + 1]].to_vec()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_doc_example() {
        let costs = [3, 3, 3, 3, 9, 9, 9, 9];
        // Prefix sums 0 3 6 9 12 21 30 39 48; half is 24: 21 is 3 away, 30 is 6.
        assert_eq!(split(&costs, 2), [0, 5, 8]);
        assert_eq!(split(&costs, 1), [0, 8]);
        // Quarters of 48 are 12, 24, 36: prefix 12 (index 4), 21 (5, 3 from 24 against 6
        // for 30), 39 (7, 3 from 36 against 6 for 30).
        assert_eq!(split(&costs, 4), [0, 4, 5, 7, 8]);
        let frames: Vec<u32> = (10..18).collect();
        assert_eq!(balanced_shard(&frames, &costs, 1, 2), [15, 16, 17]);
    }

    #[test]
    fn equal_costs_split_like_equal_counts_and_every_frame_once() {
        let costs = vec![5u64; 12];
        assert_eq!(split(&costs, 3), [0, 4, 8, 12]);
        for n in 1..20 {
            let b = split(&[1, 50, 2, 2, 2, 90, 1, 1, 7], n);
            assert_eq!((b[0], b[n as usize]), (0, 9));
            assert!(b.windows(2).all(|w| w[0] <= w[1]), "{b:?}");
        }
        // More shards than frames: some are empty, none repeats a frame.
        assert_eq!(split(&[4, 4], 4), [0, 0, 1, 1, 2]);
        assert_eq!(split(&[], 3), [0, 0, 0, 0]);
    }
}
