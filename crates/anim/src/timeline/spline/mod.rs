//! Centripetal Catmull-Rom camera splines (SPEC §5). `Spline` owns the curve through the
//! keys, the mapping from frames to points of it, and, for `constant_speed`, the
//! arc-length table built once by `Spline::new`. The manifest reads it from:
//!
//! ```toml
//! [camera]
//! path = "spline"
//! closed = false                   # true: the path loops back to the first key
//! constant_speed = false           # true: even speed by arc length
//! look_at = [0.0, 1.0, 0.0]        # or a look_at on every key, or none at all
//! keys = [
//!   { frame = 0,   position = [0.0, 3.0, 12.0] },
//!   { frame = 120, position = [10.0, 6.0, 0.0] },
//!   { frame = 249, position = [0.0, 2.0, -12.0] },
//! ]
//! ```
//!
//! Each segment between two keys is a centripetal (alpha = 0.5) Catmull-Rom curve in the
//! Barry-Goldman pyramid form, its knot intervals the square roots of the distances
//! between neighbouring points; a zero interval (coincident points) is guarded so that
//! no NaN can appear. The frames from one key to the next map linearly onto the
//! segment's parameter, so the camera is exactly at a key's position on its frame.
//!
//! Open paths: phantom end points by reflection (P₋₁ = 2P₀ − P₁, Pₙ = 2Pₙ₋₁ − Pₙ₋₂);
//! frames before the first key or after the last hold the end position.
//! Closed paths repeat every `frames` frames: the closing segment runs from the last
//! key's frame to the first key's frame plus `frames`, neighbours wrap around, and a
//! frame before the first key lies on the closing segment.
//! With `constant_speed` the path is re-timed by arc length: an open path from the first
//! key's frame to the last one's, a closed path over its whole loop.
//! Per-key look-at points follow their own centripetal curve, on the same segment and
//! segment parameter as the position, so they too are exact wherever the camera is at a
//! key.

use super::ease::Ease;
use glam::DVec3;
use whitted::limits::MAX_COORD;

/// Arc-length samples per segment: `ARC_STEPS_TOTAL` / segments, clamped to this range.
const ARC_STEPS_MAX: usize = 1024;
const ARC_STEPS_MIN: usize = 4;
const ARC_STEPS_TOTAL: usize = 1 << 20;

/// A spline key: a frame, a position and an optional look-at point.
#[derive(Clone, Debug, PartialEq)]
pub struct Key {
    /// The frame at which the camera is exactly at `position`.
    pub frame: u32,
    /// The camera's eye at that frame.
    pub position: DVec3,
    /// The point looked at from that frame, when every key has one.
    pub look_at: Option<DVec3>,
    /// How the segment from this key to the next is paced (`Ease`, as a track key's):
    /// the segment's parameter is ease(u) for the key timing's u.
    pub ease: Ease,
}

/// A camera spline through keys. Build it with [`Spline::new`], which validates the keys
/// and precomputes the arc-length table; the public fields are for reading.
#[derive(Clone, Debug, PartialEq)]
pub struct Spline {
    /// The keys, at least two, in increasing frame order.
    pub keys: Vec<Key>,
    /// Whether the path loops from the last key back to the first.
    pub closed: bool,
    /// Whether the camera moves at even speed along the path (re-timed by arc length).
    pub constant_speed: bool,
    /// A fixed look-at point for the whole path.
    pub look_at: Option<DVec3>,
    /// Cumulative arc length at `steps` even parameter steps per segment
    /// (`constant_speed` only, else empty).
    arc: Vec<f64>,
    steps: usize,
}

/// Why keys do not make a spline. `index` is 0-based, and messages name the key as the
/// manifest's other errors do (`camera.keys[2]`), so one key has one name everywhere.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum SplineError {
    /// Fewer than two keys.
    #[error("a spline needs at least two keys, found {count}")]
    TooFewKeys {
        /// The number of keys given.
        count: usize,
    },
    /// A key's frame is not after the previous key's.
    #[error("camera.keys[{index}]: frame {frame} is not after the previous key's frame {previous}; keys must be in increasing frame order")]
    FrameOrder {
        /// The key, 0-based.
        index: usize,
        /// Its frame.
        frame: u32,
        /// The previous key's frame.
        previous: u32,
    },
    /// Some keys have a look_at and this one does not, or the other way round.
    #[error("camera.keys[{index}]: either every key has a look_at or none has")]
    MixedLookAt {
        /// The first key that differs from key 0, 0-based.
        index: usize,
    },
    /// Both a path-wide look_at and per-key ones.
    #[error("give either one look_at for the whole path or a look_at on each key, not both")]
    BothLookAts,
    /// A key's position or look_at is not finite or past `MAX_COORD`.
    #[error(
        "camera.keys[{index}]: coordinates must be finite and at most {MAX_COORD:e} in magnitude"
    )]
    BadCoordinate {
        /// The key, 0-based.
        index: usize,
    },
    /// The path-wide look_at is not finite or past `MAX_COORD`.
    #[error("look_at: coordinates must be finite and at most {MAX_COORD:e} in magnitude")]
    BadLookAt,
    /// A key eases its segment on a path timed by arc length, which ignores the keys'
    /// frames.
    #[error("camera.keys[{index}]: `ease` paces the segment between two keys' frames; with constant_speed = true the keys' frames do not time the path (drop one)")]
    EaseWithConstantSpeed {
        /// The key, 0-based.
        index: usize,
    },
}

