//! Which frames a run renders: `--frames 0-99,120` (inclusive ranges, as render farms
//! write them) and `--shard K/N` (the K-th of N contiguous chunks, 0-based, sizes
//! differing by at most one). A shard splits the frames the run would otherwise render, so
//! `--frames` and `--shard` compose. The camera's time always comes from the whole
//! sequence, so a subset renders exactly the frames a full run would.

use std::collections::BTreeSet;

/// A bad `--frames` or `--shard` value.
#[derive(Debug, thiserror::Error, PartialEq, Eq)]
#[error("{0}")]
pub struct SelectError(String);

/// Parses a `--frames` list against a sequence of `frames` frames: sorted, without
/// repeats.
pub fn parse_frames(spec: &str, frames: u32) -> Result<Vec<u32>, SelectError> {
    let err = |m: String| Err(SelectError(format!("--frames {spec:?}: {m}")));
    let mut set = BTreeSet::new();
    for part in spec.split(',').map(str::trim) {
        if part.is_empty() {
            return err("an empty item (two commas, or a comma at an end)".into());
        }
        let (lo, hi) = match part.split_once('-') {
            Some((a, b)) => (a.trim(), b.trim()),
            None => (part, part),
        };
        let num = |s: &str| {
            s.parse::<u32>()
                .map_err(|_| SelectError(format!("--frames {spec:?}: '{s}' is not a frame number")))
        };
        let (lo, hi) = (num(lo)?, num(hi)?);
        if lo > hi {
            return err(format!("the range {lo}-{hi} runs backwards"));
        }
        if hi >= frames {
            return err(format!("frame {hi} is past the last frame, {}", frames - 1));
        }
        set.extend(lo..=hi);
    }
    Ok(set.into_iter().collect())
}

/// Parses `K/N` into (K, N) with N ≥ 1 and K < N.
pub fn parse_shard(spec: &str) -> Result<(u32, u32), SelectError> {
    let bad = || {
        SelectError(format!(
            "--shard {spec:?}: expected K/N with 0 ≤ K < N, as in 3/16"
        ))
    };
    let (k, n) = spec.split_once('/').ok_or_else(bad)?;
    let k: u32 = k.trim().parse().map_err(|_| bad())?;
    let n: u32 = n.trim().parse().map_err(|_| bad())?;
    if n == 0 || k >= n {
        return Err(bad());
    }
    Ok((k, n))
}

/// The frames of a run over a `total`-frame sequence: all, or the `--frames` list, then
/// the `--shard` of that.
pub fn select(
    total: u32,
    frames: Option<&str>,
    shard_spec: Option<&str>,
) -> Result<Vec<u32>, SelectError> {
    let mut list = match frames {
        Some(spec) => parse_frames(spec, total)?,
        None => (0..total).collect(),
    };
    if let Some(spec) = shard_spec {
        let (k, n) = parse_shard(spec)?;
        list = shard(&list, k, n);
    }
    Ok(list)
}

/// The K-th of N contiguous chunks of `frames`: chunk k is `frames[k·L/N .. (k+1)·L/N]`.
pub fn shard(frames: &[u32], k: u32, n: u32) -> Vec<u32> {
    let len = frames.len() as u64;
    let start = (k as u64 * len / n as u64) as usize;
    let end = ((k as u64 + 1) * len / n as u64) as usize;
    frames[start..end].to_vec()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges_and_singles() {
        assert_eq!(
            parse_frames("0-3,10, 7", 20).unwrap(),
            vec![0, 1, 2, 3, 7, 10]
        );
        assert_eq!(parse_frames("5", 6).unwrap(), vec![5]);
        assert_eq!(parse_frames("2-4,3-5", 6).unwrap(), vec![2, 3, 4, 5]);
    }

    #[test]
    fn bad_lists() {
        assert!(parse_frames("6", 6).is_err());
        assert!(parse_frames("4-2", 6).is_err());
        assert!(parse_frames("1,,2", 6).is_err());
        assert!(parse_frames("a-2", 6).is_err());
        assert!(parse_frames("-1", 6).is_err());
        assert!(parse_frames("", 6).is_err());
    }

    #[test]
    fn shards_cover_everything_once_with_near_equal_sizes() {
        let all: Vec<u32> = (0..250).collect();
        for n in 1..=17 {
            let parts: Vec<Vec<u32>> = (0..n).map(|k| shard(&all, k, n)).collect();
            let joined: Vec<u32> = parts.concat();
            assert_eq!(joined, all, "n = {n}");
            let sizes: Vec<usize> = parts.iter().map(Vec::len).collect();
            let (min, max) = (sizes.iter().min().unwrap(), sizes.iter().max().unwrap());
            assert!(max - min <= 1, "{sizes:?}");
        }
        // 10 frames in 3 shards: 3, 3, 4.
        assert_eq!(shard(&(0..10).collect::<Vec<_>>(), 0, 3), vec![0, 1, 2]);
        assert_eq!(shard(&(0..10).collect::<Vec<_>>(), 2, 3), vec![6, 7, 8, 9]);
    }

    #[test]
    fn shard_of_a_subset() {
        assert_eq!(select(10, None, None).unwrap(), (0..10).collect::<Vec<_>>());
        assert_eq!(select(10, Some("2-7"), Some("1/2")).unwrap(), vec![5, 6, 7]);
        assert!(select(10, Some("2-7"), Some("2/2")).is_err());
    }

    #[test]
    fn shard_specs() {
        assert_eq!(parse_shard("3/16").unwrap(), (3, 16));
        assert!(parse_shard("16/16").is_err());
        assert!(parse_shard("0/0").is_err());
        assert!(parse_shard("1").is_err());
        assert!(parse_shard("x/2").is_err());
    }
}
