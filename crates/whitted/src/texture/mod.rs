//! Solid textures (report V.1, SPEC §2): the object's colour C at a world point.
//!
//! In Scene.txt a texture is `1 R G B` (one colour) or
//! `2 Type C1r C1g C1b C2r C2g C2b C3r C3g C3b` with Type 1 checker, 2 Perlin, 3 wood,
//! 4 marble. All of them are evaluated at the world hit point, so no mapping coordinates
//! are needed.
//!
//! - checker: ⌊x+1e-4⌋ + ⌊y+1e-4⌋ + ⌊z+1e-4⌋ even → C1, odd → C2 (unit squares; C3 unused)
//! - Perlin: n = clamp((noise(p)+1)/2, 0, 1) on a ramp C1 at 0, C2 at ½, C3 at 1
//! - wood: T = 20·noise(p), n = T − ⌊T⌋, f = (1 − cos πn)/2, C = C1(1−f) + C2·f
//! - marble: n = (1 + cos(x + noise(p)))/2, C = C1(1−n) + C2·n
//!
//! A procedural texture may be scaled (`Scaled`, from an animation's `texture_scale`
//! track; no Scene.txt syntax): evaluated at p/s, its pattern is s times larger, about
//! the world's origin. Scale 1 is the texture itself, not wrapped, so every picture
//! without a scale keeps its bytes.
//!
//! The third form, `3 "file" Map Interp Size` (SPEC §16), maps an image onto its object
//! (`image`, `map`, `load`): it needs the object's shape, so `Object::color_at` is what
//! the tracer asks.

mod faces;
mod image;
mod load;
pub mod map;
mod map_kind;

pub use self::image::{ImageTexture, Interp, Pixels, Wrap};
pub use load::{from_bytes, load};
pub use map_kind::MapKind;

use crate::noise::{floor, noise};
use glam::DVec3;
use std::sync::Arc;

use crate::base::Color;

/// Offset that keeps the plane y = 0 from flickering between checker squares.
pub const CHECKER_OFFSET: f64 = 1e-4;

/// `s.rem_euclid(2.0) == 0.0` for a whole number `s` (the checker's parity, negative sums
/// included), without the fmod call: s/2 is whole exactly when s is even (every float past
/// 2^53 is even, as rem_euclid says too); infinities and NaN are odd, as rem_euclid's NaN.
#[inline(always)]
fn is_even(s: f64) -> bool {
    let h = s * 0.5;
    s.is_finite() && floor(h) == h
}

/// The colour pattern of an object.
#[derive(Clone, Debug, PartialEq)]
pub enum Texture {
    /// `1 R G B`: one colour everywhere.
    Uniform(Color),
    /// `2 1 …`: a checker of the two colours.
    Checker(Color, Color),
    /// `2 2 …`: Perlin noise blending the three colours.
    Perlin(Color, Color, Color),
    /// `2 3 …`: wood rings between the two colours.
    Wood(Color, Color),
    /// `2 4 …`: marble veins between the two colours.
    Marble(Color, Color),
    /// `3 "file" Map Interp Size`: an image mapped onto the object.
    Image(Arc<ImageTexture>),
    /// A procedural texture (checker, Perlin, wood, marble) evaluated at p/s: its pattern
    /// s times larger (s > 0, never 1: see `scaled`).
    Scaled(Box<Texture>, f64),
}

impl Texture {
    /// The texture as records name it: its kind (`uniform`, `checker`, `perlin`, `wood`,
    /// `marble`, `image`), its number in that order from 1, and its colours as the file
    /// gives them (none for an image).
    pub fn record(&self) -> (&'static str, u8, Vec<Color>) {
        match *self {
            Texture::Uniform(c) => ("uniform", 1, vec![c]),
            Texture::Checker(a, b) => ("checker", 2, vec![a, b]),
            Texture::Perlin(a, b, c) => ("perlin", 3, vec![a, b, c]),
            Texture::Wood(a, b) => ("wood", 4, vec![a, b]),
            Texture::Marble(a, b) => ("marble", 5, vec![a, b]),
            Texture::Image(_) => ("image", 6, vec![]),
            Texture::Scaled(ref t, _) => t.record(),
        }
    }

    /// Whether the texture is a pattern that can be scaled: checker, Perlin, wood, marble.
    pub fn is_procedural(&self) -> bool {
        !matches!(self, Texture::Uniform(_) | Texture::Image(_))
    }

    /// The pattern's scale: s of `Scaled`, else 1.
    pub fn scale(&self) -> f64 {
        match self {
            Texture::Scaled(_, s) => *s,
            _ => 1.0,
        }
    }

    /// The texture without its scale.
    pub fn pattern(&self) -> &Texture {
        match self {
            Texture::Scaled(t, _) => t,
            t => t,
        }
    }

    /// The texture without its scale, to change its colours.
    pub fn pattern_mut(&mut self) -> &mut Texture {
        match self {
            Texture::Scaled(t, _) => t,
            t => t,
        }
    }

