//! The manifest as TOML text says it: serde structs with every value spanned, so that
//! the checks in `manifest` and `manifest::camera` can point at the offending value.
//! Unknown keys are refused (`deny_unknown_fields`), which makes serde name the valid
//! ones. The `[camera]` table is read twice: `Probe` finds its `path`, then the whole
//! manifest is read with the table of that path (`RawCircle`, `RawSpline`, or `RawStill`
//! without a path), so that keys of another kind of path are reported as unknown, with
//! the valid keys listed.

use serde::Deserialize;
use toml::Spanned;

/// A spanned `[x, y, z]`.
pub(super) type Vec3 = Spanned<[f64; 3]>;

/// First pass: only `[camera] path`; every other key is ignored here.
#[derive(Deserialize)]
pub(super) struct Probe {
    pub camera: Option<Spanned<CameraProbe>>,
    /// Read here so that `time = "2.5s"` keys can be turned into frames (checked later).
    pub fps: Option<toml::Value>,
}

#[derive(Deserialize)]
#[serde(expecting = "a [camera] table")]
pub(super) struct CameraProbe {
    pub path: Option<Spanned<String>>,
    /// A glTF scene's camera (`[camera] name`), read here for every kind of path.
    pub name: Option<Spanned<String>>,
}

/// `[animation]`: a glTF file's animations that play (`name`: one name or a list).
#[derive(Deserialize)]
#[serde(deny_unknown_fields, expecting = "an [animation] table")]
pub(super) struct RawAnimation {
    pub name: Option<Spanned<toml::Value>>,
}

/// A point `[x, y, z]` or an object `"sphere 2"`: read as a TOML value, told apart later.
pub(super) type PointOrObject = Spanned<toml::Value>;

/// Second pass: the whole manifest, `C` being the camera table of the probed path.
#[derive(Deserialize)]
#[serde(deny_unknown_fields, expecting = "a manifest table")]
pub(super) struct RawManifest<C> {
    pub scene: Spanned<String>,
    pub frames: Option<Spanned<i64>>,
    pub animation: Option<Spanned<RawAnimation>>,
    pub fps: Option<Spanned<f64>>,
    #[serde(rename = "loop")]
    pub looped: Option<Spanned<bool>>,
    pub camera: Option<C>,
    pub output: Option<RawOutput>,
    pub render: Option<RawRender>,
    pub check: Option<RawCheck>,
    pub track: Option<Vec<RawTrack>>,
}

/// `[camera]` without a path: the scene file's eye holds still.
#[derive(Deserialize)]
#[serde(deny_unknown_fields, expecting = "a [camera] table")]
pub(super) struct RawStill {
    #[allow(dead_code)] // read by the probe
    pub name: Option<Spanned<String>>,
    pub look_at: Option<PointOrObject>,
    pub fov: Option<Spanned<f64>>,
    pub roll: Option<Spanned<f64>>,
}

/// `[[track]]`: keys, or `path = "circle"` with the circle's keys.
#[derive(Deserialize)]
#[serde(deny_unknown_fields, expecting = "a [[track]] table")]
pub(super) struct RawTrack {
    /// `"sphere 1 center"`, or a glTF node's `{ node = "…", field = "…" }`.
    pub target: Spanned<toml::Value>,
    pub interpolation: Option<Spanned<String>>,
    pub ease: Option<Spanned<String>>,
    pub keys: Option<Spanned<Vec<Spanned<RawTrackKey>>>>,
    pub path: Option<Spanned<String>>,
    pub center: Option<Vec3>,
    pub radius: Option<Spanned<f64>>,
    pub height: Option<Spanned<f64>>,
    pub start_angle: Option<Spanned<f64>>,
    pub turns: Option<Spanned<f64>>,
}

#[derive(Deserialize)]
#[serde(
    deny_unknown_fields,
    expecting = "a key: { frame = 0, value = 1.0 } or { frame = 0, value = [x, y, z] }"
)]
pub(super) struct RawTrackKey {
    pub frame: Option<Spanned<i64>>,
    pub time: Option<Spanned<String>>,
    pub value: Spanned<toml::Value>,
    pub ease: Option<Spanned<String>>,
}

/// `motion_blur = { shutter = 0.5, samples = 8 }`.
#[derive(Deserialize)]
#[serde(
    deny_unknown_fields,
    expecting = "motion_blur = { shutter = 0.5, samples = 8 }"
)]
pub(super) struct RawBlur {
    pub shutter: Option<Spanned<f64>>,
    pub samples: Option<Spanned<i64>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields, expecting = "a [camera] table")]
