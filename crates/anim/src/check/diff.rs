//! Frame comparison on OpenImageIO idiff's rules, for `animate check`.
//!
//! Channels are compared as 8-bit values (0..255). A pixel fails when any channel differs
//! by more than `fail`; a frame fails when more than `fail_percent` % of its pixels fail,
//! or when any channel differs by more than `hard_fail`. Alongside the verdict: the largest
//! difference and where, the mean absolute error per channel, and the PSNR
//! 10·log10(255² / MSE) (infinite for identical frames). A FLIP limit (`flip.rs`) may be
//! added to the tolerance; [`Tolerance::failed`] names every limit a frame breaks.

use serde::Serialize;
use whitted::base::Frame;

/// The thresholds of a check.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Tolerance {
    /// A pixel fails when a channel differs by more than this, 0..255.
    pub fail: u8,
    /// A frame fails when more than this percentage of its pixels fail, 0..100.
    pub fail_percent: f64,
    /// A frame fails when any channel differs by more than this, 0..255.
    pub hard_fail: u8,
    /// The largest mean FLIP error a frame may have; `None`: FLIP is not computed.
    pub flip: Option<f64>,
}

/// A limit of the tolerance that a frame can break.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Limit {
    /// More than `fail_percent` % of the pixels differ by more than `fail`.
    FailPercent,
    /// A channel differs by more than `hard_fail`.
    HardFail,
    /// The mean FLIP error is above `flip`.
    Flip,
}

impl Limit {
    /// The name of the limit as the manifest's `[check]` spells it.
    pub fn name(self) -> &'static str {
        match self {
            Limit::FailPercent => "fail_percent",
            Limit::HardFail => "hard_fail",
            Limit::Flip => "flip",
        }
    }
}

impl Tolerance {
    /// The SPEC's example thresholds, used when a manifest has no `[check]`.
    pub const DEFAULT: Tolerance = Tolerance {
        fail: 2,
        fail_percent: 0.1,
        hard_fail: 64,
        flip: None,
    };

    /// The limits that a frame with these figures breaks (none: it passes).
    pub fn failed(&self, c: &Comparison, flip: Option<f64>) -> Vec<Limit> {
        let mut limits = Vec::new();
        if c.failing_percent > self.fail_percent {
            limits.push(Limit::FailPercent);
        }
        if c.max_diff > self.hard_fail {
            limits.push(Limit::HardFail);
        }
        if let (Some(limit), Some(mean)) = (self.flip, flip) {
            if mean > limit {
                limits.push(Limit::Flip);
            }
        }
        limits
    }
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
    /// `failing_pixels` as a percentage of all pixels, 0..100.
    pub failing_percent: f64,
    /// Mean absolute difference over all channels, 0..255.
    pub mean_error: f64,
    /// In dB; `None` when the frames are identical (infinite PSNR).
    pub psnr: Option<f64>,
}

/// Compares `rendered` with `reference`, which must have the same size.
pub fn compare(reference: &Frame, rendered: &Frame, tol: Tolerance) -> Comparison {
    debug_assert_eq!(reference.pixels.len(), rendered.pixels.len());
    let (a, b) = (&reference.pixels, &rendered.pixels);
    let pairs = a.len().min(b.len()) / 3;
    compare_by(pairs, a.len() / 3, reference.width, tol, |i, c| {
        f64::from(a[3 * i + c].abs_diff(b[3 * i + c]))
    })
}

/// Compares two float beauties (EXR frames, rows top to bottom, `width` wide) on the same
/// rules with float limits: differences are measured in levels of 1/255 without rounding
/// or clamping (so `fail = 2` fails a channel off by more than 2/255 = 0.00784), the
/// PSNR's peak is 1.0, and `max_diff` reports the largest difference in levels rounded up
/// (255 at most: a difference of several whole units is off the 8-bit scale).
pub fn compare_float(
    reference: &[[f32; 3]],
    rendered: &[[f32; 3]],
    width: u32,
    tol: Tolerance,
) -> Comparison {
    let pairs = reference.len().min(rendered.len());
    compare_by(pairs, reference.len(), width, tol, |i, c| {
        let d = (f64::from(reference[i][c]) - f64::from(rendered[i][c])).abs() * 255.0;
        if d.is_nan() {
            f64::INFINITY
        } else {
            d
        }
    })
}

