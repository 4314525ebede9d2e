//! `[[track]]` tables, `look_at` points or objects, and `[render] motion_blur`: checked as
//! far as the manifest alone allows (names, kinds of values, key order, circle values),
//! every refusal located. Targets are resolved against the scene later, by the timeline.
//!
//! ```toml
//! [[track]]
//! target = "sphere 1 center"
//! interpolation = "smooth"                 # linear | smooth | step
//! ease = "in-out"                          # none | in | out | in-out
//! keys = [{ frame = 0, value = [0.0, 1.0, 0.0] }, { frame = 40, value = [0.0, 4.0, 0.0], ease = "out" }]
//!
//! [camera]
//! look_at = "sphere 2"                     # or [x, y, z]
//!
//! [render]
//! motion_blur = { shutter = 0.5, samples = 8 }
//! ```

use super::raw::{PointOrObject, RawBlur, RawTrack, RawTrackKey};
use super::{ManifestError, Source};
use crate::timeline::{Ease, Interpolation, Kind, LookAt, Motion, MotionBlur, TrackKey, TrackSpec};
use glam::DVec3;
use toml::Spanned;
use whitted::limits::{MAX_BLUR_SAMPLES, MAX_COORD};

impl Source<'_> {
    /// A number or `[x, y, z]` of a track key (integers are numbers too).
    fn value(&self, v: &Spanned<toml::Value>) -> Result<(DVec3, Kind), ManifestError> {
        let num = |x: &toml::Value| match x {
            toml::Value::Float(f) => Some(*f),
            toml::Value::Integer(i) => Some(*i as f64),
            _ => None,
        };
        let found = match v.get_ref() {
            toml::Value::Array(items) if items.len() == 3 => {
                let xs: Option<Vec<f64>> = items.iter().map(num).collect();
                xs.map(|x| (DVec3::new(x[0], x[1], x[2]), Kind::Vector))
            }
            other => num(other).map(|x| (DVec3::new(x, 0.0, 0.0), Kind::Number)),
        };
        match found {
            Some((p, kind)) if p.is_finite() => Ok((p, kind)),
            _ => Err(self.error(
                v.span(),
                "`value` must be a finite number or [x, y, z] of finite numbers",
            )),
        }
    }

    /// `look_at`: a point, or an object named `KIND N`.
    pub(super) fn look_at(&self, v: &PointOrObject) -> Result<LookAt, ManifestError> {
        if let toml::Value::String(name) = v.get_ref() {
            let loc = self.loc(v.span());
            return Ok(LookAt::Object {
                name: name.clone(),
                loc,
            });
        }
        match self.value(v) {
            Ok((p, Kind::Vector)) if crate::timeline::coord_ok(p) => Ok(LookAt::Point(p)),
            _ => Err(self.error(
                v.span(),
                format!(
                    "`look_at` must be a point [x, y, z] (coordinates at most {MAX_COORD:e} in magnitude) or an object such as \"sphere 2\""
                ),
            )),
        }
    }

    pub(super) fn name_of<T>(
        &self,
        v: &Option<Spanned<String>>,
        what: &str,
        names: &[&str],
        parse: impl Fn(&str) -> Option<T>,
    ) -> Result<Option<T>, ManifestError> {
        let Some(v) = v else { return Ok(None) };
        match parse(v.get_ref()) {
            Some(x) => Ok(Some(x)),
            None => Err(self.error(
                v.span(),
                format!(
                    "unknown {what} `{}`, expected one of {}",
                    v.get_ref(),
                    names.join(", ")
                ),
            )),
        }
    }

    /// Every `[[track]]`; key frames must lie in `0..frames`.
    pub(super) fn tracks(
        &self,
        raw: Vec<RawTrack>,
        frames: u32,
    ) -> Result<Vec<TrackSpec>, ManifestError> {
        raw.into_iter().map(|t| self.track(t, frames)).collect()
    }

    fn track(&self, mut raw: RawTrack, frames: u32) -> Result<TrackSpec, ManifestError> {
        let loc = self.loc(raw.target.span());
        let interpolation = self.name_of(
            &raw.interpolation,
            "interpolation",
            &Interpolation::NAMES,
            Interpolation::from_name,
        )?;
        let ease = self.name_of(&raw.ease, "ease", &Ease::NAMES, Ease::from_name)?;
        let keys = raw.keys.take();
        let motion = match (&raw.path, keys) {
            (Some(path), None) if path.get_ref() == "circle" => self.track_circle(&raw)?,
            (Some(path), None) => {
                let message = format!(
                    "unknown track path `{}`: a track follows `keys`, or path = \"circle\"",
                    path.get_ref()
                );
                return Err(self.error(path.span(), message));
            }
            (Some(path), Some(_)) => {
                let message = "a track has either `keys` or `path = \"circle\"`, not both";
                return Err(self.error(path.span(), message));
            }
            (None, Some(keys)) => {
                let circle_key = [&raw.radius, &raw.height, &raw.start_angle, &raw.turns]
                    .into_iter()
                    .flatten()
                    .next()
                    .map(|v| v.span())
                    .or(raw.center.as_ref().map(|c| c.span()));
                if let Some(span) = circle_key {
                    let message = "this key belongs to `path = \"circle\"`; a track with `keys` does not take it";
                    return Err(self.error(span, message));
                }
                Motion::Keys {
                    interpolation: interpolation.unwrap_or_default(),
                    keys: self.track_keys(keys, ease.unwrap_or_default(), frames)?,
                }
            }
            (None, None) => {
                let message = "a track needs `keys = [...]` or `path = \"circle\"`";
                return Err(self.error(raw.target.span(), message));
            }
        };
        Ok(TrackSpec {
            target: self.track_target(&raw.target)?,
            loc,
            motion,
        })
    }

    /// A track's target as text: the string, or a glTF node's `{ node, field }` table
    /// in its canonical form (`timeline::node::written`).
    fn track_target(&self, v: &Spanned<toml::Value>) -> Result<String, ManifestError> {
        let bad = || {
            self.error(
                v.span(),
                "a track's target is a string (`sphere 1 center`) or a glTF node's { node = \"…\", field = \"translation\" | \"rotation\" | \"scale\" }",
            )
        };
        match v.get_ref() {
            toml::Value::String(s) => Ok(s.clone()),
            toml::Value::Table(t) if t.len() == 2 => {
                let node = t.get("node").and_then(|n| n.as_str()).ok_or_else(bad)?;
                let field = t.get("field").and_then(|f| f.as_str()).ok_or_else(bad)?;
                Ok(crate::timeline::node::written(node, field))
            }
            _ => Err(bad()),
        }
    }

    fn track_keys(
        &self,
        keys: Spanned<Vec<Spanned<RawTrackKey>>>,
        ease: Ease,
        frames: u32,
    ) -> Result<Vec<TrackKey>, ManifestError> {
        if keys.get_ref().is_empty() {
            return Err(self.error(keys.span(), "a track needs at least one key"));
        }
        let mut out: Vec<TrackKey> = Vec::with_capacity(keys.get_ref().len());
        for key in keys.get_ref() {
            let span = key.span();
            let key = key.get_ref();
            let (frame, when) =
                self.key_when(key.frame.as_ref(), key.time.as_ref(), span, frames)?;
            if let Some(previous) = out.last() {
                if frame <= previous.frame {
                    let message = format!(
                        "key frame {frame} is not after the previous key's frame {}; keys must be in increasing frame order",
                        previous.frame
                    );
                    return Err(self.error(when, message));
                }
            }
            let (value, kind) = self.value(&key.value)?;
            if let Some(first) = out.first() {
                if first.kind != kind {
                    let message = "every key of a track gives the same kind of value: all numbers or all [x, y, z]";
                    return Err(self.error(key.value.span(), message));
                }
            }
            let own = self.name_of(&key.ease, "ease", &Ease::NAMES, Ease::from_name)?;
            out.push(TrackKey {
                frame,
                value,
                kind,
                ease: own.unwrap_or(ease),
                loc: self.loc(when),
            });
        }
        Ok(out)
    }

    /// A key's frame, refused outside `0..frames`.
    pub(super) fn key_frame(&self, v: &Spanned<i64>, frames: u32) -> Result<u32, ManifestError> {
        match u32::try_from(*v.get_ref()) {
            Ok(f) if f < frames => Ok(f),
            _ => {
                let last = frames.saturating_sub(1);
                let message = format!(
                    "key frame {} is outside the sequence: frames run from 0 to {last}",
                    v.get_ref()
                );
                Err(self.error(v.span(), message))
            }
        }
    }

    fn track_circle(&self, raw: &RawTrack) -> Result<Motion, ManifestError> {
        let missing = |what: &str| {
            let message = format!("a circle track needs `{what}`");
            self.error(raw.target.span(), message)
        };
        let center = raw.center.as_ref().ok_or_else(|| missing("center"))?;
        let radius = raw.radius.as_ref().ok_or_else(|| missing("radius"))?;
        let height = raw.height.as_ref().ok_or_else(|| missing("height"))?;
        let circle = self.circle_values(
            center,
            radius,
            height,
            raw.start_angle.as_ref(),
            raw.turns.as_ref(),
        )?;
        Ok(Motion::Circle(circle))
    }

    /// `motion_blur`: shutter in (0, 1] frames (default 0.5), samples 1..=64 (default 8).
    pub(super) fn motion_blur(&self, raw: &Spanned<RawBlur>) -> Result<MotionBlur, ManifestError> {
        let raw = raw.get_ref();
        let shutter = match &raw.shutter {
            Some(v) if !(*v.get_ref() > 0.0 && *v.get_ref() <= 1.0) => {
                let message = format!(
                    "`shutter` is in frames and must be above 0 and at most 1, found {}",
                    v.get_ref()
                );
                return Err(self.error(v.span(), message));
            }
            Some(v) => *v.get_ref(),
            None => MotionBlur::DEFAULT.shutter,
        };
        let samples = match &raw.samples {
            Some(v) => self.int(v, "samples", 1..=i64::from(MAX_BLUR_SAMPLES))? as u32,
            None => MotionBlur::DEFAULT.samples,
        };
        Ok(MotionBlur { shutter, samples })
    }
}
