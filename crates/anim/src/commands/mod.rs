//! The subcommands of `animate` as library calls: a request in, text written to the
//! caller's standard output, an `Outcome` (the exit-status row) out. The binary parses the
//! command line into these requests and shows progress; the work is here.
//!
//! A reader that goes away (`animate status M | head -1`) ends a command quietly: no panic
//! and no message. A report whose verdict is known before it is printed (`status`,
//! `clean`) keeps its verdict's status; a command whose text is its product (`estimate`,
//! `job` on standard output) was cut short, [`CUT_SHORT`] (141, as a shell reports a
//! process ended by SIGPIPE).
//!
//! - `status`: `animate status`, the folder's state as a table or JSON;
//! - `stats`: `animate stats`, what the frames cost against their prediction;
//! - `farm`: `animate job` (an OpenJD template) and `animate estimate`;
//! - `folder`: `animate clean` and `animate encode`;
//! - `check`: `animate check` and `animate bless`.

pub mod check;
pub mod farm;
pub mod folder;
pub mod stats;
pub mod status;

use crate::error::AnimError;
use std::io::Write;
use whitted::exit::Outcome;

/// The outcome of a command whose text was cut short by its reader: 128 + SIGPIPE.
pub const CUT_SHORT: Outcome = Outcome::Interrupted(13);

/// Writes `text` to `out` and flushes it: `Ok(false)` when the reader has gone away (a
/// closed pipe), an error for any other failure (a full disk).
pub fn emit(out: &mut dyn Write, text: &[u8]) -> Result<bool, AnimError> {
    match out.write_all(text).and_then(|()| out.flush()) {
        Ok(()) => Ok(true),
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(false),
        Err(e) => Err(AnimError::Stdout(e)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A reader that went away after `room` bytes.
    struct Pipe {
        room: usize,
    }

    impl Write for Pipe {
        fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
            if self.room == 0 {
                return Err(std::io::ErrorKind::BrokenPipe.into());
            }
            let n = buf.len().min(self.room);
            self.room -= n;
            Ok(n)
        }
        fn flush(&mut self) -> std::io::Result<()> {
            Ok(())
        }
    }

    #[test]
    fn a_closed_pipe_is_no_error_and_a_full_disk_is() {
        assert!(emit(&mut Pipe { room: 10 }, b"short").unwrap());
        assert!(!emit(&mut Pipe { room: 3 }, b"longer than that").unwrap());
        let mut full = std::io::Cursor::new([0u8; 2]);
        let mut slice: &mut [u8] = full.get_mut();
        assert!(emit(&mut slice, b"abc").is_err());
        assert_eq!(CUT_SHORT.code(), 141);
    }
}
