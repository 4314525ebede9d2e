//! `raytrace [SCENE] [-o OUT] [--size WxH] [--fov DEG] [--roll DEG]
//! [--samples N | --aa adaptive[:T[:D]]] [--threads N] [--display tev] [--passes LIST] [--pass NAME] [--exr-depth half|float]
//! [--colour srgb|linear] [--spd] [--stats] [--info]`: one image from a Scene.txt (the report's main()) or an NFF file
//! (`*.nff`; `--spd` draws it by the SPD's testing procedure, `--stats` prints the ray
//! counts as a JSON line last on standard error; `--info` draws nothing and prints what the
//! scene holds, `whitted::info`). It parses the command line (`cli`),
//! shows a progress bar, and calls the library (`whitted::still::Job`); exit statuses
//! follow `whitted::exit` (2 bad input, 1 a failed write, 130/143 stopped by SIGINT/SIGTERM).

pub mod cli;

use anyhow::Context;
use clap::Parser;
use cli::Args;
use indicatif::{ProgressBar, ProgressStyle};
use std::io::IsTerminal;
use std::process::ExitCode;
use whitted::exit::Outcome;
use whitted::still::{Job, StillError};
use whitted_cmd::process;
use whitted_cmd::progress::RowPoller;

/// A bar of the image's rows on a terminal (hidden otherwise, or with `--quiet`), moved by
/// the library's rows poller until it is finished.
fn progress(rows: u32, quiet: bool) -> (ProgressBar, Option<RowPoller>) {
    if quiet || !std::io::stderr().is_terminal() {
        return (ProgressBar::hidden(), None);
    }
    let bar = ProgressBar::new(u64::from(rows));
    let style = ProgressStyle::with_template(
        "{elapsed_precise} [{wide_bar}] {pos}/{len} rows  {per_sec}  ETA {eta}",
    )
    .unwrap_or_else(|_| ProgressStyle::default_bar());
    bar.set_style(style.progress_chars("=> "));
    let watch = bar.clone();
    let poll = RowPoller::start(move |rows| watch.set_position(rows));
    (bar, Some(poll))
}

/// `--info`: what the scene holds on standard output, its warnings on standard error.
fn info(args: &Args) -> anyhow::Result<()> {
    let info = whitted::info::describe(&args.request())?;
    if !args.quiet {
        for w in &info.warnings {
            eprintln!("raytrace: warning: {w}");
        }
    }
    print!("{info}");
    Ok(())
}

fn run(args: Args) -> anyhow::Result<()> {
    if args.info {
        return info(&args);
    }
    let started = std::time::Instant::now();
    process::exit_on_signals();
    let job = Job::prepare(&args.request())?;
    let pool = process::pool(args.threads).context("cannot start the worker threads")?;
    if !args.quiet {
        if let Some(w) = job.non_square() {
            eprintln!("raytrace: warning: {w}");
        }
        if let Some(w) = job.aspect_warning() {
            eprintln!("raytrace: warning: {w}");
        }
        for w in job.mesh_warnings() {
            eprintln!("raytrace: warning: {w}");
        }
        if let Some(e) = pool.install(|| job.enormous()) {
            eprintln!("raytrace: warning: {e} (Ctrl-C stops)");
        }
    }
    let (bar, poll) = progress(job.height(), args.quiet);
    let done = pool.install(|| job.run());
    drop(poll);
    bar.finish_and_clear();
    let done = done?;
    if !args.quiet {
        eprintln!("raytrace: {}", done.summary());
    }
    // Last, so that `tail -1` of standard error is the stats line.
    if args.stats {
        let wall = started.elapsed().as_secs_f64();
        let cpu = whitted_cmd::stats::cpu_seconds();
        eprintln!("{}", whitted_cmd::stats::line(&done.rays, wall, cpu));
    }
    Ok(())
}

/// `raytrace`'s whole run: the exit status of the command line the process was given.
pub fn main() -> ExitCode {
    if let Err(e) = process::check_cpu() {
        eprintln!("raytrace: {e}");
        return ExitCode::from(Outcome::BadInput.code());
    }
    match run(Args::parse()) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("raytrace: {e}");
            let outcome = e
                .downcast_ref::<StillError>()
                .map_or(Outcome::Failed, StillError::outcome);
            ExitCode::from(outcome.code())
        }
    }
}
