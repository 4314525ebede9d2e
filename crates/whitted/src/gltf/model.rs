//! A glTF file read (`Model`): its rig, the camera it is seen through (`Options`) and the
//! pose its scene was built at, so that an animation can pose it again at every frame;
//! which animations play (`select`) and how many frames they span (`frames`). Building a
//! scene from it is `build`'s (`Model::scene_at`).

use super::error::GltfError;
use super::pose::Put;
use super::rig::Rig;
use std::path::Path;
use std::sync::Arc;

/// What picks the view: the camera's name (`raytrace --camera`), if any.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Options {
    /// The camera to look through.
    pub camera: Option<String>,
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
        let rig = super::read::read(bytes, &file, dir)?;
        Ok(Model {
            rig: Arc::new(rig),
            options,
            posed: None,
        })
    }

    /// A build without the tracer's `gltf` feature reads no glTF file.
    #[cfg(not(feature = "gltf"))]
    pub fn read(path: &Path, _bytes: &[u8], _options: Options) -> Result<Model, GltfError> {
        Err(super::error::at(
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
}
