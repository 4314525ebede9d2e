//! The sRGB transfer curve (IEC 61966-2-1) and the two ways a float frame stores the
//! tracer's colours (SPEC §12).
//!
//! - `decode` is the sRGB EOTF: v/12.92 up to 0.04045, else ((v + 0.055)/1.055)^2.4;
//!   `encode` its inverse. Both extend past 1 along the same curve and are odd below 0.
//! - `Transfer::Srgb` (the default) stores the report's display values decoded to linear
//!   light; `Transfer::Linear` stores them as they are. `ATTRIBUTE` names the EXR header
//!   attribute that records which.

use super::to_byte;

/// How an EXR stores the tracer's colours (`[output] colour`, `raytrace --colour`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Transfer {
    /// The display values decoded to linear light with the sRGB EOTF (the default): a
    /// compositor's sRGB view shows the PNG's look.
    #[default]
    Srgb,
    /// The tracer's values as they are (`round(255·clamp(v))` is the PNG's byte).
    Linear,
}

/// The name of the header attribute that says which (`srgb` or `linear`); a frame
/// without it was written before it existed, with the values as they are.
pub const ATTRIBUTE: &str = "whitted:colour";

impl Transfer {
    /// The names a manifest or the command line accepts.
    pub const NAMES: [&'static str; 2] = ["srgb", "linear"];

    /// The encoding a name gives.
    pub fn from_name(name: &str) -> Option<Transfer> {
        match name {
            "srgb" => Some(Transfer::Srgb),
            "linear" => Some(Transfer::Linear),
            _ => None,
        }
    }

    /// Its name, as the header attribute records it.
    pub fn name(self) -> &'static str {
        match self {
            Transfer::Srgb => "srgb",
            Transfer::Linear => "linear",
        }
    }

    /// The value a file stores for the display value `v`.
    pub fn store(self, v: f64) -> f64 {
        match self {
            Transfer::Srgb => decode(v),
            Transfer::Linear => v,
        }
    }

    /// The display value a stored value `v` stands for.
    pub fn shown(self, v: f64) -> f64 {
        match self {
            Transfer::Srgb => encode(v),
            Transfer::Linear => v,
        }
    }

    /// The byte a stored value shows: the clamp-and-round of its display value.
    pub fn byte(self, v: f64) -> u8 {
        to_byte(self.shown(v))
    }
}

/// A linear-light colour (a glTF scene's, SPEC §18) as the display value the frame
/// stores: each channel sRGB-encoded (negative values, which no term makes, map to 0).
#[cold]
#[inline(never)]
pub fn display(c: super::Color) -> super::Color {
    super::Color::new(
        encode(c.x.max(0.0)),
        encode(c.y.max(0.0)),
        encode(c.z.max(0.0)),
    )
}

/// The sRGB EOTF: a display value to linear light.
pub fn decode(v: f64) -> f64 {
    let a = v.abs();
    let lin = if a <= 0.04045 {
        a / 12.92
    } else {
        ((a + 0.055) / 1.055).powf(2.4)
    };
    lin.copysign(v)
}

/// The inverse of `decode`: linear light to a display value.
pub fn encode(v: f64) -> f64 {
    let a = v.abs();
    let shown = if a <= 0.0031308 {
        a * 12.92
    } else {
        1.055 * a.powf(1.0 / 2.4) - 0.055
    };
    shown.copysign(v)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_srgb_curve_at_hand_computed_points() {
        // ((0.5 + 0.055)/1.055)^2.4 = 0.526066^2.4 = 0.214041 (IEC 61966-2-1).
        assert!(
            (decode(0.5) - 0.214_041_140_5).abs() < 1e-9,
            "{}",
            decode(0.5)
        );
        // The linear toe: 0.02/12.92; the knee meets within 1e-7.
        assert_eq!(decode(0.02), 0.02 / 12.92);
        assert!((decode(0.04045) - 0.0031308).abs() < 1e-7);
        assert_eq!((decode(0.0), decode(1.0)), (0.0, 1.0));
        // Past 1 along the curve: ((2 + 0.055)/1.055)^2.4 = 1.947867^2.4
        // = e^(2.4·0.666710) = e^1.600104 = 4.95385.
        assert!((decode(2.0) - 4.953_85).abs() < 1e-5, "{}", decode(2.0));
        assert_eq!(decode(-0.5), -decode(0.5));
        for k in -100..=400 {
            let v = f64::from(k) / 200.0;
            assert!((encode(decode(v)) - v).abs() < 1e-12, "{v}");
        }
    }
}
