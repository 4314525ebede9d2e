//! `animate MANIFEST.toml`: renders the frames of an animation manifest into a folder,
//! or streams them to standard output or ffmpeg; `status`, `preview`, `check`, `bless` and
//! `view` are subcommands. This file turns the command line (`cli`) into library calls and their
//! outcome into an exit status (`whitted::exit`); `report` shows progress and results.

mod cli;
mod report;

use anyhow::Context;
use clap::Parser;
use cli::{
    BlessArgs, CheckArgs, CleanArgs, Cli, Command, EncodeArgs, EstimateArgs, JobArgs, PreviewArgs,
    RenderArgs, StatusArgs, ViewArgs,
};
use std::process::ExitCode;
use std::time::Instant;
use whitted::exit::Outcome;
use whitted::fileloc::shown;
use whitted::output::ImageFormat;
use whitted_anim::check::{self, CheckOptions};
use whitted_anim::frames::estimate::Estimate;
use whitted_anim::frames::run::{self, Destination, Policy};
use whitted_anim::frames::status::{ranges, status};
use whitted_anim::frames::{balance, encode, folder};
use whitted_anim::job::{openjd_template, relative_to, Chunking};
use whitted_anim::select::sorted;
use whitted_anim::view::ViewOptions;
use whitted_anim::{guard, preview, AnimError, Animation, Reporter};

fn pool(threads: Option<u32>) -> anyhow::Result<rayon::ThreadPool> {
    whitted_anim::process::pool(threads).context("cannot start the worker threads")
}

/// What an interrupted stream or video says (`--resume` does not apply to them): its two
/// lines, whether the run stopped by itself or was ended stuck on a write.
fn stream_stopped(sig: i32) -> String {
    format!(
        "animate: interrupted by signal {sig}\nanimate: hint: a stream or video cannot be \
         resumed: run the command again, or render into a folder (`--resume` completes \
         that) and `animate encode` it"
    )
}

fn render(args: RenderArgs) -> anyhow::Result<Outcome> {
    let c = &args.common;
    if args.stdout.is_some() && whitted_anim::process::stdout_closed() {
        return Err(AnimError::StdoutClosed.into());
    }
    let project = c.load()?;
    let (m, mut anim) = (&project.manifest, Animation::new(&project)?);
    if let Some(display) = &args.display {
        anim = anim.displayed(display, "animate");
    }
    let shard = args.shard()?;
    let pool = pool(c.threads)?;
    let frames = match args.balance {
        // The pre-pass traces sample frames: on the --threads pool like the render.
        true => pool.install(|| balance::select_balanced(&anim, c.frames.as_deref(), shard))?,
        false => run::frames_of(&anim, c.frames.as_deref(), shard)?,
    };
    let destination = args.destination(m)?;
    let policy = args.policy()?;
    if !c.quiet {
        report::announce(&anim, frames.len(), args.stdout == Some(ImageFormat::Raw));
    }
    let stop = whitted_anim::process::watch_signals("animate");
    if matches!(destination, Destination::Stream(_)) {
        // A reader that stops reading would hold a write, and the run, forever.
        whitted_anim::process::exit_when_stuck(stop.clone(), stream_stopped);
    }
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
            &policy,
            &mut out,
            reporter,
            &stop,
        )
    });
    bar.finish();
    let summary = match (summary, &destination) {
        (Err(AnimError::Interrupted(sig)), Destination::Stream(_) | Destination::Video(_)) => {
            eprintln!("{}", stream_stopped(sig));
            return Ok(Outcome::Interrupted(sig));
        }
        (summary, _) => summary?,
    };
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

fn encode_command(args: EncodeArgs) -> anyhow::Result<Outcome> {
    let project = whitted_anim::Project::load(&args.manifest)?;
    let (m, anim) = (&project.manifest, Animation::new(&project)?);
    let dir = args.dir.clone().unwrap_or_else(|| m.output.dir.clone());
    let video = args
        .out
        .clone()
        .unwrap_or_else(|| encode::default_video(&dir));
    let policy = Policy {
        force: args.force,
        encoding: args.encoding.encoding(),
        ..Policy::default()
    };
    let stop = whitted_anim::process::watch_signals("animate");
    let bar = report::Bar::new(m.frames as usize, args.quiet);
    let start = Instant::now();
    let summary = encode::encode(&anim, &dir, &video, &policy, &bar, &stop);
    bar.finish();
    let summary = summary?;
    if !args.quiet {
        let secs = start.elapsed().as_secs_f64();
        eprintln!(
            "animate: encoded {} frames of {} at {} fps in {secs:.2} s -> {}",
            summary.rendered,
            shown(&dir),
            m.fps,
            shown(&video)
        );
    }
    Ok(Outcome::Success)
}

fn clean_command(args: CleanArgs) -> anyhow::Result<Outcome> {
    let project = whitted_anim::Project::load(&args.manifest)?;
    let (m, anim) = (&project.manifest, Animation::new(&project)?);
    let dir = args.out.clone().unwrap_or_else(|| m.output.dir.clone());
    if args.dry_run {
        let past: Vec<u32> = folder::beyond(&anim, &dir).iter().map(|f| f.0).collect();
        println!(
            "{}: would remove {} frame(s) past the end ({}) and {} temporary file(s)",
            shown(&dir),
            past.len(),
            ranges(&past),
            folder::temporaries(&anim, &dir).len()
        );
        return Ok(Outcome::Success);
    }
    let cleaned = folder::clean(&anim, &dir, args.force)?;
    println!(
        "{}: removed {} frame(s) past the end ({}) and {} temporary file(s)",
        shown(&dir),
        cleaned.beyond.len(),
        ranges(&cleaned.beyond),
        cleaned.temporaries
    );
    Ok(Outcome::Success)
}

