//! Image files (SPEC §3): the report's `.raw`, and PNG, JPEG and PPM, chosen by extension.
//!
//! - `.raw`: width·height·3 bytes, RGB, rows top to bottom, no header (the report's);
//! - `.png`: 8-bit RGB, fast deflate (frames are written by the hundred);
//! - `.jpg`/`.jpeg`: baseline JPEG, quality 90 unless set;
//! - `.ppm`: binary P6 with maxval 255.
//!
//! `write_atomic` writes to a temporary file in the destination folder and renames it into
//! place, so a file under its final name is always complete.

use crate::render::Frame;
use image::codecs::jpeg::JpegEncoder;
use image::codecs::png::{CompressionType, FilterType, PngEncoder};
use image::{ExtendedColorType, ImageEncoder};
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

/// JPEG quality when none is given.
pub const DEFAULT_JPEG_QUALITY: u8 = 90;

/// An output image format.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum ImageFormat {
    /// The report's `.raw`: width·height·3 RGB bytes, rows top to bottom, no header.
    Raw,
    /// `.png`: 8-bit RGB, lossless.
    Png,
    /// `.jpg`/`.jpeg`: baseline JPEG.
    Jpeg {
        /// Encoder quality, 1 (smallest) to 100 (best); `DEFAULT_JPEG_QUALITY` unless set.
        quality: u8,
    },
    /// `.ppm`: binary P6, maxval 255.
    Ppm,
}

