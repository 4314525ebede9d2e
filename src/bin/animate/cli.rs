//! The command line of `animate` (clap): what each subcommand and option is. The work is
//! the library's; `main.rs` turns these into its calls.

use clap::{Args, Parser, Subcommand};
use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use whitted::output::ImageFormat;
use whitted_anim::check::export::{Exporter, Html, Json, Junit, Sink, Table};
use whitted_anim::check::Overrides;
use whitted_anim::frames::run::{Destination, Encoding, Policy};
use whitted_anim::preview::{self, PreviewOptions};
use whitted_anim::select::{process_env, SelectError, Shard};
use whitted_anim::{AnimError, Manifest, Project};

use super::report::Usage;

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
    /// folder's state, picking, and live reload of the manifest and scene. Ctrl-C stops.
    View(ViewArgs),
}

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
}

#[derive(Args, Debug)]
pub struct RenderArgs {
    #[command(flatten)]
    pub common: Common,
    /// The frame folder, instead of the manifest's `[output] dir`.
    #[arg(short, long, value_name = "DIR")]
    pub out: Option<PathBuf>,
    /// Render the K-th of N contiguous chunks of the frames (0-based), or `auto`: the
    /// index from a Slurm array job, Kubernetes Indexed Job or AWS Batch array job.
    #[arg(long, value_name = "K/N|auto")]
    pub shard: Option<Shard>,
    /// Split the frames into shards of equal predicted cost (rays of a 1/8-size pre-pass)
    /// instead of equal frame counts; still contiguous.
    #[arg(long, requires = "shard")]
    pub balance: bool,
    /// The number of tasks, for `--shard auto` under Kubernetes or AWS Batch (under Slurm
    /// it must agree with the array's size).
    #[arg(long, value_name = "N", requires = "shard",
          value_parser = clap::value_parser!(u32).range(1..=MAX_SHARDS))]
    pub shards: Option<u32>,
    /// Render only the frames that are missing or whose recorded inputs differ from what
    /// the manifest now gives them; leave up-to-date files untouched.
    #[arg(long, conflicts_with_all = ["stdout", "video"])]
    pub resume: bool,
    /// With --resume: decode every frame kept (as `status --verify`), so that damage the
    /// default checks cannot see is rendered again.
    #[arg(long, requires = "resume")]
    pub verify: bool,
    /// Write the frames in order to standard output instead of files: raw (RGB bytes),
    /// ppm or png.
    #[arg(long, value_name = "FORMAT", value_parser = stream_format,
          conflicts_with_all = ["video", "out"])]
    pub stdout: Option<ImageFormat>,
    /// Write over what a run otherwise refuses to: frames in the folder recorded by another
    /// manifest, files under frame names with no record, an existing --video file, binary
    /// --stdout frames on a terminal.
    #[arg(long)]
    pub force: bool,
    /// Pipe the frames into ffmpeg (from PATH) to make this video file (written beside
    /// it under a temporary name, renamed when ffmpeg succeeds).
    #[arg(long, value_name = "FILE", conflicts_with = "out")]
    pub video: Option<PathBuf>,
    #[command(flatten)]
    pub encoding: EncodingArgs,
    /// Report progress as JSON lines on standard error (for schedulers and scripts)
    /// instead of a progress bar.
    #[arg(long)]
    pub events: bool,
    /// Also show each frame as it finishes in a running tev viewer: `tev` (at
    /// 127.0.0.1:14158) or `tev=HOST:PORT`. A missing viewer is a warning.
    #[arg(long, value_name = "tev[=HOST:PORT]")]
    pub display: Option<whitted::display::Display>,
}

/// How ffmpeg encodes a video (`--video`, `animate encode`).
#[derive(Args, Debug, Clone, Default)]
pub struct EncodingArgs {
    /// The video codec, ffmpeg's `-c:v` (e.g. libx264, libx265, libvpx-vp9; default:
    /// ffmpeg's for the file's extension).
    #[arg(long, value_name = "CODEC")]
    pub codec: Option<String>,
    /// The quality, ffmpeg's `-crf` (lower is better: 0 to 63; default: the codec's).
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u8).range(0..=63))]
    pub crf: Option<u8>,
    /// The video's pixel format, ffmpeg's output `-pix_fmt` (default yuv420p, which plays
    /// everywhere).
    #[arg(long, value_name = "FORMAT")]
    pub pix_fmt: Option<String>,
}

impl EncodingArgs {
    pub fn encoding(&self) -> Encoding {
        Encoding {
            codec: self.codec.clone(),
            crf: self.crf,
            pix_fmt: self.pix_fmt.clone(),
        }
    }

    fn given(&self) -> bool {
        self.codec.is_some() || self.crf.is_some() || self.pix_fmt.is_some()
    }
}

