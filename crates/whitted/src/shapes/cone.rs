//! The open cone (or cylinder) of NFF's `c` record: the surface between two end circles,
//! centres B (base) and A (apex) with radii r_B and r_A, without caps.
//!
//! With the unit axis a = (A − B)/h, h = |A − B|, and the slope k = (r_A − r_B)/h, the
//! radius at height s along the axis is ρ(s) = r_B + k·s. For a ray O + tD, with
//! O' = O − B, s(t) = O'·a + t·D·a and the radial parts O⊥ = O' − (O'·a)a,
//! D⊥ = D − (D·a)a, the surface is |O⊥ + tD⊥|² = ρ(s(t))²:
//! A t² + B t + C = 0 with A = |D⊥|² − k²(D·a)², B = 2(O⊥·D⊥ − k·ρ₀·(D·a)),
//! C = |O⊥|² − ρ₀², ρ₀ = r_B + k·(O'·a). Roots outside 0 ≤ s ≤ h are cut away (the cone
//! is open). The outward normal at p is the gradient of |p⊥| − ρ(s): p⊥/|p⊥| − k·a,
//! normalised. Negative radii (NFF's "inside only") are taken by their size.

use super::Roots;
use crate::optics::Ray;
use glam::DVec3;

/// An open cone or cylinder.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cone {
    /// The centre of the base circle.
    pub base: DVec3,
    /// The radius at the base, ≥ 0.
    pub base_radius: f64,
    /// The centre of the apex circle.
    pub apex: DVec3,
    /// The radius at the apex, ≥ 0.
    pub apex_radius: f64,
    axis: DVec3,
    height: f64,
    slope: f64,
}

impl Cone {
    /// The cone between the two circles; `None` when the centres coincide, something is
    /// not finite, or both radii are 0.
    pub fn new(base: DVec3, base_radius: f64, apex: DVec3, apex_radius: f64) -> Option<Cone> {
        let (rb, ra) = (base_radius.abs(), apex_radius.abs());
        let height = (apex - base).length();
        let axis = (apex - base).try_normalize()?;
        let ok = base.is_finite() && apex.is_finite() && rb.is_finite() && ra.is_finite();
        (ok && height > 0.0 && height.is_finite() && rb.max(ra) > 0.0).then_some(Cone {
            base,
            base_radius: rb,
            apex,
            apex_radius: ra,
            axis,
            height,
            slope: (ra - rb) / height,
        })
    }

    /// The unit axis, from the base towards the apex.
    pub fn axis(&self) -> DVec3 {
        self.axis
    }

    /// The distance between the end centres.
    pub fn height(&self) -> f64 {
        self.height
    }

    /// The radius's change per unit of height, (r_A − r_B)/h.
    pub fn slope(&self) -> f64 {
        self.slope
    }

    /// Where the ray's line crosses the open surface, ascending, any sign.
    #[inline]
    pub fn roots(&self, ray: &Ray) -> Roots {
        let o = ray.origin - self.base;
        let (os, ds) = (o.dot(self.axis), ray.dir.dot(self.axis));
        let (op, dp) = (o - os * self.axis, ray.dir - ds * self.axis);
        let k = self.slope;
        let rho0 = self.base_radius + k * os;
        let a = dp.length_squared() - k * k * ds * ds;
        let b = 2.0 * (op.dot(dp) - k * rho0 * ds);
        let c = op.length_squared() - rho0 * rho0;
        let within = |t: f64| {
            let s = os + t * ds;
            (0.0..=self.height).contains(&s)
        };
        let mut found = [0.0; 2];
        let mut n = 0;
        let mut keep = |t: f64| {
            if t.is_finite() && within(t) {
                found[n] = t;
                n += 1;
            }
        };
        if a == 0.0 {
            if b != 0.0 {
                keep(-c / b);
            }
        } else {
            let disc = b * b - 4.0 * a * c;
            if disc < 0.0 {
                return Roots::NONE;
            }
            // The stable pair: q = −(B + sign(B)√Δ)/2, roots q/A and C/q.
            let q = -0.5 * (b + disc.sqrt().copysign(b));
            keep(q / a);
            if q != 0.0 {
                keep(c / q);
            } else {
                keep(0.0);
            }
        }
        match n {
            0 => Roots::NONE,
            1 => Roots::one(found[0]),
            _ => Roots::two(found[0], found[1]),
        }
    }

