//! Camera paths of SPEC §5: where the camera is, and what it looks at, on each frame.
//! `CameraPath` owns the circle (the report's orbit) and dispatches splines to `spline`.
//! The manifest's `[camera]` table for a circle:
//!
//! ```toml
//! [camera]
//! path = "circle"
//! center = [0.0, 1.0, 0.0]         # the camera turns around this point and looks at it
//! radius = 12.0                    # > 0
//! height = 3.0                     # camera y
//! start_angle = 0.0                # degrees; 0 puts the camera on the +z side of center
//! turns = 1.0                      # negative turns go the other way
//! # look_at = [x, y, z]            # optional, defaults to center
//! ```
//!
//! Frame i of N is at θ = start_angle + 360°·turns·i/N and the eye at
//! (center.x + radius·sin θ, height, center.z + radius·cos θ). The fraction turns·i/N is
//! reduced modulo 1 before it becomes an angle, so frame N is exactly frame 0 when turns
//! is a whole number and the video loops without a repeated frame.
//!
//! A scene whose world's up is not y (an NFF view's `up`, SPEC §17) turns the circle about
//! that axis: the same construction in the frame the shortest rotation taking y to `up`
//! makes (`height` is then along `up`; for z up, θ = 0 puts the eye on the −y side of the
//! centre: (center.x + radius·sin θ, center.y − radius·cos θ, height)).

use super::spline::Spline;
use glam::{DQuat, DVec3};

/// A horizontal circle travelled over the sequence: the camera's orbit, and the path of
/// a tracked position that follows a circle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Circle {
    /// The circle's centre; only its x and z are used (`height` gives y).
    pub center: DVec3,
    /// The circle's radius, > 0.
    pub radius: f64,
    /// The absolute y of every point.
    pub height: f64,
    /// Degrees; 0 puts the point on the +z side of `center`.
    pub start_angle: f64,
    /// Turns over the whole sequence; fractional is fine, negative goes the other way.
    pub turns: f64,
}

impl Circle {
    /// The point at time `frame` of a `frames`-frame sequence: θ = start_angle +
    /// 360°·(turns·frame/n mod 1), (center.x + radius·sin θ, height, center.z + radius·cos θ).
    pub fn at(&self, frame: f64, frames: u32) -> DVec3 {
        let n = f64::from(frames.max(1));
        let fraction = (self.turns * frame / n).rem_euclid(1.0);
        let theta = (self.start_angle + 360.0 * fraction).to_radians();
        let (sin, cos) = libm::sincos(theta);
        let c = self.center;
        DVec3::new(
            c.x + self.radius * sin,
            self.height,
            c.z + self.radius * cos,
        )
    }
}

impl Circle {
    /// `at`, the circle turning about the unit `up` (`at` itself for y).
    pub fn at_about(&self, frame: f64, frames: u32, up: DVec3) -> DVec3 {
        if up == DVec3::Y {
            return self.at(frame, frames);
        }
        let q = DQuat::from_rotation_arc(DVec3::Y, up);
        let local = Circle {
            center: q.inverse() * self.center,
            ..*self
        };
        q * local.at(frame, frames)
    }
}

/// Where the camera is on each frame.
#[derive(Clone, Debug, PartialEq)]
pub enum CameraPath {
    /// The report's orbit, looking at `look_at` (defaults to the circle's centre).
    Circle {
        /// The orbit.
        circle: Circle,
        /// The point looked at; `None`: the circle's centre.
        look_at: Option<DVec3>,
    },
    /// A Catmull-Rom spline through camera keys.
    Spline(Spline),
}

impl CameraPath {
    /// Eye and look-at point of frame `frame` of a `frames`-frame sequence;
    /// `scene_look_at` is the scene file's point, used when the path gives none.
    pub fn at(&self, frame: f64, frames: u32, scene_look_at: DVec3) -> (DVec3, DVec3) {
        self.at_about(frame, frames, scene_look_at, DVec3::Y)
    }

    /// `at` in a world whose unit up is `up`: a circle turns about it.
    pub fn at_about(
        &self,
        frame: f64,
        frames: u32,
        scene_look_at: DVec3,
        up: DVec3,
    ) -> (DVec3, DVec3) {
        match self {
            CameraPath::Circle { circle, look_at } => (
                circle.at_about(frame, frames, up),
                look_at.unwrap_or(circle.center),
            ),
            CameraPath::Spline(spline) => spline.at(frame, frames, scene_look_at),
        }
    }

    /// The path made to loop over `frames` frames (`loop = true`): a spline closed (after
    /// its last key it runs back to its first, arriving `frames` frames after the first
    /// key's frame), a circle as it is. Refused, with the reason, when it cannot loop: a
    /// circle of fractional turns. (Keys lie within the sequence, so within one loop.)
    pub fn looped(self) -> Result<CameraPath, String> {
        match self {
            CameraPath::Circle { circle, .. } if circle.turns.fract() != 0.0 => Err(format!(
                "loop = true: the camera's circle must make whole turns to loop, found turns = {}",
                circle.turns
            )),
            CameraPath::Spline(s) => {
                let closed = Spline::new(s.keys.clone(), true, s.constant_speed, s.look_at);
                Ok(CameraPath::Spline(closed.unwrap_or(s)))
            }
            path => Ok(path),
        }
    }

