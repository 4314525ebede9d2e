//! The subcommands about a frame folder and its pictures: `status`, `stats`, `clean`, `encode`,
//! `preview` and `view`.

use super::{Common, DraftArgs};
use clap::Args;
use std::path::PathBuf;
use whitted_anim::commands::folder::{CleanRequest, EncodeRequest};
use whitted_anim::commands::stats::StatsRequest;
use whitted_anim::commands::status::StatusRequest;
use whitted_anim::preview::{self, PreviewOptions};

use super::EncodingArgs;

#[derive(Args, Debug)]
pub struct ViewArgs {
    /// The animation manifest (TOML).
    pub manifest: PathBuf,
    /// The port to listen on (0: any free port; the URL printed says which).
    #[arg(long, default_value_t = whitted_anim::view::DEFAULT_PORT)]
    pub port: u16,
    /// The address to listen on; loopback unless told otherwise.
    #[arg(long, value_name = "ADDR", default_value = "127.0.0.1")]
    pub bind: std::net::IpAddr,
    /// Worker threads for rendering (default: all cores).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=1024))]
    pub threads: Option<u32>,
    #[command(flatten)]
    pub draft: DraftArgs,
}

#[derive(Args, Debug)]
pub struct PreviewArgs {
    /// The animation manifest (TOML).
    pub manifest: PathBuf,
    /// The folder for the pictures (default: the frame folder's name + `-preview`).
    #[arg(short, long, value_name = "DIR")]
    pub out: Option<PathBuf>,
    /// Draw the frames at 1/K of their size.
    #[arg(long, value_name = "K", default_value_t = preview::DEFAULT_SCALE,
          value_parser = clap::value_parser!(u32).range(1..=1024))]
    pub scale: u32,
    /// One contact-sheet tile every N frames (default: about 24 tiles).
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..))]
    pub every: Option<u32>,
    /// Worker threads (default: all cores).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=1024))]
    pub threads: Option<u32>,
    /// No progress bar and no summary.
    #[arg(short, long)]
    pub quiet: bool,
}

impl PreviewArgs {
    pub fn options(&self) -> PreviewOptions {
        PreviewOptions {
            manifest: self.manifest.clone(),
            out: self.out.clone(),
            scale: self.scale,
            every: self.every,
        }
    }
}

#[derive(Args, Debug)]
pub struct StatusArgs {
    #[command(flatten)]
    pub common: Common,
    #[command(flatten)]
    pub draft: DraftArgs,
    /// The frame folder, instead of the manifest's `[output] dir`.
    #[arg(short, long, value_name = "DIR")]
    pub out: Option<PathBuf>,
    /// Print the states as JSON on standard output.
    #[arg(long)]
    pub json: bool,
    /// Also decode every frame (slower): finds damage that the default checks (PNG chunk
    /// CRCs, RAW pixel hashes, sizes and end markers) cannot, such as in a JPEG's data.
    #[arg(long)]
    pub verify: bool,
}

#[derive(Args, Debug)]
pub struct StatsArgs {
    #[command(flatten)]
    pub common: Common,
    #[command(flatten)]
    pub draft: DraftArgs,
    /// The frame folder, instead of the manifest's `[output] dir`.
    #[arg(short, long, value_name = "DIR")]
    pub out: Option<PathBuf>,
    /// Print the report as JSON on standard output.
    #[arg(long)]
    pub json: bool,
    /// Also draw seconds per frame against the prediction into this PNG.
    #[arg(long, value_name = "FILE.png")]
    pub plot: Option<PathBuf>,
}

impl StatsArgs {
    /// The library's request.
    pub fn request(&self) -> StatsRequest {
        StatsRequest {
            frames: self.common.frames.clone(),
            dir: self.out.clone(),
            json: self.json,
            plot: self.plot.clone(),
        }
    }
}

#[derive(Args, Debug)]
pub struct EncodeArgs {
    /// The animation manifest (TOML) whose frames are encoded, at its fps.
    pub manifest: PathBuf,
    #[command(flatten)]
    pub draft: DraftArgs,
    /// The frame folder, instead of the manifest's `[output] dir`.
    #[arg(long, value_name = "DIR")]
    pub dir: Option<PathBuf>,
    /// The video file (default: the frame folder's path with .mp4).
    #[arg(short, long, value_name = "VIDEO")]
    pub out: Option<PathBuf>,
    #[command(flatten)]
    pub encoding: EncodingArgs,
    /// Replace an existing video file.
    #[arg(long)]
    pub force: bool,
    /// Encode a folder whose frames are sound but mixed (drafts among finals, frames of
    /// another renderer version or other settings); missing or broken frames are still
    /// refused.
    #[arg(long)]
    pub allow_mixed: bool,
    /// No progress bar and no summary.
    #[arg(short, long)]
    pub quiet: bool,
}

#[derive(Args, Debug)]
pub struct CleanArgs {
    /// The animation manifest (TOML).
    pub manifest: PathBuf,
    /// The frame folder, instead of the manifest's `[output] dir`.
    #[arg(short, long, value_name = "DIR")]
    pub out: Option<PathBuf>,
    /// Say what would be removed, and remove nothing.
    #[arg(long)]
    pub dry_run: bool,
    /// Also remove files past the end that this manifest did not render (another
    /// manifest's frames, files with no record).
    #[arg(long)]
    pub force: bool,
}

impl StatusArgs {
    /// The library's request.
    pub fn request(&self) -> StatusRequest {
        StatusRequest {
            frames: self.common.frames.clone(),
            dir: self.out.clone(),
            json: self.json,
            verify: self.verify,
        }
    }
}

impl CleanArgs {
    /// The library's request.
    pub fn request(&self) -> CleanRequest {
        CleanRequest {
            dir: self.out.clone(),
            dry_run: self.dry_run,
            force: self.force,
        }
    }
}

impl EncodeArgs {
    /// The library's request.
    pub fn request(&self) -> EncodeRequest {
        EncodeRequest {
            dir: self.dir.clone(),
            video: self.out.clone(),
            encoding: self.encoding.encoding(),
            force: self.force,
            allow_mixed: self.allow_mixed,
        }
    }
}
