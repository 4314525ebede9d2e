//! NVIDIA's FLIP, the perceptual difference of two frames, through the `nv-flip` crate
//! (the reference implementation's C++ code, as wgpu's test suite uses it).
//!
//! FLIP gives every pixel an error from 0 (no visible difference) to 1, for a viewer at
//! the library's default distance (67 pixels per degree, a 0.7 m look at a 24" 4K screen).
//! A check keeps the mean of the error map, the figure `[check] flip` limits, and the map
//! itself coloured with FLIP's magma scale (black 0, through purple and orange, to pale
//! yellow 1) for the report.

use whitted::base::Frame;

/// The FLIP figures of a frame against its reference.
#[derive(Clone, Debug, PartialEq)]
pub struct Flip {
    /// The mean per-pixel FLIP error, 0..1.
    pub mean: f64,
    /// The per-pixel error through the magma colour map.
    pub map: Frame,
}

/// Runs FLIP on two frames of the same size (sRGB, 8 bits a channel).
pub fn flip(reference: &Frame, rendered: &Frame) -> Flip {
    debug_assert_eq!(
        (reference.width, reference.height),
        (rendered.width, rendered.height)
    );
    let (w, h) = (reference.width, reference.height);
    let a = nv_flip::FlipImageRgb8::with_data(w, h, &reference.pixels);
    let b = nv_flip::FlipImageRgb8::with_data(w, h, &rendered.pixels);
    let errors = nv_flip::flip(a, b, nv_flip::DEFAULT_PIXELS_PER_DEGREE);
    // Summed in f64 in pixel order, so the mean is the same on every run and thread count.
    let values = errors.to_vec();
    let mean = values.iter().map(|&e| e as f64).sum::<f64>() / values.len().max(1) as f64;
    let map = errors.apply_color_lut(&nv_flip::magma_lut());
    Flip {
        mean,
        map: Frame {
            width: w,
            height: h,
            pixels: map.to_vec(),
        },
    }
}

/// FLIP's magma colour scale as a 256×1 strip, error 0 at the left and 1 at the right.
pub fn legend() -> Frame {
    Frame {
        width: 256,
        height: 1,
        pixels: nv_flip::magma_lut().to_vec(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grey(w: u32, h: u32, v: u8) -> Frame {
        Frame {
            width: w,
            height: h,
            pixels: vec![v; (w * h * 3) as usize],
        }
    }

    /// A 32×32 grey frame with a 8×8 square of `colour` at (12, 12).
    fn with_square(colour: [u8; 3]) -> Frame {
        let mut f = grey(32, 32, 128);
        for y in 12..20 {
            for x in 12..20 {
                let i = 3 * (y * 32 + x);
                f.pixels[i..i + 3].copy_from_slice(&colour);
            }
        }
        f
    }

    #[test]
    fn identical_frames_score_zero_and_a_black_map() {
        let f = with_square([200, 30, 30]);
        let r = flip(&f, &f);
        assert_eq!(r.mean, 0.0);
        assert_eq!((r.map.width, r.map.height), (32, 32));
        // Magma at 0 is black (0, 0, 4 in FLIP's table: near black).
        assert!(r.map.pixels.chunks(3).all(|p| p[0] < 8 && p[1] < 8));
    }

    #[test]
    fn legend_runs_from_black_to_pale_yellow() {
        let l = legend();
        assert_eq!(l.pixels.len(), 256 * 3);
        assert!(l.pixels[..3].iter().all(|&c| c < 8), "{:?}", &l.pixels[..3]);
        let last = &l.pixels[255 * 3..];
        assert!(last[0] > 240 && last[1] > 240 && last[2] > 150, "{last:?}");
    }

    #[test]
    fn a_visible_change_scores_above_a_small_one() {
        let reference = with_square([128, 128, 128]); // plain grey
        let faint = flip(&reference, &with_square([130, 128, 128]));
        let strong = flip(&reference, &with_square([255, 0, 255]));
        assert!(faint.mean > 0.0, "{}", faint.mean);
        assert!(
            strong.mean > 5.0 * faint.mean,
            "{} {}",
            strong.mean,
            faint.mean
        );
        // The square is 64 of 1024 pixels; a full-strength error there, with some spread,
        // is a mean of a few hundredths.
        assert!(strong.mean > 0.02 && strong.mean < 0.2, "{}", strong.mean);
        // The map is bright where the square changed and dark far from it.
        let at = |x: usize, y: usize| strong.map.pixels[3 * (y * 32 + x)] as u32;
        assert!(at(15, 15) > 150, "{}", at(15, 15));
        assert!(at(1, 1) < 20, "{}", at(1, 1));
    }
}
