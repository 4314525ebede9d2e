//! The render command (`animate MANIFEST`): the library's run (`frames::run`) with what a
//! person at a terminal sees around it: the announcement, the warning for an enormous
//! render, the progress bar or JSON events, the summary, and the lines a stopped stream
//! prints.

use super::cli::RenderArgs;
use super::{pool, report};
use std::sync::Arc;
use std::time::Instant;
use whitted::exit::Outcome;
use whitted::output::ImageFormat;
use whitted_anim::frames::balance;
use whitted_anim::frames::run::{self, Destination};
use whitted_anim::progress::Weighted;
use whitted_anim::{AnimError, Animation, Reporter};

/// What an interrupted stream or video says (`--resume` does not apply to them): its two
/// lines, whether the run stopped by itself or was ended stuck on a write.
fn stream_stopped(sig: i32) -> String {
    format!(
        "animate: interrupted by signal {sig}\nanimate: hint: a stream or video cannot be \
         resumed: run the command again, or render into a folder (`--resume` completes \
         that) and `animate encode` it"
    )
}

/// Renders the frames `args` ask for.
pub fn render(args: RenderArgs) -> anyhow::Result<Outcome> {
    let c = &args.common;
    if args.stdout.is_some() && whitted_anim::process::stdout_closed() {
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
    let stop = whitted_anim::process::watch_signals("animate");
    if matches!(destination, Destination::Stream(_)) {
        // A reader that stops reading would hold a write, and the run, forever.
        whitted_anim::process::exit_when_stuck(stop.clone(), stream_stopped);
    }
    if !c.quiet {
        pool.install(|| report::warn_if_enormous(&anim, &frames));
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
    let mut out = std::io::BufWriter::with_capacity(1 << 20, std::io::stdout());
    let start = Instant::now();
    let summary = pool.install(|| {
        let (d, p) = (&destination, &policy);
        run::render(&anim, &frames, d, p, &mut out, reporter, &stop)
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
