//! `[camera]` of the manifest: checks a raw circle or spline table and builds the
//! `CameraPath`, every refusal located at the offending value. The tables it reads:
//!
//! ```toml
//! [camera]
//! path = "circle"            # center, radius, height required; start_angle 0, turns 1
//! center = [0.0, 1.0, 0.0]
//! radius = 12.0
//! height = 3.0
//!
//! [camera]
//! path = "spline"            # closed and constant_speed default to false
//! keys = [ { frame = 0, position = [0.0, 3.0, 12.0], look_at = [0.0, 1.0, 0.0] }, ... ]
//! ```

use super::raw::{RawCircle, RawSpline, Vec3};
use super::{ManifestError, Source};
use crate::anim::path::CameraPath;
use crate::anim::spline::{coord_ok, Key, Spline, SplineError, MAX_COORD};
use glam::DVec3;
use toml::Spanned;

/// The largest number of turns a circle accepts (keeps turns·frame finite).
pub const MAX_TURNS: f64 = 1e6;

impl Source<'_> {
    /// A point, refused unless finite and within `MAX_COORD`.
    fn point(&self, v: &Vec3, what: &str) -> Result<DVec3, ManifestError> {
        let p = DVec3::from_array(*v.get_ref());
        if coord_ok(p) {
            return Ok(p);
        }
        let message =
            format!("`{what}` coordinates must be finite and at most {MAX_COORD:e} in magnitude");
        Err(self.error(v.span(), message))
    }

    /// A number, refused unless finite and within `-limit..=limit`.
    fn number(&self, v: &Spanned<f64>, what: &str, limit: f64) -> Result<f64, ManifestError> {
        let x = *v.get_ref();
        if x.abs() <= limit {
            return Ok(x);
        }
        let message = format!("`{what}` must be finite and at most {limit:e} in magnitude");
        Err(self.error(v.span(), message))
    }

    pub(super) fn circle(&self, raw: RawCircle) -> Result<CameraPath, ManifestError> {
        let center = self.point(&raw.center, "center")?;
        let radius = self.number(&raw.radius, "radius", MAX_COORD)?;
        if radius <= 0.0 {
            let message = format!("`radius` must be greater than 0, found {radius}");
            return Err(self.error(raw.radius.span(), message));
        }
        let height = self.number(&raw.height, "height", MAX_COORD)?;
        let start_angle = match &raw.start_angle {
            Some(v) => self.number(v, "start_angle", f64::MAX)?,
            None => 0.0,
        };
        let turns = match &raw.turns {
            Some(v) => self.number(v, "turns", MAX_TURNS)?,
            None => 1.0,
        };
        let look_at = match &raw.look_at {
            Some(v) => Some(self.point(v, "look_at")?),
            None => None,
        };
        Ok(CameraPath::Circle {
            center,
            radius,
            height,
            start_angle,
            turns,
            look_at,
        })
    }

    /// A spline; key frames must lie in `0..frames`.
    pub(super) fn spline(&self, raw: RawSpline, frames: u32) -> Result<CameraPath, ManifestError> {
        let look_at = match &raw.look_at {
            Some(v) => Some(self.point(v, "look_at")?),
            None => None,
        };
        let mut keys = Vec::with_capacity(raw.keys.get_ref().len());
        for key in raw.keys.get_ref() {
            let key = key.get_ref();
            let frame = *key.frame.get_ref();
            let frame = match u32::try_from(frame) {
                Ok(f) if f < frames => f,
                _ => {
                    let last = frames.saturating_sub(1);
                    let message = format!(
                        "key frame {frame} is outside the sequence: frames run from 0 to {last}"
                    );
                    return Err(self.error(key.frame.span(), message));
                }
            };
            let position = self.point(&key.position, "position")?;
            let key_look_at = match &key.look_at {
                Some(v) => Some(self.point(v, "look_at")?),
                None => None,
            };
            keys.push(Key {
                frame,
                position,
                look_at: key_look_at,
            });
        }
        let closed = raw.closed.unwrap_or(false);
        let constant_speed = raw.constant_speed.unwrap_or(false);
        match Spline::new(keys, closed, constant_speed, look_at) {
            Ok(spline) => Ok(CameraPath::Spline(spline)),
            Err(e) => Err(self.error(spline_error_span(&raw, &e), e.to_string())),
        }
    }
}

/// Where a spline refusal points: the key's frame for the order, the key for its
/// look_at, the fixed look_at when both are given, the keys array otherwise.
fn spline_error_span(raw: &RawSpline, e: &SplineError) -> std::ops::Range<usize> {
    let keys = raw.keys.get_ref();
    let key = |index: usize| keys.get(index);
    let span = match e {
        SplineError::FrameOrder { index, .. } => key(*index).map(|k| k.get_ref().frame.span()),
        SplineError::MixedLookAt { index } | SplineError::BadCoordinate { index } => {
            key(*index).map(|k| k.span())
        }
        SplineError::BothLookAts | SplineError::BadLookAt => raw.look_at.as_ref().map(|v| v.span()),
        SplineError::TooFewKeys { .. } => None,
    };
    span.unwrap_or_else(|| raw.keys.span())
}
