//! An 8-bit RGB image (`Frame`) and the clamp-and-round that turns the tracer's colours
//! into its bytes (SPEC §2: `round(255·clamp(c, 0, 1))`, half away from zero; NaN is 0).
//! Every writer, reader and pass of the crate takes its pixels from here.

use super::Color;

/// An 8-bit RGB image, rows top to bottom.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Frame {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// width·height·3 bytes.
    pub pixels: Vec<u8>,
}

/// A colour's three bytes, each channel as `to_byte` rounds it.
#[inline]
pub fn to_rgb(c: Color) -> [u8; 3] {
    [to_byte(c.x), to_byte(c.y), to_byte(c.z)]
}

/// Clamp to 0..1, then round(255·c).
#[inline]
pub fn to_byte(c: f64) -> u8 {
    // round(v) for v in 0..=255 (half away from zero) without the libm call `f64::round`
    // is on a baseline x86-64: truncate, then add one when the fraction (exact: v − ⌊v⌋
    // loses nothing here) is at least one half. NaN clamps to NaN, which `as u32` makes 0
    // and the comparison leaves there: a broken pixel is black, never a panic.
    let v = c.clamp(0.0, 1.0) * 255.0;
    let t = v as u32;
    (if v - t as f64 >= 0.5 { t + 1 } else { t }) as u8
}

impl Frame {
    /// The frame of `colors` (width·height, rows top to bottom), each channel through the
    /// clamp-and-round of SPEC §2 (`to_byte`).
    pub fn from_colors(colors: impl IntoIterator<Item = Color>, width: u32, height: u32) -> Frame {
        let pixels = colors.into_iter().flat_map(to_rgb).collect();
        Frame {
            width,
            height,
            pixels,
        }
    }

    /// The frame whose pixels are `sum / count`, rounded as every pixel is (`to_byte`).
    pub fn from_sum(sum: &[Color], count: u32, width: u32, height: u32) -> Frame {
        let k = f64::from(count.max(1));
        Frame::from_colors(sum.iter().map(|c| *c / k), width, height)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn clamp_then_round() {
        assert_eq!(to_byte(-0.5), 0);
        assert_eq!(to_byte(0.0), 0);
        assert_eq!(to_byte(1.0), 255);
        assert_eq!(to_byte(3.7), 255);
        // 255·0.5 = 127.5 rounds half away from zero to 128.
        assert_eq!(to_byte(0.5), 128);
        // 255·0.2 = 51.00000000000001 → 51; 255·0.1 = 25.5 → 26.
        assert_eq!(to_byte(0.2), 51);
        assert_eq!(to_byte(0.1), 26);
        assert_eq!(to_rgb(Color::new(0.1, 0.5, 3.7)), [26, 128, 255]);
        assert_eq!(to_byte(f64::NAN), 0);
    }

    #[test]
    fn from_sum_divides_then_rounds() {
        // Two sub-frames of 0.2 and 0.3: mean 0.25, 255·0.25 = 63.75 → 64.
        let sum = [Color::new(0.5, 0.0, 2.0)];
        assert_eq!(Frame::from_sum(&sum, 2, 1, 1).pixels, vec![64, 0, 255]);
    }

    #[test]
    fn same_bytes_as_clamp_times_255_round() {
        let reference = |c: f64| (c.clamp(0.0, 1.0) * 255.0).round() as u8;
        let mut cs = vec![
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
            -0.0,
            0.0,
            1.0,
            2.0,
        ];
        for k in 0..=512 {
            // Every half step of 1/255 and its neighbours, where rounding decides.
            let c = k as f64 / 510.0;
            cs.extend([c, c.next_up(), c.next_down(), (k as f64 + 0.5) / 255.0]);
        }
        for k in 0..200_000 {
            cs.push(k as f64 / 180_000.0 - 0.05);
        }
        for c in cs {
            assert_eq!(to_byte(c), reference(c), "{c:e}");
        }
    }
}