    /// This texture's pattern at scale `s`: itself, unwrapped, at 1; a one-colour or image
    /// texture is returned as it is (it has no pattern to scale).
    pub fn scaled(self, s: f64) -> Texture {
        let pattern = match self {
            Texture::Scaled(t, _) => *t,
            t => t,
        };
        match s == 1.0 || !pattern.is_procedural() {
            true => pattern,
            false => Texture::Scaled(Box::new(pattern), s),
        }
    }

    /// The colour at world point `p`. `#[inline]`, as before the passes: as
    /// `#[inline(never)]` it was one exported function with the C calling convention (the
    /// return slot's address handed back, `noisy_at` called instead of jumped to), and
    /// with `Accel::transmission` inlined again, inlining it into both glass loops of
    /// `shading::direct` takes 9.5 M instructions off `direct` + `color_at` on the orbit at
    /// one thread (callgrind).
    ///
    /// An image texture needs its object's shape: `Object::color_at` answers for it (here
    /// it is black).
    #[inline]
    pub fn color_at(&self, p: DVec3) -> Color {
        // The two cheap kinds by conditional branches, which are predicted from their
        // history: a jump table over the kinds met in turn along a pixel's rays (a
        // checker floor, then a uniform sky, …) is mispredicted most of the time.
        if let Texture::Uniform(c) = *self {
            return c;
        }
        if let Texture::Checker(c1, c2) = *self {
            let q = p + DVec3::splat(CHECKER_OFFSET);
            let s = floor(q.x) + floor(q.y) + floor(q.z);
            return if is_even(s) { c1 } else { c2 };
        }
        self.noisy_at(p)
    }

    /// `color_at` for the noise textures.
    #[inline(never)]
    fn noisy_at(&self, p: DVec3) -> Color {
        match *self {
            Texture::Perlin(c1, c2, c3) => {
                let n = ((noise(p.x, p.y, p.z) + 1.0) / 2.0).clamp(0.0, 1.0);
                if n < 0.5 {
                    c1.lerp(c2, n * 2.0)
                } else {
                    c2.lerp(c3, (n - 0.5) * 2.0)
                }
            }
            Texture::Wood(c1, c2) => {
                let t = 20.0 * noise(p.x, p.y, p.z);
                let n = t - floor(t);
                let f = (1.0 - libm::cos(std::f64::consts::PI * n)) / 2.0;
                c1 * (1.0 - f) + c2 * f
            }
            Texture::Marble(c1, c2) => {
                let n = (1.0 + libm::cos(p.x + noise(p.x, p.y, p.z))) / 2.0;
                c1 * (1.0 - n) + c2 * n
            }
            Texture::Scaled(ref t, s) => t.color_at(p / s),
            Texture::Uniform(c) | Texture::Checker(c, _) => c, // answered by `color_at`
            Texture::Image(_) => Color::ZERO,                  // answered by `Object::color_at`
        }
    }
}

#[cfg(test)]
#[allow(clippy::approx_constant)] // 3.14 is the reference input, not π
mod tests {
    use super::*;

    const RED: Color = DVec3::new(1.0, 0.0, 0.0);
    const BLUE: Color = DVec3::new(0.0, 0.0, 1.0);

    #[test]
    fn records_kind_number_and_colours() {
        assert_eq!(Texture::Uniform(RED).record(), ("uniform", 1, vec![RED]));
        assert_eq!(
            Texture::Checker(RED, BLUE).record(),
            ("checker", 2, vec![RED, BLUE])
        );
        let p = Texture::Perlin(RED, BLUE, Color::ONE).record();
        assert_eq!(p, ("perlin", 3, vec![RED, BLUE, Color::ONE]));
        assert_eq!(
            Texture::Wood(BLUE, RED).record(),
            ("wood", 4, vec![BLUE, RED])
        );
        assert_eq!(
            Texture::Marble(RED, RED).record(),
            ("marble", 5, vec![RED, RED])
        );
    }
    const GREEN: Color = DVec3::new(0.0, 1.0, 0.0);

    fn close(a: Color, b: Color) -> bool {
        (a - b).length() < 1e-12
    }

    #[test]
    fn checker_squares_and_the_floor_offset() {
        let t = Texture::Checker(RED, BLUE);
        assert_eq!(t.color_at(DVec3::new(0.5, 0.0, 0.5)), RED); // 0+0+0
        assert_eq!(t.color_at(DVec3::new(1.5, 0.0, 0.5)), BLUE); // 1+0+0
        assert_eq!(t.color_at(DVec3::new(-0.5, 0.0, 0.5)), BLUE); // −1+0+0, odd
        assert_eq!(t.color_at(DVec3::new(-0.5, 0.0, -0.5)), RED); // −2, even
                                                                  // A floor point computed as y = −1e-9 would flicker without the offset.
        assert_eq!(t.color_at(DVec3::new(0.5, -1e-9, 0.5)), RED);
        assert_eq!(t.color_at(DVec3::new(0.5, 1e-9, 0.5)), RED);
    }

