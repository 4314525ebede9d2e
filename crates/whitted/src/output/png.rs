//! `.png`: 8-bit RGB, fast deflate, adaptive filters (frames are written by the hundred),
//! tagged sRGB (SPEC §12: the report's values are display values): an `sRGB` chunk
//! (perceptual intent) with the `gAMA` 1/2.2 and `cHRM` Rec.709/D65 that PNG asks to go
//! with it for older readers; the pixel bytes are the tracer's, untouched. Metadata as text chunks before the image data: `tEXt` when the text is Latin-1 (all the
//! stamps of ASCII names, byte for byte what they always were), `iTXt` (UTF-8) otherwise,
//! so a manifest or scene called `日本.toml` or `сцена😀.txt` is recorded, not refused.

use super::OutputError;
use crate::base::Frame;
use std::io::Write;

/// Whether `text` fits a `tEXt` chunk (every character Latin-1).
pub(crate) fn latin1(text: &str) -> bool {
    text.chars().all(|c| u32::from(c) < 256)
}

/// Encodes the frame, tagged sRGB, with text chunks when there is metadata.
pub(super) fn encode(
    frame: &Frame,
    meta: &[(String, String)],
    out: &mut dyn Write,
) -> Result<(), OutputError> {
    let (w, h) = (frame.width, frame.height);
    let mut enc = png::Encoder::new(out, w, h);
    enc.set_color(png::ColorType::Rgb);
    enc.set_depth(png::BitDepth::Eight);
    enc.set_compression(png::Compression::Fast);
    enc.set_filter(png::Filter::Adaptive);
    enc.set_source_srgb(png::SrgbRenderingIntent::Perceptual);
    enc.set_source_gamma(png::ScaledFloat::from_scaled(45455));
    let s = png::ScaledFloat::from_scaled;
    enc.set_source_chromaticities(png::SourceChromaticities {
        white: (s(31270), s(32900)),
        red: (s(64000), s(33000)),
        green: (s(30000), s(60000)),
        blue: (s(15000), s(6000)),
    });
    for (k, v) in meta {
        if latin1(v) {
            enc.add_text_chunk(k.clone(), v.clone())
        } else {
            enc.add_itxt_chunk(k.clone(), v.clone())
        }
        .map_err(png_error)?;
    }
    let mut writer = enc.write_header().map_err(png_error)?;
    writer.write_image_data(&frame.pixels).map_err(png_error)?;
    writer.finish().map_err(png_error)?;
    Ok(())
}

fn png_error(e: png::EncodingError) -> OutputError {
    OutputError::Stream(std::io::Error::other(e))
}
