//! The animation pipeline of SPEC §5-§11, one home per idea:
//!
//! - `manifest`: the TOML manifest, read and checked, every refusal located (`refusal`:
//!   the error both `manifest` and `timeline` raise, so that neither imports the other);
//! - `timeline`: values over time — camera paths (circle, spline), tracks, easing, motion
//!   blur — answering "what is frame t?" with a scene and a camera;
//! - `project`: a manifest with its scene and timeline, loaded once (`Project::load`), and
//!   `Animation`, which draws any frame of it from the frame's plan (`FramePlan`: its
//!   path, states and digest, built once);
//! - `frames`: producing frames — selection and shards, the render command, the pipeline
//!   and its events, provenance and status, video;
//! - checking frames: `check` (`animate check` and `bless`: idiff metrics, FLIP, one
//!   report value and its exporters: table, JSON, JUnit, HTML);
//! - `guard`: outputs (reports, templates) that must not overwrite inputs or others' files;
//! - `commands`: the subcommands of `animate` as library calls (request in, text out);
//! - `job`: job templates for render farms (Open Job Description);
//! - `preview`: quick pictures for people (a GIF, a contact sheet, a plot of the paths);
//! - `view`: `animate view`, a page that shows the animation while it is made (live
//!   reload, picking, the folder's state);
//! - `error`: why a run stopped, and its exit status; `typo`: the "did you mean" of every
//!   message that refuses a name.

#![warn(missing_docs)]

pub mod check;
pub mod commands;
pub mod error;
pub mod frames;
pub mod guard;
pub mod job;
pub mod manifest;
pub mod preview;
pub mod project;
pub mod refusal;
pub mod timeline;
mod typo;
pub mod view;

pub use error::AnimError;
pub use frames::events::{Event, Reporter};
pub use frames::select;
pub use manifest::{Manifest, ManifestError};
pub use project::{Animation, Project, Settings};
pub use timeline::{CameraPath, Timeline};