fn view(args: ViewArgs) -> anyhow::Result<Outcome> {
    let options = ViewOptions {
        manifest: args.manifest.clone(),
        bind: args.bind,
        port: args.port,
        threads: args.threads,
    };
    let stop = whitted_anim::process::watch_signals("animate");
    let sig = whitted_anim::view::serve(&options, &stop, &|url| {
        eprintln!(
            "animate: view of {} at {url} (Ctrl-C to stop)",
            args.manifest.display()
        );
        whitted_anim::view::print_url(url);
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
    let blessed =
        pool(c.threads)?.install(|| check::bless(&anim, &frames, &refs, args.force))?;
    if !c.quiet {
        eprintln!(
            "animate: blessed {} reference(s) in {}: {}",
            blessed.len(),
            shown(&refs),
            check::bless_counts(&blessed)
        );
    }
    Ok(Outcome::Success)
}

fn check_command(args: CheckArgs) -> anyhow::Result<Outcome> {
    let project = args.bless.common.load()?;
    let anim = Animation::new(&project)?;
    let opts =
        CheckOptions::new(&project.manifest, &args.overrides()).map_err(report::with_flags)?;
    let (inputs, force) = (guard::inputs(&project), args.bless.force);
    if let Some(file) = &args.junit {
        guard::output(file, &inputs, guard::JUNIT, force)?;
    }
    if let Some(dir) = &args.html {
        guard::output(&dir.join("index.html"), &inputs, guard::HTML, force)?;
    }
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
    let frames = sorted(&run::frames_of(&anim, c.frames.as_deref(), None)?);
    let dir = args.out.clone().unwrap_or_else(|| m.output.dir.clone());
    let pool = pool(c.threads)?;
    let report = pool.install(|| status(&anim, &dir, &frames, args.verify));
    match args.json {
        true => {
            let mut doc = report.json(&dir);
            let costs = pool.install(|| balance::predicted_costs(&anim, &frames))?;
            let per_frame: serde_json::Map<String, serde_json::Value> = frames
                .iter()
                .zip(costs)
                .map(|(f, c)| (f.to_string(), c.into()))
                .collect();
            doc["predicted_rays"] = per_frame.into();
            println!("{}", serde_json::to_string_pretty(&doc)?)
        }
        false => print!("{}", report.table(&dir)),
    }
    Ok(if report.complete() {
        Outcome::Success
    } else {
        Outcome::Failed
    })
}

fn job(args: JobArgs) -> anyhow::Result<Outcome> {
    let c = &args.common;
    let project = c.load()?;
    let (m, anim) = (&project.manifest, Animation::new(&project)?);
    let frames = sorted(&run::frames_of(&anim, c.frames.as_deref(), None)?);
    if let Some(file) = &args.out {
        guard::output(file, &guard::inputs(&project), guard::OPENJD, args.force)?;
    }
    let chunking = match args.chunk_seconds {
        Some(target) => {
            let e = pool(c.threads)?.install(|| Estimate::new(&anim, &frames))?;
            let per_frame = e.seconds(e.total()) / frames.len().max(1) as f64;
            Chunking::Seconds { target, per_frame }
        }
        None => Chunking::Frames(args.chunk.unwrap_or(10)),
    };
    let absolute = |p: &std::path::Path| std::path::absolute(p).unwrap_or(p.to_path_buf());
    let out_dir = absolute(args.out_dir.as_deref().unwrap_or(&m.output.dir));
    let manifest = absolute(c.manifest.as_deref().unwrap_or(std::path::Path::new("")));
    // OpenJD wants the default paths relative to the template's folder.
    let here = absolute(std::path::Path::new("."));
    let folder = match &args.out {
        Some(file) => match file.parent().filter(|p| !p.as_os_str().is_empty()) {
            Some(parent) => absolute(parent),
            None => here,
        },
        None => here,
    };
    let (manifest, out_dir) = (
        relative_to(&manifest, &folder),
        relative_to(&out_dir, &folder),
    );
    let template = openjd_template(m, &manifest, &out_dir, &frames, chunking);
    let text = serde_json::to_string_pretty(&template)? + "\n";
    match &args.out {
        Some(file) => {
            let write = || -> std::io::Result<()> {
                let mut tmp = whitted::output::temp_beside(file)?;
                std::io::Write::write_all(&mut tmp, text.as_bytes())?;
                tmp.persist(file).map_err(|e| e.error)?;
                Ok(())
            };
            write().with_context(|| format!("cannot write {}", file.display()))?
        }
        None => print!("{text}"),
    }
    if !c.quiet {
        let size = chunking.size();
        eprintln!(
            "animate: an OpenJD template of {} frames in chunks of {size}",
            frames.len()
        );
    }
    Ok(Outcome::Success)
}

fn estimate(args: EstimateArgs) -> anyhow::Result<Outcome> {
    let c = &args.common;
    let project = c.load()?;
    let anim = Animation::new(&project)?;
    let frames = run::frames_of(&anim, c.frames.as_deref(), None)?;
    let e = pool(c.threads)?.install(|| Estimate::new(&anim, &frames))?;
    print!("{}", e.table(args.shards.unwrap_or(0)));
    Ok(Outcome::Success)
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
    if let Err(e) = whitted_anim::process::check_cpu() {
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
        Some(Command::Job(args)) => job(args),
        Some(Command::Estimate(args)) => estimate(args),
        Some(Command::Encode(args)) => encode_command(args),
        Some(Command::Clean(args)) => clean_command(args),
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
