//! The command lines of the whitted ray tracer, as a library the two binaries call
//! (`src/bin/raytrace.rs`, `src/bin/animate.rs` are one line each) and the tests read:
//!
//! - `raytrace`: one image from a Scene.txt or NFF file (`raytrace::cli` its arguments);
//! - `animate` (with the `anim` feature, on by default): the animation pipeline's
//!   command line (`animate::cli`), its subcommands and its reports.
//!
//! `raytrace` needs only the tracer (`whitted`) and what the commands share
//! (`whitted-cmd`): `cargo build --release --no-default-features --bin raytrace` builds it
//! without the pipeline.

#[cfg(feature = "anim")]
pub mod animate;
pub mod raytrace;
