//! Frame comparison on OpenImageIO idiff's rules, for `animate check`.
//!
//! Channels are compared as 8-bit values (0..255). A pixel fails when any channel differs
//! by more than `fail`; a frame fails when more than `fail_percent` % of its pixels fail,
//! or when any channel differs by more than `hard_fail`. Alongside the verdict: the largest
//! difference and where, the mean absolute error per channel, and the PSNR
//! 10·log10(255² / MSE) (infinite for identical frames).

use crate::render::Frame;
use serde::Serialize;

/// The thresholds of a check.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Tolerance {
    pub fail: u8,
    pub fail_percent: f64,
    pub hard_fail: u8,
}

impl Tolerance {
    /// The SPEC's example thresholds, used when a manifest has no `[check]`.
    pub const DEFAULT: Tolerance = Tolerance {
        fail: 2,
        fail_percent: 0.1,
        hard_fail: 64,
    };
}

/// How a rendered frame compares with its reference.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Comparison {
    /// The largest channel difference, 0..255.
    pub max_diff: u8,
    /// Pixel (x, y) and channel (0 R, 1 G, 2 B) of the first largest difference.
    pub max_at: Option<(u32, u32, usize)>,
    /// Pixels with a channel differing by more than `fail`.
    pub failing_pixels: u64,
    pub failing_percent: f64,
    /// Mean absolute difference over all channels, 0..255.
    pub mean_error: f64,
    /// In dB; `None` when the frames are identical (infinite PSNR).
    pub psnr: Option<f64>,
    pub pass: bool,
}

/// Compares `rendered` with `reference`, which must have the same size.
pub fn compare(reference: &Frame, rendered: &Frame, tol: Tolerance) -> Comparison {
    debug_assert_eq!(reference.pixels.len(), rendered.pixels.len());
    let mut max_diff = 0u8;
    let mut max_at = None;
    let mut failing = 0u64;
    let mut abs_sum = 0u64;
    let mut sq_sum = 0u64;
    let width = reference.width.max(1) as usize;
    let pairs = reference
        .pixels
        .chunks_exact(3)
        .zip(rendered.pixels.chunks_exact(3));
    for (i, (a, b)) in pairs.enumerate() {
        let mut pixel_fails = false;
        for c in 0..3 {
            let d = a[c].abs_diff(b[c]);
            abs_sum += d as u64;
            sq_sum += (d as u64) * (d as u64);
            pixel_fails |= d > tol.fail;
            if d > max_diff {
                max_diff = d;
                max_at = Some(((i % width) as u32, (i / width) as u32, c));
            }
        }
        failing += pixel_fails as u64;
    }
    let pixels = (reference.pixels.len() / 3).max(1) as f64;
    let failing_percent = 100.0 * failing as f64 / pixels;
    let mse = sq_sum as f64 / (pixels * 3.0);
    Comparison {
        max_diff,
        max_at,
        failing_pixels: failing,
        failing_percent,
        mean_error: abs_sum as f64 / (pixels * 3.0),
        psnr: (mse > 0.0).then(|| 10.0 * (255.0f64 * 255.0 / mse).log10()),
        pass: failing_percent <= tol.fail_percent && max_diff <= tol.hard_fail,
    }
}

/// A heat map of the differences: black where the frames agree, then red, yellow and
/// white as the largest channel difference of a pixel grows towards the frame's maximum.
pub fn heat_map(reference: &Frame, rendered: &Frame) -> Frame {
    let diffs: Vec<u8> = reference
        .pixels
        .chunks_exact(3)
        .zip(rendered.pixels.chunks_exact(3))
        .map(|(a, b)| (0..3).map(|c| a[c].abs_diff(b[c])).max().unwrap_or(0))
        .collect();
    let top = diffs.iter().copied().max().unwrap_or(0).max(1) as f64;
    let ramp = |t: f64| (t.clamp(0.0, 1.0) * 255.0).round() as u8;
    let pixels = diffs
        .iter()
        .flat_map(|&d| {
            let t = if d == 0 {
                0.0
            } else {
                (d as f64 / top) * 0.8 + 0.2
            };
            [ramp(3.0 * t), ramp(3.0 * t - 1.0), ramp(3.0 * t - 2.0)]
        })
        .collect();
    Frame {
        width: reference.width,
        height: reference.height,
        pixels,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const TOL: Tolerance = Tolerance {
        fail: 2,
        fail_percent: 10.0,
        hard_fail: 64,
    };

    fn grey(w: u32, h: u32, v: u8) -> Frame {
        Frame {
            width: w,
            height: h,
            pixels: vec![v; (w * h * 3) as usize],
        }
    }

    #[test]
    fn identical_frames() {
        let c = compare(&grey(4, 4, 100), &grey(4, 4, 100), TOL);
        assert_eq!((c.max_diff, c.max_at, c.failing_pixels), (0, None, 0));
        assert_eq!((c.mean_error, c.psnr, c.pass), (0.0, None, true));
    }

    #[test]
    fn one_channel_at_fail_passes_and_one_more_fails_the_pixel() {
        let reference = grey(10, 1, 100);
        let mut r = reference.clone();
        r.pixels[3 * 7 + 1] = 102; // pixel 7, green, off by exactly `fail`
        let c = compare(&reference, &r, TOL);
        assert_eq!(
            (c.max_diff, c.max_at, c.failing_pixels),
            (2, Some((7, 0, 1)), 0)
        );
        r.pixels[3 * 7 + 1] = 103;
        let c = compare(&reference, &r, TOL);
        assert_eq!(c.failing_pixels, 1);
        // 1 pixel of 10 is 10 %: not more than fail_percent, so the frame still passes.
        assert_eq!((c.failing_percent, c.pass), (10.0, true));
        r.pixels[0] = 90;
        let c = compare(&reference, &r, TOL);
        assert_eq!((c.failing_percent, c.pass), (20.0, false));
    }

    #[test]
    fn hard_fail_trips_on_one_pixel() {
        let reference = grey(100, 100, 10);
        let mut r = reference.clone();
        r.pixels[3 * (5 * 100 + 42) + 2] = 75; // 65 > 64 at (42, 5), blue
        let c = compare(&reference, &r, TOL);
        assert_eq!(c.max_at, Some((42, 5, 2)));
        assert!(c.failing_percent < 0.02);
        assert!(!c.pass);
        r.pixels[3 * (5 * 100 + 42) + 2] = 74; // 64: not more than hard_fail
        assert!(compare(&reference, &r, TOL).pass);
    }

    #[test]
    fn mean_error_and_psnr_by_hand() {
        // Every channel off by 5: mean error 5, MSE 25, PSNR = 10·log10(65025/25) = 34.151…
        let c = compare(&grey(2, 2, 50), &grey(2, 2, 55), TOL);
        assert_eq!(c.mean_error, 5.0);
        let psnr = c.psnr.unwrap();
        assert!((psnr - 34.15140352195873).abs() < 1e-9, "{psnr}");
    }

    #[test]
    fn heat_map_is_black_where_equal() {
        let reference = grey(3, 1, 0);
        let mut r = reference.clone();
        r.pixels[3] = 200;
        let h = heat_map(&reference, &r);
        assert_eq!(&h.pixels[0..3], &[0, 0, 0]);
        assert_eq!(&h.pixels[3..6], &[255, 255, 255]); // the maximum is white
        assert_eq!(&h.pixels[6..9], &[0, 0, 0]);
    }
}