/// Whether every coordinate is finite and within [`MAX_COORD`].
pub fn coord_ok(v: DVec3) -> bool {
    v.to_array().iter().all(|c| c.abs() <= MAX_COORD)
}

impl Spline {
    /// Validates the keys (at least two, strictly increasing frames, look-at points on all
    /// keys or none and not with a fixed one, coordinates within [`MAX_COORD`]) and
    /// precomputes the arc-length table when `constant_speed` is set.
    pub fn new(
        keys: Vec<Key>,
        closed: bool,
        constant_speed: bool,
        look_at: Option<DVec3>,
    ) -> Result<Spline, SplineError> {
        if keys.len() < 2 {
            return Err(SplineError::TooFewKeys { count: keys.len() });
        }
        let with_look_at = keys[0].look_at.is_some();
        for (index, key) in keys.iter().enumerate() {
            let look_ok = key.look_at.is_none_or(coord_ok);
            if !coord_ok(key.position) || !look_ok {
                return Err(SplineError::BadCoordinate { index });
            }
            if key.look_at.is_some() != with_look_at {
                return Err(SplineError::MixedLookAt { index });
            }
            if constant_speed && key.ease != Ease::None {
                return Err(SplineError::EaseWithConstantSpeed { index });
            }
            if index > 0 && key.frame <= keys[index - 1].frame {
                let previous = keys[index - 1].frame;
                let frame = key.frame;
                return Err(SplineError::FrameOrder {
                    index,
                    frame,
                    previous,
                });
            }
        }
        if look_at.is_some_and(|p| !coord_ok(p)) {
            return Err(SplineError::BadLookAt);
        }
        if with_look_at && look_at.is_some() {
            return Err(SplineError::BothLookAts);
        }
        let mut spline = Spline {
            keys,
            closed,
            constant_speed,
            look_at,
            arc: Vec::new(),
            steps: 0,
        };
        if constant_speed {
            spline.build_arc_table();
        }
        Ok(spline)
    }

    /// Eye and look-at point at time `frame` (in frames, possibly fractional) of a
    /// `frames`-frame sequence; without any look_at in the spline the camera looks at
    /// `scene_look_at`.
    pub fn at(&self, frame: f64, frames: u32, scene_look_at: DVec3) -> (DVec3, DVec3) {
        let Some(first) = self.keys.first() else {
            return (DVec3::ZERO, scene_look_at);
        };
        if self.keys.len() < 2 {
            let look = first.look_at.or(self.look_at).unwrap_or(scene_look_at);
            return (first.position, look);
        }
        let (segment, u) = self.locate(frame, frames);
        let eye = curve_point(&self.keys, |k| k.position, self.closed, segment, u);
        let look = if first.look_at.is_some() {
            let look_of = |k: &Key| k.look_at.unwrap_or(k.position);
            curve_point(&self.keys, look_of, self.closed, segment, u)
        } else {
            self.look_at.unwrap_or(scene_look_at)
        };
        (eye, look)
    }

    /// Total length of the path, from the arc-length table (0 without `constant_speed`).
    pub fn arc_length(&self) -> f64 {
        self.arc.last().copied().unwrap_or(0.0)
    }

    fn segments(&self) -> usize {
        if self.closed {
            self.keys.len()
        } else {
            self.keys.len() - 1
        }
    }

    fn build_arc_table(&mut self) {
        let segments = self.segments();
        let steps = (ARC_STEPS_TOTAL / segments).clamp(ARC_STEPS_MIN, ARC_STEPS_MAX);
        let mut arc = Vec::with_capacity(segments * steps + 1);
        arc.push(0.0);
        let mut total = 0.0;
        let mut previous = self.keys[0].position;
        for segment in 0..segments {
            for step in 1..=steps {
                let u = step as f64 / steps as f64;
                let p = curve_point(&self.keys, |k| k.position, self.closed, segment, u);
                total += previous.distance(p);
                arc.push(total);
                previous = p;
            }
        }
        self.arc = arc;
        self.steps = steps;
    }

