//! How deep the tracer goes and which rays it spawns (`Rules`): the report's by default
//! (5 bounces after the camera ray, a 1/256 weight cut-off), or the SPD's testing
//! procedure (`Rules::spd`: depth 5 counting the eye ray, no cut-off, and the SPD's
//! spawning, `Tracer::spawn_spd`: on total internal reflection the reflection ray
//! carries the transmitted weight too and the refraction is still counted).

use super::{RayCount, Tracer, MAX_DEPTH, MIN_WEIGHT};
use crate::base::Color;
use crate::object::Object;
use crate::optics::{reflect, refract, Ray};
use glam::DVec3;

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
