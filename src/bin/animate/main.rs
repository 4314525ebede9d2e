//! `animate MANIFEST.toml`: renders the frames of an animation manifest into a folder,
//! or streams them to standard output or ffmpeg; `status`, `preview`, `check`, `bless` and
//! `view` are subcommands. This file turns the command line (`cli`) into library calls and their
//! outcome into an exit status (`whitted::exit`); `report` shows progress and results.

mod cli;
mod report;

use anyhow::Context;
use clap::Parser;
use cli::{BlessArgs, CheckArgs, Cli, Command, PreviewArgs, RenderArgs, StatusArgs, ViewArgs};
use std::process::ExitCode;
use std::time::Instant;
use whitted::anim::check::{self, CheckOptions};
use whitted::anim::frames::run;
use whitted::anim::frames::status::status;
use whitted::anim::view::ViewOptions;
use whitted::anim::{preview, AnimError, Animation, Reporter};
use whitted::display::{Display, Tev};
use whitted::exit::Outcome;
use whitted::output::ImageFormat;

fn pool(threads: Option<u32>) -> anyhow::Result<rayon::ThreadPool> {
    whitted::process::pool(threads).context("cannot start the worker threads")
}

fn render(args: RenderArgs) -> anyhow::Result<Outcome> {
    let c = &args.common;
    let project = c.load()?;
    let (m, mut anim) = (&project.manifest, Animation::new(&project)?);
    if let Some(Display::Tev(addr)) = &args.display {
        let observer = tev_observer(addr, &anim);
        anim = anim.observed(observer);
    }
    let shard = args.shard()?;
    let frames = run::frames_of(&anim, c.frames.as_deref(), shard)?;
    let destination = args.destination(m)?;
    if !c.quiet {
        report::announce(&anim, frames.len(), args.stdout == Some(ImageFormat::Raw));
    }
    let (stop, pool) = (whitted::process::watch_signals("animate"), pool(c.threads)?);
    if !c.quiet {
        pool.install(|| report::warn_if_enormous(&anim, &frames));
    }
    let bar = report::RowBar::new(frames.len(), anim.rows_per_frame(), c.quiet || args.events);
    let reporter: &dyn Reporter = if args.events {
        &report::JsonLines
    } else {
        &bar
    };
    let mut out = std::io::BufWriter::with_capacity(1 << 20, std::io::stdout());
    let start = Instant::now();
    let summary = pool.install(|| {
        run::render(
            &anim,
            &frames,
            &destination,
            args.resume,
            &mut out,
            reporter,
            &stop,
        )
    })?;
    bar.finish();
    if !c.quiet {
        let place = match shard {
            // The shard named in the summary, so that a farm's logs say whose it is.
            Some((k, n)) => format!("{} (shard {k}/{n})", destination.describe()),
            None => destination.describe(),
        };
        report::summary(&summary, start, &place);
    }
    Ok(Outcome::Success)
}

/// Sends every finished frame to tev as image `animate: MANIFEST`, replaced frame after
/// frame (a missing viewer: one warning).
fn tev_observer(addr: &str, anim: &Animation) -> whitted::anim::project::FrameObserver {
    let tev = Tev::connect_stderr(addr, "animate");
    let name = format!("animate: {}", anim.manifest.path.display());
    if tev.connected() {
        tev.create(&name, anim.width, anim.height);
    }
    std::sync::Arc::new(move |_, frame| {
        if tev.connected() {
            tev.rows(&name, frame.width, 0, &frame.pixels);
        }
    })
}

fn view(args: ViewArgs) -> anyhow::Result<Outcome> {
    let options = ViewOptions {
        manifest: args.manifest.clone(),
        bind: args.bind,
        port: args.port,
    };
    let stop = whitted::process::watch_signals("animate");
    let pool = pool(args.threads)?;
    let sig = pool.install(|| {
        whitted::anim::view::serve(&options, &stop, &|url| {
            eprintln!(
                "animate: view of {} at {url} (Ctrl-C to stop)",
                args.manifest.display()
            );
            whitted::anim::view::print_url(url);
        })
    })?;
    Ok(Outcome::Interrupted(sig))
}

fn bless(args: BlessArgs) -> anyhow::Result<Outcome> {
    let c = &args.common;
    let project = c.load()?;
    let anim = Animation::new(&project)?;
    let targets = check::targets(
        &project.manifest,
        c.frames.as_deref(),
        args.references.as_deref(),
    );
    let (frames, refs) = targets.map_err(report::with_flags)?;
    let paths = pool(c.threads)?.install(|| check::bless(&anim, &frames, &refs))?;
    if !c.quiet {
        eprintln!(
            "animate: blessed {} reference(s) in {}",
            paths.len(),
            refs.display()
        );
    }
    Ok(Outcome::Success)
}

fn check_command(args: CheckArgs) -> anyhow::Result<Outcome> {
    let project = args.bless.common.load()?;
    let anim = Animation::new(&project)?;
    let opts =
        CheckOptions::new(&project.manifest, &args.overrides()).map_err(report::with_flags)?;
    let report = pool(args.bless.common.threads)?.install(|| check::check(&anim, &opts))?;
    for exporter in args.exporters() {
        exporter
            .export(&report)
            .map_err(|e| report::Usage(e.to_string()))?;
    }
    Ok(if report.pass {
        Outcome::Success
    } else {
        Outcome::Failed
    })
}

fn status_command(args: StatusArgs) -> anyhow::Result<Outcome> {
    let c = &args.common;
    let project = c.load()?;
    let (m, anim) = (&project.manifest, Animation::new(&project)?);
    let frames = run::frames_of(&anim, c.frames.as_deref(), None)?;
    let dir = args.out.clone().unwrap_or_else(|| m.output.dir.clone());
    let report = pool(c.threads)?.install(|| status(&anim, &dir, &frames));
    match args.json {
        true => println!("{}", serde_json::to_string_pretty(&report.json(&dir))?),
        false => print!("{}", report.table(&dir)),
    }
    Ok(if report.complete() {
        Outcome::Success
    } else {
        Outcome::Failed
    })
}

fn preview(args: PreviewArgs) -> anyhow::Result<Outcome> {
    let bar = report::Bar::new(0, args.quiet);
    let start = Instant::now();
    let s = pool(args.threads)?.install(|| preview::run(&args.options(), &|d, t| bar.set(d, t)));
    bar.finish();
    if !args.quiet {
        report::previewed(&s?, start);
    }
    Ok(Outcome::Success)
}

fn main() -> ExitCode {
    if let Err(e) = whitted::process::check_cpu() {
        eprintln!("animate: {e}");
        return ExitCode::from(Outcome::BadInput.code());
    }
    let cli = Cli::parse();
    let result = match cli.command {
        None => render(cli.render),
        Some(Command::Bless(args)) => bless(args),
        Some(Command::Check(args)) => check_command(args),
        Some(Command::Status(args)) => status_command(args),
        Some(Command::Preview(args)) => preview(args),
        Some(Command::View(args)) => view(args),
    };
    match result {
        Ok(outcome) => ExitCode::from(outcome.code()),
        Err(e) => {
            eprintln!("animate: {}", report::message(&e));
            if let Some(hint) = e.downcast_ref::<AnimError>().and_then(report::hint) {
                eprintln!("animate: hint: {hint}");
            }
            ExitCode::from(report::outcome(&e).code())
        }
    }
}
