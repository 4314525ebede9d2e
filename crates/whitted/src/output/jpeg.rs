//! `.jpg`/`.jpeg`: baseline JPEG (quality 90 unless set); metadata as one comment (COM
//! segment) of `keyword: text` lines (UTF-8) right after the start marker.

use super::OutputError;
use crate::base::Frame;
use image::codecs::jpeg::JpegEncoder;
use image::{ExtendedColorType, ImageEncoder};
use std::io::Write;

/// Encodes the frame at `quality` (1..=100) with its comment.
pub(super) fn encode(
    frame: &Frame,
    quality: u8,
    meta: &[(String, String)],
    out: &mut dyn Write,
) -> Result<(), OutputError> {
    let mut bytes = Vec::new();
    let enc = JpegEncoder::new_with_quality(&mut bytes, quality.clamp(1, 100));
    enc.write_image(
        &frame.pixels,
        frame.width,
        frame.height,
        ExtendedColorType::Rgb8,
    )?;
    // The image crate writes no comments: the COM segment (FF FE, a big-endian
    // length that counts itself, the text) goes right after SOI (FF D8).
    let text: String = meta.iter().map(|(k, v)| format!("{k}: {v}\n")).collect();
    let text = &text.as_bytes()[..text.len().min(65_000)];
    out.write_all(&bytes[..2])?;
    if !text.is_empty() {
        out.write_all(&[0xFF, 0xFE])?;
        out.write_all(&(text.len() as u16 + 2).to_be_bytes())?;
        out.write_all(text)?;
    }
    out.write_all(&bytes[2..])?;
    Ok(())
}