    /// The first crossing with `ray.t_min` < t < t_max.
    #[inline]
    pub fn hit(&self, ray: &Ray, t_max: f64) -> Option<f64> {
        self.roots(ray).first_hit(ray.t_min, t_max)
    }

    /// The outward unit normal at a point `p` of the surface.
    pub fn normal(&self, p: DVec3) -> DVec3 {
        let o = p - self.base;
        let radial = o - o.dot(self.axis) * self.axis;
        let out = radial
            .try_normalize()
            .unwrap_or(self.axis.any_orthonormal_vector());
        (out - self.slope * self.axis).normalize()
    }

    /// A box around the cone: each end circle's box, joined.
    pub fn bounds(&self) -> (DVec3, DVec3) {
        // A circle of radius r across the unit axis a spans r·√(1 − a_i²) along axis i.
        let span = |r: f64| {
            let a2 = self.axis * self.axis;
            DVec3::new(
                (1.0 - a2.x).max(0.0).sqrt(),
                (1.0 - a2.y).max(0.0).sqrt(),
                (1.0 - a2.z).max(0.0).sqrt(),
            ) * r
        };
        let (sb, sa) = (span(self.base_radius), span(self.apex_radius));
        (
            (self.base - sb).min(self.apex - sa),
            (self.base + sb).max(self.apex + sa),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn close(a: f64, b: f64) -> bool {
        (a - b).abs() < 1e-12
    }

    #[test]
    fn cylinder_by_hand() {
        // Radius 1 around the z axis from z = 0 to z = 2.
        let c = Cone::new(DVec3::ZERO, 1.0, DVec3::new(0.0, 0.0, 2.0), 1.0).unwrap();
        // From x = −5 at z = 1 along +x: in at t = 4, out at t = 6.
        let r = Ray::new(DVec3::new(-5.0, 0.0, 1.0), DVec3::X);
        assert_eq!(c.roots(&r).as_slice(), &[4.0, 6.0]);
        assert_eq!(c.hit(&r, f64::INFINITY), Some(4.0));
        assert_eq!(c.normal(DVec3::new(-1.0, 0.0, 1.0)), -DVec3::X);
        // Above the top (z = 3): open, nothing.
        let r = Ray::new(DVec3::new(-5.0, 0.0, 3.0), DVec3::X);
        assert_eq!(c.roots(&r), Roots::NONE);
        // Down the axis: no cap, no hit (A = 0, B = 0).
        let r = Ray::new(DVec3::new(0.0, 0.0, 5.0), -DVec3::Z);
        assert_eq!(c.roots(&r), Roots::NONE);
        // From inside, outwards: one crossing at t = 1.
        let r = Ray::new(DVec3::new(0.0, 0.0, 1.0), DVec3::Y);
        let got = c.roots(&r);
        assert!(got.as_slice().len() == 2 && close(got.as_slice()[1], 1.0));
        assert_eq!(c.hit(&r, f64::INFINITY), Some(1.0));
    }

    #[test]
    fn cone_by_hand() {
        // Base radius 2 at z = 0, apex radius 0 at z = 2: the surface x² + y² = (2 − z)².
        let c = Cone::new(DVec3::ZERO, 2.0, DVec3::new(0.0, 0.0, 2.0), 0.0).unwrap();
        // Along +x at z = 1 from x = −5: the radius there is 1, so in at 4, out at 6.
        let r = Ray::new(DVec3::new(-5.0, 0.0, 1.0), DVec3::X);
        let got = c.roots(&r);
        assert!(
            close(got.as_slice()[0], 4.0) && close(got.as_slice()[1], 6.0),
            "{got:?}"
        );
        // The normal at (1, 0, 1): (1, 0, 0) − (−1)(0, 0, 1) = (1, 0, 1)/√2.
        let n = c.normal(DVec3::new(1.0, 0.0, 1.0));
        let s = std::f64::consts::FRAC_1_SQRT_2;
        assert!((n - DVec3::new(s, 0.0, s)).length() < 1e-15);
        // Down the axis from above: the double cone's other nappe (z > 2) is cut away,
        // and the tip at z = 2 is a double root there.
        let r = Ray::new(DVec3::new(0.5, 0.0, 10.0), -DVec3::Z);
        // Meets x = 0.5 at radius 0.5: z = 1.5, t = 8.5 (the upper nappe's z = 2.5 is cut).
        let got = c.roots(&r);
        assert_eq!(got.as_slice().len(), 1);
        assert!(close(got.as_slice()[0], 8.5), "{got:?}");
        let (lo, hi) = c.bounds();
        assert_eq!(
            (lo, hi),
            (DVec3::new(-2.0, -2.0, 0.0), DVec3::new(2.0, 2.0, 2.0))
        );
        assert!(Cone::new(DVec3::ZERO, 1.0, DVec3::ZERO, 1.0).is_none());
    }

    /// Brute force: march along the line in small steps looking for sign changes of the
    /// implicit |p⊥| − ρ(s) inside 0 ≤ s ≤ h, then bisect.
    fn reference(c: &Cone, r: &Ray) -> Vec<f64> {
        let f = |t: f64| {
            let o = r.at(t) - c.base;
            let s = o.dot(c.axis);
            ((o - s * c.axis).length() - (c.base_radius + c.slope * s), s)
        };
        let mut out = Vec::new();
        let n = 20_000;
        let (t0, t1) = (-30.0, 30.0);
        let step = (t1 - t0) / n as f64;
        for i in 0..n {
            let (mut a, mut b) = (t0 + i as f64 * step, t0 + (i + 1) as f64 * step);
            let (fa, _) = f(a);
            let (fb, _) = f(b);
            if fa.signum() == fb.signum() {
                continue;
            }
            for _ in 0..60 {
                let m = 0.5 * (a + b);
                if f(m).0.signum() == fa.signum() {
                    a = m
                } else {
                    b = m
                }
            }
            let (_, s) = f(a);
            if (0.0..=c.height).contains(&s) {
                out.push(a);
            }
        }
        out
    }

    fn v3(r: f64) -> impl Strategy<Value = DVec3> {
        (-r..r, -r..r, -r..r).prop_map(|(x, y, z)| DVec3::new(x, y, z))
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]
        #[test]
        fn agrees_with_marching(
            b in v3(1.0), a in v3(1.0), rb in 0.1f64..1.0, ra in 0.0f64..1.0,
            o in v3(8.0), d in v3(1.0)
        ) {
            let Some(c) = Cone::new(b, rb, a, ra) else { return Ok(()) };
            prop_assume!(c.height > 0.3);
            let Some(d) = d.try_normalize() else { return Ok(()) };
            let r = Ray::new(o, d);
            let got = c.roots(&r);
            let want = reference(&c, &r);
            // Grazing rays (a tangent double root) and crossings at the rims may be seen
            // by one method only; elsewhere both find the same roots.
            let firm: Vec<f64> = want.iter().copied().filter(|&t| {
                let s = (r.at(t) - c.base).dot(c.axis);
                s > 1e-6 && s < c.height - 1e-6
            }).collect();
            for w in &firm {
                prop_assert!(
                    got.as_slice().iter().any(|g| (g - w).abs() < 1e-6),
                    "{got:?} {want:?}"
                );
            }
            for g in got.as_slice() {
                let s = (r.at(*g) - c.base).dot(c.axis);
                prop_assert!((-1e-9..=c.height + 1e-9).contains(&s));
                let p = r.at(*g) - c.base;
                let rad = (p - s * c.axis).length();
                prop_assert!((rad - (c.base_radius + c.slope * s)).abs() < 1e-7);
            }
        }
    }
}
