//! Whether a triangle stops no shadow ray of a shaft, asked of the exact test's own
//! arithmetic (`Triangle::uvt_of`: Möller–Trumbore) rather than of the triangle's box,
//! which a shaft from a point of a model always meets: the point's own triangle holds
//! it, and its neighbours touch it.
//!
//! Every ray of a shaft starts at its point p, so s = p − A, q = s × E1 and the t
//! numerator N = E2·q are the same numbers on every ray. What changes from ray to ray is
//! the unit direction D, and the test's determinant E1·(D × E2) = −D·(E1 × E2), its u
//! numerator s·(D × E2) = D·(E2 × s) and its v numerator D·q are linear in D: over the
//! shaft each keeps one sign where it has that sign at the four corners by more than
//! the sample points' placement (η) and the products' rounding can move it. With the
//! determinant's sign fixed, every ray misses when
//! - t = N / det is at most 0 (N zero, NaN or of the other sign), or below t_min;
//! - u < 0 or v < 0 on every ray (the numerator's sign against the determinant's);
//! - u > 1 or u + v > 1 on every ray, by more than the quotients' rounding.
//!
//! The point's own triangle is cleared by t (N is rounding), and where the surface is
//! convex its neighbours are cleared by an edge: the rays cross their planes beyond the
//! edge they share. The allowance for rounding is 10⁻¹² of the operands' product, some
//! ten thousand times the few ulps each product can be off.

use super::Shaft;
use glam::DVec3;

/// Rounding allowance per unit of a product's operands' magnitudes.
const ROUND: f64 = 1e-12;

/// A quotient at least this large cannot underflow to a zero of either sign (which
/// `uvt_of`'s range test would let through as u = −0).
const TINY: f64 = 1e-290;

impl Shaft {
    /// Whether no ray of the shaft (from its point towards any point of its light, with
    /// t_min ≥ 0) meets the triangle A, A + E1, A + E2 as `Triangle::uvt_of` tests it.
    /// "Met" may be said of a triangle no ray meets; "missed" never of one a ray does.
    pub fn misses_triangle(&self, a: DVec3, e1: DVec3, e2: DVec3, t_min: f64) -> bool {
        if t_min.is_nan() || t_min < 0.0 {
            return false;
        }
        let (p, far) = (self.p, self.far);
        // The sign w·D keeps over the shaft's unit directions (0 for none), and the least
        // |w·D| it can take there.
        let cone = |w: DVec3| match self.side(w) {
            Some((sign, least)) => (sign, least / far),
            None => (0.0, 0.0),
        };
        let m = e1.cross(e2);
        let k_det = ROUND * e1.length() * e2.length();
        let (sd, det_true) = cone(-m);
        let det_low = det_true - k_det;
        if sd == 0.0 || det_low.is_nan() || det_low <= 0.0 {
            return false;
        }
        // t: the same N on every ray, over a determinant of sign sd and at least det_low.
        let s = p - a;
        let q = s.cross(e1);
        let n = e2.dot(q);
        let same = n * sd;
        if same.is_nan() || same <= 0.0 || n.abs() / det_low * (1.0 + 1e-9) < t_min {
            return true;
        }
        // u < 0 and v < 0: the numerators against the determinant's sign, by more than
        // the numerators' rounding and too far from 0 for the quotient to underflow.
        let det_high = m.length() + k_det;
        let negative = |sign: f64, low: f64, k: f64| sign == -sd && (low - k) / det_high > TINY;
        let w_u = e2.cross(s);
        let k_u = ROUND * s.length() * e2.length();
        let (su, low_u) = cone(w_u);
        if negative(su, low_u, k_u) {
            return true;
        }
        let k_v = ROUND * q.length();
        let (sv, low_v) = cone(q);
        if negative(sv, low_v, k_v) {
            return true;
        }
        // u > 1 and u + v > 1: u − 1 = D·(E2 × s + m) / det, u + v − 1 = D·(E2 × s + q
        // + m) / det, each at least its numerator's least over the largest determinant,
        // which must beat the quotients' rounding.
        let u_max = s.length() * e2.length() / det_low;
        let v_max = q.length() / det_low;
        let err = |k: f64, x_max: f64| (k + x_max * k_det) / det_low + ROUND * x_max;
        let (err_u, err_v) = (err(k_u, u_max), err(k_v, v_max));
        let (s1, low1) = cone(w_u + m);
        if s1 == sd && low1 / det_high > err_u {
            return true;
        }
        let (s2, low2) = cone(w_u + q + m);
        s2 == sd && low2 / det_high > err_u + err_v + ROUND * (u_max + v_max + 1.0)
    }
}

#[cfg(test)]
#[path = "shaft_tri_tests.rs"]
mod tests;
