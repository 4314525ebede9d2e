//! A glTF file in the tracer's own terms (`Rig`): its node tree with each node's rest
//! transform, its meshes' primitives in their model space (with morph targets and skin
//! weights), its materials made into TEXTURE and MATERIAL, its cameras, lights, skins
//! and animations. Read once (`read`); `pose` and `build` make the scene of any time
//! from it, so an animation's frames share everything that does not move.

use crate::base::Color;
use crate::mesh::extra::AlphaMode;
use crate::mesh::Look;
use crate::texture::ImageTexture;
use std::path::PathBuf;
use std::sync::Arc;

/// The files a glTF file named, with their SHA-256, in the order they were read.
pub type Named = Vec<(PathBuf, [u8; 32])>;
use glam::{DMat4, DQuat, DVec3};

/// A node's transform relative to its parent.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Local {
    /// Translation, rotation (unit quaternion), scale: T·R·S.
    Trs {
        /// The translation.
        t: DVec3,
        /// The rotation.
        r: DQuat,
        /// The scale.
        s: DVec3,
    },
    /// A matrix given as is (never animated, as glTF requires).
    Matrix(DMat4),
}

impl Local {
    /// The matrix.
    pub fn matrix(&self) -> DMat4 {
        match *self {
            Local::Trs { t, r, s } => DMat4::from_scale_rotation_translation(s, r, t),
            Local::Matrix(m) => m,
        }
    }
}

/// One node of the file.
#[derive(Clone, Debug)]
pub struct Node {
    /// Its name, if the file gives one.
    pub name: Option<String>,
    /// Its children, in the file's order.
    pub children: Vec<usize>,
    /// Its rest transform.
    pub local: Local,
    /// The mesh it places, if any.
    pub mesh: Option<usize>,
    /// The camera it places, if any.
    pub camera: Option<usize>,
    /// The light it places (`KHR_lights_punctual`), if any.
    pub light: Option<usize>,
    /// The skin its mesh is deformed by, if any.
    pub skin: Option<usize>,
    /// Its morph weights, if it gives them.
    pub weights: Option<Vec<f64>>,
}

/// A morph target's displacements (empty when the target leaves that attribute).
#[derive(Clone, Debug, Default)]
pub struct Target {
    /// Position displacements, one per vertex.
    pub positions: Vec<DVec3>,
    /// Normal displacements, one per vertex.
    pub normals: Vec<DVec3>,
}

/// One mesh primitive, in its model space.
#[derive(Clone, Debug, Default)]
pub struct Prim {
    /// POSITION.
    pub positions: Vec<DVec3>,
    /// NORMAL (empty: flat, as glTF requires).
    pub normals: Vec<DVec3>,
    /// TEXCOORD_0 and TEXCOORD_1, v already flipped to point up the image (each empty
    /// when the primitive has no such set).
    pub uvs: [Vec<[f64; 2]>; 2],
    /// COLOR_0's RGB (linear).
    pub colors: Vec<DVec3>,
    /// COLOR_0's alpha, when it has one (`VEC4`).
    pub alphas: Vec<f32>,
    /// The triangles, strips and fans cut.
    pub triangles: Vec<[u32; 3]>,
    /// Index into `Rig::looks`.
    pub look: usize,
    /// Morph targets.
    pub targets: Vec<Target>,
    /// JOINTS_0: four joint numbers per vertex (into the skin's joints).
    pub joints: Vec<[u32; 4]>,
    /// WEIGHTS_0: four weights per vertex.
    pub weights: Vec<[f64; 4]>,
    /// The largest joint number of JOINTS_0 (checked against the node's skin).
    pub max_joint: u32,
}

/// What a material gives besides its TEXTURE, MATERIAL, tint and emission factor.
#[derive(Clone, Debug, Default)]
pub struct LookExtra {
    /// `alphaMode` (with `alphaCutoff`).
    pub mode: AlphaMode,
    /// `baseColorFactor`'s alpha.
    pub factor: f64,
    /// The coordinate set (0 or 1) its base colour texture is read on.
    pub base_set: usize,
    /// `emissiveTexture` (linear colours), `emissiveFactor` × strength, and the
    /// coordinate set (0 or 1) it is read on.
    pub emissive: Option<(Arc<ImageTexture>, Color, usize)>,
}