/// The figures of a comparison of the first `pairs` pixels of frames of `pixels` pixels
/// (the reference's count), `width` wide, whose channel `c` of pixel `i` differs by
/// `diff(i, c)` levels (whole for 8-bit frames, so every sum is exact in f64 and the
/// figures are those of integer arithmetic).
fn compare_by(
    pairs: usize,
    pixels: usize,
    width: u32,
    tol: Tolerance,
    diff: impl Fn(usize, usize) -> f64,
) -> Comparison {
    let (mut max, mut max_at) = (0.0f64, None);
    let (mut failing, mut abs_sum, mut sq_sum) = (0u64, 0.0f64, 0.0f64);
    let width = width.max(1) as usize;
    for i in 0..pairs {
        let mut pixel_fails = false;
        for c in 0..3 {
            let d = diff(i, c);
            abs_sum += d;
            sq_sum += d * d;
            pixel_fails |= d > f64::from(tol.fail);
            if d > max {
                max = d;
                max_at = Some(((i % width) as u32, (i / width) as u32, c));
            }
        }
        failing += pixel_fails as u64;
    }
    let count = pixels.max(1) as f64;
    let mse = sq_sum / (count * 3.0);
    Comparison {
        // A hard failure is any difference above `hard_fail` levels, fractions included.
        max_diff: max.ceil().min(255.0) as u8,
        max_at,
        failing_pixels: failing,
        failing_percent: 100.0 * failing as f64 / count,
        mean_error: abs_sum / (count * 3.0),
        psnr: (mse > 0.0).then(|| 10.0 * libm::log10(255.0f64 * 255.0 / mse)),
    }
}

/// The heat-map colour of a largest channel difference `d` (0..255), on a fixed
/// logarithmic scale: t = log2(1 + d) / 8, so 1 level is t = 1/8, 3 levels 1/4, 15 levels
/// 1/2, 255 levels 1; then black -> red -> yellow -> white as t goes 0 -> 1/3 -> 2/3 -> 1.
/// The same `d` gets the same colour in every frame, and a 1-level difference is a dim red.
pub(crate) fn heat_colour(d: u8) -> [u8; 3] {
    let t = libm::log2(1.0 + d as f64) / 8.0;
    let ramp = |x: f64| (x.clamp(0.0, 1.0) * 255.0).round() as u8;
    [ramp(3.0 * t), ramp(3.0 * t - 1.0), ramp(3.0 * t - 2.0)]
}

/// A heat map of the differences: each pixel's largest channel difference through
/// [`heat_colour`]; black where the frames agree.
pub fn heat_map(reference: &Frame, rendered: &Frame) -> Frame {
    let pixels = reference
        .pixels
        .chunks_exact(3)
        .zip(rendered.pixels.chunks_exact(3))
        .flat_map(|(a, b)| heat_colour((0..3).map(|c| a[c].abs_diff(b[c])).max().unwrap_or(0)))
        .collect();
    Frame {
        width: reference.width,
        height: reference.height,
        pixels,
    }
}

