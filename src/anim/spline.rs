//! STUB — being written. Centripetal Catmull-Rom camera splines (SPEC §5).

use glam::DVec3;

/// A spline key: a frame, a position and an optional look-at point.
#[derive(Clone, Debug, PartialEq)]
pub struct Key {
    pub frame: u32,
    pub position: DVec3,
    pub look_at: Option<DVec3>,
}

/// A camera spline through keys.
#[derive(Clone, Debug, PartialEq)]
pub struct Spline {
    pub keys: Vec<Key>,
    pub closed: bool,
    pub constant_speed: bool,
    /// A fixed look-at point for the whole path.
    pub look_at: Option<DVec3>,
}
