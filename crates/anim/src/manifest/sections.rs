//! `[output]`, `[render]` and `[check]` of the manifest: defaults, ranges and paths.
//!
//! ```toml
//! [output]
//! dir = "../out/orbit"      # default: <manifest name without .toml>-frames, beside it
//! name = "frame_####"       # default "frame_####"; a file name: no / or \, not empty;
//!                           # also frame_@@@@, frame_%04d, frame_$F4 (`pattern`)
//! format = "png"            # png | jpeg | ppm | raw; default png
//! jpeg_quality = 90         # 1..=100; default 90
//! exr_depth = "half"        # exr only: half | float; default half
//! exr_compression = "zip"   # exr only: none | rle | zips | zip | piz; default zip
//! passes = ["depth", "normal", "crypto_object"]   # exr only; default none (whitted::passes)
//! colour = "srgb"           # exr only: srgb (display values decoded to linear) | linear
//!                           # (the tracer's values as they are); default srgb
//!
//! [render]
//! width = 1280              # 1..=16384 each, width·height <= 2^26 when both are given
//! height = 960
//! samples = 2               # 1..=16; default 1
//! antialias = { mode = "adaptive", threshold = 0.1, depth = 3 }   # instead of samples
//!
//! [check]
//! frames = [0, 125, 249]    # required, not empty, each < frames, no repeats;
//!                           # or a frame list: frames = "0-249x25" (`select::grammar`)
//! references = "golden"     # required
//! fail = 2                  # 0..=255; default 2
//! fail_percent = 0.1        # 0..=100; default 0.1
//! hard_fail = 64            # 0..=255; default 64
//! flip = 0.05               # optional, 0..=1: the largest mean FLIP error
//! ```

use super::raw::{RawCheck, RawFrames, RawOutput, RawRender};
use super::{CheckSpec, ManifestError, OutputSpec, RenderSpec, Source};
use crate::select::parse_frames;
use crate::select::SelectError;
use std::collections::HashSet;
use std::path::Path;
use toml::Spanned;
use whitted::base::Transfer;
use whitted::limits::{MAX_PIXELS, MAX_SAMPLES, MAX_SIDE};
use whitted::output::{ExrCompression, ExrDepth, ExrOptions, ImageFormat};
use whitted::passes::{Pass, PassSet};

