//! One exit-status table for both binaries (`raytrace`, `animate`):
//!
//! | status | meaning |
//! |---|---|
//! | 0 | success (for `animate check`: every frame passed; `animate status`: all up to date) |
//! | 1 | the run started and failed: a frame could not be rendered or written, ffmpeg failed, a check failed, frames are stale |
//! | 2 | nothing was rendered because the request cannot be carried out as given: bad arguments, manifest or scene, an output location that cannot be used, a missing tool (ffmpeg) or processor feature (`process::check_cpu`), a check that cannot run |
//! | 128 + N | stopped by signal N (130 SIGINT, 143 SIGTERM); finished frames are kept |
//!
//! Errors of the library say which row they belong to (`Outcome`); the binaries turn that
//! into the process status.

/// How a command ended, as far as the exit status is concerned.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Outcome {
    /// Everything asked for was done (status 0).
    Success,
    /// The run started and something failed (status 1).
    Failed,
    /// The request cannot be carried out as given (status 2).
    BadInput,
    /// Stopped by a signal.
    Interrupted(i32),
}

impl Outcome {
    /// The process exit status.
    pub fn code(self) -> u8 {
        match self {
            Outcome::Success => 0,
            Outcome::Failed => 1,
            Outcome::BadInput => 2,
            Outcome::Interrupted(sig) => (128 + sig).clamp(0, 255) as u8,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_table() {
        assert_eq!(Outcome::Success.code(), 0);
        assert_eq!(Outcome::Failed.code(), 1);
        assert_eq!(Outcome::BadInput.code(), 2);
        assert_eq!(Outcome::Interrupted(2).code(), 130);
        assert_eq!(Outcome::Interrupted(15).code(), 143);
    }
}
