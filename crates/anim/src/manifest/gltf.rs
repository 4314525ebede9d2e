//! What a manifest says of a glTF scene (SPEC §18): `[animation] name` (one name or a
//! list: the animations that play; every one without it), `[camera] name` (the file's
//! camera to look through), and, when `frames` is left out, the frame count the playing
//! animations give: from t = 0 to their last key at `fps`, both ends included.
//!
//! ```toml
//! scene = "walk.glb"     # frames left out: the animations say how many
//! fps = 24
//! [animation]
//! name = ["Walk", "Blink"]
//! [camera]
//! name = "Close-up"
//! ```

use super::raw::RawAnimation;
use super::source::Source;
use super::ManifestError;
use std::path::Path;
use toml::Spanned;
use whitted::fileloc::FileLoc;
use whitted::limits::MAX_FRAMES;

/// `[animation] name`, read: the names and where the table is.
pub(super) type Picked = Option<(Vec<String>, FileLoc)>;

impl Source<'_> {
    /// The names `[animation] name` gives (a string or an array of strings).
    pub(super) fn animation(&self, raw: &Spanned<RawAnimation>) -> Result<Picked, ManifestError> {
        let loc = self.loc(raw.span());
        let Some(name) = &raw.get_ref().name else {
            return Ok(None);
        };
        let bad = || {
            self.error(
                name.span(),
                "`name` is an animation's name or an array of names",
            )
        };
        let names = match name.get_ref() {
            toml::Value::String(s) => vec![s.clone()],
            toml::Value::Array(list) if !list.is_empty() => list
                .iter()
                .map(|v| v.as_str().map(str::to_string).ok_or_else(bad))
                .collect::<Result<_, _>>()?,
            _ => return Err(bad()),
        };
        Ok(Some((names, loc)))
    }

    /// The frame count of a manifest without `frames`: its glTF scene's animations'.
    pub(super) fn frames_of_scene(
        &self,
        scene: Option<&Path>,
        picked: &Picked,
        fps: f64,
        looped: bool,
    ) -> Result<u32, ManifestError> {
        let missing = "`frames` is required (only a glTF scene's animations can give it)";
        let Some(scene) = scene.filter(|s| whitted::gltf::is_gltf(s)) else {
            return Err(self.error(0..0, missing));
        };
        let unread = |why: String| {
            self.error(
                0..0,
                format!(
                    "`frames` is left out and the glTF scene cannot be read to count them: {why}"
                ),
            )
        };
        let limit = whitted::limits::MAX_SCENE_BYTES;
        let bytes = whitted::input::read_regular(scene, limit, "scene")
            .map_err(|e| unread(format!("{}: {e}", scene.display())))?;
        let options = whitted::gltf::Options::default();
        let model = whitted::gltf::Model::read(scene, &bytes, options)
            .map_err(|e| unread(e.to_string()))?;
        let names = picked.as_ref().map(|(n, _)| n.as_slice());
        let playing = model.select(names).map_err(|m| match picked {
            Some((_, loc)) => ManifestError::Invalid {
                loc: loc.clone(),
                message: format!("[animation] name: {m}"),
            },
            None => self.error(0..0, m),
        })?;
        let frames = model.frames(&playing, fps, looped);
        u32::try_from(frames)
            .ok()
            .filter(|&f| f <= MAX_FRAMES)
            .ok_or_else(|| {
                self.error(
                    0..0,
                    format!("the animations give {frames} frames, over the limit of {MAX_FRAMES}"),
                )
            })
    }
}