    /// The path's name as the manifest writes it: `circle` or `spline`.
    pub fn name(&self) -> &'static str {
        match self {
            CameraPath::Circle { .. } => "circle",
            CameraPath::Spline(_) => "spline",
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn orbit(start_angle: f64, turns: f64, look_at: Option<DVec3>) -> CameraPath {
        let circle = Circle {
            center: DVec3::new(2.0, 1.0, -3.0),
            radius: 12.0,
            height: 3.0,
            start_angle,
            turns,
        };
        CameraPath::Circle { circle, look_at }
    }

    fn assert_close(a: DVec3, b: DVec3) {
        assert!(a.distance(b) < 1e-12, "{a} is not {b}");
    }

    #[test]
    fn a_circle_turns_about_z_when_z_is_up() {
        // Centre (2, 1, −3), radius 12, height 3, z up: frame 0 at (2, 1 − 12, 3), a quarter
        // turn at (2 + 12, 1, 3); the look-at point is the centre itself.
        let path = orbit(0.0, 1.0, None);
        let (eye, look) = path.at_about(0.0, 4, DVec3::ZERO, DVec3::Z);
        assert_close(eye, DVec3::new(2.0, -11.0, 3.0));
        assert_close(look, DVec3::new(2.0, 1.0, -3.0));
        let (eye, _) = path.at_about(1.0, 4, DVec3::ZERO, DVec3::Z);
        assert_close(eye, DVec3::new(14.0, 1.0, 3.0));
        // y up: exactly `at`.
        assert_eq!(
            path.at_about(1.0, 4, DVec3::ZERO, DVec3::Y),
            path.at(1.0, 4, DVec3::ZERO)
        );
    }

    #[test]
    fn frame_zero_is_on_the_plus_z_side_looking_at_the_center() {
        let (eye, look) = orbit(0.0, 1.0, None).at(0.0, 100, DVec3::ZERO);
        assert_close(eye, DVec3::new(2.0, 3.0, 9.0));
        assert_eq!(look, DVec3::new(2.0, 1.0, -3.0));
    }

    #[test]
    fn a_quarter_turn_moves_to_plus_x_and_negative_turns_to_minus_x() {
        let (eye, _) = orbit(0.0, 1.0, None).at(25.0, 100, DVec3::ZERO);
        assert_close(eye, DVec3::new(14.0, 3.0, -3.0));
        let (eye, _) = orbit(0.0, -1.0, None).at(25.0, 100, DVec3::ZERO);
        assert_close(eye, DVec3::new(-10.0, 3.0, -3.0));
        // Half a turn in 100 frames: frame 50 is a quarter.
        let (eye, _) = orbit(0.0, 0.5, None).at(50.0, 100, DVec3::ZERO);
        assert_close(eye, DVec3::new(14.0, 3.0, -3.0));
    }

    #[test]
    fn start_angle_is_in_degrees() {
        let (eye, _) = orbit(180.0, 1.0, None).at(0.0, 100, DVec3::ZERO);
        assert_close(eye, DVec3::new(2.0, 3.0, -15.0));
        let (eye, _) = orbit(-90.0, 2.0, None).at(25.0, 100, DVec3::ZERO);
        assert_close(eye, DVec3::new(14.0, 3.0, -3.0));
    }

    #[test]
    fn frame_n_is_frame_zero() {
        for turns in [1.0, -1.0, 3.0] {
            let path = orbit(37.0, turns, None);
            let (first, _) = path.at(0.0, 250, DVec3::ZERO);
            let (wrapped, _) = path.at(250.0, 250, DVec3::ZERO);
            assert_close(first, wrapped);
            let (last, _) = path.at(249.0, 250, DVec3::ZERO);
            assert!(last.distance(first) > 0.1);
        }
    }

    #[test]
    fn an_explicit_look_at_wins() {
        let p = DVec3::new(0.0, 0.0, 5.0);
        assert_eq!(orbit(0.0, 1.0, Some(p)).at(7.0, 100, DVec3::ONE).1, p);
    }

    #[test]
    fn splines_are_delegated() {
        use super::super::spline::Key;
        let keys = vec![
            Key {
                frame: 0,
                position: DVec3::ZERO,
                look_at: None,
                ease: Default::default(),
            },
            Key {
                frame: 4,
                position: DVec3::X,
                look_at: None,
                ease: Default::default(),
            },
        ];
        let path = CameraPath::Spline(Spline::new(keys, false, false, None).unwrap());
        assert_eq!(path.at(4.0, 5, DVec3::ONE), (DVec3::X, DVec3::ONE));
        assert_eq!(path.name(), "spline");
    }
}
