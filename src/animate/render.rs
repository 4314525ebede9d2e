//! The render command (`animate MANIFEST`): the library's run (`frames::run`) with what a
//! person at a terminal sees around it: the announcement, the warning for an enormous
//! render, the progress bar or JSON events, the summary, and the lines a stopped stream
//! prints, and the hooks (`--on-frame`, `--on-done`).

use super::cli::RenderArgs;
use super::{pool, report};
use std::sync::Arc;
use std::time::Instant;
use whitted::exit::Outcome;
use whitted::output::ImageFormat;
use whitted_anim::frames::balance;
use whitted_anim::frames::hooked::{FramePath, Hooked, Tally};
use whitted_anim::frames::hooks::HookRun;
use whitted_anim::frames::run::{self, Destination};
use whitted_anim::{AnimError, Animation, Reporter};
use whitted_cmd::progress::Weighted;

/// What an interrupted stream or video says (`--resume` does not apply to them): its two
/// lines, whether the run stopped by itself or was ended stuck on a write.
fn stream_stopped(sig: i32) -> String {
    format!(
        "animate: interrupted by signal {sig}\nanimate: hint: a stream or video cannot be \
         resumed: run the command again, or render into a folder (`--resume` completes \
         that) and `animate encode` it"
    )
}

/// Shows a hook's run as it ends: a failure with its output, else what it printed.
fn told(run: &HookRun) {
    match run.failed() {
        true => eprintln!("animate: {}", run.report()),
        false => eprint!("{}", run.output),
    }
}

/// Renders the frames `args` ask for, then runs `--on-done`: the run's error, if any, is
/// said first, and the hook is told the exit status it gives. A failed hook makes a run
/// that succeeded end with status 1.
pub fn render(args: RenderArgs) -> anyhow::Result<Outcome> {
    let on_done = args.on_done.clone();
    let mut tally = Tally::default();
    let result = render_frames(args, &mut tally);
    let hooks_failed = tally.hooks_failed > 0;
    let Some(hook) = on_done else {
        return result.map(|o| failed_if(o, hooks_failed));
    };
    let outcome = match result {
        Ok(outcome) => failed_if(outcome, hooks_failed),
        Err(e) => {
            super::say(&e);
            report::outcome(&e)
        }
    };
    let done = hook.run_done(tally.rendered, tally.failed, outcome.code());
    told(&done);
    Ok(failed_if(outcome, done.failed()))
}

/// `outcome`, or a failure when it was a success and `failed`.
fn failed_if(outcome: Outcome, failed: bool) -> Outcome {
    match (outcome, failed) {
        (Outcome::Success, true) => Outcome::Failed,
        (o, _) => o,
    }
}

/// The render itself; `tally` gets what the run did, however it ends.
fn render_frames(args: RenderArgs, tally: &mut Tally) -> anyhow::Result<Outcome> {
    let c = &args.common;
    if args.stdout.is_some() && whitted_cmd::process::stdout_closed() {
        return Err(AnimError::StdoutClosed.into());
    }
    let project = c.load_draft(&args.draft)?;
    let (m, mut anim) = (&project.manifest, Animation::new(&project)?);
    if let Some(display) = &args.display {
        anim = anim.displayed(display, "animate");
    }
    let shard = args.shard()?;
    let pool = pool(c.threads)?;
    let frames = pool.install(|| run::planned(&anim, c.frames.as_deref(), shard, args.balance))?;
    let destination = args.destination(m)?;
    let policy = args.policy()?;
    if !c.quiet {
        report::announce(&anim, frames.len(), args.stdout == Some(ImageFormat::Raw));
    }
    let stop = whitted_cmd::process::watch_signals("animate");
    if matches!(destination, Destination::Stream(_)) {
        // A reader that stops reading would hold a write, and the run, forever.
        whitted_cmd::process::exit_when_stuck(stop.clone(), stream_stopped);
    }
    if !c.quiet {
        report::warn_if_non_square(&anim);
    }
    let quiet = c.quiet || args.events;
    // The bar's ETA weighs each frame by the pre-pass's predicted cost (1/64 of the
    // pixels at one sample), only when the bar shows.
    let weighted = match report::bar::RowBar::shown(quiet) {
        true => {
            let costs = pool.install(|| balance::predicted_costs(&anim, &frames))?;
            let rows = anim.rows_per_frame();
            Some(Arc::new(Weighted::new(&frames, &costs, rows)))
        }
        false => None,
    };
    let bar = report::bar::RowBar::weighted(frames.len(), anim.rows_per_frame(), quiet, weighted);
    let reporter: &dyn Reporter = match args.events {
        true => &report::JsonLines,
        false => &bar,
    };
    // The warning before an enormous render, once the run knows what it renders.
    let warned = report::WarnEnormous {
        inner: reporter,
        anim: &anim,
        frames: &frames,
    };
    let reporter: &dyn Reporter = match c.quiet {
        true => reporter,
        false => &warned,
    };
    let hook = match &destination {
        Destination::Folder(_) => args.on_frame.clone(),
        _ => None,
    };
    let (dir, output, n) = (destination.folder(), m.output.clone(), m.frames);
    let path: FramePath = Box::new(move |f| dir.join(output.file_name(f, n)));
    let hooked = Hooked::new(reporter, &frames, hook, path, Box::new(told));
    let mut out = std::io::BufWriter::with_capacity(1 << 20, std::io::stdout());
    let start = Instant::now();
    let summary = pool.install(|| {
        let (d, p) = (&destination, &policy);
        run::render(&anim, &frames, d, p, &mut out, &hooked, &stop)
    });
    bar.finish();
    *tally = hooked.finish();
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
