//! Ken Perlin's improved noise (2002), the `noise()` of the report's section V.1.2.
//!
//! This is a line-for-line port of Perlin's reference implementation
//! (`ImprovedNoise.java`): quintic fade, twelve gradient directions picked by the low four
//! bits of the hash, and his reference permutation. The range is about −1..1 and the
//! noise is zero at every integer lattice point. Textures (`texture.rs`) and bump mapping
//! (`bump.rs`) both read it.

/// Ken Perlin's reference permutation of 0..=255.
const PERMUTATION: [u8; 256] = [
    151, 160, 137, 91, 90, 15, 131, 13, 201, 95, 96, 53, 194, 233, 7, 225, 140, 36, 103, 30, 69,
    142, 8, 99, 37, 240, 21, 10, 23, 190, 6, 148, 247, 120, 234, 75, 0, 26, 197, 62, 94, 252, 219,
    203, 117, 35, 11, 32, 57, 177, 33, 88, 237, 149, 56, 87, 174, 20, 125, 136, 171, 168, 68, 175,
    74, 165, 71, 134, 139, 48, 27, 166, 77, 146, 158, 231, 83, 111, 229, 122, 60, 211, 133, 230,
    220, 105, 92, 41, 55, 46, 245, 40, 244, 102, 143, 54, 65, 25, 63, 161, 1, 216, 80, 73, 209, 76,
    132, 187, 208, 89, 18, 169, 200, 196, 135, 130, 116, 188, 159, 86, 164, 100, 109, 198, 173,
    186, 3, 64, 52, 217, 226, 250, 124, 123, 5, 202, 38, 147, 118, 126, 255, 82, 85, 212, 207, 206,
    59, 227, 47, 16, 58, 17, 182, 189, 28, 42, 223, 183, 170, 213, 119, 248, 152, 2, 44, 154, 163,
    70, 221, 153, 101, 155, 167, 43, 172, 9, 129, 22, 39, 253, 19, 98, 108, 110, 79, 113, 224, 232,
    178, 185, 112, 104, 218, 246, 97, 228, 251, 34, 242, 193, 238, 210, 144, 12, 191, 179, 162,
    241, 81, 51, 145, 235, 249, 14, 239, 107, 49, 192, 214, 31, 181, 199, 106, 157, 184, 84, 204,
    176, 115, 121, 50, 45, 127, 4, 150, 254, 138, 236, 205, 93, 222, 114, 67, 29, 24, 72, 243, 141,
    128, 195, 78, 66, 215, 61, 156, 180,
];

/// `p[i] = permutation[i mod 256]` for i in 0..512, as in the reference code.
#[inline]
fn p(i: usize) -> usize {
    PERMUTATION[i & 255] as usize
}

#[inline]
fn fade(t: f64) -> f64 {
    t * t * t * (t * (t * 6.0 - 15.0) + 10.0)
}

#[inline]
fn lerp(t: f64, a: f64, b: f64) -> f64 {
    a + t * (b - a)
}

/// The gradient of the reference code: one of 12 edge directions of a cube.
#[inline]
fn grad(hash: usize, x: f64, y: f64, z: f64) -> f64 {
    let h = hash & 15;
    let u = if h < 8 { x } else { y };
    let v = if h < 4 {
        y
    } else if h == 12 || h == 14 {
        x
    } else {
        z
    };
    (if h & 1 == 0 { u } else { -u }) + (if h & 2 == 0 { v } else { -v })
}

/// `x.floor()`, bit for bit (signed zeros, infinities and NaN included), without the
/// libm call that `f64::floor` is on a baseline x86-64 (no SSE4.1 `roundsd`): below 2^52
/// in magnitude `x as i64` truncates exactly, and one step down fixes negative fractions.
#[inline(always)]
pub fn floor(x: f64) -> f64 {
    if x.abs() < 4_503_599_627_370_496.0 {
        let t = x as i64 as f64;
        let f = if t > x { t - 1.0 } else { t };
        if f == 0.0 {
            // floor(−0) = −0, floor of [+0, 1) = +0.
            0.0f64.copysign(x)
        } else {
            f
        }
    } else {
        x.floor()
    }
}

/// Lattice cell index of a coordinate from its floor `f`, wrapped to 0..=255 like
/// `(int)floor(x) & 255`. Coordinates beyond ±2^53 (or not finite) fall back to cell 0:
/// the noise there is meaningless anyway, and this keeps the function total.
#[inline]
fn cell(f: f64) -> usize {
    if f.abs() < 9.0e15 {
        (f as i64 & 255) as usize
    } else {
        0
    }
}

