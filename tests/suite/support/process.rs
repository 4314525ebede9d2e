//! Running the built binaries as processes the tests steer: `spawn_animate(manifest,
//! args)` (standard output dropped, standard error piped), `signal(&child, "INT")`,
//! waiting with a deadline (`wait_within`, `output_within`: a hang fails the test instead
//! of blocking the suite), a process's peak memory, CPU time, children and command line,
//! FIFOs, and `timed`: a time checked against a generous failure bound on a loaded machine
//! and printed beside its target, in the normal output of `cargo test`.

use std::ffi::OsStr;
use std::io::{Read, Write};
use std::path::Path;
use std::process::{Child, Command, ExitStatus, Output, Stdio};
use std::time::{Duration, Instant};

/// `animate MANIFEST ARGS` started in the background: standard output dropped, standard
/// error piped (read it with `stderr_of`).
pub fn spawn_animate(manifest: impl AsRef<OsStr>, args: &[&str]) -> Child {
    Command::new(assert_cmd::cargo::cargo_bin("animate"))
        .arg(manifest)
        .args(args)
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .expect("animate starts")
}

/// Sends `sig` (`INT`, `TERM`, `STOP`, …) to the process `pid`, through kill(1). `INT`
/// and `TERM` wait first (up to 30 s) until the process catches them: a process that is
/// still starting has the default action, death by the signal, not the 130 or 143 its
/// handler exits with; on a loaded machine a fixed sleep is not enough to be past that.
pub fn signal_pid(pid: u32, sig: &str) {
    if let Some(number) = match sig {
        "INT" => Some(2),
        "TERM" => Some(15),
        _ => None,
    } {
        let ready = poll_until(Duration::from_secs(30), || {
            !alive(pid) || catches(pid, number)
        });
        assert!(ready.is_some(), "process {pid} never caught SIG{sig}");
    }
    let ok = Command::new("kill")
        .args(["-s", sig, &pid.to_string()])
        .status()
        .expect("kill runs");
    assert!(ok.success(), "kill -s {sig} {pid} failed");
}

/// Sends `sig` to `child`.
pub fn signal(child: &Child, sig: &str) {
    signal_pid(child.id(), sig);
}

/// All of `child`'s piped standard error (read to its end).
pub fn stderr_of(child: &mut Child) -> String {
    let mut err = String::new();
    if let Some(mut pipe) = child.stderr.take() {
        pipe.read_to_string(&mut err).unwrap();
    }
    err
}

/// Polls `done` every 10 ms until it is true, at most `limit`; how long that took, or
/// `None` when the time ran out.
pub fn poll_until(limit: Duration, mut done: impl FnMut() -> bool) -> Option<Duration> {
    let start = Instant::now();
    loop {
        if done() {
            return Some(start.elapsed());
        }
        if start.elapsed() > limit {
            return None;
        }
        std::thread::sleep(Duration::from_millis(10));
    }
}

/// Waits for `child`, at most `limit`: its exit code and how long the wait took. Past
/// `limit` the child is killed and the test fails.
pub fn wait_within(child: &mut Child, limit: Duration) -> (Option<i32>, Duration) {
    let mut status = None;
    let took = poll_until(limit, || {
        status = child.try_wait().unwrap();
        status.is_some()
    });
    match (took, status) {
        (Some(took), Some(status)) => (status.code(), took),
        _ => {
            let _ = child.kill();
            let _ = child.wait();
            panic!("still running after {limit:?}");
        }
    }
}

/// Runs `cmd` to its end with its output captured, at most `limit`; past that it is
/// killed and the test fails.
pub fn output_within(cmd: &mut Command, limit: Duration) -> Output {
    let mut child = cmd
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut status = None;
    let done = poll_until(limit, || {
        status = child.try_wait().unwrap();
        status.is_some()
    });
    if done.is_none() {
        let _ = child.kill();
        let _ = child.wait();
        panic!("still running after {limit:?}: {cmd:?}");
    }
    child.wait_with_output().unwrap()
}