impl RenderArgs {
    /// What the run may keep and replace.
    pub fn policy(&self) -> Result<Policy, Usage> {
        if self.encoding.given() && self.video.is_none() {
            let why = "--codec, --crf and --pix-fmt apply to --video (and `animate encode`)";
            return Err(Usage(why.into()));
        }
        Ok(Policy {
            resume: self.resume,
            verify: self.verify,
            force: self.force,
            encoding: self.encoding.encoding(),
        })
    }

    /// The shard of this task: `K/N`, or resolved from the scheduler's environment.
    pub fn shard(&self) -> Result<Option<(u32, u32)>, AnimError> {
        let resolve = |s: Shard| s.resolve(process_env, self.shards, "--shards");
        let shard = self.shard.map(resolve).transpose();
        Ok(shard.map_err(SelectError::from)?)
    }

    /// Where the frames go: a stream, a video, or a folder (`-o`, else the manifest's).
    /// Binary frames are refused on a terminal unless forced.
    pub fn destination(&self, m: &Manifest) -> Result<Destination, Usage> {
        if self.stdout.is_some() && std::io::stdout().is_terminal() && !self.force {
            let why = "refusing to write binary frames to a terminal: redirect standard output, or add --force";
            return Err(Usage(why.into()));
        }
        Ok(match (self.stdout, &self.video) {
            (Some(format), _) => Destination::Stream(format),
            (None, Some(video)) => Destination::Video(video.clone()),
            (None, None) => Destination::Folder(self.out.clone().unwrap_or(m.output.dir.clone())),
        })
    }
}

fn stream_format(s: &str) -> Result<ImageFormat, String> {
    match ImageFormat::from_name(s) {
        Some(f @ (ImageFormat::Raw | ImageFormat::Ppm | ImageFormat::Png)) => Ok(f),
        _ => Err("expected raw, ppm or png".into()),
    }
}

#[derive(Args, Debug)]
pub struct BlessArgs {
    #[command(flatten)]
    pub common: Common,
    /// The references folder, instead of the manifest's `[check] references`.
    #[arg(long, value_name = "DIR")]
    pub references: Option<PathBuf>,
    /// bless: replace references that another manifest recorded; check: write --junit and
    /// --html over files that animate did not write.
    #[arg(long)]
    pub force: bool,
}

#[derive(Args, Debug)]
pub struct CheckArgs {
    #[command(flatten)]
    pub bless: BlessArgs,
    /// Where images of failing frames go (default: the frame folder's name + `-check`).
    #[arg(long, value_name = "DIR")]
    pub report: Option<PathBuf>,
    /// A pixel fails when a channel differs by more than this (0..255).
    #[arg(long)]
    pub fail: Option<u8>,
    /// A frame fails when more than this percentage of its pixels fail.
    #[arg(long, value_name = "PERCENT")]
    pub fail_percent: Option<f64>,
    /// A frame fails when any channel differs by more than this (0..255).
    #[arg(long)]
    pub hard_fail: Option<u8>,
    /// A frame fails when its mean FLIP error (NVIDIA's perceptual metric, 0..1) is
    /// above this.
    #[arg(long, value_name = "X")]
    pub flip: Option<f64>,
    /// Print the results as JSON on standard output instead of a table.
    #[arg(long)]
    pub json: bool,
    /// Also write the results as JUnit XML into this file.
    #[arg(long, value_name = "FILE")]
    pub junit: Option<PathBuf>,
    /// Also write a report page, DIR/index.html, with the images of failing frames.
    #[arg(long, value_name = "DIR")]
    pub html: Option<PathBuf>,
}

impl CheckArgs {
    /// The command line's share of the check's options.
    pub fn overrides(&self) -> Overrides<'_> {
        Overrides {
            frames: self.bless.common.frames.as_deref(),
            references: self.bless.references.as_deref(),
            report: self.report.as_deref(),
            fail: self.fail,
            fail_percent: self.fail_percent,
            hard_fail: self.hard_fail,
            flip: self.flip,
        }
    }

    /// The exporters asked for: the table or JSON on standard output, JUnit, HTML.
    pub fn exporters(&self) -> Vec<Box<dyn Exporter>> {
        let mut out: Vec<Box<dyn Exporter>> = match self.json {
            true => vec![Box::new(Json(Sink::Stdout))],
            false => vec![Box::new(Table(Sink::Stdout))],
        };
        if let Some(file) = &self.junit {
            out.push(Box::new(Junit(file.clone())));
        }
        if let Some(dir) = &self.html {
            out.push(Box::new(Html(dir.clone())));
        }
        out
    }
}

#[derive(Args, Debug)]
pub struct StatusArgs {
    #[command(flatten)]
    pub common: Common,
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
pub struct EncodeArgs {
    /// The animation manifest (TOML) whose frames are encoded, at its fps.
    pub manifest: PathBuf,
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
}

#[derive(Args, Debug)]
pub struct EstimateArgs {
    #[command(flatten)]
    pub common: Common,
    /// Also the predicted cost of each of N shards, balanced and by equal counts.
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..=MAX_SHARDS))]
    pub shards: Option<u32>,
}
