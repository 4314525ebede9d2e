//! The image formats by name and extension (`ImageFormat`: PNG, JPEG, PPM, RAW, EXR with
//! its options), and which of them a build leaves out (`ImageFormat::feature`).

use super::OutputError;
use crate::passes::PassSet;
use std::path::Path;

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
    /// `.exr`: OpenEXR, the beauty unclamped and the passes asked for.
    Exr(ExrOptions),
}

/// How an EXR frame is written (`[output] exr_depth`, `exr_compression`, `passes`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
pub struct ExrOptions {
    /// The beauty's sample type.
    pub depth: ExrDepth,
    /// The compression of every block.
    pub compression: ExrCompression,
    /// The passes beside the beauty.
    pub passes: PassSet,
    /// How the beauty's colours are stored (`[output] colour`).
    pub colour: crate::base::Transfer,
}

/// The beauty's sample type in an EXR frame.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum ExrDepth {
    /// 16-bit half (the default, as Blender's "Half").
    #[default]
    Half,
    /// 32-bit float.
    Float,
}

impl ExrDepth {
    /// The names a manifest accepts.
    pub const NAMES: [&'static str; 2] = ["half", "float"];

    /// The depth a name gives.
    pub fn from_name(name: &str) -> Option<ExrDepth> {
        match name {
            "half" => Some(ExrDepth::Half),
            "float" => Some(ExrDepth::Float),
            _ => None,
        }
    }
}

/// The compression of an EXR frame's blocks.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum ExrCompression {
    /// None.
    None,
    /// Run-length.
    Rle,
    /// Deflate, one line a block.
    Zips,
    /// Deflate, 16 lines a block (the default).
    #[default]
    Zip,
    /// Wavelet (PIZ), lossless.
    Piz,
}

impl ExrCompression {
    /// The names a manifest accepts.
    pub const NAMES: [&'static str; 5] = ["none", "rle", "zips", "zip", "piz"];

    /// The compression a name gives.
    pub fn from_name(name: &str) -> Option<ExrCompression> {
        match name {
            "none" => Some(ExrCompression::None),
            "rle" => Some(ExrCompression::Rle),
            "zips" => Some(ExrCompression::Zips),
            "zip" => Some(ExrCompression::Zip),
            "piz" => Some(ExrCompression::Piz),
            _ => None,
        }
    }
}

impl ImageFormat {
    /// The format named by a path's extension (case-insensitive).
    pub fn from_path(path: &Path) -> Result<ImageFormat, OutputError> {
        let format = path
            .extension()
            .and_then(|e| e.to_str())
            .and_then(ImageFormat::from_name)
            .ok_or_else(|| OutputError::UnknownExtension {
                path: path.to_path_buf(),
            })?;
        match format.feature() {
            Some(feature) => Err(OutputError::NotBuilt {
                format: format.extension(),
                feature,
            }),
            None => Ok(format),
        }
    }

    /// The tracer's cargo feature this format needs when this build leaves it out.
    pub fn feature(&self) -> Option<&'static str> {
        match self {
            ImageFormat::Exr(_) if cfg!(not(feature = "exr")) => Some("exr"),
            ImageFormat::Jpeg { .. } if cfg!(not(feature = "jpeg")) => Some("jpeg"),
            _ => None,
        }
    }

    /// The names a manifest or `--stdout` accepts, in the order messages list them.
    pub const NAMES: [&'static str; 6] = ["png", "jpeg", "jpg", "ppm", "raw", "exr"];

    /// The format a name gives (`png`, `jpeg` or `jpg`, `ppm`, `raw`, `exr`; JPEG at the
    /// default quality, EXR half with ZIP and no pass), case-insensitively.
    pub fn from_name(name: &str) -> Option<ImageFormat> {
        match name.to_ascii_lowercase().as_str() {
            "png" => Some(ImageFormat::Png),
            "jpg" | "jpeg" => Some(ImageFormat::Jpeg {
                quality: DEFAULT_JPEG_QUALITY,
            }),
            "ppm" => Some(ImageFormat::Ppm),
            "raw" => Some(ImageFormat::Raw),
            "exr" => Some(ImageFormat::Exr(ExrOptions::default())),
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
            ImageFormat::Exr(_) => "exr",
        }
    }

    /// The passes this format is asked to carry (none but for EXR).
    pub fn passes(&self) -> PassSet {
        match self {
            ImageFormat::Exr(o) => o.passes,
            _ => PassSet::NONE,
        }
    }

    /// Whether frames in this format are drawn as layers (unclamped floats) rather than
    /// 8-bit pictures.
    pub fn is_layered(&self) -> bool {
        matches!(self, ImageFormat::Exr(_))
    }
}
