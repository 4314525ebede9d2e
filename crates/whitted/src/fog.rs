//! White fog (report V.3, SPEC §2), by the distance d from the camera to the primary hit.
//!
//! colour = C·(1 − f) + white·f, applied to the final unclamped colour of a primary ray:
//! - type 1, linear: f = min(d/D, 1) (the report's formula swaps C and the fog; its text,
//!   "fog grows steadily and is total from D on", is what this follows)
//! - type 2, exponential: f = 1 − e^(−d/D)
//! - type 3, exponential squared: f = 1 − e^(−(d/D)²)
//!
//! A primary ray that hits nothing has d = ∞: black without fog, white with it.

use crate::base::Color;

/// The scene's fog: type and distance D.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Fog {
    /// Type 0: no fog.
    None,
    /// Type 1, linear: f = d/D, full fog from distance D on.
    Linear(f64),
    /// Type 2, exponential: f = 1 − e^(−d/D).
    Exponential(f64),
    /// Type 3, exponential squared: f = 1 − e^(−(d/D)²).
    ExponentialSquared(f64),
}

impl Fog {
    /// The fog fraction f in 0..1 at distance `d` (∞ allowed).
    pub fn amount(&self, d: f64) -> f64 {
        match *self {
            Fog::None => 0.0,
            Fog::Linear(dist) => (d / dist).min(1.0),
            Fog::Exponential(dist) => 1.0 - libm::exp(-d / dist),
            Fog::ExponentialSquared(dist) => 1.0 - libm::exp(-(d / dist).powi(2)),
        }
    }

    /// The colour `c` seen through the fog at distance `d`.
    #[inline]
    pub fn apply(&self, c: Color, d: f64) -> Color {
        if let Fog::None = self {
            return c;
        }
        let f = self.amount(d);
        c * (1.0 - f) + Color::ONE * f
    }

    /// `apply` with the fraction already known: `f` = `self.amount(d)` gives the same
    /// bits as `self.apply(c, d)` (the recording path hears f and then applies it).
    #[inline]
    pub fn apply_amount(&self, c: Color, f: f64) -> Color {
        if let Fog::None = self {
            return c;
        }
        c * (1.0 - f) + Color::ONE * f
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn linear_by_hand() {
        let fog = Fog::Linear(10.0);
        assert_eq!(fog.amount(0.0), 0.0);
        assert_eq!(fog.amount(2.5), 0.25);
        assert_eq!(fog.amount(10.0), 1.0);
        assert_eq!(fog.amount(30.0), 1.0);
        // A red object at a quarter of D: 0.75·red + 0.25·white.
        let c = fog.apply(Color::new(1.0, 0.0, 0.0), 2.5);
        assert_eq!(c, Color::new(1.0, 0.25, 0.25));
    }

    #[test]
    fn exponential_by_hand() {
        let fog = Fog::Exponential(10.0);
        // d = D: f = 1 − 1/e = 0.6321205588285577.
        assert!((fog.amount(10.0) - 0.6321205588285577).abs() < 1e-15);
        // d = 5D: f = 1 − e^−5 = 0.9932620530009145, "total at 5·D" in the report's words.
        assert!((fog.amount(50.0) - 0.9932620530009145).abs() < 1e-15);
    }

    #[test]
    fn exponential_squared_by_hand() {
        let fog = Fog::ExponentialSquared(10.0);
        // d = D/2: f = 1 − e^−0.25 = 0.22119921692859512; d = 2D: 1 − e^−4 = 0.9816843611112658.
        assert!((fog.amount(5.0) - 0.22119921692859512).abs() < 1e-15);
        assert!((fog.amount(20.0) - 0.9816843611112658).abs() < 1e-15);
    }

    #[test]
    fn nothing_hit_is_white_in_fog_and_black_without() {
        let black = Color::ZERO;
        for fog in [
            Fog::Linear(3.0),
            Fog::Exponential(3.0),
            Fog::ExponentialSquared(3.0),
        ] {
            assert_eq!(fog.apply(black, f64::INFINITY), Color::ONE);
        }
        assert_eq!(Fog::None.apply(black, f64::INFINITY), black);
    }

    #[test]
    fn apply_amount_is_apply() {
        // The same bits as `apply` for every fog, including −0.0 without fog.
        let fogs = [
            Fog::None,
            Fog::Linear(3.0),
            Fog::Exponential(3.0),
            Fog::ExponentialSquared(3.0),
        ];
        let c = Color::new(-0.0, 0.3, 2.5);
        for fog in fogs {
            for d in [0.0, 1.7, 3.0, 40.0, f64::INFINITY] {
                let (a, b) = (fog.apply(c, d), fog.apply_amount(c, fog.amount(d)));
                assert_eq!(
                    a.to_array().map(f64::to_bits),
                    b.to_array().map(f64::to_bits)
                );
            }
        }
        // By hand: linear fog 3 at d = 1.5 is f = 0.5: 0.5·c + 0.5.
        let half = Fog::Linear(3.0).apply_amount(Color::new(1.0, 0.0, 0.5), 0.5);
        assert_eq!(half, Color::new(1.0, 0.5, 0.75));
    }

    #[test]
    fn unclamped_colour_goes_in() {
        // Fog mixes the unclamped colour: 2.0 at half linear fog gives 1.5, clamped later.
        let c = Fog::Linear(2.0).apply(Color::splat(2.0), 1.0);
        assert_eq!(c, Color::splat(1.5));
    }
}
