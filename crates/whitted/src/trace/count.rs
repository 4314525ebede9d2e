//! How many rays of each kind a render cast: camera, reflected, refracted, shadow.

/// Counts of rays cast, for rays-per-second figures and the SPD's table.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RayCount {
    /// Camera rays.
    pub primary: u64,
    /// Reflected and refracted rays (`reflect + refract`).
    pub secondary: u64,
    /// Rays towards lights.
    pub shadow: u64,
    /// Camera rays that hit an object.
    pub eye_hits: u64,
    /// Reflected rays (total internal reflection included).
    pub reflect: u64,
    /// Refracted rays.
    pub refract: u64,
}

impl RayCount {
    /// All rays: primary, secondary and shadow.
    pub fn total(&self) -> u64 {
        self.primary + self.secondary + self.shadow
    }
}

impl std::ops::Add for RayCount {
    type Output = RayCount;
    fn add(self, o: RayCount) -> RayCount {
        RayCount {
            primary: self.primary + o.primary,
            secondary: self.secondary + o.secondary,
            shadow: self.shadow + o.shadow,
            eye_hits: self.eye_hits + o.eye_hits,
            reflect: self.reflect + o.reflect,
            refract: self.refract + o.refract,
        }
    }
}
