//! `animate MANIFEST.toml`: renders the frames of an animation manifest into a folder,
//! or streams them to standard output or ffmpeg; `status`, `stats`, `preview`, `check`, `bless` and
//! `view` are subcommands. This file turns the command line (`cli`) into library calls
//! (`whitted_anim::commands`, `render` for the render itself) and their outcome into an
//! exit status (`whitted::exit`); `report` shows progress and results.

mod cli;
mod render;
mod report;

use anyhow::Context;
use clap::Parser;
use cli::{BlessArgs, CheckArgs, Cli, Command, EncodeArgs, JobArgs, PreviewArgs, ViewArgs};
use std::process::ExitCode;
use std::time::Instant;
use whitted::exit::Outcome;
use whitted::fileloc::shown;
use whitted_anim::commands::{self, check::CheckRequest};
use whitted_anim::view::ViewOptions;
use whitted_anim::{check, preview, AnimError, Animation};

fn pool(threads: Option<u32>) -> anyhow::Result<rayon::ThreadPool> {
    whitted_anim::process::pool(threads).context("cannot start the worker threads")
}

fn encode(args: EncodeArgs) -> anyhow::Result<Outcome> {
    let project = whitted_anim::Project::load_draft(&args.manifest, &args.draft.draft())?;
    let stop = whitted_anim::process::watch_signals("animate");
    let bar = report::bar::Bar::new(project.manifest.frames as usize, args.quiet);
    let start = Instant::now();
    let encoded = commands::folder::encode(&project, &args.request(), &bar, &stop);
    bar.finish();
    let e = encoded?;
    if !args.quiet {
        let (secs, fps) = (start.elapsed().as_secs_f64(), project.manifest.fps);
        let (n, dir, video) = (e.summary.rendered, shown(&e.dir), shown(&e.video));
        eprintln!("animate: encoded {n} frames of {dir} at {fps} fps in {secs:.2} s -> {video}");
    }
    Ok(Outcome::Success)
}

fn view(args: ViewArgs) -> anyhow::Result<Outcome> {
    let options = ViewOptions {
        manifest: args.manifest.clone(),
        bind: args.bind,
        port: args.port,
        threads: args.threads,
        draft: args.draft.draft(),
    };
    let stop = whitted_anim::process::watch_signals_quietly();
    let ready = |url: &str| report::view_ready(&args.manifest, url, args.bind);
    let sig = whitted_anim::view::serve(&options, &stop, &ready)?;
    Ok(Outcome::Interrupted(sig))
}

fn bless(args: BlessArgs) -> anyhow::Result<Outcome> {
    let (c, project) = (&args.common, args.common.load_draft(&args.draft)?);
    let anim = Animation::new(&project)?;
    let (list, refs) = (c.frames.as_deref(), args.references.as_deref());
    let (frames, refs) =
        check::targets(&project.manifest, list, refs).map_err(report::with_flags)?;
    let bless = || check::bless(&anim, &frames, &refs, args.force);
    let blessed = pool(c.threads)?.install(bless)?;
    if !c.quiet {
        let (n, counts) = (blessed.len(), check::bless_counts(&blessed));
        eprintln!(
            "animate: blessed {n} reference(s) in {}: {counts}",
            shown(&refs)
        );
    }
    Ok(Outcome::Success)
}

fn check(args: CheckArgs) -> anyhow::Result<Outcome> {
    let project = args.bless.common.load_draft(&args.bless.draft)?;
    let overrides = args.overrides();
    let options =
        check::CheckOptions::new(&project.manifest, &overrides).map_err(report::with_flags)?;
    let request = CheckRequest {
        options,
        exporters: args.exporters(),
        outputs: args.outputs(),
        force: args.bless.force,
    };
    let pool = pool(args.bless.common.threads)?;
    Ok(pool.install(|| commands::check::check(&project, &request))?)
}

fn job(args: JobArgs) -> anyhow::Result<Outcome> {
    let project = args.common.load()?;
    let pool = pool(args.common.threads)?;
    let written = pool.install(|| commands::farm::job(&project, &args.request(), &mut stdout()))?;
    let job = match written {
        Ok(job) => job,
        Err(cut_short) => return Ok(cut_short),
    };
    if !args.common.quiet {
        let (n, size) = (job.frames, job.chunk);
        eprintln!("animate: an OpenJD template of {n} frames in chunks of {size}");
    }
    Ok(Outcome::Success)
}

fn preview(args: PreviewArgs) -> anyhow::Result<Outcome> {
    let bar = report::bar::Bar::new(0, args.quiet);
    let start = Instant::now();
    let s = pool(args.threads)?.install(|| preview::run(&args.options(), &|d, t| bar.set(d, t)));
    bar.finish();
    if !args.quiet {
        report::previewed(&s?, start);
    }
    Ok(Outcome::Success)
}

fn stdout() -> std::io::StdoutLock<'static> {
    std::io::stdout().lock()
}

fn run(cli: Cli) -> anyhow::Result<Outcome> {
    Ok(match cli.command {
        None => render::render(cli.render)?,
        Some(Command::Bless(args)) => bless(args)?,
        Some(Command::Check(args)) => check(args)?,
        Some(Command::Status(a)) => {
            let (project, pool) = (a.common.load_draft(&a.draft)?, pool(a.common.threads)?);
            pool.install(|| commands::status::status(&project, &a.request(), &mut stdout()))?
        }
        Some(Command::Stats(a)) => {
            let (project, pool) = (a.common.load_draft(&a.draft)?, pool(a.common.threads)?);
            pool.install(|| commands::stats::stats(&project, &a.request(), &mut stdout()))?
        }
        Some(Command::Preview(args)) => preview(args)?,
        Some(Command::Job(args)) => job(args)?,
        Some(Command::Estimate(a)) => {
            let (project, pool) = (a.common.load()?, pool(a.common.threads)?);
            let list = a.common.frames.as_deref();
            pool.install(|| commands::farm::estimate(&project, list, a.shards, &mut stdout()))?
        }
        Some(Command::Encode(args)) => encode(args)?,
        Some(Command::Clean(a)) => {
            let project = whitted_anim::Project::load(&a.manifest)?;
            commands::folder::clean(&project, &a.request(), &mut stdout())?
        }
        Some(Command::View(args)) => view(args)?,
    })
}

/// Says why a command failed, with the hint that helps.
fn say(e: &anyhow::Error) {
    eprintln!("animate: {}", report::message(e));
    if let Some(hint) = e.downcast_ref::<AnimError>().and_then(report::hint) {
        eprintln!("animate: hint: {hint}");
    }
}

fn main() -> ExitCode {
    if let Err(e) = whitted_anim::process::check_cpu() {
        eprintln!("animate: {e}");
        return ExitCode::from(Outcome::BadInput.code());
    }
    match run(Cli::parse()) {
        Ok(outcome) => ExitCode::from(outcome.code()),
        Err(e) => {
            say(&e);
            ExitCode::from(report::outcome(&e).code())
        }
    }
}
