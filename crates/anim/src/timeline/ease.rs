//! Easing and interpolation between two track keys (SPEC §7). A track or a key names them:
//!
//! ```toml
//! interpolation = "linear"   # linear (default) | smooth | step
//! ease = "in-out"            # none (default) | in | out | in-out; a key may set its own
//! ```
//!
//! Between keys (f0, a) and (f1, b), at time f: u = (f − f0)/(f1 − f0) and e = ease(u),
//! with none u, in u², out 1 − (1 − u)², in-out 3u² − 2u³. `linear` gives a + (b − a)·e;
//! `step` holds a until f1; `smooth` takes the centripetal Catmull-Rom curve through the
//! keys at e (in `track`).

/// How the parameter between two keys is shaped.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Ease {
    /// e = u: even pace.
    #[default]
    None,
    /// e = u²: starts slow, ends fast.
    In,
    /// e = 1 − (1 − u)²: starts fast, ends slow.
    Out,
    /// e = 3u² − 2u³: slow at both ends.
    InOut,
}

impl Ease {
    /// The names the manifest accepts, in the order messages list them.
    pub const NAMES: [&'static str; 4] = ["none", "in", "out", "in-out"];

    /// The ease a manifest names, if any.
    pub fn from_name(name: &str) -> Option<Ease> {
        match name {
            "none" => Some(Ease::None),
            "in" => Some(Ease::In),
            "out" => Some(Ease::Out),
            "in-out" => Some(Ease::InOut),
            _ => None,
        }
    }

    /// e = ease(u) for u in 0..1 (u outside is clamped first).
    pub fn apply(self, u: f64) -> f64 {
        let u = u.clamp(0.0, 1.0);
        match self {
            Ease::None => u,
            Ease::In => u * u,
            Ease::Out => 1.0 - (1.0 - u) * (1.0 - u),
            Ease::InOut => 3.0 * u * u - 2.0 * u * u * u,
        }
    }
}

/// How a track goes from one key's value to the next.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Interpolation {
    /// a + (b − a)·e: straight from key to key.
    #[default]
    Linear,
    /// The centripetal Catmull-Rom curve through the keys (smooth at keys).
    Smooth,
    /// Holds each key's value until the next key's frame.
    Step,
}

impl Interpolation {
    /// The names the manifest accepts.
    pub const NAMES: [&'static str; 3] = ["linear", "smooth", "step"];

    /// The interpolation a manifest names, if any.
    pub fn from_name(name: &str) -> Option<Interpolation> {
        match name {
            "linear" => Some(Interpolation::Linear),
            "smooth" => Some(Interpolation::Smooth),
            "step" => Some(Interpolation::Step),
            _ => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn eases_by_hand() {
        // u = 0.25: in 0.0625, out 1 − 0.5625 = 0.4375, in-out 3/16 − 2/64 = 0.15625.
        assert_eq!(Ease::None.apply(0.25), 0.25);
        assert_eq!(Ease::In.apply(0.25), 0.0625);
        assert_eq!(Ease::Out.apply(0.25), 0.4375);
        assert_eq!(Ease::InOut.apply(0.25), 0.15625);
        // u = 0.5: in-out is symmetric, 0.75 − 0.25 = 0.5.
        assert_eq!(Ease::InOut.apply(0.5), 0.5);
        // u = 0.75: in-out 27/16 − 54/64 = 0.84375.
        assert_eq!(Ease::InOut.apply(0.75), 0.84375);
    }

    #[test]
    fn every_ease_keeps_the_ends_and_clamps() {
        for ease in [Ease::None, Ease::In, Ease::Out, Ease::InOut] {
            assert_eq!(ease.apply(0.0), 0.0, "{ease:?}");
            assert_eq!(ease.apply(1.0), 1.0, "{ease:?}");
            assert_eq!(ease.apply(-3.0), 0.0, "{ease:?}");
            assert_eq!(ease.apply(7.0), 1.0, "{ease:?}");
        }
    }

    #[test]
    fn names_round_trip() {
        for name in Ease::NAMES {
            assert!(Ease::from_name(name).is_some(), "{name}");
        }
        for name in Interpolation::NAMES {
            assert!(Interpolation::from_name(name).is_some(), "{name}");
        }
        assert_eq!(Ease::from_name("inout"), None);
        assert_eq!(Interpolation::from_name("cubic"), None);
    }
}
