//! `whitted-cmd`: what the two command lines (`raytrace`, `animate`) and the animation
//! pipeline (`whitted-anim`) share, below the pipeline so that `raytrace` is built
//! without it:
//!
//! - `process`: the processor check, the worker pool, SIGINT and SIGTERM;
//! - `progress`: the rows poller that moves the progress bars, and cost-weighted ETAs;
//! - `stats`: the `--stats` JSON line and the process's CPU time;
//! - `size`: the `WIDTHxHEIGHT` value both commands take.

#![warn(missing_docs)]

pub mod process;
pub mod progress;
pub mod size;
pub mod stats;
