//! The render's options (the command without a subcommand): frames, shard, resume, where
//! the frames go (a folder, standard output, a video), ffmpeg's encoding, progress, the
//! hooks run after each frame and after the run.

use super::super::report::Usage;
use super::{Common, DraftArgs, MAX_SHARDS};
use clap::Args;
use std::io::IsTerminal;
use std::path::PathBuf;
use std::time::Duration;
use whitted::output::ImageFormat;
use whitted_anim::frames::hooks::Hook;
use whitted_anim::frames::run::{Destination, Encoding, Policy};
use whitted_anim::select::{process_env, SelectError, Shard};
use whitted_anim::{AnimError, Manifest};

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
    /// manifest, files under frame names with no record, the manifest's finals under a
    /// draft (`--size … -o` into their folder), an existing --video file, binary --stdout
    /// frames on a terminal.
    #[arg(long)]
    pub force: bool,
    /// Pipe the frames into ffmpeg (from PATH) to make this video file (written beside
    /// it under a temporary name, renamed when ffmpeg succeeds).
    #[arg(long, value_name = "FILE", conflicts_with = "out")]
    pub video: Option<PathBuf>,
    #[command(flatten)]
    pub encoding: EncodingArgs,
    #[command(flatten)]
    pub draft: DraftArgs,
    /// Report progress as JSON lines on standard error (for schedulers and scripts)
    /// instead of a progress bar.
    #[arg(long)]
    pub events: bool,
    /// Also show each frame as it finishes in a running tev viewer: `tev` (at
    /// 127.0.0.1:14158) or `tev=HOST:PORT`. A missing viewer is a warning.
    #[arg(long, value_name = "tev[=HOST:PORT]")]
    pub display: Option<whitted::display::Display>,
    /// Run CMD after each frame is written or found up to date, in the run's order of
    /// frames, with ANIMATE_FRAME, ANIMATE_PATH and ANIMATE_STATE (rendered, up-to-date,
    /// failed) in its environment. CMD is split into words as a shell would but not run
    /// by one (write `sh -c '…'` for that). A failing hook is reported with its output
    /// and makes the exit status 1; the render goes on.
    #[arg(long, value_name = "CMD", conflicts_with_all = ["stdout", "video"])]
    pub on_frame: Option<Hook>,
    /// Run CMD after the run however it ends, with ANIMATE_RENDERED, ANIMATE_FAILED (frame
    /// counts) and ANIMATE_EXIT (the run's exit status) in its environment; split into
    /// words as --on-frame is. A failing hook makes the exit status 1.
    #[arg(long, value_name = "CMD")]
    pub on_done: Option<Hook>,
    /// End a hook (its whole process group) that runs longer than SECONDS, and count it
    /// as failed (default: no limit; a hook always ends with a run stopped by a signal).
    #[arg(long, value_name = "SECONDS", value_parser = parse_timeout)]
    pub hook_timeout: Option<Duration>,
}

/// `--hook-timeout`: seconds, more than 0 and at most a year.
fn parse_timeout(s: &str) -> Result<Duration, String> {
    match s.parse::<f64>() {
        Ok(t) if t > 0.0 && t <= 365.0 * 86400.0 => Ok(Duration::from_secs_f64(t)),
        _ => Err(format!(
            "expected seconds, more than 0 and at most a year (31536000), found {s:?}"
        )),
    }
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
            allow_mixed: false,
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
        if let Some(dir) = &self.out {
            looks_like_an_image(dir)?;
        }
        Ok(match (self.stdout, &self.video) {
            (Some(format), _) => Destination::Stream(format),
            (None, Some(video)) => Destination::Video(video.clone()),
            (None, None) => Destination::Folder(self.out.clone().unwrap_or(m.output.dir.clone())),
        })
    }
}

/// Refuses `-o still.png`: `-o` names the frames' folder, and a path ending in an image
/// format's extension that is not already a folder is taken for a still's file name.
fn looks_like_an_image(dir: &std::path::Path) -> Result<(), Usage> {
    let ext = dir.extension().and_then(|e| e.to_str()).unwrap_or_default();
    if dir.is_dir() || ImageFormat::from_name(&ext.to_ascii_lowercase()).is_none() {
        return Ok(());
    }
    Err(Usage(format!(
        "-o names the folder the frames go into, and {} is the name of an image: write one \
         frame with `--frames N -o DIR` (DIR/frame_NNNN.{ext}), or a still with `raytrace`",
        dir.display()
    )))
}

fn stream_format(s: &str) -> Result<ImageFormat, String> {
    match ImageFormat::from_name(s) {
        Some(f @ (ImageFormat::Raw | ImageFormat::Ppm | ImageFormat::Png)) => Ok(f),
        _ => Err("expected raw, ppm or png".into()),
    }
}
