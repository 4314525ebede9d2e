//! Rays and the laws of Descartes (report IV.1 and IV.3): the ray type, the report's
//! epsilon, mirror reflection and refraction by the report's formula.
//!
//! Vectors are `glam::DVec3` (f64): the reference noise value and the SPEC's hand-computed
//! tests are in double precision, and on a CPU f64 costs about what f32 does.

use glam::DVec3;

/// The report's epsilon: a hit counts only for t > 0.01. Directions are unit, so t is a
/// distance in scene units.
pub const T_MIN: f64 = 0.01;

/// A half-line `origin + t·dir`, t > `t_min`, with `dir` of unit length.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray {
    /// Where the ray starts.
    pub origin: DVec3,
    /// Its direction, of unit length.
    pub dir: DVec3,
    /// A hit counts only past this distance: the report's `T_MIN` for a Scene.txt, the
    /// scene's own epsilon for an NFF scene (`Scene::t_min`).
    pub t_min: f64,
}

impl Ray {
    /// A ray from `origin` along `dir`, which must already be unit length, with the
    /// report's epsilon.
    #[inline]
    pub fn new(origin: DVec3, dir: DVec3) -> Ray {
        Ray {
            origin,
            dir,
            t_min: T_MIN,
        }
    }

    /// This ray with another epsilon.
    #[inline]
    pub fn with_t_min(self, t_min: f64) -> Ray {
        Ray { t_min, ..self }
    }

    /// A ray from `origin` along the unit `dir` with this ray's epsilon (a reflected,
    /// refracted or shadow ray spawned at a hit of this one).
    #[inline]
    pub fn spawn(&self, origin: DVec3, dir: DVec3) -> Ray {
        Ray {
            origin,
            dir,
            t_min: self.t_min,
        }
    }

    /// The point at parameter `t`.
    #[inline]
    pub fn at(&self, t: f64) -> DVec3 {
        self.origin + self.dir * t
    }
}

/// Mirror reflection of `v` about the unit normal `n`: R = V − 2(V·N)N (report IV.3.1).
#[inline]
pub fn reflect(v: DVec3, n: DVec3) -> DVec3 {
    v - 2.0 * v.dot(n) * n
}

/// Refraction of the unit direction `v` through a surface whose unit normal `n` faces the
/// incoming ray (v·n ≤ 0), with `eta` = n1/n2. The report's formula (IV.3.2):
/// T = η V − (η cosθi + √(1 − sin²θt)) N, with cosθi = V·N and sin²θt = η²(1 − cos²θi).
/// Returns `None` on total internal reflection (sin²θt > 1).
#[inline]
pub fn refract(v: DVec3, n: DVec3, eta: f64) -> Option<DVec3> {
    let cos_i = v.dot(n);
    let sin2_t = eta * eta * (1.0 - cos_i * cos_i);
    if sin2_t > 1.0 {
        return None;
    }
    // η·cosθi is negative here (n faces the ray), so this is the familiar
    // ηV + (η·c − √(1 − sin²θt))N with c = −V·N.
    Some(eta * v - (eta * cos_i + (1.0 - sin2_t).sqrt()) * n)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: DVec3, b: DVec3) -> bool {
        (a - b).length() < 1e-12
    }

    #[test]
    fn reflect_hand_values() {
        // 45° onto the floor: (1,-1,0)/√2 bounces to (1,1,0)/√2.
        let s = std::f64::consts::FRAC_1_SQRT_2;
        let r = reflect(DVec3::new(s, -s, 0.0), DVec3::Y);
        assert!(close(r, DVec3::new(s, s, 0.0)));
        // Head-on: straight back.
        assert!(close(reflect(-DVec3::Z, DVec3::Z), DVec3::Z));
    }

    #[test]
    fn refract_straight_through_at_normal_incidence() {
        let t = refract(-DVec3::Y, DVec3::Y, 1.0 / 1.5).unwrap();
        assert!(close(t, -DVec3::Y), "{t}");
    }

    #[test]
    fn refract_obeys_snell_at_45_degrees() {
        // Air to glass (1.5) at 45°: sinθt = sin45°/1.5 = 0.4714045207910317.
        let s = std::f64::consts::FRAC_1_SQRT_2;
        let t = refract(DVec3::new(s, -s, 0.0), DVec3::Y, 1.0 / 1.5).unwrap();
        assert!((t.length() - 1.0).abs() < 1e-12);
        assert!((t.x - 0.4714045207910317).abs() < 1e-12, "{t}");
        // cosθt = √(1 − 0.2222…) = 0.8819171036881969, going down.
        assert!((t.y + 0.8819171036881969).abs() < 1e-12, "{t}");
        assert_eq!(t.z, 0.0);
    }

    #[test]
    fn total_internal_reflection_past_the_critical_angle() {
        // Glass to air (η = 1.5) at 45°: sin²θt = 2.25 · 0.5 = 1.125 > 1.
        let s = std::f64::consts::FRAC_1_SQRT_2;
        assert_eq!(refract(DVec3::new(s, -s, 0.0), DVec3::Y, 1.5), None);
        // At 30° it still passes: sinθt = 1.5 · 0.5 = 0.75.
        let v = DVec3::new(0.5, -(0.75f64).sqrt(), 0.0);
        let t = refract(v, DVec3::Y, 1.5).unwrap();
        assert!((t.x - 0.75).abs() < 1e-12);
    }

    #[test]
    fn ray_at() {
        let r = Ray::new(DVec3::new(1.0, 2.0, 3.0), DVec3::X);
        assert_eq!(r.at(2.5), DVec3::new(3.5, 2.0, 3.0));
    }
}
