//! The render farm's subcommands: `job` (an OpenJD template) and `estimate`.

use super::{Common, EncodingArgs, MAX_SHARDS};
use clap::Args;
use std::path::PathBuf;
use whitted_anim::commands::farm::JobRequest;

#[derive(Args, Debug)]
pub struct JobArgs {
    #[command(flatten)]
    pub common: Common,
    /// Write an Open Job Description template (the only kind for now).
    #[arg(long, required = true)]
    pub openjd: bool,
    /// The frame folder the job renders into (default: the manifest's `[output] dir`).
    #[arg(long, value_name = "DIR")]
    pub out_dir: Option<PathBuf>,
    /// Write the template into this file (default: standard output).
    #[arg(short, long, value_name = "FILE")]
    pub out: Option<PathBuf>,
    /// Write the template over an existing file that animate did not write.
    #[arg(long)]
    pub force: bool,
    /// Frames a task.
    #[arg(long, value_name = "N", conflicts_with = "chunk_seconds",
          value_parser = clap::value_parser!(u32).range(1..))]
    pub chunk: Option<u32>,
    /// About this many seconds a task, from the cost estimate (renders a pre-pass and one
    /// frame to find out).
    #[arg(long, value_name = "S", value_parser = clap::value_parser!(u32).range(1..))]
    pub chunk_seconds: Option<u32>,
    /// The video step's encoding (a job of every frame has one), as `encode`'s.
    #[command(flatten)]
    pub encoding: EncodingArgs,
}

#[derive(Args, Debug)]
pub struct EstimateArgs {
    #[command(flatten)]
    pub common: Common,
    /// Also the predicted cost of each of N shards, balanced and by equal counts.
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..=MAX_SHARDS))]
    pub shards: Option<u32>,
}

impl JobArgs {
    /// The library's request.
    pub fn request(&self) -> JobRequest {
        JobRequest {
            manifest: self.common.manifest.clone().unwrap_or_default(),
            frames: self.common.frames.clone(),
            out_dir: self.out_dir.clone(),
            out: self.out.clone(),
            chunk: self.chunk,
            chunk_seconds: self.chunk_seconds,
            force: self.force,
            encoding: self.encoding.encoding(),
        }
    }
}
