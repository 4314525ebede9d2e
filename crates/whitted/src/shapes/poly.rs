//! Real roots of a polynomial of degree at most 4 on a closed interval, found by
//! isolation rather than by a closed formula: the roots of p′ (found the same way,
//! recursively, down to a line) cut [lo, hi] into pieces on which p is monotone, and each
//! piece whose ends differ in sign holds exactly one root, which a safeguarded Newton
//! iteration (a bisection whenever Newton leaves the bracket) pins to the last bit.
//!
//! This is the torus's solver: Ferrari's closed form loses most of its digits when the
//! roots cluster (grazing rays), whereas a bracketed root is always found and always lies
//! in its bracket. A double root where p only touches zero (a tangent ray) is found when
//! p is exactly zero there; otherwise the ray counts as missing, either answer being right
//! at a tangent. Deterministic: no randomness, a fixed iteration cap.

/// At most this many Newton/bisection steps per root (64-bit bisection needs < 1100).
const MAX_STEPS: usize = 200;

/// p(x) for coefficients in ascending order (c[0] + c[1]·x + …), by Horner.
#[inline]
pub fn eval(c: &[f64], x: f64) -> f64 {
    c.iter().rev().fold(0.0, |acc, &k| acc * x + k)
}

/// The derivative's coefficients (ascending), into `out`; returns their count.
fn derivative(c: &[f64], out: &mut [f64; 4]) -> usize {
    for i in 1..c.len() {
        out[i - 1] = c[i] * i as f64;
    }
    c.len() - 1
}

/// The real roots of `c` (ascending coefficients, at most 5) in [lo, hi], ascending,
/// into `out`; returns how many. Leading zero coefficients lower the degree.
pub fn roots_in(c: &[f64], lo: f64, hi: f64, out: &mut [f64; 4]) -> usize {
    let mut len = c.len();
    while len > 0 && c[len - 1] == 0.0 {
        len -= 1;
    }
    let c = &c[..len];
    match len {
        0 | 1 => 0,
        2 => {
            let x = -c[0] / c[1];
            if x >= lo && x <= hi {
                out[0] = x;
                1
            } else {
                0
            }
        }
        _ => {
            let mut d = [0.0; 4];
            let dn = derivative(c, &mut d);
            let mut crit = [0.0; 4];
            let nc = roots_in(&d[..dn], lo, hi, &mut crit);
            let mut n = 0;
            let mut a = lo;
            let mut fa = eval(c, a);
            if fa == 0.0 {
                out[0] = a;
                n = 1;
            }
            for &b in crit[..nc].iter().chain(std::iter::once(&hi)) {
                let fb = eval(c, b);
                if b > a && n < 4 {
                    if fb == 0.0 {
                        out[n] = b;
                        n += 1;
                    } else if fa != 0.0 && (fa < 0.0) != (fb < 0.0) {
                        out[n] = bracketed(c, &d[..dn], a, b, fa);
                        n += 1;
                    }
                }
                (a, fa) = (b, fb);
            }
            n
        }
    }
}

/// The root of `c` in (a, b), where p(a) = fa and p(b) differ in sign and p is monotone.
fn bracketed(c: &[f64], d: &[f64], mut a: f64, mut b: f64, fa: f64) -> f64 {
    let rising = fa < 0.0;
    let mut x = 0.5 * (a + b);
    for _ in 0..MAX_STEPS {
        let fx = eval(c, x);
        if fx == 0.0 {
            return x;
        }
        // Keep p(a) on fa's side and p(b) on the other.
        if (fx < 0.0) == rising {
            a = x;
        } else {
            b = x;
        }
        let step = fx / eval(d, x);
        let newton = x - step;
        let next = if newton > a && newton < b {
            newton
        } else {
            0.5 * (a + b)
        };
        if next == x || !(next > a && next < b) {
            return x;
        }
        x = next;
    }
    x
}

#[cfg(test)]
mod tests {
    use super::*;

    fn solve(c: &[f64], lo: f64, hi: f64) -> Vec<f64> {
        let mut out = [0.0; 4];
        let n = roots_in(c, lo, hi, &mut out);
        out[..n].to_vec()
    }

    #[test]
    fn quartic_with_four_roots() {
        // (x − 1)(x − 2)(x − 3)(x − 4) = x⁴ − 10x³ + 35x² − 50x + 24.
        let r = solve(&[24.0, -50.0, 35.0, -10.0, 1.0], -10.0, 10.0);
        assert_eq!(r.len(), 4);
        for (x, want) in r.iter().zip([1.0, 2.0, 3.0, 4.0]) {
            assert!((x - want).abs() < 1e-13, "{r:?}");
        }
        // Only the two inside [1.5, 3.5].
        let r = solve(&[24.0, -50.0, 35.0, -10.0, 1.0], 1.5, 3.5);
        assert_eq!(r.len(), 2);
        assert!((r[0] - 2.0).abs() < 1e-13 && (r[1] - 3.0).abs() < 1e-13);
    }

    #[test]
    fn clustered_roots_keep_their_digits() {
        // (x − 1)(x − 1.000001)(x + 2)(x − 5): two roots 1e-6 apart.
        let (p, q) = (1.0, 1.000001);
        // Expand (x² − (p+q)x + pq)(x² − 3x − 10).
        let (s, m) = (p + q, p * q);
        let c = [
            -10.0 * m,
            10.0 * s - 3.0 * m,
            m - 10.0 + 3.0 * s,
            -3.0 - s,
            1.0,
        ];
        let r = solve(&c, -10.0, 10.0);
        assert_eq!(r.len(), 4, "{r:?}");
        assert!((r[1] - p).abs() < 1e-9 && (r[2] - q).abs() < 1e-9, "{r:?}");
    }

    #[test]
    fn lower_degrees_and_no_roots() {
        assert_eq!(solve(&[-2.0, 1.0], 0.0, 5.0), vec![2.0]);
        assert_eq!(solve(&[-4.0, 0.0, 1.0, 0.0, 0.0], -5.0, 5.0).len(), 2);
        assert!(solve(&[1.0, 0.0, 1.0], -5.0, 5.0).is_empty());
        // x⁴ + 1 has no real root.
        assert!(solve(&[1.0, 0.0, 0.0, 0.0, 1.0], -5.0, 5.0).is_empty());
        // An exact double root at a critical point is found once: (x − 1)².
        assert_eq!(solve(&[1.0, -2.0, 1.0], -5.0, 5.0), vec![1.0]);
    }
}
