//! What the pipeline reports while it works, as events (after cargo-nextest's reporter):
//! a run starts (sharing its folder with another run or not), each frame finishes, is
//! skipped as up to date, is rendered by another run, or fails. The pipeline
//! calls a `Reporter`; drawing a progress bar, printing a summary or JSON lines for a
//! scheduler is the reporter's business (the binaries own those), so the library never
//! draws anything.

use whitted::trace::RayCount;

/// One thing that happened during a run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Event {
    /// The run has `total` frames, of which `skipped` are already up to date.
    Started {
        /// The frames this run covers, skipped ones included.
        total: usize,
        /// How many of them are up to date and will not be rendered (`--resume`).
        skipped: usize,
    },
    /// Frame `frame` was rendered and delivered (written, or sent to the stream) after
    /// `seconds` of work on its worker, casting `rays`.
    Finished {
        /// The frame's number in the sequence (0-based).
        frame: u32,
        /// Wall-clock seconds its worker spent rendering and delivering it.
        seconds: f64,
        /// The rays cast for it, by kind.
        rays: RayCount,
    },
    /// Frame `frame` is up to date and was left as it is.
    Skipped {
        /// The frame's number in the sequence (0-based).
        frame: u32,
    },
    /// Frame `frame` was rendered by another run sharing the folder (`claim`).
    Elsewhere {
        /// The frame's number in the sequence (0-based).
        frame: u32,
    },
    /// The run shares its folder with another run of the same manifest, process `pid`
    /// (sent before `Started`).
    Sharing {
        /// The other run's process id, as its lock file says.
        pid: u32,
    },
    /// Frame `frame` could not be rendered or written; the run stops after it.
    Failed {
        /// The frame's number in the sequence (0-based).
        frame: u32,
    },
}

/// Receives the events of a run, from any worker thread.
pub trait Reporter: Sync {
    /// Called once per event, possibly from several threads at once; must return quickly.
    fn event(&self, event: Event);
}

/// A reporter that ignores everything.
pub struct Silent;

impl Reporter for Silent {
    fn event(&self, _: Event) {}
}

impl<F: Fn(Event) + Sync> Reporter for F {
    fn event(&self, event: Event) {
        self(event)
    }
}
