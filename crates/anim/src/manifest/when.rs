//! When a key happens, a camera spline's or a track's: its frame, or its time in seconds,
//! which the manifest's `fps` turns into the nearest frame, so that changing `fps` does
//! not mean retiming every key:
//!
//! ```toml
//! keys = [{ frame = 0, value = 1.0 }, { time = "2.5s", value = 2.0 }]   # 2.5 s at 25 fps: frame 63
//! ```
//!
//! `time` is a string of seconds ending in `s` (`"2.5s"`, `"10s"`, `"0s"`), at least 0;
//! the frame is round(time·fps) (halves up), and must lie in `0..frames` like a frame.
//! A key gives one of `frame` and `time`.

use super::{ManifestError, Source};
use std::ops::Range;
use toml::Spanned;

/// The frame of `seconds` at `fps`: the nearest, halves up.
pub(super) fn frame_of(seconds: f64, fps: f64) -> f64 {
    (seconds * fps + 0.5).floor()
}

impl Source<'_> {
    /// A key's frame, from its `frame` or its `time` (the key spans `key`), refused
    /// outside `0..frames`; with the span of what gave it.
    pub(super) fn key_when(
        &self,
        frame: Option<&Spanned<i64>>,
        time: Option<&Spanned<String>>,
        key: Range<usize>,
        frames: u32,
    ) -> Result<(u32, Range<usize>), ManifestError> {
        match (frame, time) {
            (Some(f), None) => Ok((self.key_frame(f, frames)?, f.span())),
            (None, Some(t)) => Ok((self.key_time(t, frames)?, t.span())),
            (Some(_), Some(t)) => {
                Err(self.error(t.span(), "a key gives `frame` or `time`, not both"))
            }
            (None, None) => Err(self.error(
                key,
                "a key needs `frame = N` or `time = \"2.5s\"` (seconds)",
            )),
        }
    }

    fn key_time(&self, v: &Spanned<String>, frames: u32) -> Result<u32, ManifestError> {
        let text = v.get_ref().trim();
        let seconds = text
            .strip_suffix('s')
            .and_then(|n| n.trim().parse::<f64>().ok())
            .filter(|s| s.is_finite() && *s >= 0.0);
        let Some(seconds) = seconds else {
            let message = format!(
                "expected a time in seconds such as \"2.5s\" (at least 0), found {:?}",
                v.get_ref()
            );
            return Err(self.error(v.span(), message));
        };
        let frame = frame_of(seconds, self.fps);
        if frame < f64::from(frames) {
            return Ok(frame as u32);
        }
        let last = frames.saturating_sub(1);
        let message = format!(
            "key time {text} is frame {frame} at {} fps, outside the sequence: frames run from 0 to {last}",
            self.fps
        );
        Err(self.error(v.span(), message))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn seconds_become_the_nearest_frame() {
        // 2.5 s at 25 fps is 62.5 frames: 63; at 24 fps exactly 60; 0.02 s at 25 is 0.5: 1.
        assert_eq!(frame_of(2.5, 25.0), 63.0);
        assert_eq!(frame_of(2.5, 24.0), 60.0);
        assert_eq!(frame_of(0.02, 25.0), 1.0);
        assert_eq!(frame_of(0.0, 30.0), 0.0);
    }
}
