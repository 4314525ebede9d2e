//! The animation pipeline of SPEC §5-§11, one home per idea:
//!
//! - `manifest`: the TOML manifest, read and checked, every refusal located;
//! - `timeline`: values over time — camera paths (circle, spline), tracks, easing, motion
//!   blur — answering "what is frame t?" with a scene and a camera;
//! - `project`: a manifest with its scene and timeline, loaded once (`Project::load`), and
//!   `Animation`, which draws any frame of it;
//! - producing frames: `run` (the render command: frames, destination, checks first),
//!   `pipeline` (folders and streams, reporting `events`), `frames::select` (frame lists,
//!   shards, a render farm's task index), `provenance` (what made a frame), `status` (which
//!   frames are up to date), `video` (ffmpeg);
//! - checking frames: `check` (`animate check` and `bless`: idiff metrics, FLIP, one
//!   report value and its exporters: table, JSON, JUnit, HTML);
//! - `preview`: quick pictures for people (a GIF, a contact sheet, a plot of the paths);
//! - `error`: why a run stopped, and its exit status.

pub mod check;
pub mod error;
pub mod events;
pub mod frames;
pub mod manifest;
pub mod pipeline;
pub mod preview;
pub mod project;
pub mod provenance;
pub mod run;
pub mod status;
pub mod timeline;
pub mod video;

pub use error::AnimError;
pub use events::{Event, Reporter};
pub use frames::select;
pub use manifest::{Manifest, ManifestError};
pub use project::{Animation, Project, Settings};
pub use timeline::{CameraPath, Timeline};
