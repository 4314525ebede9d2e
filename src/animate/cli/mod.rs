//! The command line of `animate` (clap): what each subcommand and option is, one file per
//! group of subcommands (`render`: the render itself; `checks`: check and bless; `folder`:
//! status, stats, clean, encode, preview and view; `farm`: job and estimate), each turning its
//! options into the library's request. The work is the library's; `main.rs` calls it.

use clap::{Args, Parser, Subcommand};
use std::path::{Path, PathBuf};
use whitted::render::Adaptive;
use whitted_anim::project::draft::Draft;
use whitted_anim::{AnimError, Project};
use whitted_cmd::size::parse_size;

mod checks;
mod farm;
mod folder;
mod render;

pub use checks::{BlessArgs, CheckArgs};
pub use farm::{EstimateArgs, JobArgs};
pub use folder::{CleanArgs, EncodeArgs, PreviewArgs, StatsArgs, StatusArgs, ViewArgs};
pub use render::{EncodingArgs, RenderArgs};

/// The most shards, for clap's ranges.
const MAX_SHARDS: i64 = whitted::limits::MAX_SHARDS as i64;

const AFTER_HELP: &str = "\
Exit status: 0 success; 1 the run started and failed (a frame could not be rendered or
written, ffmpeg failed; `check`: a frame failed; `status`: frames are stale or missing);
2 nothing was rendered because the request cannot be carried out as given (bad arguments,
manifest or scene, an unusable output location, ffmpeg missing); 130/143 interrupted
(finished frames are kept; `--resume` completes the run).

Into ffmpeg without files:
  animate M.toml --stdout raw | ffmpeg -f rawvideo -pix_fmt rgb24 -s WxH -r FPS -i - out.mp4
  animate M.toml --stdout png | ffmpeg -f image2pipe -framerate FPS -i - out.mp4
(with --stdout raw, animate prints the exact -s and -r of the manifest on standard error)

The manifest format: docs/manifest.md; the Scene.txt format: docs/scene-format.md.";

/// Render the frames of an animation manifest: a Scene.txt, a camera and tracks over time.
#[derive(Parser, Debug)]
#[command(
    name = "animate",
    version,
    about,
    after_help = AFTER_HELP,
    args_conflicts_with_subcommands = true,
    subcommand_negates_reqs = true
)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Option<Command>,
    #[command(flatten)]
    pub render: RenderArgs,
}

#[derive(Subcommand, Debug)]
pub enum Command {
    /// Render the `[check]` frames (or --frames) and compare them with the references
    /// (OpenImageIO idiff's rules). Exit 0 all pass, 1 any fails, 2 the check cannot run.
    Check(CheckArgs),
    /// Render the `[check]` frames (or --frames) and write them as the references.
    Bless(BlessArgs),
    /// Say which frames of the folder are up to date, stale or missing, from the frames'
    /// recorded provenance; renders nothing. Exit 0 all up to date, 1 not, 2 bad input.
    Status(StatusArgs),
    /// What the frames cost, from the records each run writes beside them: totals (wall
    /// and CPU seconds, peak memory, rays by kind), the slowest frames, and the frames more
    /// than 2x off the pre-pass's prediction; `--plot` draws seconds per frame.
    Stats(StatsArgs),
    /// Write a render-farm job template: an Open Job Description template (AWS Deadline
    /// Cloud's format) with a chunked render step and a video step after it.
    Job(JobArgs),
    /// Print the predicted cost of the render per frame range and per shard, from a 1/8-size
    /// pre-pass, and the wall time expected on this machine from one timed frame.
    Estimate(EstimateArgs),
    /// Encode a rendered frame folder into a video with ffmpeg, without rendering: the
    /// folder must be complete and up to date. Exit 0 done, 1 ffmpeg failed, 2 not ready.
    Encode(EncodeArgs),
    /// Remove from the frame folder the files of frames past the end of the sequence (after
    /// `frames` was lowered) and the temporary files that killed runs left.
    Clean(CleanArgs),
    /// Write quick pictures for people into a folder: a looping GIF of every frame at 1/K
    /// size, a contact sheet of every N-th frame and a plot of the camera and tracked paths.
    Preview(PreviewArgs),
    /// Serve a page that shows the animation while you edit it: the current frame (a
    /// quarter size first, then whole), a timeline, play and step keys, the output
    /// folder's state, picking, the camera's and tracks' paths over the picture, the
    /// camera copied as a manifest key, an A/B wipe, and live reload of the manifest and
    /// scene. Ctrl-C stops.
    View(ViewArgs),
}

/// Options shared by every subcommand.
#[derive(Args, Debug, Clone)]
pub struct Common {
    /// The animation manifest (TOML).
    #[arg(required = true)]
    pub manifest: Option<PathBuf>,
    /// Worker threads (default: all cores).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=1024))]
    pub threads: Option<u32>,
    /// Only these frames, in fileseq's grammar: `0-99`, `0,10,20-30`, `0-99x5` (every 5th),
    /// `0-99y5` (the others), `0-99:5` (coarse to fine: x5, x4, … x1); rendered in that order.
    #[arg(long, value_name = "LIST", allow_hyphen_values = true)]
    pub frames: Option<String>,
    /// No progress bar and no summary.
    #[arg(short, long)]
    pub quiet: bool,
}

impl Common {
    /// The manifest's project (clap requires the manifest wherever `Common` is parsed).
    pub fn load(&self) -> Result<Project, AnimError> {
        Project::load(self.manifest.as_deref().unwrap_or(Path::new("")))
    }

    /// The manifest's project with a draft's overrides.
    pub fn load_draft(&self, draft: &DraftArgs) -> Result<Project, AnimError> {
        let path = self.manifest.as_deref().unwrap_or(Path::new(""));
        Project::load_draft(path, &draft.draft())
    }
}

/// A draft's overrides of the manifest, for one run (render, status, stats, encode, check,
/// bless, view): recorded in the frames, and written to the draft's own folder
/// (`DIR-draft-WxH`, `-sN`, `-aa`) unless told where.
#[derive(Args, Debug, Clone, Default)]
pub struct DraftArgs {
    /// Draft: frames of this size instead of the manifest's (WIDTHxHEIGHT, e.g. 160x120).
    #[arg(long, value_name = "WxH", value_parser = parse_size, conflicts_with = "scale")]
    pub size: Option<(u32, u32)>,
    /// Draft: frames at 1/K of the manifest's size (as `preview --scale K`).
    #[arg(long, value_name = "K", value_parser = clap::value_parser!(u32).range(1..=1024))]
    pub scale: Option<u32>,
    /// Draft: an N×N grid of samples per pixel instead of the manifest's anti-aliasing.
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..=16),
          conflicts_with = "aa")]
    pub samples: Option<u32>,
    /// Draft: adaptive anti-aliasing instead of the manifest's (as `raytrace --aa`).
    #[arg(long, value_name = "adaptive[:T[:D[:MEASURE]]]",
          value_parser = |s: &str| s.parse::<Adaptive>().map_err(|e| e.to_string()))]
    pub aa: Option<Adaptive>,
}

impl DraftArgs {
    /// The library's draft.
    pub fn draft(&self) -> Draft {
        Draft {
            size: self.size,
            scale: self.scale,
            samples: self.samples,
            aa: self.aa,
        }
    }
}