/// The heat map's legend: a `width`×`height` strip of the scale, even in t: column x
/// shows d = round(2^(8x / (width − 1)) − 1), so on a 256-wide strip d = 1, 3, 15, 63 and
/// 255 sit at columns 32, 64, 128, 191 and 255.
pub fn heat_legend(width: u32, height: u32) -> Frame {
    let row: Vec<u8> = (0..width)
        .flat_map(|x| {
            let t = x as f64 / (width.max(2) - 1) as f64;
            heat_colour((libm::exp2(8.0 * t) - 1.0).round() as u8)
        })
        .collect();
    Frame {
        width,
        height,
        pixels: row.repeat(height as usize),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const TOL: Tolerance = Tolerance {
        fail: 2,
        fail_percent: 10.0,
        hard_fail: 64,
        flip: Some(0.05),
    };

    fn pass(c: &Comparison) -> bool {
        TOL.failed(c, None).is_empty()
    }

    fn grey(w: u32, h: u32, v: u8) -> Frame {
        Frame {
            width: w,
            height: h,
            pixels: vec![v; (w * h * 3) as usize],
        }
    }

    #[test]
    fn float_beauties_compare_in_levels_of_1_over_255() {
        // One channel off by 3/255 + 1e-4 (fails `fail` = 2, not `hard_fail`), one by
        // 10 (an HDR value: off the 8-bit scale, max_diff 255), of two pixels.
        let a = [[0.5f32, 0.5, 0.5], [2.0, 0.0, 0.0]];
        let b = [[0.5f32 + 3.0 / 255.0 + 1e-4, 0.5, 0.5], [2.0, 0.0, 0.0]];
        let c = compare_float(&a, &b, 2, TOL);
        assert_eq!(
            (c.max_diff, c.max_at, c.failing_pixels),
            (4, Some((0, 0, 0)), 1)
        );
        assert_eq!(c.failing_percent, 50.0);
        assert!(compare_float(&a, &a, 2, TOL).psnr.is_none());
        let hdr = [[0.5f32, 0.5, 0.5], [12.0, 0.0, 0.0]];
        let c = compare_float(&a, &hdr, 2, TOL);
        assert_eq!((c.max_diff, c.max_at), (255, Some((1, 0, 0))));
        assert!(!TOL.failed(&c, None).is_empty());
    }

    #[test]
    fn identical_frames() {
        let c = compare(&grey(4, 4, 100), &grey(4, 4, 100), TOL);
        assert_eq!((c.max_diff, c.max_at, c.failing_pixels), (0, None, 0));
        assert_eq!((c.mean_error, c.psnr, pass(&c)), (0.0, None, true));
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
        assert_eq!((c.failing_percent, pass(&c)), (10.0, true));
        r.pixels[0] = 90;
        let c = compare(&reference, &r, TOL);
        assert_eq!(TOL.failed(&c, None), [Limit::FailPercent]);
        assert_eq!(c.failing_percent, 20.0);
    }

    #[test]
    fn hard_fail_trips_on_one_pixel() {
        let reference = grey(100, 100, 10);
        let mut r = reference.clone();
        r.pixels[3 * (5 * 100 + 42) + 2] = 75; // 65 > 64 at (42, 5), blue
        let c = compare(&reference, &r, TOL);
        assert_eq!(c.max_at, Some((42, 5, 2)));
        assert!(c.failing_percent < 0.02);
        assert_eq!(TOL.failed(&c, None), [Limit::HardFail]);
        r.pixels[3 * (5 * 100 + 42) + 2] = 74; // 64: not more than hard_fail
        assert!(pass(&compare(&reference, &r, TOL)));
    }

    #[test]
    fn flip_limit_is_judged_only_when_a_figure_exists() {
        let c = compare(&grey(2, 2, 50), &grey(2, 2, 50), TOL);
        assert_eq!(TOL.failed(&c, Some(0.05)), []); // not more than the limit
        assert_eq!(TOL.failed(&c, Some(0.0501)), [Limit::Flip]);
        let no_flip = Tolerance { flip: None, ..TOL };
        assert_eq!(no_flip.failed(&c, Some(0.9)), []);
        let c = compare(&grey(1, 1, 0), &grey(1, 1, 200), TOL);
        assert_eq!(
            TOL.failed(&c, Some(0.6)),
            [Limit::FailPercent, Limit::HardFail, Limit::Flip]
        );
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
    fn heat_colours_on_the_fixed_log_scale_by_hand() {
        // t = log2(1 + d) / 8; red = 3t, green = 3t - 1, blue = 3t - 2 (× 255, rounded).
        assert_eq!(heat_colour(0), [0, 0, 0]);
        assert_eq!(heat_colour(1), [96, 0, 0]); // t = 1/8: 95.625
        assert_eq!(heat_colour(3), [191, 0, 0]); // t = 1/4: 191.25
        assert_eq!(heat_colour(15), [255, 128, 0]); // t = 1/2: green 127.5
        assert_eq!(heat_colour(255), [255, 255, 255]);
    }

    #[test]
    fn heat_map_does_not_depend_on_the_frame_maximum() {
        let reference = grey(3, 1, 0);
        let mut r = reference.clone();
        r.pixels[3] = 1; // pixel 1 off by one level, the frame's largest difference
        let h = heat_map(&reference, &r);
        assert_eq!(&h.pixels, &[0, 0, 0, 96, 0, 0, 0, 0, 0]);
        r.pixels[8] = 255; // pixel 2 off by 255: pixel 1 keeps its colour
        let h = heat_map(&reference, &r);
        assert_eq!(&h.pixels, &[0, 0, 0, 96, 0, 0, 255, 255, 255]);
    }

    #[test]
    fn legend_runs_from_equal_to_255() {
        let l = heat_legend(256, 2);
        assert_eq!((l.width, l.height, l.pixels.len()), (256, 2, 256 * 2 * 3));
        assert_eq!(&l.pixels[0..3], &[0, 0, 0]);
        assert_eq!(&l.pixels[32 * 3..33 * 3], &[96, 0, 0]); // 2^(256/255) - 1 = 1.005: d = 1
        assert_eq!(&l.pixels[128 * 3..129 * 3], &[255, 128, 0]); // 15.17: d = 15
        assert_eq!(&l.pixels[255 * 3..256 * 3], &[255, 255, 255]);
        assert_eq!(&l.pixels[256 * 3..256 * 3 + 3], &[0, 0, 0]); // row 2 repeats
        assert_eq!(&l.pixels[(256 + 32) * 3..(256 + 33) * 3], &[96, 0, 0]);
    }
}
