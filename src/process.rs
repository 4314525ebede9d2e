//! What both binaries set up for a run: the pool of worker threads (`--threads`, default
//! all cores), and what SIGINT and SIGTERM do: raise the stop flag that the animation
//! pipeline reads between frames (`animate`), or end a run that has no such point at once
//! (`raytrace`'s one image), in both cases with the exit-status table's 128 + N.

use std::sync::atomic::{AtomicBool, AtomicUsize};
use std::sync::Arc;

/// The worker pool: `threads` workers, or one per core when `None`.
pub fn pool(threads: Option<u32>) -> Result<rayon::ThreadPool, rayon::ThreadPoolBuildError> {
    let n = threads.unwrap_or(0) as usize;
    rayon::ThreadPoolBuilder::new().num_threads(n).build()
}

/// A flag that holds the number of the first SIGINT or SIGTERM received (0 until then).
/// Without a handler the default action (terminate) remains; temporary files are still
/// never visible under final names.
pub fn watch_signals() -> Arc<AtomicUsize> {
    let stop = Arc::new(AtomicUsize::new(0));
    for sig in [signal_hook::consts::SIGINT, signal_hook::consts::SIGTERM] {
        let _ = signal_hook::flag::register_usize(sig, Arc::clone(&stop), sig as usize);
    }
    stop
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
    fn pools_have_the_threads_asked_for() {
        assert_eq!(super::pool(Some(3)).unwrap().current_num_threads(), 3);
    }
}
