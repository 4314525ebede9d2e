//! Reading an image texture's file (SPEC §16): PNG and JPEG through `image`, read as
//! their bytes are (no gamma: byte/255, or /65535 for 16-bit PNGs, like every colour of
//! the report), an alpha channel kept beside the colours; OpenEXR through `exr`, whose linear values are sRGB-encoded (§12) and
//! clamped to 0..1, so that an EXR frame of ours maps exactly like its PNG (a frame
//! written with `colour = "linear"` says so in its header and is taken as it is).
//!
//! The file must be a regular file of at most `MAX_TEXTURE_BYTES`, and its header's size
//! within `MAX_TEXTURE_SIDE` and `MAX_TEXTURE_PIXELS`, and within what is left of the
//! scene's budget (`MAX_SCENE_TEXTURE_PIXELS` for all its images together), before
//! anything is decoded. A PNG's size is read from its IHDR chunk first, so that a width
//! the decoder's own memory limit refuses still meets these rules.

use super::image::Pixels;
#[cfg(feature = "exr")]
use crate::base::srgb::{encode, Transfer};
use crate::limits::{
    MAX_SCENE_TEXTURE_PIXELS, MAX_TEXTURE_BYTES, MAX_TEXTURE_PIXELS, MAX_TEXTURE_SIDE,
};
use std::path::Path;

/// The pixels of the image file `path`, when the scene's images read before it hold
/// `used` pixels, or why it gives none (one line, for a located error that names the
/// file).
pub fn load(path: &Path, used: u64) -> Result<Pixels, String> {
    let bytes =
        crate::input::read_regular(path, MAX_TEXTURE_BYTES, "image").map_err(|e| e.to_string())?;
    from_bytes(&bytes, used)
}

/// `load` of an image's bytes already read (a glTF file's image, from a buffer view or
/// a data URI), under the same limits.
pub fn from_bytes(bytes: &[u8], used: u64) -> Result<Pixels, String> {
    if bytes.len() as u64 > MAX_TEXTURE_BYTES {
        return Err(format!(
            "it is larger than the limit of {MAX_TEXTURE_BYTES} bytes for an image"
        ));
    }
    let check = |w: u64, h: u64| {
        check_size(w, h)?;
        within_budget(w, h, used)
    };
    if let Some((w, h)) = png_size(bytes) {
        check(w, h)?;
    }
    let pixels = if bytes.starts_with(&[0x76, 0x2f, 0x31, 0x01]) {
        exr_pixels(bytes, check)
    } else {
        picture_pixels(bytes, check)
    };
    pixels.map(|p| p.with_source(crate::input::digest(bytes)))
}

/// Refuses a size past the limits.
fn check_size(w: u64, h: u64) -> Result<(), String> {
    let side = u64::from(MAX_TEXTURE_SIDE);
    if w == 0 || h == 0 || w > side || h > side || w * h > MAX_TEXTURE_PIXELS {
        return Err(format!(
            "it is {w}×{h}, past the limits of an image texture ({MAX_TEXTURE_SIDE} a side, {MAX_TEXTURE_PIXELS} pixels)"
        ));
    }
    Ok(())
}

/// Refuses an image that would take the scene's images past their budget.
fn within_budget(w: u64, h: u64, used: u64) -> Result<(), String> {
    if used + w * h > MAX_SCENE_TEXTURE_PIXELS {
        return Err(format!(
            "it is {w}×{h}, and the images before it hold {used} pixels: a scene's images may hold {MAX_SCENE_TEXTURE_PIXELS} pixels in all"
        ));
    }
    Ok(())
}

/// A PNG's width and height from its IHDR chunk (the first, right after the signature).
fn png_size(bytes: &[u8]) -> Option<(u64, u64)> {
    const SIGNATURE: [u8; 8] = [0x89, b'P', b'N', b'G', b'\r', b'\n', 0x1a, b'\n'];
    if bytes.len() < 24 || bytes[..8] != SIGNATURE || &bytes[12..16] != b"IHDR" {
        return None;
    }
    let word = |at: usize| u64::from(u32::from_be_bytes(bytes[at..at + 4].try_into().unwrap()));
    Some((word(16), word(20)))
}

/// A PNG or JPEG, by its bytes; `check` refuses a size before anything is decoded.
fn picture_pixels(
    bytes: &[u8],
    check: impl Fn(u64, u64) -> Result<(), String>,
) -> Result<Pixels, String> {
    let reader = image::ImageReader::new(std::io::Cursor::new(bytes))
        .with_guessed_format()
        .map_err(|e| e.to_string())?;
    if reader.format().is_none() {
        return Err("it is not a PNG, JPEG or EXR image".to_string());
    }
    let decoder = reader.into_decoder().map_err(|e| e.to_string())?;
    let (w, h) = image::ImageDecoder::dimensions(&decoder);
    check(u64::from(w), u64::from(h))?;
    let picture = image::DynamicImage::from_decoder(decoder).map_err(|e| e.to_string())?;
    let wide = matches!(
        picture.color(),
        image::ColorType::L16
            | image::ColorType::La16
            | image::ColorType::Rgb16
            | image::ColorType::Rgba16
    );
    let data: Vec<[f32; 3]> = if wide {
        picture
            .to_rgb16()
            .pixels()
            .map(|p| p.0.map(|c| (f64::from(c) / 65535.0) as f32))
            .collect()
    } else {
        picture
            .to_rgb8()
            .pixels()
            .map(|p| p.0.map(|c| (f64::from(c) / 255.0) as f32))
            .collect()
    };
    let pixels = Pixels::new(w, h, data).ok_or_else(|| "it holds no pixels".to_string())?;
    if !picture.color().has_alpha() {
        return Ok(pixels);
    }
    // The alpha channel, kept beside the colours (a glTF material's coverage).
    let alpha: Vec<f32> = if wide {
        let rgba = picture.to_rgba16();
        rgba.pixels()
            .map(|p| (f64::from(p.0[3]) / 65535.0) as f32)
            .collect()
    } else {
        let rgba = picture.to_rgba8();
        rgba.pixels()
            .map(|p| (f64::from(p.0[3]) / 255.0) as f32)
            .collect()
    };
    pixels
        .with_alpha(alpha)
        .ok_or_else(|| "its alpha channel does not match its pixels".to_string())
}

