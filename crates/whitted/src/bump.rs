//! Bump mapping (report V.2): the normal perturbed by differences of Perlin noise.
//!
//! With ε = BumpValue and N the unit normal:
//! - type 1 (uniform): x = noise(Nx−ε, Ny, Nz) − noise(Nx+ε, Ny, Nz), likewise y and z,
//!   taken around N itself;
//! - type 2 (plane / water): the same differences around (Nx+px, 50·Ny+100·py, Nz+pz),
//!   p the hit point, so a flat plane (all normals equal) still gets ripples.
//!
//! The differences are added to N and the result normalised again. The tracer perturbs the
//! outward geometric normal, then turns it to face the ray (see docs/decisions.md).

use crate::noise::noise;
use glam::DVec3;

/// How a material perturbs its normal.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Bump {
    /// Type 0: the geometric normal, unchanged.
    None,
    /// Type 1 with its ε.
    Uniform(f64),
    /// Type 2 with its ε.
    Water(f64),
}

/// The central differences of noise around `c` with step `eps`.
#[inline]
fn differences(c: DVec3, eps: f64) -> DVec3 {
    DVec3::new(
        noise(c.x - eps, c.y, c.z) - noise(c.x + eps, c.y, c.z),
        noise(c.x, c.y - eps, c.z) - noise(c.x, c.y + eps, c.z),
        noise(c.x, c.y, c.z - eps) - noise(c.x, c.y, c.z + eps),
    )
}

impl Bump {
    /// The bump as Scene.txt records it: `BumpType BumpValue` (0 0 for none, 1 ε
    /// uniform, 2 ε water), as pictures, records and Cryptomatte names write it.
    pub fn record(&self) -> (u8, f64) {
        match *self {
            Bump::None => (0, 0.0),
            Bump::Uniform(e) => (1, e),
            Bump::Water(e) => (2, e),
        }
    }

    /// The perturbed unit normal for unit normal `n` at point `p`. If the perturbation
    /// cancels the normal exactly, the normal is left as it was. Always inlined: once the
    /// passes' shading called it beside `shade`, LLVM stopped inlining it into `shade` on
    /// its own, 15.6 M instructions more on the orbit at one thread (callgrind).
    #[inline(always)]
    pub fn apply(&self, n: DVec3, p: DVec3) -> DVec3 {
        let delta = match *self {
            Bump::None => return n,
            Bump::Uniform(eps) => differences(n, eps),
            Bump::Water(eps) => differences(
                DVec3::new(n.x + p.x, 50.0 * n.y + 100.0 * p.y, n.z + p.z),
                eps,
            ),
        };
        (n + delta).try_normalize().unwrap_or(n)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::noise::noise;

    #[test]
    fn records_as_the_file_writes_it() {
        assert_eq!(Bump::None.record(), (0, 0.0));
        assert_eq!(Bump::Uniform(0.5).record(), (1, 0.5));
        assert_eq!(Bump::Water(0.125).record(), (2, 0.125));
    }

    #[test]
    fn none_leaves_the_normal() {
        assert_eq!(
            Bump::None.apply(DVec3::Y, DVec3::new(1.0, 2.0, 3.0)),
            DVec3::Y
        );
    }

    #[test]
    fn uniform_by_hand() {
        // N = (0,1,0), ε = 0.5: x = noise(−0.5,1,0) − noise(0.5,1,0), etc.
        let eps = 0.5;
        let d = DVec3::new(
            noise(-0.5, 1.0, 0.0) - noise(0.5, 1.0, 0.0),
            noise(0.0, 0.5, 0.0) - noise(0.0, 1.5, 0.0),
            noise(0.0, 1.0, -0.5) - noise(0.0, 1.0, 0.5),
        );
        let got = Bump::Uniform(eps).apply(DVec3::Y, DVec3::new(7.0, 7.0, 7.0));
        assert!((got - (DVec3::Y + d).normalize()).length() < 1e-15);
        assert!((got.length() - 1.0).abs() < 1e-12);
        // Type 1 ignores the hit point.
        assert_eq!(got, Bump::Uniform(eps).apply(DVec3::Y, DVec3::ZERO));
    }

    #[test]
    fn water_depends_on_the_hit_point() {
        let eps = 0.3;
        let p = DVec3::new(0.25, 0.01, 1.75);
        let c = DVec3::new(0.25, 50.0 + 1.0, 1.75);
        let d = DVec3::new(
            noise(c.x - eps, c.y, c.z) - noise(c.x + eps, c.y, c.z),
            noise(c.x, c.y - eps, c.z) - noise(c.x, c.y + eps, c.z),
            noise(c.x, c.y, c.z - eps) - noise(c.x, c.y, c.z + eps),
        );
        let got = Bump::Water(eps).apply(DVec3::Y, p);
        assert!((got - (DVec3::Y + d).normalize()).length() < 1e-15);
        let elsewhere = Bump::Water(eps).apply(DVec3::Y, DVec3::new(3.6, 0.01, -2.2));
        assert_ne!(got, elsewhere);
    }
}