pub(super) struct RawCircle {
    #[allow(dead_code)] // read by the probe
    pub name: Option<Spanned<String>>,
    #[allow(dead_code)] // read by the probe
    pub path: String,
    pub center: Vec3,
    pub radius: Spanned<f64>,
    pub height: Spanned<f64>,
    pub start_angle: Option<Spanned<f64>>,
    pub turns: Option<Spanned<f64>>,
    pub look_at: Option<PointOrObject>,
    pub fov: Option<Spanned<f64>>,
    pub roll: Option<Spanned<f64>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields, expecting = "a [camera] table")]
pub(super) struct RawSpline {
    #[allow(dead_code)] // read by the probe
    pub name: Option<Spanned<String>>,
    #[allow(dead_code)] // read by the probe
    pub path: String,
    pub closed: Option<bool>,
    pub constant_speed: Option<bool>,
    pub look_at: Option<PointOrObject>,
    pub fov: Option<Spanned<f64>>,
    pub roll: Option<Spanned<f64>>,
    pub keys: Spanned<Vec<Spanned<RawKey>>>,
}

#[derive(Deserialize)]
#[serde(
    deny_unknown_fields,
    expecting = "a key: { frame = 0, position = [x, y, z] }"
)]
pub(super) struct RawKey {
    pub frame: Option<Spanned<i64>>,
    pub time: Option<Spanned<String>>,
    pub position: Vec3,
    pub look_at: Option<Vec3>,
    pub ease: Option<Spanned<String>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields, expecting = "an [output] table")]
pub(super) struct RawOutput {
    pub dir: Option<Spanned<String>>,
    pub name: Option<Spanned<String>>,
    pub format: Option<Spanned<String>>,
    pub jpeg_quality: Option<Spanned<i64>>,
    pub exr_depth: Option<Spanned<String>>,
    pub exr_compression: Option<Spanned<String>>,
    pub passes: Option<Spanned<Vec<Spanned<String>>>>,
    pub colour: Option<Spanned<String>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields, expecting = "a [render] table")]
pub(super) struct RawRender {
    pub width: Option<Spanned<i64>>,
    pub height: Option<Spanned<i64>>,
    pub samples: Option<Spanned<i64>>,
    pub motion_blur: Option<Spanned<RawBlur>>,
    pub antialias: Option<Spanned<RawAntialias>>,
}

/// `antialias = { mode = "adaptive", threshold = 0.1, depth = 3 }`.
#[derive(Deserialize)]
#[serde(
    deny_unknown_fields,
    expecting = "antialias = { mode = \"adaptive\", threshold = 0.1, depth = 3 }"
)]
pub(super) struct RawAntialias {
    pub mode: Spanned<String>,
    pub threshold: Option<Spanned<f64>>,
    pub depth: Option<Spanned<i64>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields, expecting = "a [check] table")]
pub(super) struct RawCheck {
    pub frames: Spanned<RawFrames>,
    pub references: Spanned<String>,
    pub fail: Option<Spanned<i64>>,
    pub fail_percent: Option<Spanned<f64>>,
    pub hard_fail: Option<Spanned<i64>>,
    pub flip: Option<Spanned<f64>>,
}

/// `[check] frames`: a list of frame numbers, or a frame list in the fileseq grammar
/// (`"0-249x25"`), read with a visitor so that the numbers keep their spans.
pub(super) enum RawFrames {
    /// `[0, 125, 249]`.
    List(Vec<Spanned<i64>>),
    /// `"0-249x25"`.
    Spec(String),
}

impl<'de> Deserialize<'de> for RawFrames {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<RawFrames, D::Error> {
        struct Frames;
        impl<'de> serde::de::Visitor<'de> for Frames {
            type Value = RawFrames;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("a list of frame numbers or a frame list such as \"0-249x25\"")
            }
            fn visit_str<E: serde::de::Error>(self, s: &str) -> Result<RawFrames, E> {
                Ok(RawFrames::Spec(s.to_string()))
            }
            fn visit_seq<A: serde::de::SeqAccess<'de>>(
                self,
                mut seq: A,
            ) -> Result<RawFrames, A::Error> {
                let mut list = Vec::new();
                while let Some(f) = seq.next_element()? {
                    list.push(f);
                }
                Ok(RawFrames::List(list))
            }
        }
        d.deserialize_any(Frames)
    }
}
