//! `.ppm`: binary P6, maxval 255; metadata as `# keyword: text` comment lines in the
//! header, between the magic number and the size.

use super::OutputError;
use crate::base::Frame;
use std::io::Write;

/// Writes the P6 header, its comments, then the pixels.
pub(super) fn encode(
    frame: &Frame,
    meta: &[(String, String)],
    out: &mut dyn Write,
) -> Result<(), OutputError> {
    writeln!(out, "P6")?;
    for (k, v) in meta {
        writeln!(out, "# {k}: {v}")?;
    }
    write!(out, "{} {}\n255\n", frame.width, frame.height)?;
    out.write_all(&frame.pixels)?;
    Ok(())
}
