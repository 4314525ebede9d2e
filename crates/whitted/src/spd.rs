//! The Standard Procedural Databases' testing procedure (Haines, SPD README, "Testing
//! Procedures" 6 to 10; SPEC §17) as a render setting, beside the report's rules:
//!
//! - 513 × 513 eye rays through the pixel corners of a 512 × 512 picture, each pixel the
//!   average of its four corners (each corner clamped to 0..1 first, as supersamples
//!   are): `render_corners`. The corner rays are the pixel centres of a 513 × 513 view,
//!   so an NFF's `angle` spans the outer corner rays;
//! - a tree depth of 5 with the eye ray at depth 1 (4 bounces after it), and no weight
//!   cut-off: `Rules::spd`;
//! - every ray hitting a reflective (Ks > 0) or transmitting (T > 0) surface spawns a
//!   reflection ray, and a transmitting one a refraction ray too; on total internal
//!   reflection there is no refracted ray, the reflection ray carries the transmitted
//!   weight as well, and the refraction is still counted (that is the SPD table's count:
//!   see docs/decisions.md): `Tracer::spawn_spd`;
//! - shadow rays only to the lights the (ray-facing) shading normal faces, as always.

use crate::camera::Camera;
use crate::object::Object;
use crate::optics::{reflect, refract, Ray};
use crate::render::{par_rows, Frame};
use crate::texture::Color;
use crate::trace::{RayCount, Tracer, MAX_DEPTH, MIN_WEIGHT};
use glam::DVec3;

/// The SPD's picture size, 512 × 512.
pub const SPD_SIZE: u32 = 512;
/// The SPD's deepest ray counting the eye ray as 1: 5.
pub const SPD_DEPTH: u32 = 5;

/// How deep the tracer goes and which rays it spawns.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rules {
    /// Bounces allowed after the camera ray.
    pub max_depth: u32,
    /// Secondary rays weighing less than this are not traced.
    pub min_weight: f64,
    /// The SPD's spawning (`Tracer::spawn_spd`) instead of the report's.
    pub spd: bool,
}

impl Default for Rules {
    /// The report's: 5 bounces after the camera ray, a 1/256 weight cut-off.
    fn default() -> Rules {
        Rules {
            max_depth: MAX_DEPTH,
            min_weight: MIN_WEIGHT,
            spd: false,
        }
    }
}

impl Rules {
    /// The SPD's: depth 5 counting the eye ray (4 bounces), no weight cut-off.
    pub fn spd() -> Rules {
        Rules {
            max_depth: SPD_DEPTH - 1,
            min_weight: 0.0,
            spd: true,
        }
    }
}

impl Tracer<'_> {
    /// The secondary rays of a hit under the SPD's rules: what they add to the colour.
    #[allow(clippy::too_many_arguments)]
    #[inline(never)]
    pub(crate) fn spawn_spd(
        &self,
        ray: &Ray,
        p: DVec3,
        n: DVec3,
        c: Color,
        obj: &Object,
        entering: bool,
        depth: u32,
        count: &mut RayCount,
    ) -> Color {
        let m = &obj.material;
        let v = ray.dir;
        let mut out = Color::ZERO;
        let refracted = (m.kt > 0.0).then(|| {
            let eta = if entering { 1.0 / m.ior } else { m.ior };
            refract(v, n, eta)
        });
        if m.kr > 0.0 || m.kt > 0.0 {
            // On total internal reflection the transmitted weight goes this way too.
            let w = m.kr
                + if matches!(refracted, Some(None)) {
                    m.kt
                } else {
                    0.0
                };
            count.reflect += 1;
            let r = ray.spawn(p, reflect(v, n).normalize());
            out += w * self.trace(&r, depth + 1, w, count);
        }
        if let Some(dir) = refracted {
            // Counted whether it leaves (refracted) or not (totally reflected).
            count.refract += 1;
            if let Some(dir) = dir {
                let r = ray.spawn(p, dir.normalize());
                out += m.kt * c * self.trace(&r, depth + 1, m.kt, count);
            }
        }
        out
    }
}

/// A `width` × `height` picture whose pixels average the four of the
/// (width + 1) × (height + 1) rays `corners` shoots through its pixel centres (a camera
/// for that size: its pixel centres are the picture's pixel corners).
pub fn render_corners(
    tracer: &Tracer,
    corners: &Camera,
    width: u32,
    height: u32,
) -> (Frame, RayCount) {
    let (cw, ch) = (width + 1, height + 1);
    let mut grid = vec![Color::ZERO; cw as usize * ch as usize];
    let count = par_rows(&mut grid, cw, ch, |j, row, count| {
        for (i, c) in row.iter_mut().enumerate() {
            let ray = corners.ray(i as f64 + 0.5, j as f64 + 0.5);
            *c = tracer.primary(&ray, count).clamp(Color::ZERO, Color::ONE);
        }
    });
    let at = |i: u32, j: u32| grid[(j * cw + i) as usize];
    let colors = (0..height).flat_map(|j| {
        (0..width).map(move |i| (at(i, j) + at(i + 1, j) + at(i, j + 1) + at(i + 1, j + 1)) / 4.0)
    });
    (Frame::from_colors(colors, width, height), count)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rules_by_hand() {
        let r = Rules::default();
        assert_eq!((r.max_depth, r.min_weight, r.spd), (5, 1.0 / 256.0, false));
        let s = Rules::spd();
        assert_eq!((s.max_depth, s.min_weight, s.spd), (4, 0.0, true));
    }
}
