//! `fade Distance Power` (SPEC §16, POV-Ray's `fade_distance` / `fade_power`): a light's
//! intensity times 2 / (1 + (d / Distance)^Power), d the distance to the light (to an
//! area light's centre). Not on a directional light (the reader refuses it).

/// A light's attenuation with distance.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fade {
    /// Where the factor is 1.
    pub distance: f64,
    /// How fast it falls.
    pub power: f64,
}

impl Fade {
    /// The factor on the intensity at distance `d`.
    #[inline]
    pub fn factor(&self, d: f64) -> f64 {
        2.0 / (1.0 + (d / self.distance).powf(self.power))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn factor_by_hand() {
        let f = Fade {
            distance: 5.0,
            power: 2.0,
        };
        assert_eq!(f.factor(5.0), 1.0);
        assert_eq!(f.factor(0.0), 2.0);
        // d = 10: 2 / (1 + 4) = 0.4.
        assert!((f.factor(10.0) - 0.4).abs() < 1e-15);
    }
}
