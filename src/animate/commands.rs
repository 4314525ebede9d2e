//! `animate`'s subcommands other than the render itself, each a library call
//! (`whitted_anim::commands`, `check`, `preview`, `view`) on the worker pool, its outcome
//! reported on standard error unless `--quiet`.

use super::cli::{BlessArgs, CheckArgs, EncodeArgs, JobArgs, PreviewArgs, ViewArgs};
use super::report;
use anyhow::Context;
use std::time::Instant;
use whitted::exit::Outcome;
use whitted::fileloc::shown;
use whitted_anim::commands::{self, check::CheckRequest};
use whitted_anim::view::ViewOptions;
use whitted_anim::{check, preview, Animation};

pub(super) fn pool(threads: Option<u32>) -> anyhow::Result<rayon::ThreadPool> {
    whitted_cmd::process::pool(threads).context("cannot start the worker threads")
}

pub(super) fn encode(args: EncodeArgs) -> anyhow::Result<Outcome> {
    let project = whitted_anim::Project::load_draft(&args.manifest, &args.draft.draft())?;
    let stop = whitted_cmd::process::watch_signals("animate");
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

pub(super) fn view(args: ViewArgs) -> anyhow::Result<Outcome> {
    let options = ViewOptions {
        manifest: args.manifest.clone(),
        bind: args.bind,
        port: args.port,
        threads: args.threads,
        draft: args.draft.draft(),
    };
    let stop = whitted_cmd::process::watch_signals_quietly();
    let ready = |url: &str| report::view_ready(&args.manifest, url, args.bind);
    let sig = whitted_anim::view::serve(&options, &stop, &ready)?;
    Ok(Outcome::Interrupted(sig))
}

pub(super) fn bless(args: BlessArgs) -> anyhow::Result<Outcome> {
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

pub(super) fn check(args: CheckArgs) -> anyhow::Result<Outcome> {
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

pub(super) fn job(args: JobArgs) -> anyhow::Result<Outcome> {
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

pub(super) fn preview(args: PreviewArgs) -> anyhow::Result<Outcome> {
    let bar = report::bar::Bar::new(0, args.quiet);
    let start = Instant::now();
    let s = pool(args.threads)?.install(|| preview::run(&args.options(), &|d, t| bar.set(d, t)));
    bar.finish();
    if !args.quiet {
        report::previewed(&s?, start);
    }
    Ok(Outcome::Success)
}

pub(super) fn stdout() -> std::io::StdoutLock<'static> {
    std::io::stdout().lock()
}
