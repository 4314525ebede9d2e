//! Commands a run starts for its user: `--on-frame CMD` after each frame it delivers or
//! finds up to date, `--on-done CMD` after the run.
//!
//! CMD is split into words as a POSIX shell splits them (quotes and backslashes, through
//! the `shlex` crate) and started directly, never through a shell: `sh -c '…'` is how a
//! user asks for one. The hook gets the run's environment plus its own variables
//! (`ANIMATE_FRAME`, `ANIMATE_PATH`, `ANIMATE_STATE` for a frame; `ANIMATE_RENDERED`,
//! `ANIMATE_FAILED`, `ANIMATE_EXIT` for the run), no standard input, and the last 64 KiB
//! of its standard output and of its error are kept: shown with the failure when it
//! fails, passed on when it succeeds. The run waits for the hook's process (not for what
//! it left in the background), and ends its process group when the run is stopped or the
//! hook's time (`Limits::timeout`) runs out (`hook_process`).
//!
//! Frame hooks run one at a time on a thread of their own (a slow hook never holds a
//! render worker), in the order the run takes its frames (`Hooked`): a frame's hook waits
//! until every frame before it in that order has been delivered, found up to date,
//! failed, or left to another run, so the order is the same on any thread count.

use super::hook_process::{self, Ended};
use std::collections::HashMap;
use std::process::Command;
use std::sync::atomic::AtomicUsize;
use std::sync::Arc;
use std::time::Duration;

/// What bounds a hook's run: the run's stop flag (a signal number once SIGINT or SIGTERM
/// came) and the hook's time (`--hook-timeout`), if any.
#[derive(Clone, Debug, Default)]
pub struct Limits {
    /// The run's stop flag.
    pub stop: Arc<AtomicUsize>,
    /// The most a hook may run.
    pub timeout: Option<Duration>,
}

/// A command to run, split into words.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Hook {
    words: Vec<String>,
}

/// Why a command line cannot be a hook.
#[derive(Debug, thiserror::Error, PartialEq, Eq)]
pub enum HookError {
    /// Nothing to run.
    #[error("an empty command")]
    Empty,
    /// Quotes that do not close, or a backslash at the end.
    #[error("cannot split {0:?} into words as a shell would (a quote that does not close?)")]
    Unsplittable(String),
}

impl std::str::FromStr for Hook {
    type Err = HookError;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let words = shlex::split(s).ok_or_else(|| HookError::Unsplittable(s.into()))?;
        match words.is_empty() {
            true => Err(HookError::Empty),
            false => Ok(Hook { words }),
        }
    }
}

/// What became of one frame, for its hook (`ANIMATE_STATE`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FrameState {
    /// Rendered and written by this run.
    Rendered,
    /// Already up to date (`--resume`), left as it was.
    UpToDate,
    /// Could not be rendered or written.
    Failed,
}

impl FrameState {
    /// The word the hook sees.
    pub fn word(self) -> &'static str {
        match self {
            FrameState::Rendered => "rendered",
            FrameState::UpToDate => "up-to-date",
            FrameState::Failed => "failed",
        }
    }
}

/// One hook's run: what it was for, whether it succeeded, what it printed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct HookRun {
    /// `--on-frame` or `--on-done`.
    pub option: &'static str,
    /// The frame, for a frame hook.
    pub frame: Option<u32>,
    /// `None` on success; else how it failed ("exit status 3", "cannot start: …").
    pub failure: Option<String>,
    /// Its standard output then its standard error, as text.
    pub output: String,
}

impl HookRun {
    /// Whether the hook failed.
    pub fn failed(&self) -> bool {
        self.failure.is_some()
    }

    /// The line that reports a failed hook, its output after it, indented.
    pub fn report(&self) -> String {
        let whose = match self.frame {
            Some(f) => format!("{} hook for frame {f}", self.option),
            None => format!("{} hook", self.option),
        };
        let how = self.failure.as_deref().unwrap_or("succeeded");
        let mut text = format!("{whose} failed ({how})");
        let output = self.output.trim_end();
        if output.is_empty() {
            text.push_str(", printing nothing");
        } else {
            text.push_str(", printing:");
            for line in output.lines() {
                text.push_str("\n    ");
                text.push_str(line);
            }
        }
        text
    }
}

impl Hook {
    /// The words, as given.
    pub fn words(&self) -> &[String] {
        &self.words
    }

