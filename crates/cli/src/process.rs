//! What both binaries set up for a run: a check that the processor has the instruction
//! set the build was compiled for (`.cargo/config.toml`: x86-64-v2 on x86-64), the pool
//! of worker threads (`--threads`, default all cores), and what SIGINT and SIGTERM do:
//! for `animate`, the first raises the stop flag that the pipeline reads between frames
//! and cancels the frames in progress between rows (`render::control`), saying at once
//! how many frames it stops; a second ends the process at once. `raytrace`'s one image
//! ends at once. Both exit with the exit-status table's 128 + N.

use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::Arc;
use std::time::Duration;

/// The processor lacks instructions that this build was compiled to use.
#[derive(Debug, thiserror::Error)]
#[error(
    "this processor lacks {0}, which this build was compiled to use (.cargo/config.toml \
     targets x86-64-v2, every x86-64 CPU since about 2010); rebuild with \
     RUSTFLAGS=\"-C target-cpu=x86-64\" (same pixels, a little slower)"
)]
pub struct CpuError(pub String);

/// The instruction-set extensions the build was compiled to use (`cfg!(target_feature)`)
/// that the running processor does not report, joined by ", "; `Ok` when it has them
/// all. Called first by both binaries, before any code that may use them: a missing one
/// would otherwise kill the process with SIGILL in the middle of a render.
pub fn check_cpu() -> Result<(), CpuError> {
    #[allow(unused_mut)]
    let mut missing: Vec<&str> = Vec::new();
    #[cfg(target_arch = "x86_64")]
    {
        macro_rules! need {
            ($($f:tt),*) => {$(
                if cfg!(target_feature = $f) && !std::is_x86_feature_detected!($f) {
                    missing.push($f);
                }
            )*};
        }
        need!(
            "sse3",
            "ssse3",
            "sse4.1",
            "sse4.2",
            "popcnt",
            "cmpxchg16b",
            "avx",
            "avx2",
            "fma"
        );
    }
    if missing.is_empty() {
        Ok(())
    } else {
        Err(CpuError(missing.join(", ")))
    }
}

/// The worker pool: `threads` workers, or one per core when `None`.
pub fn pool(threads: Option<u32>) -> Result<rayon::ThreadPool, rayon::ThreadPoolBuildError> {
    let n = threads.unwrap_or(0) as usize;
    rayon::ThreadPoolBuilder::new().num_threads(n).build()
}

/// A flag that holds the number of the first SIGINT or SIGTERM received (0 until then).
/// Without a handler the default action (terminate) remains; temporary files are still
/// never visible under final names.
///
/// On the first signal the frames in progress stop before their next row (and are not
/// written) and a line `<name>: stopping: N frames in progress …` goes to standard error
/// at once, from a watcher thread (a signal handler itself only sets flags); a second
/// signal ends the process at once with 128 + N.
pub fn watch_signals(name: &'static str) -> Arc<AtomicUsize> {
    watch(Some(name))
}

/// `watch_signals` for a process that renders no frames of its own run (`animate view`):
/// no "stopping: N frames in progress" line, the flag alone.
pub fn watch_signals_quietly() -> Arc<AtomicUsize> {
    watch(None)
}

fn watch(name: Option<&'static str>) -> Arc<AtomicUsize> {
    use signal_hook::consts::{SIGINT, SIGTERM};
    let stop = Arc::new(AtomicUsize::new(0));
    let seen = Arc::new(AtomicBool::new(false));
    for sig in [SIGINT, SIGTERM] {
        // Registered first, so it sees `seen` as the earlier signal left it.
        let _ = signal_hook::flag::register_conditional_shutdown(sig, 128 + sig, seen.clone());
        let _ = signal_hook::flag::register(sig, seen.clone());
        let _ = signal_hook::flag::register_usize(sig, Arc::clone(&stop), sig as usize);
    }
    if let Ok(mut signals) = signal_hook::iterator::Signals::new([SIGINT, SIGTERM]) {
        std::thread::spawn(move || {
            if let Some(sig) = signals.forever().next() {
                whitted::render::control::cancel(sig as usize);
                let Some(name) = name else {
                    return;
                };
                let n = whitted::render::control::frames_in_progress();
                let frames = if n == 1 { "frame" } else { "frames" };
                eprintln!(
                    "{name}: stopping: {n} {frames} in progress (finished frames are kept; \
                     a second Ctrl-C ends at once)"
                );
            }
        });
    }
    stop
}