/// An OpenEXR in a build without the tracer's `exr` feature.
#[cfg(not(feature = "exr"))]
fn exr_pixels(
    _bytes: &[u8],
    _check: impl Fn(u64, u64) -> Result<(), String>,
) -> Result<Pixels, String> {
    Err("it is an OpenEXR, which this build does not read (the tracer's `exr` feature)".into())
}

/// An OpenEXR's first part: its R, G, B channels (Y for a grey image), sRGB-encoded.
#[cfg(feature = "exr")]
fn exr_pixels(
    bytes: &[u8],
    check: impl Fn(u64, u64) -> Result<(), String>,
) -> Result<Pixels, String> {
    let meta = exr::meta::MetaData::read_from_buffered(std::io::Cursor::new(bytes), false)
        .map_err(|e| e.to_string())?;
    let header = meta.headers.first().ok_or("it has no part")?;
    let size = header.layer_size;
    check(size.width() as u64, size.height() as u64)?;
    let stored = crate::output::exr_read::read_rgb_layer(bytes)?;
    // A texture without the attribute is linear light, as EXRs are (§12).
    let raw = stored.colour == Some(Transfer::Linear);
    let shown = |v: f32| {
        let v = f64::from(v);
        let v = if raw { v } else { encode(v) };
        // NaN (or −0) maps to 0, like `to_byte`.
        v.clamp(0.0, 1.0).max(0.0) as f32
    };
    let data = (stored.pixels.into_iter())
        .map(|[r, g, b]| [shown(r), shown(g), shown(b)])
        .collect();
    let (w, h) = (stored.width, stored.height);
    Pixels::new(w, h, data).ok_or_else(|| "it holds no pixels".to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn png_bytes_are_read_as_they_are() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("t.png");
        let img = image::RgbImage::from_raw(2, 1, vec![255, 128, 0, 1, 2, 3]).unwrap();
        img.save(&path).unwrap();
        let px = load(&path, 0).unwrap();
        assert_eq!(px.size(), (2, 1));
        let c = px.sample(0.25, 0.5, super::super::Interp::Nearest);
        assert_eq!(
            c,
            glam::DVec3::new(1.0, 128.0 / 255.0, 0.0)
                .as_vec3()
                .as_dvec3()
        );
    }

    #[test]
    fn an_alpha_channel_is_kept_beside_the_colours() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("a.png");
        // Two pixels: opaque red, then green at alpha 51 (0.2).
        let img = image::RgbaImage::from_raw(2, 1, vec![255, 0, 0, 255, 0, 255, 0, 51]).unwrap();
        img.save(&path).unwrap();
        let px = load(&path, 0).unwrap();
        assert!(px.has_alpha());
        let nearest = super::super::Interp::Nearest;
        // The colours are the RGB bytes, whatever the alpha.
        assert_eq!(
            px.sample(0.75, 0.5, nearest),
            glam::DVec3::new(0.0, 1.0, 0.0)
        );
        assert_eq!(px.alpha_at(0.25, 0.5, nearest), 1.0);
        assert_eq!(
            px.alpha_at(0.75, 0.5, nearest),
            f64::from((51.0f64 / 255.0) as f32)
        );
        // An RGB file has none: alpha 1 everywhere.
        let rgb = dir.path().join("b.png");
        image::RgbImage::from_raw(1, 1, vec![1, 2, 3])
            .unwrap()
            .save(&rgb)
            .unwrap();
        let px = load(&rgb, 0).unwrap();
        assert!(!px.has_alpha());
        assert_eq!(px.alpha_at(0.5, 0.5, nearest), 1.0);
    }

    #[test]
    fn missing_and_foreign_files_say_why() {
        let dir = tempfile::tempdir().unwrap();
        assert!(load(&dir.path().join("none.png"), 0).is_err());
        let junk = dir.path().join("junk.png");
        std::fs::write(&junk, b"not an image").unwrap();
        assert!(load(&junk, 0).unwrap_err().contains("not a PNG"));
    }

    #[test]
    fn sizes_past_the_limits_are_refused() {
        assert!(check_size(16, 16).is_ok());
        assert!(check_size(u64::from(MAX_TEXTURE_SIDE) + 1, 1).is_err());
        assert!(check_size(0, 4).is_err());
        // The budget: what is left of MAX_SCENE_TEXTURE_PIXELS after the images before.
        assert!(within_budget(4096, 4096, 0).is_ok());
        assert!(within_budget(1, 1, MAX_SCENE_TEXTURE_PIXELS - 1).is_ok());
        assert!(within_budget(1, 1, MAX_SCENE_TEXTURE_PIXELS).is_err());
        // A PNG's IHDR: 2^31 − 1 by 1.
        let mut head = vec![
            0x89, b'P', b'N', b'G', b'\r', b'\n', 0x1a, b'\n', 0, 0, 0, 13,
        ];
        head.extend_from_slice(b"IHDR");
        head.extend_from_slice(&0x7fff_ffffu32.to_be_bytes());
        head.extend_from_slice(&1u32.to_be_bytes());
        assert_eq!(png_size(&head), Some((0x7fff_ffff, 1)));
        assert_eq!(png_size(b"GIF89a and some more bytes here"), None);
    }
}