    #[test]
    fn a_scaled_pattern_is_the_pattern_at_p_over_s() {
        // Scale 2: the checker's unit squares become 2 wide; (1.5, 0, 0.5) is (0.75, 0,
        // 0.25) of the pattern (sum 0, RED) where the unscaled checker is BLUE (sum 1).
        let t = Texture::Checker(RED, BLUE).scaled(2.0);
        assert_eq!(t.color_at(DVec3::new(1.5, 0.0, 0.5)), RED);
        assert_eq!(t.color_at(DVec3::new(2.5, 0.0, 0.5)), BLUE);
        let plain = Texture::Checker(RED, BLUE);
        assert_eq!(plain.color_at(DVec3::new(1.5, 0.0, 0.5)), BLUE);
        // Wood at half scale: the pattern at 2p.
        let wood = Texture::Wood(RED, BLUE);
        let p = DVec3::new(1.57, 21.0, 3.5);
        assert_eq!(wood.clone().scaled(0.5).color_at(p), wood.color_at(2.0 * p));
        // Scale 1 unwraps; a scale is replaced, not stacked; one colour has no pattern.
        assert_eq!(t.clone().scaled(1.0), Texture::Checker(RED, BLUE));
        assert_eq!(t.clone().scaled(3.0).scale(), 3.0);
        assert_eq!(t.pattern(), &Texture::Checker(RED, BLUE));
        assert_eq!(t.record(), Texture::Checker(RED, BLUE).record());
        assert_eq!(Texture::Uniform(RED).scaled(2.0), Texture::Uniform(RED));
    }

    #[test]
    fn perlin_ramp_at_lattice_points_is_c2() {
        // noise = 0 at integer points: n = 0.5, exactly the middle stop C2.
        let t = Texture::Perlin(RED, GREEN, BLUE);
        assert_eq!(t.color_at(DVec3::new(3.0, -2.0, 7.0)), GREEN);
    }

    #[test]
    fn perlin_ramp_at_the_reference_point() {
        // noise(3.14, 42, 7) = 0.13691995878400012: n = 0.568459979392, upper half of the
        // ramp, f = (n − 0.5)·2 = 0.136919958784 from C2 towards C3.
        let t = Texture::Perlin(RED, GREEN, BLUE);
        let c = t.color_at(DVec3::new(3.14, 42.0, 7.0));
        let f = 0.13691995878400012;
        assert!(close(c, DVec3::new(0.0, 1.0 - f, f)), "{c}");
    }

    #[test]
    fn wood_by_hand() {
        // At the reference point T = 2.7383991756800024, n = 0.7383991756800024,
        // f = (1 − cos(0.7383991756800024 π))/2 = 0.8397..; at a lattice point T = 0, f = 0.
        let t = Texture::Wood(RED, BLUE);
        assert_eq!(t.color_at(DVec3::new(1.0, 2.0, 3.0)), RED);
        let n: f64 = 0.7383991756800024;
        let f = (1.0 - libm::cos(std::f64::consts::PI * n)) / 2.0;
        assert!((f - 0.8397).abs() < 1e-3);
        let c = t.color_at(DVec3::new(3.14, 42.0, 7.0));
        assert!(close(c, DVec3::new(1.0 - f, 0.0, f)), "{c}");
    }

    #[test]
    fn marble_by_hand() {
        // At a lattice point with x = 0: n = (1 + cos 0)/2 = 1 → C2. With x = π: n = 0 → C1
        // (π is not a lattice point, so take x = 2 where noise = 0: n = (1 + cos 2)/2).
        let t = Texture::Marble(RED, BLUE);
        assert_eq!(t.color_at(DVec3::new(0.0, 5.0, 5.0)), BLUE);
        let n = (1.0 + 2f64.cos()) / 2.0; // 0.29192658172642888
        let c = t.color_at(DVec3::new(2.0, 1.0, 1.0));
        assert!(close(c, DVec3::new(1.0 - n, 0.0, n)), "{c}");
        assert!((n - 0.2919265817264289).abs() < 1e-15);
    }

    #[test]
    fn is_even_is_rem_euclid_parity() {
        let mut xs: Vec<f64> = (-2000..2000).map(|k| k as f64).collect();
        for e in [52, 53, 54, 60, 100, 1023] {
            let b = 2f64.powi(e);
            xs.extend([b, -b, b - 1.0, b + 1.0, b + 2.0, -(b - 1.0), -(b + 2.0)]);
        }
        xs.extend([
            -0.0,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
            f64::MAX,
            f64::MIN,
        ]);
        for s in xs {
            assert_eq!(is_even(s), s.rem_euclid(2.0) == 0.0, "{s:e}");
        }
    }

    #[test]
    fn uniform_is_constant() {
        let t = Texture::Uniform(GREEN);
        assert_eq!(t.color_at(DVec3::new(9.0, -3.0, 0.1)), GREEN);
    }
}