/// The peak resident memory (VmHWM, KiB) of a running process, polled every 2 ms until it
/// exits, and its exit status.
pub fn peak_kib_until_exit(mut child: Child) -> (u64, ExitStatus) {
    let status_file = format!("/proc/{}/status", child.id());
    let mut peak = 0;
    loop {
        if let Ok(text) = std::fs::read_to_string(&status_file) {
            let hwm = text
                .lines()
                .find_map(|l| l.strip_prefix("VmHWM:"))
                .and_then(|v| v.trim().trim_end_matches("kB").trim().parse::<u64>().ok());
            peak = peak.max(hwm.unwrap_or(0));
        }
        if let Some(status) = child.try_wait().unwrap() {
            return (peak, status);
        }
        std::thread::sleep(Duration::from_millis(2));
    }
}

/// The child processes of `pid`, started by any of its threads (from /proc: each
/// thread's `children` lists only what that thread started).
pub fn children(pid: u32) -> Vec<u32> {
    let Ok(tasks) = std::fs::read_dir(format!("/proc/{pid}/task")) else {
        return Vec::new();
    };
    let mut out: Vec<u32> = tasks
        .filter_map(|t| t.ok())
        .filter_map(|t| std::fs::read_to_string(t.path().join("children")).ok())
        .flat_map(|text| {
            text.split_whitespace()
                .filter_map(|p| p.parse().ok())
                .collect::<Vec<u32>>()
        })
        .collect();
    out.sort_unstable();
    out.dedup();
    out
}

/// The command line of the process `pid`, its arguments joined by spaces ("" once gone).
pub fn cmdline(pid: u32) -> String {
    let raw = std::fs::read(format!("/proc/{pid}/cmdline")).unwrap_or_default();
    String::from_utf8_lossy(&raw)
        .replace('\0', " ")
        .trim()
        .to_string()
}

/// The CPU time (user + system, all threads) the process `pid` has used so far; zero once
/// it is gone. Nothing else burns CPU in a test's server or renderer, so a rise says it is
/// rendering.
pub fn cpu_time(pid: u32) -> Duration {
    let stat = std::fs::read_to_string(format!("/proc/{pid}/stat")).unwrap_or_default();
    // The fields after the command's `)`: state is field 3, utime 14 and stime 15.
    let fields: Vec<&str> = stat
        .rsplit_once(')')
        .map(|(_, rest)| rest.split_whitespace().collect())
        .unwrap_or_default();
    let ticks: u64 = [11, 12]
        .iter()
        .filter_map(|&k| fields.get(k).and_then(|f| f.parse::<u64>().ok()))
        .sum();
    // USER_HZ is 100 on every Linux the tests run on.
    Duration::from_millis(ticks * 10)
}

/// Whether the process `pid` has a handler for signal `number` (its `SigCgt` mask).
pub fn catches(pid: u32, number: u32) -> bool {
    let status = std::fs::read_to_string(format!("/proc/{pid}/status")).unwrap_or_default();
    status
        .lines()
        .find_map(|l| l.strip_prefix("SigCgt:"))
        .and_then(|mask| u64::from_str_radix(mask.trim(), 16).ok())
        .is_some_and(|mask| mask & (1 << (number - 1)) != 0)
}

/// Whether the process `pid` still exists (a zombie not yet reaped counts as gone).
pub fn alive(pid: u32) -> bool {
    std::fs::read_to_string(format!("/proc/{pid}/stat")).is_ok_and(|s| {
        !s.rsplit(')')
            .next()
            .unwrap_or("")
            .trim_start()
            .starts_with('Z')
    })
}

/// Makes a FIFO at `path` (mkfifo(1)).
pub fn mkfifo(path: &Path) {
    let ok = Command::new("mkfifo")
        .arg(path)
        .status()
        .expect("mkfifo runs");
    assert!(ok.success(), "mkfifo {} failed", path.display());
}

/// Checks `took`, the time `what` took, against `bound`: a failure bound generous enough
/// for a loaded two-core CI machine, still far below what a regression costs. The time is
/// printed beside `target` (the figure the product aims at, measured by the ignored
/// measurement tests) on the real standard error, so it shows in plain `cargo test`.
pub fn timed(what: &str, took: Duration, target: Duration, bound: Duration) {
    let test = std::thread::current()
        .name()
        .unwrap_or("a test")
        .to_string();
    let line = format!(
        "TIMING {}::{test}: {what}: {took:.2?} (target {target:?}, fails past {bound:?})\n",
        env!("CARGO_CRATE_NAME")
    );
    let _ = std::io::stderr().lock().write_all(line.as_bytes());
    assert!(
        took < bound,
        "{what} took {took:?}, past the failure bound {bound:?} (target {target:?})"
    );
}
