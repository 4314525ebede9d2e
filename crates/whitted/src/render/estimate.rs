//! Before an enormous request: how many camera rays it casts (samples² per pixel, times
//! pixels, motion-blur sub-frames and frames), and the time a short sample predicts for
//! it, so that a command can warn before it starts hours of work.
//!
//! ```text
//! camera_rays(8192, 4096, 4, 1, 1) = 8192·4096·16 = 536 870 912  > ENORMOUS: sample
//! predict(total, sample_rays, sample_seconds) = sample_seconds · total / sample_rays
//! ```

/// Camera rays past which a command samples the request and warns: 2^28 (about 268
/// million, several minutes of work on a few cores).
pub const ENORMOUS: u64 = 1 << 28;

/// The side divisor of the sample picture: 1/8 of each side, 1/64 of the pixels.
pub const SAMPLE_DIVISOR: u32 = 8;

/// The camera rays of `frames` frames of `width`×`height` pixels with `samples`² samples
/// a pixel and `subframes` motion-blur sub-frames (saturating, never overflowing).
pub fn camera_rays(width: u32, height: u32, samples: u32, subframes: u32, frames: u64) -> u64 {
    let per_pixel = u64::from(samples.max(1)).pow(2) * u64::from(subframes.max(1));
    u64::from(width)
        .saturating_mul(u64::from(height))
        .saturating_mul(per_pixel)
        .saturating_mul(frames)
}

/// A request past `ENORMOUS` camera rays, as a warning says it: the count, the frames
/// and their size, and the time a short sample predicts.
#[derive(Clone, Debug, PartialEq)]
pub struct Enormous {
    /// The camera rays of the whole request.
    pub rays: u64,
    /// The frames of an animation; `None` for one picture.
    pub frames: Option<usize>,
    /// The frames' width in pixels.
    pub width: u32,
    /// Their height.
    pub height: u32,
    /// Camera rays a pixel (samples², times motion-blur sub-frames).
    pub per_pixel: u64,
    /// The seconds predicted; `None` when the sample could not be drawn.
    pub seconds: Option<f64>,
    /// The threads the sample ran on.
    pub threads: usize,
}

impl std::fmt::Display for Enormous {
    /// `N camera rays (F frame(s) of W×H, S sample(s)/px); a short sample predicts about
    /// T on K thread(s)`.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let frames = self
            .frames
            .map_or(String::new(), |n| format!("{n} frame(s) of "));
        let when = match self.seconds {
            Some(s) => format!("about {} on {} thread(s)", words(s), self.threads),
            None => "a long time".into(),
        };
        write!(
            f,
            "{} camera rays ({frames}{}×{}, {} sample(s)/px); a short sample predicts {when}",
            self.rays, self.width, self.height, self.per_pixel
        )
    }
}

/// The seconds `total` camera rays take when `sample_rays` of them took `sample_seconds`.
pub fn predict(total: u64, sample_rays: u64, sample_seconds: f64) -> f64 {
    sample_seconds * total as f64 / sample_rays.max(1) as f64
}

/// A duration in words, to the second below an hour: "45 s", "5 min 40 s", "3 h 20 min".
pub fn words(seconds: f64) -> String {
    let s = seconds.max(0.0).round() as u64;
    match s {
        0..=59 => format!("{s} s"),
        60..=3599 => format!("{} min {} s", s / 60, s % 60),
        _ => format!("{} h {} min", s / 3600, s % 3600 / 60),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rays_by_hand() {
        // 8192·4096 = 33 554 432 pixels, 16 samples each: 536 870 912.
        assert_eq!(camera_rays(8192, 4096, 4, 1, 1), 536_870_912);
        // 1920·1080·16·64 sub-frames·250 frames = 530 841 600 000.
        assert_eq!(camera_rays(1920, 1080, 4, 64, 250), 530_841_600_000);
        assert_eq!(camera_rays(640, 480, 1, 1, 1), 307_200);
        assert_eq!(camera_rays(u32::MAX, u32::MAX, 16, 64, u64::MAX), u64::MAX);
    }

    #[test]
    fn prediction_and_words() {
        // 1/64 of the rays in 2.5 s: 160 s.
        assert_eq!(predict(6400, 100, 2.5), 160.0);
        assert_eq!(words(44.6), "45 s");
        assert_eq!(words(340.0), "5 min 40 s");
        assert_eq!(words(12_000.0), "3 h 20 min");
    }
}
