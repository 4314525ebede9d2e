//! glTF 2.0, the third scene reader (SPEC §18; the full mapping, with its reasons, is in
//! docs/gltf.md). A `.gltf` (JSON, with its buffers in files beside it or in data URIs)
//! or `.glb` file is read by the `gltf` crate's document model, its bytes loaded by the
//! tracer's own bounded readers (`source`, `accessor`), into a `Rig` (`read`): the node
//! tree, the primitives in model space with their morph targets and skin weights
//! (`prims`), the materials on §2's terms (`material`, their images in `texture`),
//! cameras, lights, skins and animations (`clip`).
//! `Model::scene_at` poses the rig at a time (`pose`: animation channels, morph targets,
//! linear-blend skinning) and builds the tracer's `Scene` from it (`build`, `view`):
//!
//! ```text
//! nodes  ──►  objects `gltf 1`, `gltf 2`, … (named `Wheel`, `Wheel#2`), one per primitive
//!        ──►  lights (KHR_lights_punctual: candela / lux, range window, cone)
//!        ──►  the view (the first camera, `--camera NAME`, or one framing the bounds)
//! ```
//!
//! A glTF scene is shaded in linear light (`Scene::linear`); its frames are sRGB-encoded
//! when written as PNG, JPEG or video, and an EXR keeps the linear values.

mod build;
pub mod clip;
mod error;
pub mod material;
pub mod pose;
pub mod rig;
pub mod view;

#[cfg(feature = "gltf")]
mod accessor;
#[cfg(feature = "gltf")]
mod prims;
#[cfg(feature = "gltf")]
mod read;
#[cfg(feature = "gltf")]
mod source;
#[cfg(feature = "gltf")]
mod texture;

pub use build::Options;
pub use error::GltfError;
pub use pose::{Pose, Put};
pub use rig::Rig;

use crate::scene::Scene;
use std::path::Path;
use std::sync::Arc;

/// Whether `path` names a glTF file (`.gltf` or `.glb`, any case).
pub fn is_gltf(path: &Path) -> bool {
    path.extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case("gltf") || e.eq_ignore_ascii_case("glb"))
}

/// A glTF file read, with the options it is drawn with: what a `Scene` of it keeps, so
/// that an animation can pose it again at every frame.
#[derive(Clone, Debug)]
pub struct Model {
    /// The file, read.
    pub rig: Arc<Rig>,
    /// The camera it is seen through.
    pub options: Options,
    /// What the scene was posed with: the time in seconds, the clips playing and the
    /// values put over them (a frame's digest covers it, as the vertices follow from it).
    pub posed: Option<(f64, Vec<usize>, Vec<Put>)>,
}

impl PartialEq for Model {
    fn eq(&self, o: &Model) -> bool {
        Arc::ptr_eq(&self.rig, &o.rig) && self.options == o.options && self.posed == o.posed
    }
}

impl Model {
    /// Reads the glTF file whose bytes are `bytes`, named `path`.
    #[cfg(feature = "gltf")]
    pub fn read(path: &Path, bytes: &[u8], options: Options) -> Result<Model, GltfError> {
        let file = path.display().to_string();
        let dir = path.parent().unwrap_or(Path::new(""));
        let rig = read::read(bytes, &file, dir)?;
        Ok(Model {
            rig: Arc::new(rig),
            options,
            posed: None,
        })
    }

    /// A build without the tracer's `gltf` feature reads no glTF file.
    #[cfg(not(feature = "gltf"))]
    pub fn read(path: &Path, _bytes: &[u8], _options: Options) -> Result<Model, GltfError> {
        Err(error::at(
            &path.display().to_string(),
            "",
            "this build reads no glTF (the tracer's `gltf` feature)",
        ))
    }

    /// Every animation's index (all play together unless a manifest picks some).
    pub fn all_clips(&self) -> Vec<usize> {
        (0..self.rig.clips.len()).collect()
    }

    /// The animations named `names` (every one for `None`), or a refusal that lists the
    /// file's animations (an animation without a name is known by its number from 1).
    pub fn select(&self, names: Option<&[String]>) -> Result<Vec<usize>, String> {
        let Some(names) = names else {
            return Ok(self.all_clips());
        };
        let label = |k: usize| {
            let c = &self.rig.clips[k];
            c.name.clone().unwrap_or_else(|| format!("{}", k + 1))
        };
        let mut out = Vec::new();
        for name in names {
            match (0..self.rig.clips.len()).find(|&k| &label(k) == name) {
                Some(k) if !out.contains(&k) => out.push(k),
                Some(_) => {}
                None => {
                    let all: Vec<String> = (0..self.rig.clips.len()).map(label).collect();
                    let list = if all.is_empty() {
                        "none".to_string()
                    } else {
                        all.join(", ")
                    };
                    return Err(format!(
                        "the glTF file has no animation `{name}`; its animations: {list}"
                    ));
                }
            }
        }
        Ok(out)
    }

    /// The frame count of the clips `playing` at `fps` (SPEC §18): from t = 0 to the last
    /// key, both ends included, ⌈t_last·fps − 0.001⌉ + 1, the last left out when the
    /// sequence loops; 1 without keys.
    pub fn frames(&self, playing: &[usize], fps: f64, looped: bool) -> u64 {
        let end = self.end(playing);
        if end <= 0.0 {
            return 1;
        }
        let n = (end * fps - 0.001).ceil().max(0.0) as u64 + 1;
        if looped {
            (n - 1).max(1)
        } else {
            n
        }
    }

    /// The same file seen through the camera named `name`.
    pub fn through(&self, name: Option<String>) -> Model {
        Model {
            options: Options { camera: name },
            ..self.clone()
        }
    }

    /// The time of the last key of the clips `playing`, in seconds.
    pub fn end(&self, playing: &[usize]) -> f64 {
        playing
            .iter()
            .map(|&c| self.rig.clips[c].end())
            .fold(0.0, f64::max)
    }

    /// The scene at `t` seconds with the clips `playing` and the values `puts` over
    /// them.
    pub fn scene_at(&self, t: f64, playing: &[usize], puts: &[Put]) -> Result<Scene, GltfError> {
        let pose = Pose::at(&self.rig, t, playing, puts);
        let mut scene = build::scene(&self.rig, &pose, &self.options)?;
        scene.model = Some(Model {
            posed: Some((t, playing.to_vec(), puts.to_vec())),
            ..self.clone()
        });
        Ok(scene)
    }
}

/// The scene of a glTF file as a still shows it: every animation at t = 0.
pub fn load(path: &Path, bytes: &[u8], options: Options) -> Result<Scene, GltfError> {
    let model = Model::read(path, bytes, options)?;
    model.scene_at(0.0, &model.all_clips(), &[])
}

#[cfg(all(test, feature = "gltf"))]
mod tests;