/// For a run whose output may stall (a `--stdout` reader that stops reading holds a
/// write forever): once `stop` holds a signal, waits half a second for the run to stop
/// by itself, then prints `last_words(N)` on standard error and ends the process with
/// status 128 + N. The run normally ends first, and the process with it.
pub fn exit_when_stuck(
    stop: Arc<AtomicUsize>,
    last_words: impl Fn(i32) -> String + Send + 'static,
) {
    static NEVER: AtomicBool = AtomicBool::new(false);
    std::thread::spawn(move || {
        after_stop(&stop, &NEVER, Duration::from_millis(500), |sig| {
            eprintln!("{}", last_words(sig));
            std::process::exit(128 + sig);
        })
    });
}

/// The signal number held in `stop`, if any.
pub fn stopped(stop: &AtomicUsize) -> Option<i32> {
    match stop.load(Ordering::SeqCst) {
        0 => None,
        sig => Some(sig as i32),
    }
}

/// A watchdog, run on a thread of its own: polls `stop` every 20 ms until it holds a
/// signal, waits `grace`, then calls `action` with the signal number unless `done` was
/// set meanwhile (the work ended by itself). Returns as soon as `done` is set.
pub fn after_stop(
    stop: &AtomicUsize,
    done: &AtomicBool,
    grace: Duration,
    action: impl FnOnce(i32),
) {
    while !done.load(Ordering::SeqCst) {
        if let Some(sig) = stopped(stop) {
            std::thread::sleep(grace);
            if !done.load(Ordering::SeqCst) {
                action(sig);
            }
            return;
        }
        std::thread::sleep(Duration::from_millis(20));
    }
}

/// Whether the process was started with its standard output closed (`>&-`). Rust's
/// runtime then opens `/dev/null` read-write in its place, so writes would vanish
/// silently; a shell's `> /dev/null` opens it write-only. Linux only (`/proc`).
pub fn stdout_closed() -> bool {
    let null = std::fs::read_link("/proc/self/fd/1").is_ok_and(|p| p == *"/dev/null");
    let flags = std::fs::read_to_string("/proc/self/fdinfo/1").ok();
    let rdwr = flags
        .as_deref()
        .and_then(|t| t.lines().find_map(|l| l.strip_prefix("flags:")))
        .and_then(|f| u32::from_str_radix(f.trim(), 8).ok())
        .is_some_and(|f| f & 3 == 2);
    null && rdwr
}

/// Makes SIGINT and SIGTERM end the process at once with status 128 + N (130, 143), for
/// a run that cannot stop between pieces of work. The status is the same whatever signal
/// handling the process inherited (a job started with SIGINT ignored still stops).
/// Nothing is left under a final name: images are written under a temporary name and
/// renamed.
pub fn exit_on_signals() {
    for sig in [signal_hook::consts::SIGINT, signal_hook::consts::SIGTERM] {
        let always = Arc::new(AtomicBool::new(true));
        let _ = signal_hook::flag::register_conditional_shutdown(sig, 128 + sig, always);
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn the_build_targets_x86_64_v2_and_this_cpu_has_it() {
        // `.cargo/config.toml` compiles for x86-64-v2 on x86-64; losing that setting
        // would silently give up its speed (the pixels are the same either way).
        #[cfg(target_arch = "x86_64")]
        {
            let built = [
                cfg!(target_feature = "sse4.2"),
                cfg!(target_feature = "popcnt"),
            ];
            assert_eq!(
                built, [true; 2],
                "not built for x86-64-v2: is .cargo/config.toml in force (or RUSTFLAGS set)?"
            );
        }
        super::check_cpu().unwrap();
    }

    #[test]
    fn a_missing_feature_is_named_with_the_way_out() {
        let e = super::CpuError("sse4.2, popcnt".into()).to_string();
        assert!(e.starts_with("this processor lacks sse4.2, popcnt"), "{e}");
        assert!(e.contains("RUSTFLAGS=\"-C target-cpu=x86-64\""), "{e}");
    }

    #[test]
    fn pools_have_the_threads_asked_for() {
        assert_eq!(super::pool(Some(3)).unwrap().current_num_threads(), 3);
    }

    #[test]
    fn after_stop_acts_once_stopped_unless_done() {
        use std::sync::atomic::{AtomicBool, AtomicUsize};
        use std::time::Duration;
        let (stop, done) = (AtomicUsize::new(15), AtomicBool::new(false));
        let mut seen = None;
        super::after_stop(&stop, &done, Duration::ZERO, |sig| seen = Some(sig));
        assert_eq!(seen, Some(15));
        assert_eq!(super::stopped(&stop), Some(15));
        // Done first: it returns without acting, whatever the flag holds.
        done.store(true, std::sync::atomic::Ordering::SeqCst);
        super::after_stop(&stop, &done, Duration::ZERO, |_| panic!("acted after done"));
        assert_eq!(super::stopped(&AtomicUsize::new(0)), None);
    }
}
