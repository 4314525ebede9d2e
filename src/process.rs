//! What both binaries set up for a run: the pool of worker threads (`--threads`, default
//! all cores) and the stop flag that SIGINT and SIGTERM raise, which the animation
//! pipeline reads between frames.

use std::sync::atomic::AtomicUsize;
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

#[cfg(test)]
mod tests {
    #[test]
    fn pools_have_the_threads_asked_for() {
        assert_eq!(super::pool(Some(3)).unwrap().current_num_threads(), 3);
    }
}
