//! glTF animations (`Clip`): each channel's keys (read by `animations`), and its value
//! at any time (SPEC §18): LINEAR (rotations by slerp on the shorter arc),
//! STEP, and CUBICSPLINE in glTF's Hermite form, its tangents scaled by the key interval
//! and rotations normalised after it; before the first key and after the last the end
//! value holds. Times are the file's, in seconds from the animation's start.

/// The most keys (times) the file's animations may hold in all.
pub const MAX_KEYS: u64 = 1 << 22;

/// What a channel animates.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Path {
    /// The node's translation (3 values).
    Translation,
    /// The node's rotation (a quaternion x, y, z, w).
    Rotation,
    /// The node's scale (3 values).
    Scale,
    /// The morph weights of the node's mesh (one per target).
    Weights,
}

/// How values between keys are found.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Interp {
    /// Linear (slerp for rotations).
    Linear,
    /// The earlier key's value.
    Step,
    /// Cubic Hermite with in- and out-tangents per key.
    Cubic,
}

/// One animated value of one node.
#[derive(Clone, Debug)]
pub struct Channel {
    /// The node.
    pub node: usize,
    /// Which of its values.
    pub path: Path,
    /// How values are interpolated.
    pub interp: Interp,
    /// The keys' times, increasing.
    pub times: Vec<f64>,
    /// `width` values per key (three groups of them per key for `Cubic`: in-tangent,
    /// value, out-tangent).
    pub values: Vec<f64>,
    /// The values per element.
    pub width: usize,
}

/// One animation of the file.
#[derive(Clone, Debug)]
pub struct Clip {
    /// Its name, if any.
    pub name: Option<String>,
    /// Its channels.
    pub channels: Vec<Channel>,
}

impl Clip {
    /// The time of its last key (0 without keys).
    pub fn end(&self) -> f64 {
        let last = self.channels.iter().filter_map(|c| c.times.last());
        last.fold(0.0, |a, &b| a.max(b))
    }
}

impl Channel {
    /// Element `k`'s `part` (0 in-tangent, 1 value, 2 out-tangent for `Cubic`; 0 else).
    fn element(&self, k: usize, part: usize) -> &[f64] {
        let groups = if self.interp == Interp::Cubic { 3 } else { 1 };
        let start = (k * groups + part) * self.width;
        &self.values[start..start + self.width]
    }

    /// The value at time `t`.
    pub fn sample(&self, t: f64) -> Vec<f64> {
        let mut out = self.between(t);
        if self.path == Path::Rotation {
            let len = out.iter().map(|x| x * x).sum::<f64>().sqrt();
            if len > 0.0 {
                out.iter_mut().for_each(|x| *x /= len);
            }
        }
        out
    }

    /// The value at `t` before a rotation is normalised.
    fn between(&self, t: f64) -> Vec<f64> {
        let mid = usize::from(self.interp == Interp::Cubic);
        let n = self.times.len();
        if n == 0 {
            return Vec::new();
        }
        if t.partial_cmp(&self.times[0]) != Some(std::cmp::Ordering::Greater) {
            return self.element(0, mid).to_vec();
        }
        if t >= self.times[n - 1] {
            return self.element(n - 1, mid).to_vec();
        }
        // The key interval holding t: times[i] ≤ t < times[i + 1].
        let i = self.times.partition_point(|&k| k <= t) - 1;
        let (t0, t1) = (self.times[i], self.times[i + 1]);
        let td = t1 - t0;
        let s = if td > 0.0 { (t - t0) / td } else { 0.0 };
        match self.interp {
            Interp::Step => self.element(i, 0).to_vec(),
            Interp::Linear if self.path == Path::Rotation => {
                slerp(self.element(i, 0), self.element(i + 1, 0), s)
            }
            Interp::Linear => {
                let (a, b) = (self.element(i, 0), self.element(i + 1, 0));
                a.iter().zip(b).map(|(a, b)| a + (b - a) * s).collect()
            }
            Interp::Cubic => {
                let (s2, s3) = (s * s, s * s * s);
                let (h00, h10) = (2.0 * s3 - 3.0 * s2 + 1.0, s3 - 2.0 * s2 + s);
                let (h01, h11) = (-2.0 * s3 + 3.0 * s2, s3 - s2);
                let (v0, b0) = (self.element(i, 1), self.element(i, 2));
                let (a1, v1) = (self.element(i + 1, 0), self.element(i + 1, 1));
                (0..self.width)
                    .map(|c| h00 * v0[c] + h10 * td * b0[c] + h01 * v1[c] + h11 * td * a1[c])
                    .collect()
            }
        }
    }
}