/// Why an image could not be written.
#[derive(Debug, thiserror::Error)]
pub enum OutputError {
    /// The path's extension names no format this module writes (bad input).
    #[error("{path}: unknown image extension (use .png, .jpg, .jpeg, .ppm or .raw)")]
    UnknownExtension {
        /// The image path as given.
        path: PathBuf,
    },
    /// The path cannot take an image: its folder is missing, or it is a folder (bad
    /// input, found before rendering).
    #[error("cannot write {path}: {reason}")]
    Target {
        /// The image path as given.
        path: PathBuf,
        /// Why, e.g. "the folder out does not exist".
        reason: String,
    },
    /// Creating, writing or renaming the file failed while writing (a failed run).
    #[error("{path}: {source}")]
    Io {
        /// The file's final name (never the hidden temporary one).
        path: PathBuf,
        /// The system's reason.
        #[source]
        source: std::io::Error,
    },
    /// The encoder refused the image.
    #[error("cannot encode the image: {0}")]
    Encode(#[from] image::ImageError),
    /// Writing to a stream (standard output, a pipe) failed.
    #[error("cannot write the image: {0}")]
    Stream(#[from] std::io::Error),
}

impl OutputError {
    /// The row of the exit-status table: a target that cannot be used is bad input,
    /// found before anything renders; a failure while writing is a failed run.
    pub fn outcome(&self) -> crate::exit::Outcome {
        match self {
            OutputError::UnknownExtension { .. } | OutputError::Target { .. } => {
                crate::exit::Outcome::BadInput
            }
            _ => crate::exit::Outcome::Failed,
        }
    }
}

/// Refuses, before anything renders, an image path whose folder does not exist or that
/// is itself a folder.
pub fn check_target(path: &Path) -> Result<(), OutputError> {
    let refuse = |reason: String| {
        Err(OutputError::Target {
            path: path.to_path_buf(),
            reason,
        })
    };
    let folder = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    if !folder.is_dir() {
        return refuse(format!("the folder {} does not exist", folder.display()));
    }
    if path.is_dir() {
        return refuse("it is a folder".into());
    }
    Ok(())
}

impl ImageFormat {
    /// The format named by a path's extension (case-insensitive).
    pub fn from_path(path: &Path) -> Result<ImageFormat, OutputError> {
        path.extension()
            .and_then(|e| e.to_str())
            .and_then(ImageFormat::from_name)
            .ok_or_else(|| OutputError::UnknownExtension {
                path: path.to_path_buf(),
            })
    }

    /// The names a manifest or `--stdout` accepts, in the order messages list them.
    pub const NAMES: [&'static str; 5] = ["png", "jpeg", "jpg", "ppm", "raw"];

    /// The format a name gives (`png`, `jpeg` or `jpg`, `ppm`, `raw`; JPEG at the default
    /// quality), case-insensitively.
    pub fn from_name(name: &str) -> Option<ImageFormat> {
        match name.to_ascii_lowercase().as_str() {
            "png" => Some(ImageFormat::Png),
            "jpg" | "jpeg" => Some(ImageFormat::Jpeg {
                quality: DEFAULT_JPEG_QUALITY,
            }),
            "ppm" => Some(ImageFormat::Ppm),
            "raw" => Some(ImageFormat::Raw),
            _ => None,
        }
    }

    /// The usual file extension.
    pub fn extension(&self) -> &'static str {
        match self {
            ImageFormat::Raw => "raw",
            ImageFormat::Png => "png",
            ImageFormat::Jpeg { .. } => "jpg",
            ImageFormat::Ppm => "ppm",
        }
    }
}

/// Encodes `frame` in `format` into `out`.
pub fn encode(frame: &Frame, format: ImageFormat, out: &mut dyn Write) -> Result<(), OutputError> {
    encode_with(frame, format, &[], out)
}

/// Encodes `frame` with text metadata, `(keyword, text)` pairs (keywords of 1 to 79
/// Latin-1 characters, no line breaks in either): PNG `tEXt` chunks before the image
/// data (through the `png` crate), one JPEG comment (COM segment) of `keyword: text`
/// lines right after the start marker, `# keyword: text` comment lines in the PPM
/// header. RAW has no header and carries none.
pub fn encode_with(
    frame: &Frame,
    format: ImageFormat,
    meta: &[(String, String)],
    out: &mut dyn Write,
) -> Result<(), OutputError> {
    let (w, h) = (frame.width, frame.height);
    match format {
        ImageFormat::Raw => out.write_all(&frame.pixels)?,
        ImageFormat::Ppm => {
            writeln!(out, "P6")?;
            for (k, v) in meta {
                writeln!(out, "# {k}: {v}")?;
            }
            write!(out, "{w} {h}\n255\n")?;
            out.write_all(&frame.pixels)?;
        }
        ImageFormat::Png if meta.is_empty() => {
            let enc =
                PngEncoder::new_with_quality(out, CompressionType::Fast, FilterType::Adaptive);
            enc.write_image(&frame.pixels, w, h, ExtendedColorType::Rgb8)?;
        }
        ImageFormat::Png => {
            // The settings `PngEncoder` uses above, plus the text chunks.
            let mut enc = png::Encoder::new(out, w, h);
            enc.set_color(png::ColorType::Rgb);
            enc.set_depth(png::BitDepth::Eight);
            enc.set_compression(png::Compression::Fast);
            enc.set_filter(png::Filter::Adaptive);
            for (k, v) in meta {
                enc.add_text_chunk(k.clone(), v.clone())
                    .map_err(png_error)?;
            }
            let mut writer = enc.write_header().map_err(png_error)?;
            writer.write_image_data(&frame.pixels).map_err(png_error)?;
            writer.finish().map_err(png_error)?;
        }
        ImageFormat::Jpeg { quality } => {
            let mut bytes = Vec::new();
            let enc = JpegEncoder::new_with_quality(&mut bytes, quality.clamp(1, 100));
            enc.write_image(&frame.pixels, w, h, ExtendedColorType::Rgb8)?;
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
        }
    }
    Ok(())
}

fn png_error(e: png::EncodingError) -> OutputError {
    OutputError::Stream(std::io::Error::other(e))
}

/// A hidden temporary file (`.NAME.XXXXXX.tmp`) in `path`'s folder, to be renamed onto
/// `path` once complete. It gets the permissions of an ordinary new file (0666 less the
/// umask), not tempfile's private 0600, so renamed frames are readable as usual.
pub fn temp_beside(path: &Path) -> std::io::Result<tempfile::NamedTempFile> {
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    let name = path.file_name().and_then(|n| n.to_str()).unwrap_or("image");
    let prefix = format!(".{name}.");
    let mut builder = tempfile::Builder::new();
    builder.prefix(&prefix).suffix(".tmp");
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        builder.permissions(std::fs::Permissions::from_mode(0o666));
    }
    builder.tempfile_in(dir)
}

/// Writes `frame` to `path` atomically: a temporary file beside it, then a rename. On any
/// error the temporary file is removed and nothing appears under `path`.
pub fn write_atomic(path: &Path, frame: &Frame, format: ImageFormat) -> Result<(), OutputError> {
    write_atomic_with(path, frame, format, &[])
}

/// `write_atomic` with text metadata (see `encode_with`).
pub fn write_atomic_with(
    path: &Path,
    frame: &Frame,
    format: ImageFormat,
    meta: &[(String, String)],
) -> Result<(), OutputError> {
    let io = |source| OutputError::Io {
        path: path.to_path_buf(),
        source,
    };
    // tempfile names its hidden file in its errors; the user knows only `path`.
    let tmp = temp_beside(path).map_err(|e| io(std::io::Error::from(e.kind())))?;
    {
        let mut w = BufWriter::new(tmp.as_file());
        encode_with(frame, format, meta, &mut w)?;
        w.flush().map_err(io)?;
    }
    tmp.persist(path)
        .map_err(|e| io(std::io::Error::from(e.error.kind())))?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn frame() -> Frame {
        Frame {
            width: 2,
            height: 1,
            pixels: vec![255, 0, 0, 0, 128, 255],
        }
    }

    #[test]
    fn format_from_extension() {
        assert_eq!(
            ImageFormat::from_path(Path::new("a/b.PNG")).unwrap(),
            ImageFormat::Png
        );
        assert_eq!(
            ImageFormat::from_path(Path::new("x.jpeg")).unwrap(),
            ImageFormat::Jpeg { quality: 90 }
        );
        assert_eq!(
            ImageFormat::from_path(Path::new("x.raw")).unwrap(),
            ImageFormat::Raw
        );
        assert_eq!(
            ImageFormat::from_path(Path::new("x.ppm")).unwrap(),
            ImageFormat::Ppm
        );
        assert!(ImageFormat::from_path(Path::new("x.tiff")).is_err());
        assert!(ImageFormat::from_path(Path::new("noext")).is_err());
    }

    #[test]
    fn raw_and_ppm_bytes() {
        let mut raw = Vec::new();
        encode(&frame(), ImageFormat::Raw, &mut raw).unwrap();
        assert_eq!(raw, frame().pixels);
        let mut ppm = Vec::new();
        encode(&frame(), ImageFormat::Ppm, &mut ppm).unwrap();
        assert_eq!(&ppm[..11], b"P6\n2 1\n255\n");
        assert_eq!(&ppm[11..], &frame().pixels[..]);
    }

    #[test]
    fn png_round_trips() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("f.png");
        write_atomic(&path, &frame(), ImageFormat::Png).unwrap();
        let back = image::open(&path).unwrap().to_rgb8();
        assert_eq!(back.into_raw(), frame().pixels);
        // Only the final file is left in the folder, readable by others as a new file is.
        assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 1);
        #[cfg(unix)]
        {
            use std::os::unix::fs::PermissionsExt;
            let mode = std::fs::metadata(&path).unwrap().permissions().mode();
            assert_eq!(mode & 0o044, 0o044, "{mode:o}");
        }
    }

    #[test]
    fn targets_are_checked_before_rendering() {
        let dir = tempfile::tempdir().unwrap();
        assert!(check_target(&dir.path().join("a.png")).is_ok());
        let missing = check_target(&dir.path().join("no/a.png")).unwrap_err();
        assert!(missing.to_string().contains("does not exist"), "{missing}");
        assert_eq!(missing.outcome(), crate::exit::Outcome::BadInput);
        let folder = check_target(dir.path()).unwrap_err();
        assert!(folder.to_string().contains("it is a folder"), "{folder}");
    }

    #[test]
    fn write_errors_name_the_file_not_the_temporary_one() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("no/such/f.png");
        let shown = write_atomic(&path, &frame(), ImageFormat::Png)
            .unwrap_err()
            .to_string();
        // The hidden temporary file would be `.f.png.XXXXXX.tmp`.
        assert!(
            shown.contains("/f.png") && !shown.contains(".f.png."),
            "{shown}"
        );
    }

    #[test]
    fn failed_write_leaves_nothing() {
        let dir = tempfile::tempdir().unwrap();
        let missing = dir.path().join("no/such/dir/f.png");
        assert!(write_atomic(&missing, &frame(), ImageFormat::Png).is_err());
        assert!(!missing.exists());
    }
}
