//! `animate MANIFEST.toml`: renders every frame of an animation manifest (SPEC §5) in
//! parallel into a folder, or streams them in order to standard output or ffmpeg.
//! Exit status: 0 success, 1 a frame failed to render or write, 2 bad input,
//! 130/143 interrupted by SIGINT/SIGTERM (finished frames are kept).

use clap::{Args, Parser, Subcommand, ValueEnum};
use indicatif::{ProgressBar, ProgressState, ProgressStyle};
use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::sync::atomic::AtomicUsize;
use std::sync::Arc;
use std::time::Instant;
use whitted::anim::check::export::{Exporter, Html, Json, Junit, Sink, Table};
use whitted::anim::check::{self, CheckError, CheckOptions, Missing, Overrides};
use whitted::anim::pipeline::{render_to_folder, render_to_stream, Project};
use whitted::anim::select::select;
use whitted::anim::video::render_to_video;
use whitted::anim::{AnimError, Animation, Summary};
use whitted::output::ImageFormat;

/// Render the frames of an animation manifest (a Scene.txt and a camera path).
#[derive(Parser, Debug)]
#[command(
    name = "animate",
    version,
    about,
    args_conflicts_with_subcommands = true,
    subcommand_negates_reqs = true
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
    #[command(flatten)]
    render: RenderArgs,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Render the `[check]` frames (or --frames) and compare them with the references
    /// (OpenImageIO idiff's rules). Exit 0 all pass, 1 any fails, 2 the check cannot run.
    Check(CheckArgs),
    /// Render the `[check]` frames (or --frames) and write them as the references.
    Bless(BlessArgs),
}

#[derive(Args, Debug)]
struct BlessArgs {
    #[command(flatten)]
    common: Common,
    /// The references folder, instead of the manifest's `[check] references`.
    #[arg(long, value_name = "DIR")]
    references: Option<PathBuf>,
}

#[derive(Args, Debug)]
struct CheckArgs {
    #[command(flatten)]
    bless: BlessArgs,
    /// Where images of failing frames go (default: the frame folder's name + `-check`).
    #[arg(long, value_name = "DIR")]
    report: Option<PathBuf>,
    /// A pixel fails when a channel differs by more than this (0..255).
    #[arg(long)]
    fail: Option<u8>,
    /// A frame fails when more than this percentage of its pixels fail.
    #[arg(long, value_name = "PERCENT")]
    fail_percent: Option<f64>,
    /// A frame fails when any channel differs by more than this (0..255).
    #[arg(long)]
    hard_fail: Option<u8>,
    /// A frame fails when its mean FLIP error (NVIDIA's perceptual metric, 0..1) is
    /// above this.
    #[arg(long, value_name = "X")]
    flip: Option<f64>,
    /// Print the results as JSON on standard output instead of a table.
    #[arg(long)]
    json: bool,
    /// Also write the results as JUnit XML into this file.
    #[arg(long, value_name = "FILE")]
    junit: Option<PathBuf>,
    /// Also write a report page, DIR/index.html, with the images of failing frames.
    #[arg(long, value_name = "DIR")]
    html: Option<PathBuf>,
}

/// Options shared by every subcommand.
#[derive(Args, Debug, Clone)]
struct Common {
    /// The animation manifest (TOML).
    #[arg(required = true)]
    manifest: Option<PathBuf>,
    /// Worker threads (default: all cores).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=1024))]
    threads: Option<u32>,
    /// Only these frames: `0-99`, `0,10,20-30` (inclusive ranges).
    #[arg(long, value_name = "LIST")]
    frames: Option<String>,
    /// No progress bar and no summary.
    #[arg(short, long)]
    quiet: bool,
}

impl Common {
    /// The manifest path; clap requires it wherever `Common` is parsed.
    fn manifest(&self) -> &Path {
        self.manifest.as_deref().unwrap_or(Path::new(""))
    }
}

/// How frames leave the program when they are not files.
#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
enum StreamFormat {
    Raw,
    Ppm,
    Png,
}

