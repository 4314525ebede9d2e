//! A rig at one time (`Pose`): each node's local transform with the animations' values
//! put in (and any override after them: a manifest's track wins over the file's
//! channel), each node's morph weights, and every node's world matrix composed down the
//! tree; then a primitive's vertices in the world, morphed and skinned (SPEC §18):
//!
//! - morph: p + Σ wₖ·Δpₖ, n + Σ wₖ·Δnₖ, with the animation's weights, else the node's,
//!   else the mesh's;
//! - skin: p′ = Σᵢ wᵢ·(Jᵢ·IBMᵢ)·p over JOINTS_0 / WEIGHTS_0, Jᵢ the joint's world matrix
//!   (the skinned node's own transform is ignored, as glTF requires); normals by each
//!   matrix's inverse transpose, normalised;
//! - otherwise the node's world matrix W: p′ = W·p, n′ = W⁻ᵀ·n, and a W that mirrors
//!   (det W < 0) turns every triangle so that its front stays the front.

use super::clip::Path;
use super::rig::{Local, Prim, Rig};
use glam::{DMat3, DMat4, DQuat, DVec3};

/// A value put into one node at one time (a track's, or a channel's).
#[derive(Clone, Debug, PartialEq)]
pub struct Put {
    /// The node.
    pub node: usize,
    /// Which of its values.
    pub path: Path,
    /// The value: 3 for translation and scale, a quaternion x y z w, or weights.
    pub value: Vec<f64>,
}

/// Every node's transform, weights and world matrix at one time.
#[derive(Clone, Debug)]
pub struct Pose {
    /// Each node's world matrix.
    pub world: Vec<DMat4>,
    /// Each node's morph weights (empty: the mesh's own).
    pub weights: Vec<Vec<f64>>,
}

impl Pose {
    /// The rig at time `t` (seconds) with the clips `playing` (indices into
    /// `rig.clips`), then `puts` put in over them.
    pub fn at(rig: &Rig, t: f64, playing: &[usize], puts: &[Put]) -> Pose {
        let mut locals: Vec<Local> = rig.nodes.iter().map(|n| n.local).collect();
        let mut weights: Vec<Vec<f64>> = rig
            .nodes
            .iter()
            .map(|n| n.weights.clone().unwrap_or_default())
            .collect();
        let sampled = playing
            .iter()
            .flat_map(|&c| &rig.clips[c].channels)
            .map(|ch| Put {
                node: ch.node,
                path: ch.path,
                value: ch.sample(t),
            });
        for put in sampled.chain(puts.iter().cloned()) {
            apply(
                &mut locals[put.node],
                &mut weights[put.node],
                put.path,
                &put.value,
            );
        }
        let mut world = vec![DMat4::IDENTITY; rig.nodes.len()];
        let mut stack: Vec<(usize, DMat4)> =
            rig.roots.iter().map(|&r| (r, DMat4::IDENTITY)).collect();
        let mut seen = vec![false; rig.nodes.len()];
        while let Some((n, parent)) = stack.pop() {
            if std::mem::replace(&mut seen[n], true) {
                continue;
            }
            world[n] = parent * locals[n].matrix();
            stack.extend(rig.nodes[n].children.iter().map(|&c| (c, world[n])));
        }
        Pose { world, weights }
    }
}

/// Puts one value into a node's local transform or weights.
fn apply(local: &mut Local, weights: &mut Vec<f64>, path: Path, v: &[f64]) {
    if path == Path::Weights {
        *weights = v.to_vec();
        return;
    }
    let (mut s, mut r, mut t) = match *local {
        Local::Trs { t, r, s } => (s, r, t),
        Local::Matrix(m) => m.to_scale_rotation_translation(),
    };
    match (path, v) {
        (Path::Translation, [x, y, z]) => t = DVec3::new(*x, *y, *z),
        (Path::Scale, [x, y, z]) => s = DVec3::new(*x, *y, *z),
        (Path::Rotation, [x, y, z, w]) => r = DQuat::from_xyzw(*x, *y, *z, *w).normalize(),
        _ => return,
    }
    *local = Local::Trs { t, r, s };
}

/// A primitive's vertices and normals in the world at `pose`, and whether its triangles
/// must be turned (a mirroring world matrix).
pub fn place(rig: &Rig, pose: &Pose, node: usize, prim: &Prim) -> (Vec<DVec3>, Vec<DVec3>, bool) {
    let mesh = rig.nodes[node].mesh.unwrap_or(0);
    let own = &pose.weights[node];
    let weights = if own.is_empty() {
        &rig.mesh_weights[mesh]
    } else {
        own
    };
    let mut p = prim.positions.clone();
    let mut n = prim.normals.clone();
    for (target, &w) in prim.targets.iter().zip(weights) {
        if w == 0.0 {
            continue;
        }
        for (v, d) in p.iter_mut().zip(&target.positions) {
            *v += w * *d;
        }
        for (v, d) in n.iter_mut().zip(&target.normals) {
            *v += w * *d;
        }
    }
    let skin = rig.nodes[node].skin.map(|s| &rig.skins[s]);
    match skin {
        Some(skin) if !prim.joints.is_empty() && !prim.weights.is_empty() => {
            let mats: Vec<DMat4> = (skin.joints.iter().zip(&skin.inverse_bind))
                .map(|(&j, ibm)| pose.world[j] * *ibm)
                .collect();
            let normal_mats: Vec<DMat3> = mats.iter().map(normal_matrix).collect();
            for (k, v) in p.iter_mut().enumerate() {
                let (js, ws) = (prim.joints[k], prim.weights[k]);
                let mut sum = DVec3::ZERO;
                for c in 0..4 {
                    if let Some(m) = mats.get(js[c] as usize).filter(|_| ws[c] != 0.0) {
                        sum += ws[c] * m.transform_point3(*v);
                    }
                }
                *v = sum;
                if let Some(nv) = n.get_mut(k) {
                    let mut s = DVec3::ZERO;
                    for c in 0..4 {
                        if let Some(m) = normal_mats.get(js[c] as usize).filter(|_| ws[c] != 0.0) {
                            s += ws[c] * (*m * *nv);
                        }
                    }
                    *nv = s.normalize_or_zero();
                }
            }
            (p, n, false)
        }
        _ => {
            let w = pose.world[node];
            let nm = normal_matrix(&w);
            p.iter_mut().for_each(|v| *v = w.transform_point3(*v));
            n.iter_mut()
                .for_each(|v| *v = (nm * *v).normalize_or_zero());
            (p, n, w.determinant() < 0.0)
        }
    }
}

/// The inverse transpose of a matrix's 3×3 part (its normals' matrix).
fn normal_matrix(m: &DMat4) -> DMat3 {
    let m3 = DMat3::from_mat4(*m);
    if m3.determinant() == 0.0 {
        return m3;
    }
    m3.inverse().transpose()
}
