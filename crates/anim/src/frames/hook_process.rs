//! A hook's process, from its start to its end (`hooks`): started in a process group of
//! its own, with no standard input and its standard output and error read on threads of
//! their own into bounded tails (`Tail`: the last `TAIL_BYTES` of each, and how many
//! bytes before them were dropped), so that a hook printing gigabytes costs the run
//! kilobytes.
//!
//! The run waits for the process, not for its pipes: a hook that leaves a child in the
//! background (`sh -c 'upload & '`) ends when its own process does; what the child prints
//! afterwards is read and dropped. The wait ends early when the run is stopped (SIGINT or
//! SIGTERM: `stop` holds the signal) or the hook's time runs out (`--hook-timeout`): the
//! hook's whole process group is sent SIGTERM, then SIGKILL after `GRACE`, so neither the
//! hook nor what it started outlives the run.

use rustix::process::{kill_process_group, Pid, Signal};
use std::collections::VecDeque;
use std::io::Read;
use std::os::unix::process::CommandExt;
use std::process::{Child, Command, ExitStatus, Stdio};
use std::sync::atomic::AtomicUsize;
use std::sync::mpsc::{channel, Receiver};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// The most bytes kept of each of a hook's standard output and error (the last ones).
pub const TAIL_BYTES: usize = 64 << 10;
/// How long a hook's process group has between SIGTERM and SIGKILL.
pub const GRACE: Duration = Duration::from_secs(1);
/// How long the run waits, once a hook has ended, for the rest of what it printed: the
/// pipes stay open as long as a child it left in the background runs.
const DRAIN: Duration = Duration::from_millis(200);

/// The last bytes of a stream, and how many came before them.
#[derive(Debug, Default)]
struct Tail {
    bytes: VecDeque<u8>,
    dropped: u64,
}

impl Tail {
    fn push(&mut self, data: &[u8]) {
        let keep = data.len().min(TAIL_BYTES);
        let (cut, data) = data.split_at(data.len() - keep);
        self.dropped += cut.len() as u64;
        self.bytes.extend(data);
        let over = self.bytes.len().saturating_sub(TAIL_BYTES);
        if over > 0 {
            self.bytes.drain(..over);
            self.dropped += over as u64;
        }
    }

    /// The tail as text, led by a line saying how much was dropped before it.
    fn text(&self) -> String {
        let (a, b) = self.bytes.as_slices();
        let mut text = String::from_utf8_lossy(&[a, b].concat()).into_owned();
        if self.dropped > 0 {
            text = format!(
                "[{} bytes before these were not kept]\n{text}",
                self.dropped
            );
        }
        text
    }
}

/// Reads `pipe` into a tail on a thread of its own; the receiver hears when it ends.
fn drain(mut pipe: impl Read + Send + 'static) -> (Arc<Mutex<Tail>>, Receiver<()>) {
    let tail = Arc::new(Mutex::new(Tail::default()));
    let (done, ended) = channel();
    let kept = tail.clone();
    std::thread::spawn(move || {
        let mut buf = vec![0u8; 64 << 10];
        while let Ok(n @ 1..) = pipe.read(&mut buf) {
            if let Ok(mut tail) = kept.lock() {
                tail.push(&buf[..n]);
            }
        }
        let _ = done.send(());
    });
    (tail, ended)
}

/// How a hook's process ended.
#[derive(Debug)]
pub enum Ended {
    /// By itself, with this status.
    Exited(ExitStatus),
    /// Killed with its group because the run was stopped by this signal.
    Stopped(i32),
    /// Killed with its group when its time ran out.
    TimedOut(Duration),
}

/// What a hook's process did: how it ended, and its standard output then error (tails).
#[derive(Debug)]
pub struct Finished {
    /// How it ended.
    pub ended: Ended,
    /// Its standard output's tail, then its standard error's.
    pub output: String,
}

