//! Image files (SPEC §3, §12), chosen by extension, one file per format behind one
//! interface (`encode`: an 8-bit picture or a frame of layers in, `Image`, each format
//! takes what it can carry):
//!
//! | format | module | pixels | metadata |
//! |---|---|---|---|
//! | `.raw` | `raw` | 8-bit RGB, no header (the report's) | none (a record beside it) |
//! | `.ppm` | `ppm` | binary P6, maxval 255 | `# key: text` header comments |
//! | `.png` | `png` | 8-bit RGB, fast deflate, tagged sRGB | `tEXt` / `iTXt` chunks |
//! | `.jpg`/`.jpeg` | `jpeg` | baseline JPEG, quality 90 unless set | one COM comment |
//! | `.exr` | `exr` | half/float beauty unclamped (linear light, `colour`), float passes, alpha | string attributes |
//!
//! The 8-bit formats take the beauty through the clamp-and-round of §2 (`Layers::to_frame`,
//! which `render` does directly for the default path) and drop the passes.
//!
//! `read_rgb` reads a frame file of any of them back as its 8-bit picture (`read`).
//!
//! `write_atomic` encodes to a temporary file in the destination folder and renames it
//! into place, so a file under its final name is always complete.
//!
//! ```text
//! write_atomic(path, &frame, ImageFormat::Png, &[])?;     // a picture, no metadata
//! write_atomic(path, layers, format, &stamp)?;           // layers (taken), with metadata
//! encode(&frame, format, &[], &mut bytes)?;              // the same bytes, in memory
//! ```

#[cfg(feature = "exr")]
pub mod colour;
#[cfg(feature = "exr")]
pub mod exr;
#[cfg(feature = "exr")]
mod exr_offsets;
#[cfg(feature = "exr")]
pub mod exr_read;
#[cfg(feature = "jpeg")]
mod jpeg;
mod unbuilt;
#[cfg(not(feature = "exr"))]
pub use unbuilt::exr;
#[cfg(not(feature = "jpeg"))]
use unbuilt::jpeg;
pub(crate) mod png;
mod ppm;
mod raw;
mod read;

mod format;
pub use format::{ExrCompression, ExrDepth, ExrOptions, ImageFormat, DEFAULT_JPEG_QUALITY};
pub use read::{beauty_bytes, exr_size, read_beauty, read_rgb, ReadError};

use crate::base::Frame;
use crate::passes::Layers;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

/// Why an image could not be written.
#[derive(Debug, thiserror::Error)]
pub enum OutputError {
    /// The path's extension names no format this module writes (bad input).
    #[error("{path}: unknown image extension (use .png, .jpg, .jpeg, .ppm, .raw or .exr)")]
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
    /// The format is one this build of the tracer leaves out (bad input).
    #[error("this build writes no .{format} images (the tracer's `{feature}` feature)")]
    NotBuilt {
        /// The format's extension.
        format: &'static str,
        /// The cargo feature that brings it.
        feature: &'static str,
    },
}

