//! The animation pipeline of SPEC §5: a TOML manifest (`manifest`) names a base Scene.txt
//! and a keyframed camera path (`path`, `spline`); `pipeline` renders the frames with the
//! same library as `raytrace`, `select` picks subsets and shards, `record` fingerprints a
//! frame folder for `--resume`, `video` pipes into ffmpeg, and `check` is
//! `animate check` and `animate bless`.

pub mod check;
pub mod error;
pub mod manifest;
pub mod path;
pub mod pipeline;
pub mod record;
pub mod select;
pub mod spline;
pub mod video;

pub use error::AnimError;
pub use manifest::{Manifest, ManifestError};
pub use path::CameraPath;
pub use pipeline::{Animation, Summary};
