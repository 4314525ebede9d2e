//! Reading a frame file back as the 8-bit RGB picture it shows, at the size it must have:
//! the one reader of `animate encode`, `status --verify` and `check`'s references.
//!
//! | format | the picture |
//! |---|---|
//! | `.raw` | the bytes themselves (width·height·3) |
//! | `.ppm` | the bytes after the header `P6`, `# key: text` comments, `W H`, `255` |
//! | `.png`, `.jpg` | decoded (`image`) |
//! | `.exr` | the beauty's display values (sRGB-encoded unless stored as they are, its
//! header's `whitted:colour`), clamped and rounded (SPEC §2, §12) |
//!
//! The file is read whole only when it is a regular file of at most `MAX_FRAME_BYTES`.

use super::ImageFormat;
use crate::base::to_byte;
use crate::input::read_regular;
use crate::limits::MAX_FRAME_BYTES;
use std::path::Path;

/// Why a frame file gives no picture of the size asked.
#[derive(Debug, thiserror::Error)]
pub enum ReadError {
    /// Not a regular file of a sane size, or reading it failed.
    #[error("cannot read it: {0}")]
    Io(#[from] std::io::Error),
    /// Its bytes are not an image of its format.
    #[error("cannot decode it: {0}")]
    Decode(String),
    /// It is an image of another size (`found`: `32×24`).
    #[error("it is {found}, not {width}×{height}")]
    Size {
        /// What the file holds.
        found: String,
        /// The size asked.
        width: u32,
        /// The size asked.
        height: u32,
    },
    /// Its pixels are not as many bytes as its size needs (a RAW or PPM cut short or
    /// grown).
    #[error("it holds {found} bytes of pixels, not the {expected} of its size")]
    Length {
        /// The bytes found.
        found: usize,
        /// The bytes its size needs.
        expected: usize,
    },
}

fn size_error(found: String, width: u32, height: u32) -> ReadError {
    ReadError::Size {
        found,
        width,
        height,
    }
}

/// The RGB bytes, rows top to bottom, of the `format` frame file `path` of
/// `width`×`height` (see the module's table).
pub fn read_rgb(
    path: &Path,
    format: ImageFormat,
    width: u32,
    height: u32,
) -> Result<Vec<u8>, ReadError> {
    if format.is_layered() {
        let (beauty, colour) = read_stored(path, width, height)?;
        let byte = |v: f32| colour.byte(f64::from(v));
        return Ok(beauty.iter().flat_map(|c| c.map(byte)).collect());
    }
    let bytes = read_regular(path, MAX_FRAME_BYTES, "frame")?;
    let pixels = 3 * width as usize * height as usize;
    match format {
        ImageFormat::Raw => match bytes.len() == pixels {
            true => Ok(bytes),
            false => Err(ReadError::Length {
                found: bytes.len(),
                expected: pixels,
            }),
        },
        ImageFormat::Ppm => ppm_pixels(bytes, width, height),
        _ => {
            let image =
                image::load_from_memory(&bytes).map_err(|e| ReadError::Decode(e.to_string()))?;
            if (image.width(), image.height()) != (width, height) {
                let found = format!("{}×{}", image.width(), image.height());
                return Err(size_error(found, width, height));
            }
            Ok(image.to_rgb8().into_raw())
        }
    }
}

/// The pixels of a binary PPM (P6, maxval 255) as `ppm` writes it.
fn ppm_pixels(mut bytes: Vec<u8>, width: u32, height: u32) -> Result<Vec<u8>, ReadError> {
    let bad = |why: &str| ReadError::Decode(format!("not a P6 PPM of maxval 255 ({why})"));
    if !bytes.starts_with(b"P6\n") {
        return Err(bad("no P6 magic"));
    }
    // The header: the magic, comment lines, then the size and maxval lines.
    let mut at = 3;
    let mut line = || -> Option<&[u8]> {
        let end = at + bytes.get(at..)?.iter().position(|&b| b == b'\n')?;
        let l = &bytes[at..end];
        at = end + 1;
        Some(l)
    };
    let size = loop {
        match line() {
            Some(l) if l.starts_with(b"#") => continue,
            Some(l) => break String::from_utf8_lossy(l).into_owned(),
            None => return Err(bad("cut short in its header")),
        }
    };
    if line() != Some(b"255") {
        return Err(bad("no maxval 255"));
    }
    if size != format!("{width} {height}") {
        return Err(size_error(size.replace(' ', "×"), width, height));
    }
    let pixels = 3 * width as usize * height as usize;
    if bytes.len() - at != pixels {
        return Err(ReadError::Length {
            found: bytes.len() - at,
            expected: pixels,
        });
    }
    bytes.drain(..at);
    Ok(bytes)
}

/// The float beauty of the EXR file `path` of `width`×`height` as the display values it
/// stands for (RGB, rows top to bottom; the tracer's values, whatever the encoding).
pub fn read_beauty(path: &Path, width: u32, height: u32) -> Result<Vec<[f32; 3]>, ReadError> {
    let (beauty, colour) = read_stored(path, width, height)?;
    let shown = |v: f32| colour.shown(f64::from(v)) as f32;
    Ok(beauty.into_iter().map(|c| c.map(shown)).collect())
}

/// The beauty of the EXR file `path` of `width`×`height` as stored, and its encoding.
fn read_stored(
    path: &Path,
    width: u32,
    height: u32,
) -> Result<(Vec<[f32; 3]>, crate::base::Transfer), ReadError> {
    let bytes = read_regular(path, MAX_FRAME_BYTES, "frame")?;
    // The header first: a picture of another size is never decoded (an 8192² reference
    // would take gigabytes).
    let (w, h) = super::exr::header_size(bytes.as_slice()).map_err(ReadError::Decode)?;
    if (w, h) != (width, height) {
        return Err(size_error(format!("{w}×{h}"), width, height));
    }
    let (w, h, beauty, colour) = super::exr::read_beauty(&bytes).map_err(ReadError::Decode)?;
    match (w, h) == (width, height) {
        true => Ok((beauty, colour)),
        false => Err(size_error(format!("{w}×{h}"), width, height)),
    }
}

/// The size of the EXR file `path` from its header alone, the file being regular and at
/// most `MAX_FRAME_BYTES`.
pub fn exr_size(path: &Path) -> Result<(u32, u32), ReadError> {
    let (file, _) = crate::input::open_regular(path, MAX_FRAME_BYTES, "frame")?;
    super::exr::header_size(std::io::BufReader::new(file)).map_err(ReadError::Decode)
}

/// A float beauty's picture: each channel through the clamp-and-round of §2.
pub fn beauty_bytes(beauty: &[[f32; 3]]) -> Vec<u8> {
    beauty
        .iter()
        .flat_map(|c| c.map(|v| to_byte(f64::from(v))))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::base::Frame;

    fn written(format: ImageFormat, frame: &Frame) -> (tempfile::TempDir, std::path::PathBuf) {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join(format!("f.{}", format.extension()));
        let meta = vec![("whitted:digest".to_string(), "d 1".to_string())];
        super::super::write_atomic(&path, frame, format, &meta).unwrap();
        (dir, path)
    }

    #[test]
    fn every_lossless_format_reads_back_its_bytes() {
        let frame = Frame {
            width: 3,
            height: 2,
            pixels: (0..18).map(|i| i * 14).collect(),
        };
        for name in ["raw", "ppm", "png", "exr"] {
            let format = ImageFormat::from_name(name).unwrap();
            let (_dir, path) = written(format, &frame);
            assert_eq!(
                read_rgb(&path, format, 3, 2).unwrap(),
                frame.pixels,
                "{name}"
            );
            let e = read_rgb(&path, format, 3, 3).unwrap_err();
            let wrong = matches!(e, ReadError::Size { .. } | ReadError::Length { .. });
            assert!(wrong, "{name}: {e}");
        }
        let jpeg = ImageFormat::from_name("jpg").unwrap();
        let (_dir, path) = written(jpeg, &frame);
        assert_eq!(read_rgb(&path, jpeg, 3, 2).unwrap().len(), 18);
    }

    #[test]
    fn a_ppm_cut_short_or_not_p6_is_refused() {
        let head = b"P6\n# k: v\n2 1\n255\n".to_vec();
        let whole = [head.clone(), vec![1, 2, 3, 4, 5, 6]].concat();
        assert_eq!(ppm_pixels(whole.clone(), 2, 1).unwrap(), [1, 2, 3, 4, 5, 6]);
        let e = ppm_pixels(whole[..whole.len() - 1].to_vec(), 2, 1).unwrap_err();
        assert_eq!(
            e.to_string(),
            "it holds 5 bytes of pixels, not the 6 of its size"
        );
        let e = ppm_pixels(b"P3\n2 1\n255\n".to_vec(), 2, 1).unwrap_err();
        assert!(e.to_string().contains("no P6 magic"), "{e}");
        let e = ppm_pixels(b"P6\n2 1\n65535\n".to_vec(), 2, 1).unwrap_err();
        assert!(e.to_string().contains("maxval"), "{e}");
    }

    #[test]
    fn the_beauty_is_clamped_and_rounded() {
        // 0.6/255 rounds up to 1, 0.4/255 down to 0; 0.2·255 = 51; out of 0..1 clamps.
        let b = beauty_bytes(&[[0.6 / 255.0, -3.0, 7.0], [0.2, 0.4 / 255.0, 1.0]]);
        assert_eq!(b, [1, 0, 255, 51, 0, 255]);
    }
}
