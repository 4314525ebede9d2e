//! The animation pipeline of SPEC §5: a TOML manifest (`manifest`) names a base Scene.txt
//! and a keyframed camera path (`path`, `spline`); `pipeline` renders the frames with the
//! same library as `raytrace`, `frames::select` picks subsets and shards (and reads a render
//! farm's task index), `record` fingerprints a frame folder for `--resume`, `video` pipes
//! into ffmpeg, and `diff` and `regress` are `animate check` and `animate bless`.

pub mod diff;
pub mod error;
pub mod frames;
pub mod manifest;
pub mod path;
pub mod pipeline;
pub mod record;
pub mod regress;
pub mod spline;
pub mod video;

pub use error::AnimError;
/// Kept so `crate::anim::select` paths still compile; the module lives in `frames`.
pub use frames::select;
pub use manifest::{Manifest, ManifestError};
pub use path::CameraPath;
pub use pipeline::{Animation, Summary};
