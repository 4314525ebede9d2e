//! A run's reporter with its hooks (`hooks`): every event goes on to the reporter it
//! wraps, is counted (frames rendered and failed, for `--on-done`), and, with a frame hook,
//! puts the frame in line for it. Frames are let through in the order the run takes them:
//! a frame's hook starts once every frame before it is settled (delivered, up to date,
//! failed, or rendered by another run), and `finish` lets through what is left (frames
//! after a failure or an interruption that were never rendered get no hook). The hooks
//! run one after another on one thread of their own; once the run is stopped (SIGINT,
//! SIGTERM) the hook running is ended and no other starts.

use super::events::{Event, Reporter};
use super::hooks::{FrameState, Hook, HookRun, Limits};
use std::collections::HashMap;
use std::path::PathBuf;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::mpsc::{channel, Sender};
use std::sync::Mutex;
use std::thread::JoinHandle;

/// Where frame `f`'s file is.
pub type FramePath = Box<dyn Fn(u32) -> PathBuf + Send>;
/// What to do with each hook's run as it ends (show its output or its failure).
pub type Told = Box<dyn Fn(&HookRun) + Send>;

/// The frames in line for the hook: the run's order, how far it has gone, and what
/// became of the frames settled out of order (`None`: rendered elsewhere, no hook).
struct Line {
    order: Vec<u32>,
    next: usize,
    settled: HashMap<u32, Option<FrameState>>,
    to_hook: Option<Sender<(u32, FrameState)>>,
}

impl Line {
    /// Sends the frames now at the head of the line, in order.
    fn advance(&mut self, all: bool) {
        while self.next < self.order.len() {
            let frame = self.order[self.next];
            let state = match self.settled.remove(&frame) {
                Some(state) => state,
                None if all => None,
                None => break,
            };
            self.next += 1;
            if let (Some(state), Some(tx)) = (state, &self.to_hook) {
                let _ = tx.send((frame, state));
            }
        }
    }
}

/// What a run did, as its hooks count it.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Tally {
    /// Frames rendered and delivered.
    pub rendered: usize,
    /// Frames that failed.
    pub failed: usize,
    /// Frame hooks that failed.
    pub hooks_failed: usize,
}

/// A reporter that counts, and runs the frame hook in the run's order of frames.
pub struct Hooked<'a> {
    inner: &'a dyn Reporter,
    line: Mutex<Line>,
    rendered: AtomicUsize,
    failed: AtomicUsize,
    worker: Option<JoinHandle<usize>>,
}

impl<'a> Hooked<'a> {
    /// Wraps `inner` for a run of `order` (its frames, in the order it takes them);
    /// `hook` runs for each frame within `limits`, its frame's file at `path(frame)`, and
    /// each run of it is `told`.
    pub fn new(
        inner: &'a dyn Reporter,
        order: &[u32],
        hook: Option<(Hook, Limits)>,
        path: FramePath,
        told: Told,
    ) -> Self {
        let (to_hook, worker) = match hook {
            None => (None, None),
            Some((hook, limits)) => {
                let (tx, rx) = channel::<(u32, FrameState)>();
                let worker = std::thread::spawn(move || {
                    let mut failed = 0;
                    for (frame, state) in rx {
                        if whitted_cmd::process::stopped(&limits.stop).is_some() {
                            continue; // the run was stopped: no hook starts
                        }
                        let run = hook.run_frame(frame, &path(frame), state, &limits);
                        failed += usize::from(run.failed());
                        told(&run);
                    }
                    failed
                });
                (Some(tx), Some(worker))
            }
        };
        let line = Line {
            order: order.to_vec(),
            next: 0,
            settled: HashMap::new(),
            to_hook,
        };
        Hooked {
            inner,
            line: Mutex::new(line),
            rendered: AtomicUsize::new(0),
            failed: AtomicUsize::new(0),
            worker,
        }
    }

    fn settle(&self, frame: u32, state: Option<FrameState>) {
        if let Ok(mut line) = self.line.lock() {
            line.settled.insert(frame, state);
            line.advance(false);
        }
    }

    /// Lets the rest of the line through, waits for the hooks, and says what the run did.
    pub fn finish(self) -> Tally {
        if let Ok(mut line) = self.line.lock() {
            line.advance(true);
            line.to_hook = None; // ends the hook thread's loop
        }
        let hooks_failed = self.worker.map_or(0, |w| w.join().unwrap_or(1));
        Tally {
            rendered: self.rendered.load(Ordering::Relaxed),
            failed: self.failed.load(Ordering::Relaxed),
            hooks_failed,
        }
    }
}

impl Reporter for Hooked<'_> {
    fn event(&self, event: Event) {
        self.inner.event(event);
        match event {
            Event::Started { .. } | Event::Sharing { .. } => {}
            Event::Elsewhere { frame } => self.settle(frame, None),
            Event::Finished { frame, .. } => {
                self.rendered.fetch_add(1, Ordering::Relaxed);
                self.settle(frame, Some(FrameState::Rendered));
            }
            Event::Skipped { frame } => self.settle(frame, Some(FrameState::UpToDate)),
            Event::Failed { frame } => {
                self.failed.fetch_add(1, Ordering::Relaxed);
                self.settle(frame, Some(FrameState::Failed));
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::Arc;

    #[test]
    fn hooks_run_in_the_runs_order_whatever_order_frames_finish_in() {
        let dir = tempfile::tempdir().unwrap();
        let log = dir.path().join("log");
        let hook: Hook = format!(
            "sh -c 'echo $ANIMATE_FRAME $ANIMATE_STATE >> {}'",
            log.display()
        )
        .parse()
        .unwrap();
        let runs = Arc::new(Mutex::new(0));
        let counted = runs.clone();
        let told: Told = Box::new(move |_| *counted.lock().unwrap() += 1);
        let path: FramePath = Box::new(|f| PathBuf::from(format!("f{f}")));
        let hooked = Hooked::new(
            &super::super::events::Silent,
            &[5, 1, 3, 2, 4],
            Some((hook, Limits::default())),
            path,
            told,
        );
        let rays = whitted::trace::RayCount::default();
        let done = |frame| Event::Finished {
            frame,
            seconds: 0.0,
            rays,
        };
        hooked.event(Event::Skipped { frame: 1 });
        hooked.event(done(3));
        hooked.event(Event::Failed { frame: 2 });
        hooked.event(done(5));
        // 4 never comes (the run stopped): finish lets the rest through without it.
        let tally = hooked.finish();
        assert_eq!(
            (tally.rendered, tally.failed, tally.hooks_failed),
            (2, 1, 0)
        );
        let text = std::fs::read_to_string(&log).unwrap();
        assert_eq!(text, "5 rendered\n1 up-to-date\n3 rendered\n2 failed\n");
        assert_eq!(*runs.lock().unwrap(), 4);
    }
}