/// Starts `cmd` (its program and arguments set) in a process group of its own with no
/// standard input, and waits for it: until it exits, `stop` holds a signal, or `timeout`
/// has passed.
pub fn run(
    cmd: &mut Command,
    stop: &AtomicUsize,
    timeout: Option<Duration>,
) -> std::io::Result<Finished> {
    let mut child = cmd
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .process_group(0)
        .spawn()?;
    let mut tails = Vec::new();
    if let Some(out) = child.stdout.take() {
        tails.push(drain(out));
    }
    if let Some(err) = child.stderr.take() {
        tails.push(drain(err));
    }
    let ended = supervise(&mut child, stop, timeout)?;
    let until = Instant::now() + DRAIN;
    for (_, ended) in &tails {
        let _ = ended.recv_timeout(until.saturating_duration_since(Instant::now()));
    }
    let output = tails
        .iter()
        .map(|(tail, _)| tail.lock().map(|t| t.text()).unwrap_or_default())
        .collect();
    Ok(Finished { ended, output })
}

/// Waits for `child`, polling (every millisecond at first, then up to every 50 ms), and
/// ends its group when the run is stopped or its time is up.
fn supervise(
    child: &mut Child,
    stop: &AtomicUsize,
    timeout: Option<Duration>,
) -> std::io::Result<Ended> {
    let start = Instant::now();
    let mut poll = Duration::from_millis(1);
    loop {
        if let Some(status) = child.try_wait()? {
            return Ok(Ended::Exited(status));
        }
        if let Some(sig) = whitted_cmd::process::stopped(stop) {
            end_group(child)?;
            return Ok(Ended::Stopped(sig));
        }
        if let Some(limit) = timeout.filter(|&t| start.elapsed() >= t) {
            end_group(child)?;
            return Ok(Ended::TimedOut(limit));
        }
        std::thread::sleep(poll);
        poll = (poll * 2).min(Duration::from_millis(50));
    }
}

/// Sends the group of `child` (its leader) SIGTERM, waits up to `GRACE` for the leader,
/// then sends the group SIGKILL (whatever of it is left) and reaps the leader.
fn end_group(child: &mut Child) -> std::io::Result<()> {
    let group = Pid::from_child(child);
    let _ = kill_process_group(group, Signal::TERM);
    let start = Instant::now();
    while start.elapsed() < GRACE {
        if child.try_wait()?.is_some() {
            break;
        }
        std::thread::sleep(Duration::from_millis(10));
    }
    // The group outlives its leader while anything it started runs.
    let _ = kill_process_group(group, Signal::KILL);
    child.wait().map(drop)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_tail_keeps_the_last_bytes_and_counts_the_rest() {
        let mut tail = Tail::default();
        tail.push(b"abc");
        assert_eq!(tail.text(), "abc");
        tail.push(&vec![b'x'; TAIL_BYTES]);
        tail.push(b"end");
        assert_eq!(tail.dropped, 6);
        let text = tail.text();
        assert!(text.starts_with("[6 bytes before these were not kept]\nxxx"));
        assert!(text.ends_with("xend"));
        assert_eq!(tail.bytes.len(), TAIL_BYTES);
    }

    #[test]
    fn the_wait_is_for_the_process_and_a_stop_ends_its_group() {
        let stop = AtomicUsize::new(0);
        // A child left in the background keeps the pipes open for 30 s.
        let mut cmd = Command::new("sh");
        cmd.args(["-c", "sleep 30 & echo $!; echo bye >&2"]);
        let start = Instant::now();
        let done = run(&mut cmd, &stop, None).unwrap();
        assert!(start.elapsed() < Duration::from_secs(10));
        assert!(matches!(done.ended, Ended::Exited(s) if s.success()));
        let pid: i32 = done.output.lines().next().unwrap().parse().unwrap();
        assert!(done.output.ends_with("bye\n"), "{}", done.output);
        let _ = kill_process_group(Pid::from_raw(pid).unwrap(), Signal::KILL);
        // Stopped: the hook and its child in the background both end.
        let stop = AtomicUsize::new(15);
        let mut cmd = Command::new("sh");
        cmd.args(["-c", "sleep 30 & sleep 30"]);
        let done = run(&mut cmd, &stop, None).unwrap();
        assert!(matches!(done.ended, Ended::Stopped(15)));
        let timed = run(
            Command::new("sleep").arg("30"),
            &AtomicUsize::new(0),
            Some(Duration::from_millis(50)),
        );
        assert!(matches!(timed.unwrap().ended, Ended::TimedOut(_)));
    }
}
