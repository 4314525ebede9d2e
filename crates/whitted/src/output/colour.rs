//! How the tracer's colours are stored in float frames (SPEC §12): the report's values are
//! display values (its PNG byte is round(255·v), shown as sRGB), so an EXR's beauty holds
//! them decoded to linear light with the sRGB transfer function (`Transfer::Srgb`, the
//! default), or as they are (`Transfer::Linear`, `[output] colour = "linear"`).
//!
//! - `decode` is the sRGB EOTF (IEC 61966-2-1): v/12.92 up to 0.04045, else
//!   ((v + 0.055)/1.055)^2.4; `encode` its inverse. Both extend past 1 along the same
//!   curve (the beauty is not clamped) and are odd below 0.
//! - `Transfer::store` / `Transfer::shown`: a value as a file stores it, and a stored value as
//!   the display value it stands for (what the 8-bit formats, `check` and the video take).
//! - `keeping_byte`: the stored half (or float) nearest the exact one whose display
//!   value's clamp-and-round is the tracer's byte, so an EXR frame converted to sRGB gives
//!   the PNG's bytes exactly (one sample, no motion blur).
//! - `follow_beauty`: the colour passes follow the beauty: the light split is scaled per
//!   pixel and channel by stored/display of the beauty, and so are the `background`
//!   and `emission` layers (so the layers still sum to the stored beauty and keep their shares), the albedo (a texture's display colour)
//!   is decoded like a colour; depth, position, normal and Cryptomatte are not colours
//!   and stay as they are.

use crate::base::srgb::{decode, Transfer};
use crate::base::{to_byte, Color};
use crate::passes::{Channel, Pass};
use exr::prelude::f16;

/// The float nearest `colour.store(c)` whose byte (`Transfer::byte`) is `c`'s.
pub fn float_keeping_byte(c: f64, colour: Transfer) -> f32 {
    let (want, exact) = (to_byte(c), colour.store(c));
    let mut v = exact as f32;
    for _ in 0..8 {
        if colour.byte(f64::from(v)) == want {
            break;
        }
        v = if f64::from(v) < exact {
            v.next_up()
        } else {
            v.next_down()
        };
    }
    v
}

/// The half nearest `colour.store(c)` whose byte is `c`'s (halves are at least 8 to a
/// byte's width of 1/255 below 1, and finer in linear light, so there always is one).
pub fn half_keeping_byte(c: f64, colour: Transfer) -> f16 {
    let (want, exact) = (to_byte(c), colour.store(c));
    let mut v = f16::from_f64(exact);
    for _ in 0..8 {
        let x = v.to_f64();
        if colour.byte(x) == want || !x.is_finite() {
            break;
        }
        // Halves of one sign are ordered like their bits' magnitudes.
        let up = x < exact;
        let bits = v.to_bits();
        let away_from_zero = up == (x >= 0.0);
        v = match (away_from_zero, bits & 0x7fff) {
            (true, _) => f16::from_bits(bits + 1),
            (false, 0) => f16::from_bits(if up { 0x0001 } else { 0x8001 }),
            (false, _) => f16::from_bits(bits - 1),
        };
    }
    v
}

/// The light split's and the albedo's channels of a frame whose display beauty is
/// `beauty`, made to follow the beauty's encoding `colour` (see the module's text).
pub fn follow_beauty(channels: &mut [Channel], beauty: &[Color], colour: Transfer) {
    if colour == Transfer::Linear {
        return;
    }
    let mut light: Vec<String> = Pass::LIGHT.iter().flat_map(|p| p.channels()).collect();
    light.extend(crate::passes::record::BACKGROUND.map(String::from));
    light.extend(crate::passes::record::EMISSION.map(String::from));
    for ch in channels.iter_mut() {
        let Some(axis) = ["R", "G", "B"]
            .iter()
            .position(|a| ch.name.ends_with(&format!(".{a}")))
        else {
            continue;
        };
        if light.contains(&ch.name) {
            for (v, b) in ch.values.iter_mut().zip(beauty) {
                *v = (f64::from(*v) * ratio(b[axis])) as f32;
            }
        } else if ch.name.starts_with("albedo.") {
            for v in ch.values.iter_mut() {
                *v = decode(f64::from(*v)) as f32;
            }
        }
    }
}

/// decode(b)/b, the scale that takes a display value's parts to its linear value's (the
/// slope at 0, 1/12.92, where b is 0).
fn ratio(b: f64) -> f64 {
    if b.abs() < 1e-300 {
        1.0 / 12.92
    } else {
        decode(b) / b
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stored_values_keep_their_byte_in_both_encodings() {
        for colour in [Transfer::Srgb, Transfer::Linear] {
            for k in 0..=2550 {
                let c = (k as f64 + 0.5) / 2550.0 * 1.1 - 0.05;
                for c in [
                    c,
                    (k as f64 / 10.0 + 0.5) / 255.0,
                    ((k as f64 / 10.0 + 0.5) / 255.0).next_down(),
                ] {
                    let (want, exact) = (to_byte(c), colour.store(c));
                    let h = half_keeping_byte(c, colour);
                    assert_eq!(colour.byte(h.to_f64()), want, "{colour:?} {c:e} → half {h}");
                    let tol = 2.0 * (exact.abs() * 2f64.powi(-11) + 6e-8);
                    assert!((h.to_f64() - exact).abs() <= tol, "{c} {h}");
                    let f = float_keeping_byte(c, colour);
                    assert_eq!(colour.byte(f64::from(f)), want, "{colour:?} {c:e} → {f}");
                    let tol = 4.0 * exact.abs() * 2f64.powi(-24) + 1e-40;
                    assert!((f64::from(f) - exact).abs() <= tol, "{c} {f}");
                }
            }
        }
        assert_eq!(half_keeping_byte(3.0, Transfer::Linear).to_f64(), 3.0);
    }

    #[test]
    fn the_light_split_is_scaled_to_sum_to_the_decoded_beauty() {
        // One pixel, beauty (0.5, 0, 1): ambient 0.1 + diffuse 0.4 in red sum to 0.5,
        // and must sum to 0.214041 once decoded; albedo 0.5 decodes alike; Z stays.
        let ch = |name: &str, v: f32| Channel {
            name: name.into(),
            values: vec![v],
        };
        let mut chans = vec![
            ch("Z", 0.5),
            ch("ambient.R", 0.1),
            ch("diffuse.R", 0.4),
            ch("ambient.B", 1.0),
            ch("albedo.G", 0.5),
            ch("N.X", 0.5),
        ];
        let beauty = [Color::new(0.5, 0.0, 1.0)];
        follow_beauty(&mut chans, &beauty, Transfer::Srgb);
        let sum = f64::from(chans[1].values[0]) + f64::from(chans[2].values[0]);
        assert!((sum - 0.214_041_14).abs() < 1e-7, "{sum}");
        assert!((f64::from(chans[1].values[0]) - 0.1 * 0.428_082_28).abs() < 1e-7);
        assert_eq!(chans[3].values[0], 1.0);
        assert!((f64::from(chans[4].values[0]) - 0.214_041_14).abs() < 1e-7);
        assert_eq!((chans[0].values[0], chans[5].values[0]), (0.5, 0.5));
        let before = chans.clone();
        follow_beauty(&mut chans, &beauty, Transfer::Linear);
        assert_eq!(chans, before);
    }
}