/// A camera's projection.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Projection {
    /// `yfov` (radians, the full vertical angle) and `aspectRatio`, if given.
    Perspective {
        /// The full vertical angle, radians.
        yfov: f64,
        /// Width over height, if the file says.
        aspect: Option<f64>,
    },
    /// Half the view's width and height.
    Orthographic {
        /// xmag.
        xmag: f64,
        /// ymag.
        ymag: f64,
    },
}

/// A camera of the file.
#[derive(Clone, Debug)]
pub struct CameraDef {
    /// Its name (the camera's, else its node's is used).
    pub name: Option<String>,
    /// Its projection.
    pub projection: Projection,
}

/// What kind of `KHR_lights_punctual` light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LightType {
    /// A point light.
    Point,
    /// A spot light, half-angles in radians.
    Spot {
        /// innerConeAngle.
        inner: f64,
        /// outerConeAngle.
        outer: f64,
    },
    /// A directional light.
    Directional,
}

/// A light of the file.
#[derive(Clone, Debug)]
pub struct LightDef {
    /// Its name, if any.
    pub name: Option<String>,
    /// Its type.
    pub kind: LightType,
    /// Linear colour.
    pub color: DVec3,
    /// Candela or lux.
    pub intensity: f64,
    /// range, if given.
    pub range: Option<f64>,
}

/// A skin: its joints (nodes) and their inverse bind matrices.
#[derive(Clone, Debug)]
pub struct Skin {
    /// The joint nodes.
    pub joints: Vec<usize>,
    /// One inverse bind matrix per joint (identity when the file gives none).
    pub inverse_bind: Vec<DMat4>,
}

/// The whole file, read.
#[derive(Clone, Debug, Default)]
pub struct Rig {
    /// The file's name, for messages.
    pub file: String,
    /// Every node.
    pub nodes: Vec<Node>,
    /// The root nodes of the scene drawn (the default scene, else the first).
    pub roots: Vec<usize>,
    /// Each mesh's primitives.
    pub meshes: Vec<Vec<Prim>>,
    /// Each mesh's default morph weights.
    pub mesh_weights: Vec<Vec<f64>>,
    /// The materials, then the default material (the last).
    pub looks: Vec<Look>,
    /// Per look: its tint and emission (`Scene::pbr`; its material's `Highlight::Gltf`
    /// indexes it).
    pub pbr: Vec<crate::object::Pbr>,
    /// Per look: whether its back faces are drawn (`doubleSided`).
    pub double_sided: Vec<bool>,
    /// Per look: its alpha mode, coordinate sets and emissive texture.
    pub extras: Vec<LookExtra>,
    /// The cameras.
    pub cameras: Vec<CameraDef>,
    /// The lights.
    pub lights: Vec<LightDef>,
    /// The skins.
    pub skins: Vec<Skin>,
    /// The animations.
    pub clips: Vec<super::clip::Clip>,
    /// One line per kind of thing the file holds and the tracer does not use.
    pub warnings: Vec<String>,
    /// The files the glTF file named, with their SHA-256.
    pub named: Named,
    /// The SHA-256 of the glTF file itself.
    pub source: [u8; 32],
}

impl Rig {
    /// Adds a warning once.
    pub fn warn(&mut self, line: String) {
        if !self.warnings.contains(&line) {
            self.warnings.push(line);
        }
    }

    /// The nodes of the drawn scene in depth-first order (each once).
    pub fn order(&self) -> Vec<usize> {
        let mut out = Vec::new();
        let mut stack: Vec<usize> = self.roots.iter().rev().copied().collect();
        let mut seen = vec![false; self.nodes.len()];
        while let Some(n) = stack.pop() {
            if std::mem::replace(&mut seen[n], true) {
                continue;
            }
            out.push(n);
            stack.extend(self.nodes[n].children.iter().rev());
        }
        out
    }
}
