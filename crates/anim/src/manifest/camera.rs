//! `[camera]` of the manifest: checks a raw circle, spline or still table and builds the
//! camera of the timeline, every refusal located at the offending value. The tables it
//! reads:
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
//!                            # a key may ease the segment it starts: ease = "in" (`Ease`)
//!
//! [camera]                   # no path: the scene file's eye holds still
//! look_at = "sphere 2"       # any camera may follow an object (or look at [x, y, z])
//! fov = 30.0                 # any camera: vertical field of view, degrees, 0 < fov < 180
//! roll = 5.0                 # any camera: degrees about the view, positive banks right
//! ```

use super::raw::{RawCircle, RawSpline, RawStill, Vec3};
use super::{CameraParts, ManifestError, Source};
use crate::timeline::LookAt;
use crate::timeline::{coord_ok, CameraPath, Circle, Ease, Key, Spline, SplineError};
use glam::DVec3;
use toml::Spanned;
use whitted::camera::{Lens, MAX_ROLL};
use whitted::limits::{MAX_COORD, MAX_TURNS};

impl Source<'_> {
    /// A point, refused unless finite and within `MAX_COORD`.
    pub(super) fn point(&self, v: &Vec3, what: &str) -> Result<DVec3, ManifestError> {
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

    /// The checked values of a circle (the camera's or a track's).
    pub(super) fn circle_values(
        &self,
        center: &Vec3,
        radius: &Spanned<f64>,
        height: &Spanned<f64>,
        start_angle: Option<&Spanned<f64>>,
        turns: Option<&Spanned<f64>>,
    ) -> Result<Circle, ManifestError> {
        let center = self.point(center, "center")?;
        let r = self.number(radius, "radius", MAX_COORD)?;
        if r <= 0.0 {
            let message = format!("`radius` must be greater than 0, found {r}");
            return Err(self.error(radius.span(), message));
        }
        let height = self.number(height, "height", MAX_COORD)?;
        let start_angle = match start_angle {
            Some(v) => self.number(v, "start_angle", f64::MAX)?,
            None => 0.0,
        };
        let turns = match turns {
            Some(v) => self.number(v, "turns", MAX_TURNS)?,
            None => 1.0,
        };
        Ok(Circle {
            center,
            radius: r,
            height,
            start_angle,
            turns,
        })
    }

    /// `fov` and `roll`: fov strictly between 0 and 180 degrees, roll finite.
    fn lens(
        &self,
        fov: Option<&Spanned<f64>>,
        roll: Option<&Spanned<f64>>,
    ) -> Result<Lens, ManifestError> {
        let fov = match fov {
            Some(v) if !Lens::fov_ok(*v.get_ref()) => {
                let message = format!(
                    "`fov` is the vertical field of view in degrees and must be between 0 and 180 (both excluded), found {}",
                    v.get_ref()
                );
                return Err(self.error(v.span(), message));
            }
            Some(v) => Some(*v.get_ref()),
            None => None,
        };
        let roll = match roll {
            Some(v) => self.number(v, "roll", MAX_ROLL)?,
            None => 0.0,
        };
        Ok(Lens {
            fov,
            roll,
            ..Lens::default()
        })
    }

    /// A fixed look-at point, or the object to follow.
    fn split_look_at(
        &self,
        v: Option<&super::raw::PointOrObject>,
    ) -> Result<(Option<DVec3>, Option<LookAt>), ManifestError> {
        match v.map(|v| self.look_at(v)).transpose()? {
            Some(LookAt::Point(p)) => Ok((Some(p), None)),
            other => Ok((None, other)),
        }
    }

    pub(super) fn circle(&self, raw: RawCircle) -> Result<CameraParts, ManifestError> {
        let circle = self.circle_values(
            &raw.center,
            &raw.radius,
            &raw.height,
            raw.start_angle.as_ref(),
            raw.turns.as_ref(),
        )?;
        let (look_at, follow) = self.split_look_at(raw.look_at.as_ref())?;
        let path = CameraPath::Circle { circle, look_at };
        let lens = self.lens(raw.fov.as_ref(), raw.roll.as_ref())?;
        Ok((Some(path), follow, lens))
    }

    pub(super) fn still(&self, raw: RawStill) -> Result<CameraParts, ManifestError> {
        let lens = self.lens(raw.fov.as_ref(), raw.roll.as_ref())?;
        match self.split_look_at(raw.look_at.as_ref())? {
            (Some(p), _) => Ok((None, Some(LookAt::Point(p)), lens)),
            (None, follow) => Ok((None, follow, lens)),
        }
    }

    /// A spline; key frames must lie in `0..frames`.
    pub(super) fn spline(&self, raw: RawSpline, frames: u32) -> Result<CameraParts, ManifestError> {
        let (look_at, follow) = self.split_look_at(raw.look_at.as_ref())?;
        let lens = self.lens(raw.fov.as_ref(), raw.roll.as_ref())?;
        let mut keys = Vec::with_capacity(raw.keys.get_ref().len());
        for key in raw.keys.get_ref() {
            let span = key.span();
            let key = key.get_ref();
            let (frame, _) = self.key_when(key.frame.as_ref(), key.time.as_ref(), span, frames)?;
            let position = self.point(&key.position, "position")?;
            let key_look_at = match &key.look_at {
                Some(v) => Some(self.point(v, "look_at")?),
                None => None,
            };
            let ease = self.name_of(&key.ease, "ease", &Ease::NAMES, Ease::from_name)?;
            keys.push(Key {
                frame,
                position,
                look_at: key_look_at,
                ease: ease.unwrap_or_default(),
            });
        }
        if follow.is_some() && keys.iter().any(|k| k.look_at.is_some()) {
            let span = raw.look_at.as_ref().map_or(raw.keys.span(), |v| v.span());
            let message = SplineError::BothLookAts.to_string();
            return Err(self.error(span, message));
        }
        let closed = raw.closed.unwrap_or(false);
        let constant_speed = raw.constant_speed.unwrap_or(false);
        match Spline::new(keys, closed, constant_speed, look_at) {
            Ok(spline) => Ok((Some(CameraPath::Spline(spline)), follow, lens)),
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
        SplineError::FrameOrder { index, .. } => key(*index).map(|k| {
            let when = (k.get_ref().frame.as_ref().map(|f| f.span())).or(k
                .get_ref()
                .time
                .as_ref()
                .map(|t| t.span()));
            when.unwrap_or(k.span())
        }),
        SplineError::MixedLookAt { index }
        | SplineError::BadCoordinate { index }
        | SplineError::EaseWithConstantSpeed { index } => key(*index).map(|k| k.span()),
        SplineError::BothLookAts | SplineError::BadLookAt => raw.look_at.as_ref().map(|v| v.span()),
        SplineError::TooFewKeys { .. } => None,
    };
    span.unwrap_or_else(|| raw.keys.span())
}