    /// Runs the hook with `env` added to the environment and waits for it, within
    /// `limits`.
    pub fn run(
        &self,
        option: &'static str,
        frame: Option<u32>,
        env: &[(&str, String)],
        limits: &Limits,
    ) -> HookRun {
        let vars: HashMap<&str, &String> = env.iter().map(|(k, v)| (*k, v)).collect();
        let mut cmd = Command::new(&self.words[0]);
        cmd.args(&self.words[1..]).envs(vars);
        let (failure, output) = match hook_process::run(&mut cmd, &limits.stop, limits.timeout) {
            Err(e) => (
                Some(format!("cannot start {:?}: {e}", self.words[0])),
                String::new(),
            ),
            Ok(done) => {
                let failure = match done.ended {
                    Ended::Exited(status) => (!status.success()).then(|| shown_status(&status)),
                    Ended::Stopped(sig) => Some(format!(
                        "stopped with the run by signal {sig}: its process group was ended"
                    )),
                    Ended::TimedOut(limit) => Some(format!(
                        "ran past --hook-timeout {}: its process group was ended",
                        seconds(limit)
                    )),
                };
                (failure, done.output)
            }
        };
        HookRun {
            option,
            frame,
            failure,
            output,
        }
    }

    /// Runs the frame hook for `frame`, written at `path`, in `state`.
    pub fn run_frame(
        &self,
        frame: u32,
        path: &std::path::Path,
        state: FrameState,
        limits: &Limits,
    ) -> HookRun {
        let env = [
            ("ANIMATE_FRAME", frame.to_string()),
            ("ANIMATE_PATH", path.display().to_string()),
            ("ANIMATE_STATE", state.word().to_string()),
        ];
        self.run("--on-frame", Some(frame), &env, limits)
    }

    /// Runs the run's hook: `rendered` frames delivered, `failed` frames that failed,
    /// `exit` the status the run ends with.
    pub fn run_done(&self, rendered: usize, failed: usize, exit: u8, limits: &Limits) -> HookRun {
        let env = [
            ("ANIMATE_RENDERED", rendered.to_string()),
            ("ANIMATE_FAILED", failed.to_string()),
            ("ANIMATE_EXIT", exit.to_string()),
        ];
        self.run("--on-done", None, &env, limits)
    }
}

/// A duration as `--hook-timeout` takes it: `5 s`, `0.25 s`.
fn seconds(d: Duration) -> String {
    format!("{} s", d.as_secs_f64())
}

fn shown_status(status: &std::process::ExitStatus) -> String {
    use std::os::unix::process::ExitStatusExt;
    match (status.code(), status.signal()) {
        (Some(code), _) => format!("exit status {code}"),
        (None, Some(sig)) => format!("killed by signal {sig}"),
        _ => status.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn words_as_a_shell_splits_them() {
        let hook: Hook = r#"notify "frame done" 'a b' c\ d"#.parse().unwrap();
        assert_eq!(hook.words(), ["notify", "frame done", "a b", "c d"]);
        assert_eq!("  ".parse::<Hook>(), Err(HookError::Empty));
        assert!(matches!(
            "echo 'open".parse::<Hook>(),
            Err(HookError::Unsplittable(_))
        ));
    }

    #[test]
    fn no_shell_between_the_words_and_the_program() {
        // `$ANIMATE_FRAME` stays a word: no shell expands it.
        let hook: Hook = "echo $ANIMATE_FRAME ; x".parse().unwrap();
        let path = std::path::Path::new("f.png");
        let run = hook.run_frame(3, path, FrameState::Rendered, &Limits::default());
        assert_eq!(run.output, "$ANIMATE_FRAME ; x\n");
        assert!(!run.failed());
    }

    #[test]
    fn a_failure_is_reported_with_its_output() {
        let hook: Hook = "sh -c 'echo out; echo err >&2; exit 3'".parse().unwrap();
        let run = hook.run_done(2, 1, 1, &Limits::default());
        assert_eq!(run.failure.as_deref(), Some("exit status 3"));
        let said = "--on-done hook failed (exit status 3), printing:\n    out\n    err";
        assert_eq!(run.report(), said);
        let missing: Hook = "no-such-program-here".parse().unwrap();
        let run = missing.run_done(0, 0, 0, &Limits::default());
        assert!(run
            .failure
            .unwrap()
            .starts_with("cannot start \"no-such-program-here\""));
    }
}
