//! The render command (`animate MANIFEST`): the library's run (`frames::run`) with what a
//! person at a terminal sees around it: the announcement, the warning for an enormous
//! render, the progress bar or JSON events, the summary, and the lines a stopped stream
//! prints, and the hooks (`--on-frame`, `--on-done`).

use super::cli::RenderArgs;
use super::{pool, report};
use std::sync::atomic::AtomicUsize;
use std::sync::Arc;
use std::time::{Duration, Instant};
use whitted::exit::Outcome;
use whitted::output::ImageFormat;
use whitted_anim::frames::balance;
use whitted_anim::frames::hooked::{FramePath, Hooked, Tally};
use whitted_anim::frames::hooks::{HookRun, Limits};
use whitted_anim::frames::run::{self, Destination};
use whitted_anim::{AnimError, Animation, Reporter};
use whitted_cmd::process::stopped;
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

/// How long `--on-done` may run after a run stopped by a signal (less when
/// `--hook-timeout` says so): the run was asked to end.
const DONE_AFTER_STOP: Duration = Duration::from_secs(10);

/// Renders the frames `args` ask for, then runs `--on-done`: the run's error, if any, is
/// said first, and the hook is told the exit status it gives. A failed hook makes a run
/// that succeeded end with status 1; a signal while it runs ends it, and the run with
/// 128 + N.
pub fn render(args: RenderArgs) -> anyhow::Result<Outcome> {
    let on_done = args.on_done.clone();
    let timeout = args.hook_timeout;
    let mut tally = Tally::default();
    let mut stop = None;
    let result = render_frames(args, &mut tally, &mut stop);
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
    let limits = match (outcome, stop) {
        // Stopped already: the hook is told so, and given a short time of its own.
        (Outcome::Interrupted(_), _) => Limits {
            stop: Arc::default(),
            timeout: Some(timeout.map_or(DONE_AFTER_STOP, |t| t.min(DONE_AFTER_STOP))),
        },
        (_, stop) => Limits {
            stop: stop.unwrap_or_else(whitted_cmd::process::watch_signals_quietly),
            timeout,
        },
    };
    let done = hook.run_done(tally.rendered, tally.failed, outcome.code(), &limits);
    told(&done);
    if let (Outcome::Success | Outcome::Failed, Some(sig)) = (outcome, stopped(&limits.stop)) {
        return Ok(Outcome::Interrupted(sig));
    }
    Ok(failed_if(outcome, done.failed()))
}

/// `outcome`, or a failure when it was a success and `failed`.
fn failed_if(outcome: Outcome, failed: bool) -> Outcome {
    match (outcome, failed) {
        (Outcome::Success, true) => Outcome::Failed,
        (o, _) => o,
    }
}

/// The render itself; `tally` gets what the run did, however it ends, and `watched` the
/// run's stop flag once signals are watched.
fn render_frames(
    args: RenderArgs,
    tally: &mut Tally,
    watched: &mut Option<Arc<AtomicUsize>>,
) -> anyhow::Result<Outcome> {
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
    *watched = Some(stop.clone());
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
    let limits = Limits {
        stop: stop.clone(),
        timeout: args.hook_timeout,
    };
    let hook = match &destination {
        Destination::Folder(_) => args.on_frame.clone().map(|h| (h, limits)),
        _ => None,
    };
    let (dir, output, n) = (destination.folder(), m.output.clone(), m.frames);
    let path: FramePath = Box::new(move |f| output.path(&dir, f, n));
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
    if let Some(sig) = stopped(&stop) {
        // Every frame was done, and a signal came while the hooks ran.
        return Err(AnimError::Interrupted(sig).into());
    }
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