/// Spherical interpolation of two quaternions on the shorter arc.
fn slerp(a: &[f64], b: &[f64], s: f64) -> Vec<f64> {
    let q = |v: &[f64]| glam::DQuat::from_xyzw(v[0], v[1], v[2], v[3]).normalize();
    let (qa, mut qb) = (q(a), q(b));
    if qa.dot(qb) < 0.0 {
        qb = -qb;
    }
    qa.slerp(qb, s).to_array().to_vec()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn channel(interp: Interp, path: Path, times: &[f64], values: &[f64], width: usize) -> Channel {
        Channel {
            node: 0,
            path,
            interp,
            times: times.to_vec(),
            values: values.to_vec(),
            width,
        }
    }

    #[test]
    fn linear_step_and_the_ends_by_hand() {
        let c = channel(
            Interp::Linear,
            Path::Translation,
            &[1.0, 3.0],
            &[0.0, 0.0, 0.0, 4.0, 2.0, -2.0],
            3,
        );
        assert_eq!(c.sample(0.0), vec![0.0, 0.0, 0.0]);
        assert_eq!(c.sample(2.0), vec![2.0, 1.0, -1.0]);
        assert_eq!(c.sample(2.5), vec![3.0, 1.5, -1.5]);
        assert_eq!(c.sample(9.0), vec![4.0, 2.0, -2.0]);
        let s = Channel {
            interp: Interp::Step,
            ..c
        };
        assert_eq!(s.sample(2.9), vec![0.0, 0.0, 0.0]);
        assert_eq!(s.sample(3.0), vec![4.0, 2.0, -2.0]);
    }

    #[test]
    fn cubic_spline_is_gltf_hermite_with_scaled_tangents() {
        // One value, keys at 0 and 2: v0 = 0, out-tangent b0 = 1; v1 = 1, in-tangent a1 = 0.
        // At s = ½ (t = 1): h00 = ½, h10 = ⅛, h01 = ½, h11 = −⅛, td = 2:
        // ½·0 + ⅛·2·1 + ½·1 − ⅛·2·0 = 0.75.
        let c = channel(
            Interp::Cubic,
            Path::Weights,
            &[0.0, 2.0],
            &[9.0, 0.0, 1.0, 0.0, 1.0, 9.0],
            1,
        );
        assert_eq!(c.sample(1.0), vec![0.75]);
        assert_eq!(c.sample(-1.0), vec![0.0]);
        assert_eq!(c.sample(5.0), vec![1.0]);
    }

    #[test]
    fn rotations_take_the_shorter_arc() {
        // Identity to 90° about y, the second key written with its sign flipped.
        let h = std::f64::consts::FRAC_1_SQRT_2;
        let c = channel(
            Interp::Linear,
            Path::Rotation,
            &[0.0, 1.0],
            &[0.0, 0.0, 0.0, 1.0, 0.0, -h, 0.0, -h],
            4,
        );
        let q = c.sample(0.5);
        // 45° about y: (0, sin 22.5°, 0, cos 22.5°).
        let want = [
            0.0,
            (22.5f64).to_radians().sin(),
            0.0,
            (22.5f64).to_radians().cos(),
        ];
        for (a, b) in q.iter().zip(want) {
            assert!((a - b).abs() < 1e-12, "{q:?}");
        }
    }
}
