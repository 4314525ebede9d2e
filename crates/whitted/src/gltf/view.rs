//! The view of a glTF scene (SPEC §18): the first camera in depth-first order of the
//! scene's nodes, or the one named; it looks down its node's −z with +y up (the node's
//! scale ignored), `yfov` the full vertical angle between the image's top and bottom
//! edges, 640 × 480 by default or the camera's `aspectRatio` at a height of 480; an
//! orthographic camera casts parallel rays over 2·xmag × 2·ymag (its xmag/ymag the
//! aspect). Without
//! a camera one is placed to frame the scene's bounds, looking down −z with a vertical
//! angle of `DEFAULT_FOV`; and without a light, one stated default light
//! (`default_light`) travels from behind the camera's upper left. A picture of another
//! shape than the camera's `aspectRatio` is warned about (`aspect_warning`).

use super::rig::{Projection, Rig};
use crate::base::Color;
use crate::camera::Lens;
use crate::lights::punctual::Shape;
use glam::{DMat4, DVec3};

/// The vertical angle of the placed camera, in degrees.
pub const DEFAULT_FOV: f64 = 45.0;
/// The default image height.
pub const HEIGHT: u32 = 480;
/// The default image width.
pub const WIDTH: u32 = 640;

/// Where the camera is and how it frames.
#[derive(Clone, Debug, PartialEq)]
pub struct View {
    /// The eye.
    pub eye: DVec3,
    /// A point straight ahead.
    pub look_at: DVec3,
    /// The lens (vertical angle over the edges, and up).
    pub lens: Lens,
    /// The image size.
    pub size: (u32, u32),
    /// The camera's name, if it came from the file.
    pub name: Option<String>,
    /// An orthographic camera's view height (2·ymag): parallel rays.
    pub parallel: Option<f64>,
}

/// The camera at `world` (its node's world matrix) with projection `p`.
pub fn placed(world: &DMat4, p: Projection, name: Option<String>) -> View {
    let eye = world.w_axis.truncate();
    let forward = (-world.z_axis.truncate()).normalize_or(-DVec3::Z);
    let up = world.y_axis.truncate().normalize_or(DVec3::Y);
    // An orthographic camera's rays are parallel (`Camera::parallel_ray`); its angle
    // only sizes the view plane they are spread over.
    let (fov, aspect, parallel) = match p {
        Projection::Perspective { yfov, aspect } => (yfov.to_degrees(), aspect, None),
        Projection::Orthographic { xmag, ymag } => {
            (DEFAULT_FOV, Some(xmag / ymag), Some(2.0 * ymag.abs()))
        }
    };
    let size = match aspect {
        Some(a) if a.is_finite() && a > 0.0 => (
            ((f64::from(HEIGHT) * a).round() as u32).clamp(1, 16384),
            HEIGHT,
        ),
        _ => (WIDTH, HEIGHT),
    };
    View {
        eye,
        look_at: eye + forward,
        lens: Lens {
            fov: Some(fov.clamp(0.01, 179.0)),
            roll: 0.0,
            up,
            centres: false,
        },
        size,
        name,
        parallel,
    }
}

/// A camera framing the box `lo`..`hi`, looking down −z.
pub fn framing(lo: DVec3, hi: DVec3) -> View {
    let (lo, hi) = if lo.is_finite() && hi.is_finite() {
        (lo, hi)
    } else {
        (DVec3::splat(-1.0), DVec3::ONE)
    };
    let c = 0.5 * (lo + hi);
    let r = (0.5 * (hi - lo).length()).max(1e-6);
    let d = r / (0.5 * DEFAULT_FOV.to_radians()).sin();
    let eye = c + DVec3::new(0.0, 0.0, d);
    View {
        eye,
        look_at: c,
        lens: Lens {
            fov: Some(DEFAULT_FOV),
            roll: 0.0,
            up: DVec3::Y,
            centres: false,
        },
        size: (WIDTH, HEIGHT),
        name: None,
        parallel: None,
    }
}

/// The default light: white, 1 lux (`punctual::EXPOSURE` makes it §2's intensity 1),
/// travelling from behind the camera's upper left towards what it sees.
pub fn default_light(view: &View) -> (Shape, Color, f64) {
    let forward = (view.look_at - view.eye).normalize_or(-DVec3::Z);
    let right = forward.cross(view.lens.up).normalize_or(DVec3::X);
    let up = right.cross(forward);
    let direction = (forward + 0.5 * right - 0.8 * up).normalize();
    (Shape::Directional { direction }, Color::ONE, 1.0)
}

/// The warning for a picture of `size` seen through the camera named `name` (or the
/// first) of `rig` whose `aspectRatio` is another shape (SPEC §18: the width follows the
/// picture, `yfov` is kept and the pixels stay square): `None` when the camera gives no
/// `aspectRatio` or the picture's width is within half a pixel of it.
pub fn aspect_warning(rig: &Rig, name: Option<&str>, size: (u32, u32)) -> Option<String> {
    let (n, c) = find(rig, &rig.order(), name).ok()??;
    let Projection::Perspective {
        aspect: Some(a), ..
    } = rig.cameras[c].projection
    else {
        return None;
    };
    let (w, h) = (f64::from(size.0), f64::from(size.1.max(1)));
    if (w - a * h).abs() <= 0.5 || !(a.is_finite() && a > 0.0) {
        return None;
    }
    let label = (rig.cameras[c].name.clone())
        .or_else(|| rig.nodes[n].name.clone())
        .unwrap_or_else(|| format!("camera {}", c + 1));
    Some(format!(
        "{}: the camera `{label}` has aspectRatio {a:.4} and the picture is {}×{} ({:.4}): \
         its width follows the picture (yfov kept, square pixels); {}×{} keeps the camera's",
        rig.file,
        size.0,
        size.1,
        w / h,
        ((a * h).round() as u32).max(1),
        size.1
    ))
}

/// The camera named `name`, or the first in the scene's depth-first order; `None`
/// when the scene has none (`Err` with the names when `name` is not one of them).
pub fn find(
    rig: &Rig,
    order: &[usize],
    name: Option<&str>,
) -> Result<Option<(usize, usize)>, Vec<String>> {
    let cams: Vec<(usize, usize, String)> = order
        .iter()
        .filter_map(|&n| rig.nodes[n].camera.map(|c| (n, c)))
        .map(|(n, c)| {
            let label = rig.cameras[c]
                .name
                .clone()
                .or_else(|| rig.nodes[n].name.clone())
                .unwrap_or_else(|| format!("camera {}", c + 1));
            (n, c, label)
        })
        .collect();
    match name {
        None => Ok(cams.first().map(|(n, c, _)| (*n, *c))),
        Some(want) => {
            let hit = cams
                .iter()
                .find(|(n, _, label)| label == want || rig.nodes[*n].name.as_deref() == Some(want));
            match hit {
                Some((n, c, _)) => Ok(Some((*n, *c))),
                None => Err(cams.into_iter().map(|(_, _, l)| l).collect()),
            }
        }
    }
}
