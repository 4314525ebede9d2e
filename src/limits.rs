//! Every limit the library enforces, defined once: image sizes, counts, light intensity,
//! supersampling and motion-blur samples, frame counts and coordinate magnitudes. The
//! scene parser, the manifest and the animation pipeline all refer here.

/// The largest image side accepted.
pub const MAX_SIDE: u32 = 16384;
/// The largest pixel count accepted (2^26: 201 MB of RGB bytes, more in the float pipeline).
pub const MAX_PIXELS: u64 = 1 << 26;
/// The brightest light accepted. The report's intensities are 0..1 (IV.2); brighter ones
/// are allowed, within a bound that keeps every sum of light finite.
pub const MAX_INTENSITY: f64 = 1000.0;
/// The largest count of each kind of object or light.
pub const MAX_COUNT: u64 = 1_000_000;
/// The largest n of an n×n supersampling grid.
pub const MAX_SAMPLES: u32 = 16;
/// The most sub-frames a motion-blurred frame may average.
pub const MAX_BLUR_SAMPLES: u32 = 64;
/// The most frames a manifest may ask for.
pub const MAX_FRAMES: u32 = 1_000_000;
/// The largest coordinate magnitude a camera key, look-at point or circle accepts; keeps
/// every distance and knot finite.
pub const MAX_COORD: f64 = 1e9;
/// The largest number of turns a circle accepts (keeps turns·frame finite).
pub const MAX_TURNS: f64 = 1e6;

/// Whether `width`×`height` is a size the renderer accepts.
pub fn size_ok(width: u64, height: u64) -> bool {
    (1..=u64::from(MAX_SIDE)).contains(&width)
        && (1..=u64::from(MAX_SIDE)).contains(&height)
        && width * height <= MAX_PIXELS
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes() {
        assert!(size_ok(640, 480));
        assert!(size_ok(16384, 4096)); // exactly 2^26
        assert!(!size_ok(16384, 4097));
        assert!(!size_ok(0, 10));
        assert!(!size_ok(16385, 1));
    }
}
