//! The animation pipeline of SPEC §5: a TOML manifest (`manifest`) names a base Scene.txt
//! and a keyframed camera path (`path`, `spline`); the frames are rendered by the same
//! library as `raytrace`.

pub mod manifest;
pub mod path;
pub mod spline;

pub use manifest::{Manifest, ManifestError};
pub use path::CameraPath;