impl Source<'_> {
    pub(super) fn output(&self, raw: Option<RawOutput>) -> Result<OutputSpec, ManifestError> {
        let raw = raw.unwrap_or(RawOutput {
            dir: None,
            name: None,
            format: None,
            jpeg_quality: None,
            exr_depth: None,
            exr_compression: None,
            passes: None,
            colour: None,
        });
        let dir = match &raw.dir {
            Some(dir) => self.resolve(dir, "dir")?,
            None => default_dir(self.path),
        };
        let name = match raw.name.clone() {
            Some(name) => self.file_name_pattern(name)?,
            None => "frame_####".to_string(),
        };
        let format = match &raw.format {
            Some(f) => ImageFormat::from_name(f.get_ref()).ok_or_else(|| {
                let message = format!(
                    "unknown format `{}`, expected one of {}",
                    f.get_ref(),
                    ImageFormat::NAMES.join(", ")
                );
                self.error(f.span(), message)
            })?,
            None => ImageFormat::Png,
        };
        let format = match (&raw.jpeg_quality, format) {
            (Some(q), ImageFormat::Jpeg { .. }) => ImageFormat::Jpeg {
                quality: self.int(q, "jpeg_quality", 1..=100)? as u8,
            },
            (Some(q), _) => {
                self.int(q, "jpeg_quality", 1..=100)?;
                format
            }
            (None, _) => format,
        };
        let format = self.exr_options(&raw, format)?;
        Ok(OutputSpec { dir, name, format })
    }

    /// `exr_depth`, `exr_compression`, `passes` and `colour`: checked whatever the format (so a typo
    /// is caught before the format changes), refused with a reason when the format is not
    /// EXR (no other format can carry them).
    fn exr_options(
        &self,
        raw: &RawOutput,
        format: ImageFormat,
    ) -> Result<ImageFormat, ManifestError> {
        let mut options = ExrOptions::default();
        let named = |v: &Spanned<String>, what: &str, names: &[&str]| {
            self.error(
                v.span(),
                format!(
                    "unknown {what} `{}`, expected one of {}",
                    v.get_ref(),
                    names.join(", ")
                ),
            )
        };
        if let Some(v) = &raw.exr_depth {
            options.depth = ExrDepth::from_name(v.get_ref())
                .ok_or_else(|| named(v, "exr_depth", &ExrDepth::NAMES))?;
        }
        if let Some(v) = &raw.exr_compression {
            options.compression = ExrCompression::from_name(v.get_ref())
                .ok_or_else(|| named(v, "exr_compression", &ExrCompression::NAMES))?;
        }
        if let Some(v) = &raw.colour {
            options.colour = Transfer::from_name(v.get_ref())
                .ok_or_else(|| named(v, "colour", &Transfer::NAMES))?;
        }
        if let Some(list) = &raw.passes {
            let all: Vec<&str> = Pass::ALL.iter().map(|p| p.name()).collect();
            let mut passes = Vec::new();
            for v in list.get_ref() {
                let pass = Pass::from_name(v.get_ref()).ok_or_else(|| named(v, "pass", &all))?;
                if passes.contains(&pass) {
                    return Err(self.error(v.span(), format!("pass `{pass}` is listed twice")));
                }
                passes.push(pass);
            }
            options.passes = PassSet::of(&passes);
        }
        match format {
            ImageFormat::Exr(_) => Ok(ImageFormat::Exr(options)),
            _ => {
                let given = [
                    raw.exr_depth.as_ref().map(|v| ("exr_depth", v.span())),
                    raw.exr_compression
                        .as_ref()
                        .map(|v| ("exr_compression", v.span())),
                    raw.passes.as_ref().map(|v| ("passes", v.span())),
                    raw.colour.as_ref().map(|v| ("colour", v.span())),
                ];
                match given.into_iter().flatten().next() {
                    Some((key, span)) => Err(self.error(
                        span,
                        format!("`{key}` needs `format = \"exr\"` (only EXR frames carry it)"),
                    )),
                    None => Ok(format),
                }
            }
        }
    }

    /// A file name pattern; `@@@@`, `%04d` and `$F4` are taken for Blender's `####`.
    fn file_name_pattern(&self, name: Spanned<String>) -> Result<String, ManifestError> {
        let text = name.get_ref();
        let bad = |c: char| c == '/' || c == '\\' || c.is_control();
        if text.is_empty() || text.contains(bad) {
            let message = format!(
                "`name` must be a plain file name, not empty and without `/`, `\\` or control characters, found {text:?}"
            );
            return Err(self.error(name.span(), message));
        }
        match super::pattern::to_hashes(text) {
            Ok(pattern) => Ok(pattern),
            Err(message) => Err(self.error(name.span(), message)),
        }
    }

    pub(super) fn render(
        &self,
        raw: Option<RawRender>,
        format: ImageFormat,
    ) -> Result<RenderSpec, ManifestError> {
        let Some(raw) = raw else {
            return Ok(RenderSpec {
                samples: 1,
                ..RenderSpec::default()
            });
        };
        let side = |v: &Option<Spanned<i64>>, what| match v {
            Some(v) => self
                .int(v, what, 1..=i64::from(MAX_SIDE))
                .map(|x| Some(x as u32)),
            None => Ok(None),
        };
        let width = side(&raw.width, "width")?;
        let height = side(&raw.height, "height")?;
        if let (Some(w), Some(h), Some(at)) = (width, height, &raw.height) {
            if u64::from(w) * u64::from(h) > MAX_PIXELS {
                let message = format!(
                    "{w}×{h} is more than {MAX_PIXELS} pixels (2^26): it would exhaust memory"
                );
                return Err(self.error(at.span(), message));
            }
        }
        let samples = match &raw.samples {
            Some(v) => self.int(v, "samples", 1..=i64::from(MAX_SAMPLES))? as u32,
            None => 1,
        };
        let motion_blur = raw
            .motion_blur
            .as_ref()
            .map(|b| self.motion_blur(b))
            .transpose()?;
        let antialias = raw
            .antialias
            .as_ref()
            .map(|a| self.antialias(a, &raw.samples, format))
            .transpose()?;
        // A size from the scene is checked when the project is loaded.
        if let (Some(aa), Some(w), Some(h), Some(at)) = (&antialias, width, height, &raw.antialias)
        {
            aa.fits(w, h)
                .map_err(|e| self.error(at.span(), e.to_string()))?;
        }
        Ok(RenderSpec {
            width,
            height,
            samples,
            motion_blur,
            antialias,
        })
    }

    /// `[check] frames = [0, 125, 249]`: not empty, each in `0..frames`, no repeats.
    fn frame_numbers(
        &self,
        list: &[Spanned<i64>],
        span: std::ops::Range<usize>,
        frames: u32,
    ) -> Result<Vec<u32>, ManifestError> {
        if list.is_empty() {
            let message = "[check] `frames` must list at least one frame";
            return Err(self.error(span, message));
        }
        let mut seen = HashSet::new();
        let mut out = Vec::with_capacity(list.len());
        for f in list {
            let frame = self.int(f, "check frame", 0..=i64::from(frames) - 1)? as u32;
            if !seen.insert(frame) {
                return Err(self.error(f.span(), format!("frame {frame} is listed twice")));
            }
            out.push(frame);
        }
        Ok(out)
    }

    /// `[check] frames = "0-249x25"`: the fileseq grammar; an error points at its column
    /// inside the string when the string is written without escapes.
    fn frame_spec(
        &self,
        spec: &str,
        span: std::ops::Range<usize>,
        frames: u32,
    ) -> Result<Vec<u32>, ManifestError> {
        parse_frames(spec, frames).map_err(|e| {
            let SelectError::Frames {
                column, problem, ..
            } = &e
            else {
                return self.error(span.clone(), e.to_string());
            };
            let literal = &self.text[span.clone()];
            let plain = literal.len() == spec.len() + 2 && &literal[1..literal.len() - 1] == spec;
            let offset = match plain {
                true => {
                    1 + spec
                        .chars()
                        .take(column - 1)
                        .map(char::len_utf8)
                        .sum::<usize>()
                }
                false => 0,
            };
            let at = span.start + offset..span.end;
            self.error(at, format!("[check] `frames` {spec:?}: {problem}"))
        })
    }

    pub(super) fn check(&self, raw: RawCheck, frames: u32) -> Result<CheckSpec, ManifestError> {
        let list = match raw.frames.get_ref() {
            RawFrames::List(list) => self.frame_numbers(list, raw.frames.span(), frames)?,
            RawFrames::Spec(spec) => self.frame_spec(spec, raw.frames.span(), frames)?,
        };
        let references = self.resolve(&raw.references, "references")?;
        let byte = |v: &Option<Spanned<i64>>, what, default| match v {
            Some(v) => self.int(v, what, 0..=255).map(|x| x as u8),
            None => Ok(default),
        };
        let fail = byte(&raw.fail, "fail", 2)?;
        let hard_fail = byte(&raw.hard_fail, "hard_fail", 64)?;
        let fail_percent = match &raw.fail_percent {
            Some(v) if !(0.0..=100.0).contains(v.get_ref()) => {
                let message = format!(
                    "`fail_percent` must be between 0 and 100, found {}",
                    v.get_ref()
                );
                return Err(self.error(v.span(), message));
            }
            Some(v) => *v.get_ref(),
            None => 0.1,
        };
        let flip = match &raw.flip {
            Some(v) if !(0.0..=1.0).contains(v.get_ref()) => {
                let message = format!("`flip` must be between 0 and 1, found {}", v.get_ref());
                return Err(self.error(v.span(), message));
            }
            v => v.as_ref().map(|v| *v.get_ref()),
        };
        Ok(CheckSpec {
            frames: list,
            references,
            fail,
            fail_percent,
            hard_fail,
            flip,
        })
    }
}

/// `<manifest name without .toml>-frames`, beside the manifest.
fn default_dir(manifest: &Path) -> std::path::PathBuf {
    let name = manifest
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_else(|| "animation".to_string());
    let stem = name.strip_suffix(".toml").unwrap_or(&name);
    let folder = manifest.parent().unwrap_or(Path::new(""));
    folder.join(format!("{stem}-frames"))
}