impl OutputError {
    /// The row of the exit-status table: a target that cannot be used is bad input,
    /// found before anything renders; a failure while writing is a failed run.
    pub fn outcome(&self) -> crate::exit::Outcome {
        match self {
            OutputError::UnknownExtension { .. }
            | OutputError::Target { .. }
            | OutputError::NotBuilt { .. } => crate::exit::Outcome::BadInput,
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

/// What is written: an 8-bit picture, or a frame of layers (taken: an EXR moves their
/// values into its image). `&Frame` and `Layers` convert into it. (Passed by value for
/// one call: the layers' size on the stack is a few vectors' headers.)
#[allow(clippy::large_enum_variant)]
pub enum Image<'a> {
    /// An 8-bit picture.
    Picture(&'a Frame),
    /// The beauty unclamped, the passes, alpha and the camera.
    Layers(Layers),
}

impl<'a> From<&'a Frame> for Image<'a> {
    fn from(frame: &'a Frame) -> Image<'a> {
        Image::Picture(frame)
    }
}

impl From<Layers> for Image<'_> {
    fn from(layers: Layers) -> Self {
        Image::Layers(layers)
    }
}

/// Encodes `image` in `format` (with its options: a JPEG's quality, an EXR's depth,
/// compression, colour and passes) into `out`, with text metadata, `(keyword, text)`
/// pairs (keywords of 1 to 79 ASCII characters, no line breaks in either; none: `&[]`),
/// each format as its module says. EXR keeps a frame of layers whole and takes an 8-bit
/// picture's bytes as its beauty (values k/255), without passes; the other formats take
/// the beauty's clamp-and-round and drop the passes.
pub fn encode<'a>(
    image: impl Into<Image<'a>>,
    format: ImageFormat,
    meta: &[(String, String)],
    out: &mut dyn Write,
) -> Result<(), OutputError> {
    let frame = match (image.into(), format) {
        (Image::Layers(layers), ImageFormat::Exr(options)) => {
            return exr::encode(layers, options, meta, out)
        }
        (Image::Layers(layers), _) => std::borrow::Cow::Owned(layers.to_frame()),
        (Image::Picture(frame), _) => std::borrow::Cow::Borrowed(frame),
    };
    match format {
        ImageFormat::Raw => raw::encode(&frame, out),
        ImageFormat::Ppm => ppm::encode(&frame, meta, out),
        ImageFormat::Png => png::encode(&frame, meta, out),
        ImageFormat::Jpeg { quality } => jpeg::encode(&frame, quality, meta, out),
        ImageFormat::Exr(options) => {
            let layers = Layers {
                width: frame.width,
                height: frame.height,
                beauty: frame
                    .pixels
                    .chunks_exact(3)
                    .map(|p| crate::base::Color::new(p[0].into(), p[1].into(), p[2].into()) / 255.0)
                    .collect(),
                channels: Vec::new(),
                crypto: Vec::new(),
                camera: None,
                alpha: None,
            };
            exr::encode(layers, options, meta, out)
        }
    }
}

/// A hidden temporary file (`.NAME.XXXXXX.tmp`) in `path`'s folder, to be renamed onto
/// `path` once complete. It gets the permissions of an ordinary new file (0666 less the
/// umask), not tempfile's private 0600, so renamed frames are readable as usual.
pub fn temp_beside(path: &Path) -> std::io::Result<tempfile::NamedTempFile> {
    temp_beside_as(path, ".tmp")
}

/// `temp_beside` ending in `suffix` instead of `.tmp` (`.NAME.XXXXXX.mp4`: a video keeps
/// its extension, from which ffmpeg picks the container).
pub fn temp_beside_as(path: &Path, suffix: &str) -> std::io::Result<tempfile::NamedTempFile> {
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    let name = path.file_name().and_then(|n| n.to_str()).unwrap_or("image");
    let prefix = format!(".{name}.");
    let mut builder = tempfile::Builder::new();
    builder.prefix(&prefix).suffix(suffix);
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        builder.permissions(std::fs::Permissions::from_mode(0o666));
    }
    builder.tempfile_in(dir)
}

/// The file a hidden temporary of `temp_beside` is for: `.TARGET.XXXXXX.tmp` gives
/// TARGET; any other name gives `None`.
pub fn temporary_target(name: &str) -> Option<&str> {
    let inner = name.strip_prefix('.')?.strip_suffix(".tmp")?;
    let (target, random) = inner.rsplit_once('.')?;
    (random.len() == 6 && random.bytes().all(|b| b.is_ascii_alphanumeric())).then_some(target)
}

/// Writes `image` to `path` atomically, encoded as `encode` encodes it: a temporary file
/// beside it, then a rename. On any error the temporary file is removed and nothing
/// appears under `path`.
pub fn write_atomic<'a>(
    path: &Path,
    image: impl Into<Image<'a>>,
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
        encode(image, format, meta, &mut w)?;
        w.flush().map_err(io)?;
    }
    tmp.persist(path)
        .map_err(|e| io(std::io::Error::from(e.error.kind())))?;
    Ok(())
}

#[cfg(test)]
mod tests;
