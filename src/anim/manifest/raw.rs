//! The manifest as TOML text says it: serde structs with every value spanned, so that
//! the checks in `manifest` and `manifest::camera` can point at the offending value.
//! Unknown keys are refused (`deny_unknown_fields`), which makes serde name the valid
//! ones. The `[camera]` table is read twice: `Probe` finds its `path`, then the whole
//! manifest is read with the table of that path (`RawCircle` or `RawSpline`), so that
//! keys of the other kind of path are reported as unknown, with the valid keys listed.

use serde::Deserialize;
use toml::Spanned;

/// A spanned `[x, y, z]`.
pub(super) type Vec3 = Spanned<[f64; 3]>;

/// First pass: only `[camera] path`; every other key is ignored here.
#[derive(Deserialize)]
pub(super) struct Probe {
    pub camera: Option<Spanned<CameraProbe>>,
}

#[derive(Deserialize)]
#[serde(expecting = "a [camera] table")]
pub(super) struct CameraProbe {
    pub path: Option<Spanned<String>>,
}

/// Second pass: the whole manifest, `C` being the camera table of the probed path.
#[derive(Deserialize)]
#[serde(deny_unknown_fields, expecting = "a manifest table")]
pub(super) struct RawManifest<C> {
    pub scene: Spanned<String>,
    pub frames: Spanned<i64>,
    pub fps: Option<Spanned<f64>>,
    pub camera: C,
    pub output: Option<RawOutput>,
    pub render: Option<RawRender>,
    pub check: Option<RawCheck>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields, expecting = "a [camera] table")]
pub(super) struct RawCircle {
    #[allow(dead_code)] // read by the probe
    pub path: String,
    pub center: Vec3,
    pub radius: Spanned<f64>,
    pub height: Spanned<f64>,
    pub start_angle: Option<Spanned<f64>>,
    pub turns: Option<Spanned<f64>>,
    pub look_at: Option<Vec3>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields, expecting = "a [camera] table")]
pub(super) struct RawSpline {
    #[allow(dead_code)] // read by the probe
    pub path: String,
    pub closed: Option<bool>,
    pub constant_speed: Option<bool>,
    pub look_at: Option<Vec3>,
    pub keys: Spanned<Vec<Spanned<RawKey>>>,
}

#[derive(Deserialize)]
#[serde(
    deny_unknown_fields,
    expecting = "a key: { frame = 0, position = [x, y, z] }"
)]
pub(super) struct RawKey {
    pub frame: Spanned<i64>,
    pub position: Vec3,
    pub look_at: Option<Vec3>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields, expecting = "an [output] table")]
pub(super) struct RawOutput {
    pub dir: Option<Spanned<String>>,
    pub name: Option<Spanned<String>>,
    pub format: Option<RawFormat>,
    pub jpeg_quality: Option<Spanned<i64>>,
}

#[derive(Clone, Copy, Deserialize)]
#[serde(rename_all = "lowercase")]
pub(super) enum RawFormat {
    Png,
    Jpeg,
    Ppm,
    Raw,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields, expecting = "a [render] table")]
pub(super) struct RawRender {
    pub width: Option<Spanned<i64>>,
    pub height: Option<Spanned<i64>>,
    pub samples: Option<Spanned<i64>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields, expecting = "a [check] table")]
pub(super) struct RawCheck {
    pub frames: Spanned<Vec<Spanned<i64>>>,
    pub references: Spanned<String>,
    pub fail: Option<Spanned<i64>>,
    pub fail_percent: Option<Spanned<f64>>,
    pub hard_fail: Option<Spanned<i64>>,
    pub flip: Option<Spanned<f64>>,
}