#[derive(Args, Debug)]
struct RenderArgs {
    #[command(flatten)]
    common: Common,
    /// The frame folder, instead of the manifest's `[output] dir`.
    #[arg(short, long, value_name = "DIR")]
    out: Option<PathBuf>,
    /// Render the K-th of N contiguous chunks of the frames (0-based), e.g. for
    /// `--shard $SLURM_ARRAY_TASK_ID/16`.
    #[arg(long, value_name = "K/N")]
    shard: Option<String>,
    /// Skip frames whose file already exists.
    #[arg(long, conflicts_with_all = ["stdout", "video"])]
    resume: bool,
    /// With --resume: accept a folder whose frames came from another scene or settings.
    #[arg(long, requires = "resume")]
    force: bool,
    /// Write the frames in order to standard output instead of files.
    #[arg(long, value_enum, value_name = "FORMAT", conflicts_with_all = ["video", "out"])]
    stdout: Option<StreamFormat>,
    /// Pipe the frames into ffmpeg (from PATH) to make this video file.
    #[arg(long, value_name = "FILE", conflicts_with = "out")]
    video: Option<PathBuf>,
}

fn progress_bar(total: usize, quiet: bool) -> ProgressBar {
    if quiet || !std::io::stderr().is_terminal() {
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::new(total as u64);
    let style = ProgressStyle::with_template(
        "{elapsed_precise} [{wide_bar}] {pos}/{len} frames  {fps}  ETA {eta}",
    )
    .unwrap_or_else(|_| ProgressStyle::default_bar())
    .with_key(
        "fps",
        |state: &ProgressState, w: &mut dyn std::fmt::Write| {
            let _ = write!(w, "{:.1} frames/s", state.per_sec());
        },
    );
    bar.set_style(style.progress_chars("=> "));
    bar
}

/// Stops the run between frames on SIGINT or SIGTERM; the flag holds the signal number.
fn watch_signals() -> Arc<AtomicUsize> {
    let stop = Arc::new(AtomicUsize::new(0));
    for sig in [signal_hook::consts::SIGINT, signal_hook::consts::SIGTERM] {
        // If a handler cannot be installed the default action (terminate) remains, and
        // temporary files are still never visible under final names.
        let _ = signal_hook::flag::register_usize(sig, Arc::clone(&stop), sig as usize);
    }
    stop
}

fn pool(threads: Option<u32>) -> Result<rayon::ThreadPool, AnimError> {
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads.unwrap_or(0) as usize)
        .build()
        .map_err(|e| AnimError::Usage(format!("cannot start the worker threads: {e}")))
}

fn render_command(args: RenderArgs) -> Result<(), AnimError> {
    let project = Project::load(args.common.manifest())?;
    let manifest = &project.manifest;
    let anim = Animation::new(manifest, &project.scene)?;
    let frames = select(
        manifest.frames,
        args.common.frames.as_deref(),
        args.shard.as_deref(),
    )?;
    for &f in &frames {
        anim.camera(f)?;
    }
    let stop = watch_signals();
    let pool = pool(args.common.threads)?;
    let progress = progress_bar(frames.len(), args.common.quiet);
    let start = Instant::now();

    let (summary, place) = if let Some(kind) = args.stdout {
        let format = match kind {
            StreamFormat::Raw => ImageFormat::Raw,
            StreamFormat::Ppm => ImageFormat::Ppm,
            StreamFormat::Png => ImageFormat::Png,
        };
        let mut out = std::io::BufWriter::with_capacity(1 << 20, std::io::stdout());
        let s =
            pool.install(|| render_to_stream(&anim, &frames, &mut out, format, &progress, &stop))?;
        (s, "standard output".to_string())
    } else if let Some(video) = &args.video {
        let s = pool.install(|| render_to_video(&anim, &frames, video, &progress, &stop))?;
        (s, video.display().to_string())
    } else {
        let dir = args
            .out
            .clone()
            .unwrap_or_else(|| manifest.output.dir.clone());
        project
            .record(&anim)
            .claim(&dir, args.resume && !args.force)?;
        let s =
            pool.install(|| render_to_folder(&anim, &frames, &dir, args.resume, &progress, &stop))?;
        (s, dir.display().to_string())
    };
    progress.finish_and_clear();
    if !args.common.quiet {
        report(&summary, start.elapsed().as_secs_f64(), &place);
    }
    Ok(())
}

