//! `.png`: 8-bit RGB, fast deflate, adaptive filters (frames are written by the hundred).
//! Metadata as text chunks before the image data: `tEXt` when the text is Latin-1 (all the
//! stamps of ASCII names, byte for byte what they always were), `iTXt` (UTF-8) otherwise,
//! so a manifest or scene called `日本.toml` or `сцена😀.txt` is recorded, not refused.

use super::OutputError;
use crate::render::Frame;
use image::codecs::png::{CompressionType, FilterType, PngEncoder};
use image::{ExtendedColorType, ImageEncoder};
use std::io::Write;

/// Whether `text` fits a `tEXt` chunk (every character Latin-1).
pub(crate) fn latin1(text: &str) -> bool {
    text.chars().all(|c| u32::from(c) < 256)
}

/// Encodes the frame, with text chunks when there is metadata.
pub(super) fn encode(
    frame: &Frame,
    meta: &[(String, String)],
    out: &mut dyn Write,
) -> Result<(), OutputError> {
    let (w, h) = (frame.width, frame.height);
    if meta.is_empty() {
        let enc = PngEncoder::new_with_quality(out, CompressionType::Fast, FilterType::Adaptive);
        enc.write_image(&frame.pixels, w, h, ExtendedColorType::Rgb8)?;
        return Ok(());
    }
    // The settings `PngEncoder` uses above, plus the text chunks.
    let mut enc = png::Encoder::new(out, w, h);
    enc.set_color(png::ColorType::Rgb);
    enc.set_depth(png::BitDepth::Eight);
    enc.set_compression(png::Compression::Fast);
    enc.set_filter(png::Filter::Adaptive);
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
