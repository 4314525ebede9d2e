//! Reading a scene file of any of the three formats, one door above the readers: the
//! file's extension picks glTF (`.gltf`, `.glb`: `crate::gltf`), NFF (`.nff`:
//! `scene::nff`) or Scene.txt (anything else: `scene::parser`); and a glTF scene seen
//! again through another of its cameras, and the warning for a picture of another shape
//! than its camera's. It sits above `scene` and `gltf`, which build
//! `Scene`s, so that neither imports the other's reader.

use crate::gltf;
use crate::scene::decode::decode;
use crate::scene::nff;
use crate::scene::{Scene, SceneError};
use std::path::Path;

impl Scene {
    /// Reads and parses a scene file.
    pub fn load(path: &Path) -> Result<Scene, SceneError> {
        Scene::load_with_bytes(path).map(|(scene, _)| scene)
    }

    /// Reads and parses a scene file, returning its bytes too (to fingerprint exactly
    /// what was parsed).
    pub fn load_with_bytes(path: &Path) -> Result<(Scene, Vec<u8>), SceneError> {
        let name = path.display().to_string();
        let limit = crate::limits::MAX_SCENE_BYTES;
        let read = crate::input::read_regular(path, limit, "scene");
        let bytes = read.map_err(|source| SceneError::Io {
            path: name.clone(),
            source,
        })?;
        if gltf::is_gltf(path) {
            let options = gltf::Options::default();
            let scene = gltf::load(path, &bytes, options).map_err(SceneError::Gltf)?;
            return Ok((scene, bytes));
        }
        let text = decode(&bytes, &name)?;
        let scene = if nff::is_nff(path) {
            nff::parse(text, &name)?
        } else {
            Scene::parse(text, &name)?
        };
        Ok((scene, bytes))
    }

    /// The same glTF scene seen through its camera named `name` (`raytrace --camera`, a
    /// manifest's `[camera] name`); a refusal for a scene of another format, or a name
    /// the file does not have (with the names it has).
    pub fn through_camera(&self, name: &str) -> Result<Scene, String> {
        let Some(model) = &self.model else {
            return Err(format!(
                "a camera is picked by name in a glTF scene only; `{name}` cannot be looked for in a Scene.txt or NFF file"
            ));
        };
        let (t, playing, puts) = model.posed.clone().unwrap_or_default();
        let model = model.through(Some(name.to_string()));
        model
            .scene_at(t, &playing, &puts)
            .map_err(|e| e.to_string())
    }

    /// The warning for a picture of `size` of a glTF scene whose camera's `aspectRatio`
    /// is another shape (`gltf::view::aspect_warning`); `None` for any other scene.
    pub fn aspect_warning(&self, size: (u32, u32)) -> Option<String> {
        let model = self.model.as_ref()?;
        let name = model.options.camera.as_deref();
        gltf::view::aspect_warning(&model.rig, name, size)
    }
}