fn bless_command(args: BlessArgs) -> Result<(), AnimError> {
    let project = Project::load(args.common.manifest())?;
    let anim = Animation::new(&project.manifest, &project.scene)?;
    let (frames, refs) = check::targets(
        &project.manifest,
        args.common.frames.as_deref(),
        args.references.as_deref(),
    )
    .map_err(with_flags)?;
    let paths = pool(args.common.threads)?.install(|| check::bless(&anim, &frames, &refs))?;
    if !args.common.quiet {
        eprintln!(
            "animate: blessed {} reference(s) in {}",
            paths.len(),
            refs.display()
        );
    }
    Ok(())
}

/// The library's check error, with the flag that settles it.
fn with_flags(e: CheckError) -> AnimError {
    let hint = match &e {
        CheckError::NoCheckSection { what, .. } => match what {
            Missing::Frames => "; name them with --frames",
            Missing::References => "; name it with --references",
        },
        CheckError::FailPercent(_) => " (--fail-percent or [check] fail_percent)",
        CheckError::Flip(_) => " (--flip or [check] flip)",
        CheckError::Frames(_) => "",
    };
    AnimError::Usage(format!("{e}{hint}"))
}

/// Runs a check; `Ok(false)` when a frame failed.
fn check_command(args: CheckArgs) -> Result<bool, AnimError> {
    let common = &args.bless.common;
    let project = Project::load(common.manifest())?;
    let anim = Animation::new(&project.manifest, &project.scene)?;
    let over = Overrides {
        frames: common.frames.as_deref(),
        references: args.bless.references.as_deref(),
        report: args.report.as_deref(),
        fail: args.fail,
        fail_percent: args.fail_percent,
        hard_fail: args.hard_fail,
        flip: args.flip,
    };
    let opts = CheckOptions::new(&project.manifest, &over).map_err(with_flags)?;
    let report = pool(common.threads)?.install(|| check::check(&anim, &opts))?;
    let mut exporters: Vec<Box<dyn Exporter>> = Vec::new();
    if args.json {
        exporters.push(Box::new(Json(Sink::Stdout)));
    } else {
        exporters.push(Box::new(Table(Sink::Stdout)));
    }
    if let Some(file) = args.junit {
        exporters.push(Box::new(Junit(file)));
    }
    if let Some(dir) = args.html {
        exporters.push(Box::new(Html(dir)));
    }
    for exporter in exporters {
        exporter
            .export(&report)
            .map_err(|e| AnimError::Usage(e.to_string()))?;
    }
    Ok(report.pass)
}

/// The one-line summary: frames, wall time, frames/s, rays/s.
fn report(s: &Summary, secs: f64, place: &str) {
    let secs = secs.max(1e-9);
    eprintln!(
        "animate: {} frames rendered ({} skipped) in {:.2} s: {:.2} frames/s, {:.1} Mrays/s -> {}",
        s.rendered,
        s.skipped,
        secs,
        s.rendered as f64 / secs,
        s.rays.total() as f64 / secs / 1e6,
        place
    );
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        None => render_command(cli.render).map(|()| true),
        Some(Command::Bless(args)) => bless_command(args).map(|()| true),
        Some(Command::Check(args)) => check_command(args),
    };
    match result {
        Ok(true) => ExitCode::SUCCESS,
        Ok(false) => ExitCode::from(1),
        Err(e) => {
            eprintln!("animate: {e}");
            ExitCode::from(e.exit_code())
        }
    }
}
