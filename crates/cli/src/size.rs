//! The `WIDTHxHEIGHT` value of `raytrace --size` and `animate --size`: two whole numbers
//! separated by `x` or `X`, within the tracer's image limits (`whitted::limits::size_ok`:
//! 16384 a side, 2^26 pixels).

/// The size `s` names, or the message clap shows for it.
pub fn parse_size(s: &str) -> Result<(u32, u32), String> {
    let bad = || format!("expected WIDTHxHEIGHT within 16384 a side and 2^26 pixels, found {s:?}");
    let (w, h) = s.split_once(['x', 'X']).ok_or_else(bad)?;
    let (w, h): (u32, u32) = (w.parse().map_err(|_| bad())?, h.parse().map_err(|_| bad())?);
    whitted::limits::size_ok(w.into(), h.into())
        .then_some((w, h))
        .ok_or_else(bad)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_by_hand() {
        assert_eq!(parse_size("640x480"), Ok((640, 480)));
        assert_eq!(parse_size("32X24"), Ok((32, 24)));
        // 16384 a side is the limit; 16384 × 4096 = 2^26 pixels is the most.
        assert_eq!(parse_size("16384x4096"), Ok((16384, 4096)));
        for bad in ["16385x1", "16384x4097", "0x10", "10", "ax3", "3x", "-1x4"] {
            let e = parse_size(bad).unwrap_err();
            assert!(e.contains("WIDTHxHEIGHT") && e.contains(bad), "{bad}: {e}");
        }
    }
}
