//! `animate MANIFEST.toml`: renders every frame of an animation manifest (SPEC §5-§8) in
//! parallel into a folder, or streams them in order to standard output or ffmpeg;
//! `check`, `bless` and `status` are subcommands. This file only turns the command line
//! (`cli`) into library calls and their outcome into an exit status (`whitted::exit`);
//! `report` draws the progress.

mod cli;
mod report;

use anyhow::Context;
use clap::Parser;
use cli::{BlessArgs, CheckArgs, Cli, Command, PreviewArgs, RenderArgs, StatusArgs};
use std::process::ExitCode;
use std::time::Instant;
use whitted::anim::run;
use whitted::anim::status::status;
use whitted::anim::{preview, regress, AnimError, Animation, Reporter};
use whitted::exit::Outcome;
use whitted::output::ImageFormat;

fn pool(threads: Option<u32>) -> anyhow::Result<rayon::ThreadPool> {
    whitted::process::pool(threads).context("cannot start the worker threads")
}

fn render(args: RenderArgs) -> anyhow::Result<Outcome> {
    let c = &args.common;
    let project = c.load()?;
    let (m, anim) = (&project.manifest, Animation::new(&project)?);
    let frames = run::frames_of(&anim, c.frames.as_deref(), args.shard()?)?;
    if frames.is_empty() && !c.quiet {
        eprintln!(
            "animate: this shard has no frames ({} in all): nothing to do",
            m.frames
        );
    }
    let destination = args.destination(m)?;
    if args.stdout == Some(ImageFormat::Raw) && !c.quiet {
        eprintln!(
            "animate: raw RGB frames; for ffmpeg: {}",
            run::ffmpeg_raw_input(&anim)
        );
    }
    let (stop, pool) = (whitted::process::watch_signals(), pool(c.threads)?);
    let bar = report::Bar::new(frames.len(), c.quiet || args.events);
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
        report::summary(
            &summary,
            start.elapsed().as_secs_f64(),
            &destination.describe(),
        );
    }
    Ok(Outcome::Success)
}

fn bless(args: BlessArgs) -> anyhow::Result<Outcome> {
    let project = args.common.load()?;
    let anim = Animation::new(&project)?;
    let (frames, refs) = regress::targets(
        &project.manifest,
        args.common.frames.as_deref(),
        args.references.as_deref(),
    )?;
    let paths = pool(args.common.threads)?.install(|| regress::bless(&anim, &frames, &refs))?;
    if !args.common.quiet {
        eprintln!(
            "animate: blessed {} reference(s) in {}",
            paths.len(),
            refs.display()
        );
    }
    Ok(Outcome::Success)
}

fn check(args: CheckArgs) -> anyhow::Result<Outcome> {
    let common = &args.bless.common;
    let project = common.load()?;
    let (manifest, anim) = (&project.manifest, Animation::new(&project)?);
    let (frames, refs) = regress::targets(
        manifest,
        common.frames.as_deref(),
        args.bless.references.as_deref(),
    )?;
    let tol = regress::tolerance(manifest, args.fail, args.fail_percent, args.hard_fail)?;
    let report = args
        .report
        .clone()
        .unwrap_or_else(|| regress::default_report(manifest));
    let results =
        pool(common.threads)?.install(|| regress::check(&anim, &frames, &refs, tol, &report))?;
    let pass = results.iter().all(|r| r.comparison.pass);
    if args.json {
        let doc = serde_json::json!({"manifest": manifest.path, "references": refs,
            "report": report, "tolerance": tol, "pass": pass, "frames": results});
        println!("{}", serde_json::to_string_pretty(&doc)?);
    } else {
        print!("{}", regress::table(&results));
        let failed = results.iter().filter(|r| !r.comparison.pass).count();
        match failed {
            0 => println!("PASS: {} frame(s) within tolerance", results.len()),
            n => println!(
                "FAIL: {n} of {} frame(s); rendered frames and diff images in {}",
                results.len(),
                report.display()
            ),
        }
    }
    Ok(if pass {
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
    let s = s?;
    if !args.quiet {
        let (secs, w, h) = (start.elapsed().as_secs_f64(), s.width, s.height);
        eprintln!(
            "animate: preview of {} frames at {w}×{h} in {secs:.2} s -> {}",
            s.frames,
            s.dir.display()
        );
    }
    Ok(Outcome::Success)
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        None => render(cli.render),
        Some(Command::Bless(args)) => bless(args),
        Some(Command::Check(args)) => check(args),
        Some(Command::Status(args)) => status_command(args),
        Some(Command::Preview(args)) => preview(args),
    };
    match result {
        Ok(outcome) => ExitCode::from(outcome.code()),
        Err(e) => {
            eprintln!("animate: {e}");
            if let Some(hint) = e.downcast_ref::<AnimError>().and_then(report::hint) {
                eprintln!("animate: hint: {hint}");
            }
            ExitCode::from(report::outcome(&e).code())
        }
    }
}
