//! The animation pipeline of SPEC §5-§11, one home per idea:
//!
//! - `manifest`: the TOML manifest, read and checked, every refusal located;
//! - `timeline`: values over time — camera paths (circle, spline), tracks, easing, motion
//!   blur — answering "what is frame t?" with a scene and a camera;
//! - `project`: a manifest with its scene and timeline, loaded once (`Project::load`), and
//!   `Animation`, which draws any frame of it;
//! - `frames`: producing frames — selection and shards, the render command, the pipeline
//!   and its events, provenance and status, video;
//! - checking frames: `check` (`animate check` and `bless`: idiff metrics, FLIP, one
//!   report value and its exporters: table, JSON, JUnit, HTML);
//! - `job`: job templates for render farms (Open Job Description);
//! - `preview`: quick pictures for people (a GIF, a contact sheet, a plot of the paths);
//! - `error`: why a run stopped, and its exit status.

pub mod check;
pub mod error;
pub mod frames;
pub mod job;
pub mod manifest;
pub mod preview;
pub mod project;
pub mod timeline;

pub use error::AnimError;
pub use frames::events::{Event, Reporter};
pub use frames::select;
pub use manifest::{Manifest, ManifestError};
pub use project::{Animation, Project, Settings};
pub use timeline::{CameraPath, Timeline};
