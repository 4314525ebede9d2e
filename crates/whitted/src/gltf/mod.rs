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
pub mod error;
pub mod material;
pub mod model;
pub mod pose;
pub mod rig;
pub mod view;

#[cfg(feature = "gltf")]
mod accessor;
#[cfg(feature = "gltf")]
mod animations;
#[cfg(feature = "gltf")]
mod prims;
#[cfg(feature = "gltf")]
mod read;
#[cfg(feature = "gltf")]
mod source;
#[cfg(feature = "gltf")]
mod texture;

pub use build::load;
pub use error::GltfError;
pub use model::{Model, Options};
pub use pose::{Pose, Put};
pub use rig::Rig;

use std::path::Path;

/// Whether `path` names a glTF file (`.gltf` or `.glb`, any case).
pub fn is_gltf(path: &Path) -> bool {
    path.extension()
        .and_then(|e| e.to_str())
        .is_some_and(|e| e.eq_ignore_ascii_case("gltf") || e.eq_ignore_ascii_case("glb"))
}

#[cfg(all(test, feature = "gltf"))]
mod tests;