/// Perlin's improved noise at (x, y, z). Deterministic, about −1..1, 0 at lattice points.
pub fn noise(x: f64, y: f64, z: f64) -> f64 {
    let (fx, fy, fz) = (floor(x), floor(y), floor(z));
    let (xi, yi, zi) = (cell(fx), cell(fy), cell(fz));
    let (x, y, z) = (x - fx, y - fy, z - fz);
    let (u, v, w) = (fade(x), fade(y), fade(z));
    let a = p(xi) + yi;
    let aa = p(a) + zi;
    let ab = p(a + 1) + zi;
    let b = p(xi + 1) + yi;
    let ba = p(b) + zi;
    let bb = p(b + 1) + zi;
    lerp(
        w,
        lerp(
            v,
            lerp(u, grad(p(aa), x, y, z), grad(p(ba), x - 1.0, y, z)),
            lerp(
                u,
                grad(p(ab), x, y - 1.0, z),
                grad(p(bb), x - 1.0, y - 1.0, z),
            ),
        ),
        lerp(
            v,
            lerp(
                u,
                grad(p(aa + 1), x, y, z - 1.0),
                grad(p(ba + 1), x - 1.0, y, z - 1.0),
            ),
            lerp(
                u,
                grad(p(ab + 1), x, y - 1.0, z - 1.0),
                grad(p(bb + 1), x - 1.0, y - 1.0, z - 1.0),
            ),
        ),
    )
}

#[cfg(test)]
#[allow(clippy::approx_constant)] // 3.14 is the reference input, not π
mod tests {
    use super::*;

    #[test]
    fn reference_value_of_perlins_java_code() {
        // The value ImprovedNoise.noise(3.14, 42, 7) prints in Java.
        assert_eq!(noise(3.14, 42.0, 7.0), 0.13691995878400012);
    }

    #[test]
    fn permutation_is_a_permutation() {
        let mut seen = [false; 256];
        for &v in PERMUTATION.iter() {
            assert!(!seen[v as usize], "{v} appears twice");
            seen[v as usize] = true;
        }
    }

    #[test]
    fn zero_on_the_integer_lattice() {
        for &(x, y, z) in &[(0.0, 0.0, 0.0), (1.0, 2.0, 3.0), (-5.0, 7.0, -11.0)] {
            assert_eq!(noise(x, y, z), 0.0);
        }
    }

    #[test]
    fn fade_and_grad_hand_values() {
        // fade(0.5) = 0.125 * (0.5 * (3 - 15) + 10) = 0.125 * 4 = 0.5
        assert_eq!(fade(0.5), 0.5);
        assert_eq!(fade(0.0), 0.0);
        assert_eq!(fade(1.0), 1.0);
        // hash 0: x + y; hash 13: -y + z (h >= 8 so u = y, h != 12/14 so v = z, h&1 negates u)
        assert_eq!(grad(0, 1.0, 2.0, 3.0), 3.0);
        assert_eq!(grad(13, 1.0, 2.0, 3.0), 1.0);
        // hash 14: u = y, v = x, h&2 negates v: 2 - 1
        assert_eq!(grad(14, 1.0, 2.0, 3.0), 1.0);
    }

    #[test]
    fn floor_is_f64_floor_bit_for_bit() {
        let mut xs = vec![
            0.0,
            -0.0,
            0.5,
            -0.5,
            1.0,
            -1.0,
            0.999_999_999_999_999_9,
            -0.999_999_999_999_999_9,
            1e-300,
            -1e-300,
            f64::MIN_POSITIVE / 4.0,
            -f64::MIN_POSITIVE / 4.0,
            4_503_599_627_370_495.5,
            -4_503_599_627_370_495.5,
            4_503_599_627_370_496.0,
            -4_503_599_627_370_497.0,
            9.0e15,
            1e300,
            -1e300,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
            f64::MAX,
            f64::MIN,
        ];
        for k in -3000..3000 {
            let x = k as f64 * 0.25;
            xs.extend([x, x.next_up(), x.next_down(), x * 1e7 + 0.3, x * 1e-7]);
        }
        let mut state = 0x2545_f491_4f6c_dd1du64;
        for _ in 0..100_000 {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            xs.push(f64::from_bits(state));
        }
        for x in xs {
            assert_eq!(floor(x).to_bits(), x.floor().to_bits(), "{x:e}");
        }
    }

    #[test]
    fn bounded_and_total_on_odd_inputs() {
        for &(x, y, z) in &[
            (1e300, -1e300, 0.5),
            (f64::NAN, 0.0, 0.0),
            (0.37, -12.9, 1e7 + 0.25),
        ] {
            let n = noise(x, y, z);
            assert!(n.is_nan() || (-1.1..=1.1).contains(&n), "{n}");
        }
        for i in 0..1000 {
            let t = i as f64 * 0.0137;
            let n = noise(t * 3.1, t * 1.7 - 4.0, t * 0.3 + 2.0);
            assert!((-1.1..=1.1).contains(&n));
        }
    }
}