    /// The segment and its parameter u ∈ [0, 1] of a (possibly fractional) frame.
    fn locate(&self, frame: f64, frames: u32) -> (usize, f64) {
        let n = self.keys.len();
        let first = f64::from(self.keys[0].frame);
        let last = f64::from(self.keys[n - 1].frame);
        let timed = self.constant_speed && self.arc.len() == self.segments() * self.steps + 1;
        if self.closed {
            // A period shorter than the keys span (misuse) is widened to keep the
            // closing segment at least one frame long.
            let period = f64::from(frames).max(last - first + 1.0);
            let t = first + (frame - first).rem_euclid(period);
            if timed {
                return self.by_length((t - first) / period);
            }
            if t >= last {
                let u = (t - last) / (first + period - last);
                return (n - 1, self.keys[n - 1].ease.apply(u));
            }
            return self.by_keys(t);
        }
        if frame <= first {
            return (0, 0.0);
        }
        if frame >= last {
            return (n - 2, 1.0);
        }
        if timed {
            return self.by_length((frame - first) / (last - first));
        }
        self.by_keys(frame)
    }

    /// Key timing: the segment whose keys' frames surround `t` (first ≤ t < last).
    fn by_keys(&self, t: f64) -> (usize, f64) {
        let after = self.keys.partition_point(|k| f64::from(k.frame) <= t);
        let segment = after.clamp(1, self.keys.len() - 1) - 1;
        let start = f64::from(self.keys[segment].frame);
        let end = f64::from(self.keys[segment + 1].frame);
        let u = ((t - start) / (end - start)).clamp(0.0, 1.0);
        (segment, self.keys[segment].ease.apply(u))
    }

    /// Arc-length timing: the point at `fraction` ∈ [0, 1] of the total length, by binary
    /// search in the table and linear interpolation between its samples.
    fn by_length(&self, fraction: f64) -> (usize, f64) {
        let total = self.arc_length();
        if total <= 0.0 || self.steps == 0 {
            return (0, 0.0);
        }
        let s = (fraction.clamp(0.0, 1.0)) * total;
        let after = self.arc.partition_point(|&a| a <= s);
        let i = after.clamp(1, self.arc.len() - 1) - 1;
        let width = self.arc[i + 1] - self.arc[i];
        let within = if width > 0.0 {
            ((s - self.arc[i]) / width).clamp(0.0, 1.0)
        } else {
            0.0
        };
        let g = (i as f64 + within) / self.steps as f64;
        let segment = (g.floor() as usize).min(self.segments() - 1);
        (segment, (g - segment as f64).clamp(0.0, 1.0))
    }
}

/// The point at parameter `u` of segment `segment` of the curve through `point(key)`
/// (camera keys here; track keys in `track`, numbers as `(x, 0, 0)`).
pub(super) fn curve_point<K>(
    keys: &[K],
    point: impl Fn(&K) -> DVec3,
    closed: bool,
    segment: usize,
    u: f64,
) -> DVec3 {
    let n = keys.len();
    let p = |i: usize| point(&keys[i % n]);
    let controls = if closed {
        [
            p(segment + n - 1),
            p(segment),
            p(segment + 1),
            p(segment + 2),
        ]
    } else {
        let (p1, p2) = (p(segment), p(segment + 1));
        let p0 = if segment == 0 {
            2.0 * p1 - p2
        } else {
            p(segment - 1)
        };
        let p3 = if segment + 2 < n {
            p(segment + 2)
        } else {
            2.0 * p2 - p1
        };
        [p0, p1, p2, p3]
    };
    catmull_rom(controls, u)
}

/// Centripetal Catmull-Rom between `p[1]` (u = 0, exactly) and `p[2]` (u = 1, exactly),
/// Barry-Goldman pyramid form.
fn catmull_rom(p: [DVec3; 4], u: f64) -> DVec3 {
    if u.is_nan() || u <= 0.0 {
        return p[1];
    }
    if u >= 1.0 {
        return p[2];
    }
    let t0 = 0.0;
    let t1 = t0 + p[0].distance(p[1]).sqrt();
    let t2 = t1 + p[1].distance(p[2]).sqrt();
    let t3 = t2 + p[2].distance(p[3]).sqrt();
    if t2 <= t1 {
        return p[1]; // coincident keys: the segment is a point
    }
    let t = t1 + u * (t2 - t1);
    let a1 = lerp(p[0], p[1], t0, t1, t);
    let a2 = lerp(p[1], p[2], t1, t2, t);
    let a3 = lerp(p[2], p[3], t2, t3, t);
    let b1 = lerp(a1, a2, t0, t2, t);
    let b2 = lerp(a2, a3, t1, t3, t);
    lerp(b1, b2, t1, t2, t)
}

/// The point of the line a (at ta) → b (at tb) at t; b when the interval is empty (then
/// a and b coincide, up to underflow).
fn lerp(a: DVec3, b: DVec3, ta: f64, tb: f64, t: f64) -> DVec3 {
    let span = tb - ta;
    if span > 0.0 {
        a + (b - a) * ((t - ta) / span)
    } else {
        b
    }
}

#[cfg(test)]
mod tests;
