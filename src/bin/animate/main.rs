//! `animate MANIFEST.toml`: renders every frame of an animation manifest (SPEC §5-§8) in
//! parallel into a folder, or streams them in order to standard output or ffmpeg;
//! `check`, `bless` and `status` are subcommands. This file only turns the command line
//! (`cli`) into library calls and their outcome into an exit status (`whitted::exit`);
//! `report` draws the progress.

mod cli;
mod report;

use anyhow::Context;
use clap::Parser;
use cli::{BlessArgs, CheckArgs, Cli, Command, RenderArgs, StatusArgs};
use std::io::IsTerminal;
use std::process::ExitCode;
use std::sync::atomic::AtomicUsize;
use std::sync::Arc;
use std::time::Instant;
use whitted::anim::pipeline::{render_to_folder, render_to_stream};
use whitted::anim::status::{ranges, status};
use whitted::anim::{regress, select::select, video::render_to_video};
use whitted::anim::{AnimError, Animation, Reporter};
use whitted::exit::Outcome;
use whitted::output::ImageFormat;

/// Stops the run between frames on SIGINT or SIGTERM; the flag holds the signal number.
fn watch_signals() -> Arc<AtomicUsize> {
    let stop = Arc::new(AtomicUsize::new(0));
    for sig in [signal_hook::consts::SIGINT, signal_hook::consts::SIGTERM] {
        // Without a handler the default action (terminate) remains; temporary files are
        // still never visible under final names.
        let _ = signal_hook::flag::register_usize(sig, Arc::clone(&stop), sig as usize);
    }
    stop
}

fn pool(threads: Option<u32>) -> anyhow::Result<rayon::ThreadPool> {
    let n = threads.unwrap_or(0) as usize;
    let pool = rayon::ThreadPoolBuilder::new().num_threads(n).build();
    pool.context("cannot start the worker threads")
}

fn render(args: RenderArgs) -> anyhow::Result<Outcome> {
    let c = &args.common;
    let project = c.load()?;
    let (m, anim) = (&project.manifest, Animation::new(&project)?);
    let frames =
        select(m.frames, c.frames.as_deref(), args.shard.as_deref()).map_err(AnimError::from)?;
    if frames.is_empty() && !c.quiet {
        eprintln!(
            "animate: this shard has no frames ({} in all): nothing to do",
            m.frames
        );
    }
    anim.check_cameras(&frames)?;
    if args.stdout.is_some() && std::io::stdout().is_terminal() && !args.force {
        anyhow::bail!(AnimError::Usage("refusing to write binary frames to a terminal: redirect standard output, or add --force".into()));
    }
    let (stop, pool) = (watch_signals(), pool(c.threads)?);
    let bar = report::Bar::new(frames.len(), c.quiet || args.events);
    let reporter: &dyn Reporter = if args.events {
        &report::JsonLines
    } else {
        &bar
    };
    let start = Instant::now();
    let (summary, place) = if let Some(format) = args.stdout {
        if format == ImageFormat::Raw && !c.quiet {
            let (w, h, fps) = (anim.width, anim.height, m.fps);
            eprintln!("animate: raw RGB frames; for ffmpeg: -f rawvideo -pix_fmt rgb24 -s {w}x{h} -r {fps} -i -");
        }
        let mut out = std::io::BufWriter::with_capacity(1 << 20, std::io::stdout());
        let s =
            pool.install(|| render_to_stream(&anim, &frames, &mut out, format, reporter, &stop))?;
        (s, "standard output".to_string())
    } else if let Some(video) = &args.video {
        let s = pool.install(|| render_to_video(&anim, &frames, video, reporter, &stop))?;
        (s, video.display().to_string())
    } else {
        let dir = args.out.clone().unwrap_or_else(|| m.output.dir.clone());
        let s =
            pool.install(|| render_to_folder(&anim, &frames, &dir, args.resume, reporter, &stop))?;
        (s, dir.display().to_string())
    };
    bar.finish();
    if !c.quiet {
        report::summary(&summary, start.elapsed().as_secs_f64(), &place);
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
    let frames = select(m.frames, c.frames.as_deref(), None).map_err(AnimError::from)?;
    let dir = args.out.clone().unwrap_or_else(|| m.output.dir.clone());
    let report = pool(c.threads)?.install(|| status(&anim, &dir, &frames));
    if args.json {
        let doc = serde_json::json!({"folder": dir, "frames": frames.len(),
            "complete": report.complete(), "up_to_date": ranges(&report.up_to_date),
            "stale": ranges(&report.stale), "missing": ranges(&report.missing)});
        println!("{}", serde_json::to_string_pretty(&doc)?);
    } else {
        println!("{}: {} frame(s)", dir.display(), frames.len());
        for (what, list) in [
            ("up to date", &report.up_to_date),
            ("stale", &report.stale),
            ("missing", &report.missing),
        ] {
            println!("{what:>11}: {:>7}  {}", list.len(), ranges(list));
        }
    }
    Ok(if report.complete() {
        Outcome::Success
    } else {
        Outcome::Failed
    })
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        None => render(cli.render),
        Some(Command::Bless(args)) => bless(args),
        Some(Command::Check(args)) => check(args),
        Some(Command::Status(args)) => status_command(args),
    };
    match result {
        Ok(outcome) => ExitCode::from(outcome.code()),
        Err(e) => {
            let anim = e.downcast_ref::<AnimError>();
            eprintln!("animate: {e}");
            if let Some(hint) = anim.and_then(report::hint) {
                eprintln!("animate: hint: {hint}");
            }
            ExitCode::from(anim.map_or(Outcome::Failed, AnimError::outcome).code())
        }
    }
}
