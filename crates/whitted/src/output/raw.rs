//! `.raw`, the report's format: width·height·3 bytes, RGB, rows top to bottom, no header,
//! so no metadata (an animation keeps a RAW frame's record beside it).

use super::OutputError;
use crate::base::Frame;
use std::io::Write;

/// Writes the pixels as they are.
pub(super) fn encode(frame: &Frame, out: &mut dyn Write) -> Result<(), OutputError> {
    out.write_all(&frame.pixels)?;
    Ok(())
}
