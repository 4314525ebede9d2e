//! The camera as a track's subject, spelled as tracks spell everything else:
//!
//! ```toml
//! target = "camera position"   # [x, y, z]: the eye (the scene file's line 2)
//! target = "camera look_at"    # [x, y, z]: the point looked at (line 3)
//! target = "camera fov"        # degrees, 0 < fov < 180: the vertical field of view
//! ```
//!
//! A value is written into the frame's scene (its eye, its look-at point, its lens's
//! field of view) as any track's is, so a still camera, a spline path that looks at the
//! scene's point and the frames' digests all see it. What a `[camera]` table already
//! gives (a path's positions, a table's or a key's `look_at`, a `fov`) is not tracked
//! besides: `refusal` says why, at the track (see `Timeline::new`).

use super::{Field, Kind, Target};
use crate::timeline::{CameraPath, LookAt};
use glam::DVec3;
use whitted::camera::Lens;
use whitted::scene::Scene;

/// The camera's fields a track may animate.
pub const FIELDS: [(&str, Field); 3] = [
    ("position", Field::CameraPosition),
    ("look_at", Field::CameraLookAt),
    ("fov", Field::CameraFov),
];

/// `camera FIELD`.
pub fn target(field: &str) -> Result<Target, String> {
    let field = super::pick("the camera", field, &FIELDS)?;
    Ok(Target { field, index: 0 })
}

/// Whether `field` is one of the camera's.
pub fn is_camera(field: Field) -> bool {
    matches!(
        field,
        Field::CameraPosition | Field::CameraLookAt | Field::CameraFov
    )
}

/// The kind of a camera field's values.
pub fn kind(field: Field) -> Kind {
    match field {
        Field::CameraFov => Kind::Number,
        _ => Kind::Vector,
    }
}

/// The vertical field of view of the report's view plane (0.35 high at distance 1):
/// 2·atan(0.175) ≈ 19.85°, what `camera fov` reads on a Scene.txt without one.
pub fn report_fov() -> f64 {
    2.0 * (whitted::camera::VIEW_HEIGHT / 2.0).atan().to_degrees()
}

/// The value `scene` holds (a number as `(x, 0, 0)`).
pub fn read(field: Field, scene: &Scene) -> DVec3 {
    match field {
        Field::CameraPosition => scene.eye,
        Field::CameraLookAt => scene.look_at,
        _ => DVec3::new(scene.lens.fov.unwrap_or_else(report_fov), 0.0, 0.0),
    }
}

/// Writes `v` into `scene`: the eye, the look-at point, or a field of view that spans
/// the picture's edges (as `[camera] fov` does, an NFF view's included).
pub fn put(field: Field, scene: &mut Scene, v: DVec3) {
    match field {
        Field::CameraPosition => scene.eye = v,
        Field::CameraLookAt => scene.look_at = v,
        _ => {
            scene.lens.fov = Some(v.x);
            scene.lens.centres = false;
        }
    }
}

/// The bound `v` breaks, if any.
pub fn check(field: Field, v: DVec3) -> Result<(), String> {
    match field {
        Field::CameraFov if !Lens::fov_ok(v.x) => Err(
            "the fov is the vertical field of view in degrees, between 0 and 180 (both excluded)"
                .into(),
        ),
        Field::CameraFov => Ok(()),
        _ if !v.is_finite() => Err("coordinates must be finite".into()),
        _ => Ok(()),
    }
}

/// What the manifest's `[camera]` gives that a camera track would fight with.
#[derive(Clone, Copy, Debug, Default)]
pub struct Given<'a> {
    /// The path, if any.
    pub path: Option<&'a CameraPath>,
    /// The table's `look_at`, if any.
    pub look_at: Option<&'a LookAt>,
    /// The table's `fov`, if any.
    pub fov: Option<f64>,
}

/// Why a track of `field` cannot be beside what `[camera]` gives, if it cannot.
pub fn refusal(field: Field, given: Given) -> Option<String> {
    let why = match field {
        Field::CameraPosition => format!(
            "the camera's position is the `[camera] path = \"{}\"`'s: track it or give the path, not both",
            given.path?.name()
        ),
        Field::CameraLookAt => match (given.look_at, given.path) {
            (Some(_), _) => {
                "`[camera] look_at` already says what the camera looks at: track it or give look_at, not both".to_string()
            }
            (None, Some(CameraPath::Circle { .. })) => {
                "a `[camera] path = \"circle\"` looks at its centre (or its look_at) on every frame: a tracked look_at needs a spline path or none".to_string()
            }
            (None, Some(CameraPath::Spline(s))) if s.keys.iter().any(|k| k.look_at.is_some()) => {
                "the camera's spline keys give their own look_at: track it or give it on the keys, not both".to_string()
            }
            _ => return None,
        },
        Field::CameraFov => {
            given.fov?;
            "`[camera] fov` already gives the field of view: track it or give fov, not both"
                .to_string()
        }
        _ => return None,
    };
    Some(why)
}
