//! Shards of equal predicted cost (`--shard K/N --balance`): each frame's cost is predicted
//! by the rays a pre-pass casts at 1/8 of the width and height with one sample per pixel
//! and no adaptive refinement (1/64 of the pixels, so about 1/64 of the work at one
//! sample); ray counts, not times,
//! so every task of an array job computes the same split with no shared state. The split
//! stays contiguous in frame numbers:
//!
//! ```text
//! costs   3 3 3 3 9 9 9 9          (a camera turning from empty sky to the glass spheres)
//! 2 equal-count shards   0-3 = 12, 4-7 = 36
//! 2 balanced shards      0-5 = 30, 6-7 = 18   (the boundary nearest half the total, 24)
//! ```

use super::select::{in_order, select, sorted};
use crate::error::AnimError;
use crate::project::Animation;
use rayon::prelude::*;
use whitted::render::estimate::SAMPLE_DIVISOR;

/// The pre-pass of `anim`: its frames at 1/`SAMPLE_DIVISOR` (8) of each side (at least
/// one pixel), one sample per pixel and no adaptive anti-aliasing, on `anim`'s BVH.
pub fn prepass<'p>(anim: &Animation<'p>) -> Animation<'p> {
    anim.scaled(SAMPLE_DIVISOR, Some(1))
}

/// The predicted cost of each of `frames` (in that order): the rays its pre-pass casts.
pub fn predicted_costs(anim: &Animation, frames: &[u32]) -> Result<Vec<u64>, AnimError> {
    let small = prepass(anim);
    small.check_cameras(frames)?;
    frames
        .par_iter()
        .map(|&f| small.render(&small.plan(f)).map(|(_, rays)| rays.total()))
        .collect()
}

/// The frames of a run with `--balance`: the `list` (all frames when `None`), then part
/// `(k, n)` of it by predicted cost, in the list's order.
pub fn select_balanced(
    anim: &Animation,
    list: Option<&str>,
    shard: Option<(u32, u32)>,
) -> Result<Vec<u32>, AnimError> {
    let all = select(anim.manifest.frames, list, None).map_err(AnimError::from)?;
    let Some((k, n)) = shard else {
        return Ok(all);
    };
    let by_number = sorted(&all);
    let costs = predicted_costs(anim, &by_number)?;
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
    fn the_prepass_is_an_eighth_a_side_at_one_sample_without_refinement() {
        let dir = tempfile::tempdir().unwrap();
        let scene = "67 41  0 1 6  0 1 0  0 0  1 0 0 1\n1.0  0 1 0   1 0.9 0.2 0.1   0.7 0.3 0 1 0 0\n5 10 5  1 1 1  0.9";
        std::fs::write(dir.path().join("s.txt"), scene).unwrap();
        let m = dir.path().join("m.toml");
        let aa = "[render]\nantialias = { mode = \"adaptive\", threshold = 0.1, depth = 3 }\n";
        std::fs::write(&m, format!("scene = \"s.txt\"\nframes = 2\n{aa}")).unwrap();
        let project = crate::project::Project::load(&m).unwrap();
        let anim = Animation::new(&project).unwrap();
        assert!(anim.antialias.is_some());
        let small = prepass(&anim);
        // 67 / 8 = 8, 41 / 8 = 5 (rounded down).
        assert_eq!((small.width, small.height, small.samples), (8, 5, 1));
        assert!(small.antialias.is_none());
        // A frame of it casts one camera ray a pixel.
        let (_, rays) = small.render(&small.plan(0)).unwrap();
        assert_eq!(rays.primary, 40);
    }

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
