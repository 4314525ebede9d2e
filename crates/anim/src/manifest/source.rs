//! The manifest text and where it came from (`Source`): turns byte spans into located
//! errors (`path:line:column`), deserializes the TOML in TOML's words, resolves paths
//! against the manifest's folder and assembles a `Manifest` from its checked sections.
//! The sections' own checks (`camera`, `sections`, `tracks`, `antialias`) are further
//! `impl Source` blocks in their files.

/// What a `[camera]` table becomes: the path, and an object followed (or a still point).
use super::raw::RawManifest;
use super::{locate::key_path, Manifest, ManifestError, DEFAULT_FPS};
use crate::timeline::{CameraPath, LookAt};
use std::ops::{Range, RangeInclusive};
use std::path::{Path, PathBuf};
use toml::Spanned;
use whitted::camera::Lens;
use whitted::fileloc::FileLoc;
use whitted::limits::{MAX_FPS, MAX_FRAMES, MIN_FPS};

pub(super) type CameraParts = (Option<CameraPath>, Option<LookAt>, Lens);

/// The manifest text and where it came from: turns spans into located errors.
pub(super) struct Source<'a> {
    pub(super) text: &'a str,
    pub(super) path: &'a Path,
    /// The manifest's frames per second, for keys given in seconds (`when`).
    pub(super) fps: f64,
}

impl Source<'_> {
    /// The place of the start of `span`.
    pub(super) fn loc(&self, span: Range<usize>) -> FileLoc {
        FileLoc::of_offset(&self.path.display().to_string(), self.text, span.start)
    }

    /// An error at the start of `span`.
    pub(super) fn error(&self, span: Range<usize>, message: impl Into<String>) -> ManifestError {
        ManifestError::Invalid {
            loc: self.loc(span),
            message: message.into(),
        }
    }

    pub(super) fn deserialize<T: serde::de::DeserializeOwned>(&self) -> Result<T, ManifestError> {
        toml::from_str(self.text).map_err(|e| {
            let span = e.span().unwrap_or(0..0);
            let message = in_toml_words(e.message());
            match key_path(self.text, span.start) {
                Some(key) => self.error(span, format!("{key}: {message}")),
                None => self.error(span, message),
            }
        })
    }

    /// A path of the manifest, relative to its folder; refused when empty.
    pub(super) fn resolve(
        &self,
        v: &Spanned<String>,
        what: &str,
    ) -> Result<PathBuf, ManifestError> {
        if v.get_ref().is_empty() {
            return Err(self.error(v.span(), format!("`{what}` must not be empty")));
        }
        let folder = self.path.parent().unwrap_or(Path::new(""));
        Ok(folder.join(v.get_ref()))
    }

    /// An integer, refused outside `range`.
    pub(super) fn int(
        &self,
        v: &Spanned<i64>,
        what: &str,
        range: RangeInclusive<i64>,
    ) -> Result<i64, ManifestError> {
        let x = *v.get_ref();
        if range.contains(&x) {
            return Ok(x);
        }
        let (lo, hi) = (range.start(), range.end());
        let message = format!("`{what}` must be between {lo} and {hi}, found {x}");
        Err(self.error(v.span(), message))
    }

    /// The manifest of `raw`. Every part is checked even when another is refused, and the
    /// refusal reported is the first in the file (parts are read in an order of their
    /// own: what counts frames after `frames`, `[render]` after `[output]`).
    pub(super) fn manifest<C>(
        &self,
        raw: RawManifest<C>,
        camera: impl FnOnce(&Self, C, u32) -> Result<CameraParts, ManifestError>,
    ) -> Result<Manifest, ManifestError> {
        let mut errors = Vec::new();
        let scene = keep(self.resolve(&raw.scene, "scene"), &mut errors);
        let scene_loc = self.loc(raw.scene.span());
        let picked = match &raw.animation {
            Some(a) => keep(self.animation(a), &mut errors).flatten(),
            None => None,
        };
        let fps = match &raw.fps {
            Some(v) if !(MIN_FPS..=MAX_FPS).contains(v.get_ref()) => {
                let message = format!(
                    "`fps` must be a number from {MIN_FPS} to {MAX_FPS}, found {:?}",
                    v.get_ref()
                );
                Err(self.error(v.span(), message))
            }
            Some(v) => Ok(*v.get_ref()),
            None => Ok(DEFAULT_FPS),
        };
        let fps = keep(fps, &mut errors);
        let looped = raw.looped.as_ref().is_some_and(|l| *l.get_ref());
        let frames = match &raw.frames {
            Some(v) => self
                .int(v, "frames", 1..=i64::from(MAX_FRAMES))
                .map(|f| f as u32),
            None => self.frames_of_scene(
                scene.as_deref(),
                &picked,
                fps.unwrap_or(DEFAULT_FPS),
                looped,
            ),
        };
        let frames = keep(frames, &mut errors);
        let output = keep(self.output(raw.output), &mut errors);
        let render = match &output {
            Some(o) => keep(self.render(raw.render, o.format), &mut errors),
            None => None,
        };
        let (mut parts, mut tracks, mut check) = (None, None, None);
        if let Some(frames) = frames {
            let cam = match raw.camera {
                Some(c) => camera(self, c, frames),
                None => Ok((None, None, Lens::default())),
            };
            parts = keep(cam, &mut errors);
            tracks = keep(
                self.tracks(raw.track.unwrap_or_default(), frames),
                &mut errors,
            );
            let checked = raw.check.map(|c| self.check(c, frames)).transpose();
            check = keep(checked, &mut errors);
        }
        let all = (scene, frames, fps, output, render, parts, tracks, check);
        let (
            Some(scene),
            Some(frames),
            Some(fps),
            Some(output),
            Some(render),
            Some(parts),
            Some(tracks),
            Some(check),
        ) = all
        else {
            let first = errors
                .into_iter()
                .min_by_key(|e| e.loc().map(|l| (l.line, l.column)));
            return Err(first.unwrap_or_else(|| self.error(0..0, "the manifest cannot be read")));
        };
        let (camera, look_at, lens) = parts;
        let camera = match (camera, &raw.looped) {
            (Some(path), Some(at)) if looped => {
                Some(path.looped().map_err(|m| self.error(at.span(), m))?)
            }
            (camera, _) => camera,
        };
        Ok(Manifest {
            path: self.path.to_path_buf(),
            scene,
            scene_loc,
            camera_loc: FileLoc::default(),
            frames,
            fps,
            looped,
            camera,
            look_at,
            lens,
            tracks,
            render,
            output,
            check,
            draft: None,
            animation: picked,
            camera_name: None,
        })
    }
}

/// The value of `result`, or `None` with its error put in `errors`.
pub(super) fn keep<T>(
    result: Result<T, ManifestError>,
    errors: &mut Vec<ManifestError>,
) -> Option<T> {
    result.map_err(|e| errors.push(e)).ok()
}

/// serde's words for TOML types, in TOML's words.
pub(super) fn in_toml_words(message: &str) -> String {
    message
        .trim_end()
        .replace("expected i64", "expected an integer")
        .replace("expected f64", "expected a number")
        .replace("expected a sequence", "expected an array")
}
