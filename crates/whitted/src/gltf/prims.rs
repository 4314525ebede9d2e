//! A glTF file's mesh primitives (SPEC §18), each read into a `Prim` in its model space:
//! TRIANGLES, TRIANGLE_STRIP and TRIANGLE_FAN cut into triangles in glTF's vertex orders
//! (POINTS and LINES skipped with a warning); POSITION (finite), NORMAL, TEXCOORD_0 and
//! TEXCOORD_1 (v flipped to point up the image), COLOR_0 (RGB, and its alpha kept
//! apart), JOINTS_0 and WEIGHTS_0, and morph targets' POSITION and NORMAL. Every count is
//! checked against the file's vertex and triangle budgets before anything is allocated.

use super::accessor::Buffers;
use super::error::{at, GltfError};
use super::rig::{Prim, Rig};
use crate::limits::{MAX_MESH_TRIANGLES, MAX_MESH_VERTICES};
use glam::DVec3;
use gltf::mesh::{Mode, Semantic};

/// Every mesh's primitives, within the vertex and triangle budgets.
pub fn read(doc: &gltf::Document, b: &Buffers, rig: &mut Rig) -> Result<(), GltfError> {
    let file = rig.file.clone();
    let (mut vertices, mut triangles) = (0u64, 0u64);
    let default_look = rig.looks.len() - 1;
    for mesh in doc.meshes() {
        let mut prims = Vec::new();
        for p in mesh.primitives() {
            let path = format!("meshes[{}].primitives[{}]", mesh.index(), p.index());
            if !matches!(
                p.mode(),
                Mode::Triangles | Mode::TriangleStrip | Mode::TriangleFan
            ) {
                rig.warn(format!(
                    "{}: {:?} primitives are not drawn (triangles only)",
                    rig.file,
                    p.mode()
                ));
                prims.push(Prim::default());
                continue;
            }
            let budget = MAX_MESH_VERTICES - vertices;
            let Some(pos) = p.get(&Semantic::Positions) else {
                return Err(at(&rig.file, format!("{path}.attributes"), "no POSITION"));
            };
            let positions: Vec<DVec3> = b
                .floats::<3>(&pos, budget)?
                .into_iter()
                .map(DVec3::from)
                .collect();
            if let Some(k) = positions.iter().position(|p| !p.is_finite()) {
                return Err(at(
                    &rig.file,
                    format!("accessors[{}]", pos.index()),
                    format!("position {k} is not a finite number"),
                ));
            }
            let n = positions.len() as u64;
            vertices += n;
            let same = |what: &str, len: usize| -> Result<(), GltfError> {
                if len as u64 != n {
                    return Err(at(
                        &file,
                        format!("{path}.attributes.{what}"),
                        format!("{len} values for {n} positions"),
                    ));
                }
                Ok(())
            };
            let mut prim = Prim {
                positions,
                look: p.material().index().unwrap_or(default_look),
                ..Prim::default()
            };
            if let Some(a) = p.get(&Semantic::Normals) {
                prim.normals = b.floats::<3>(&a, n)?.into_iter().map(DVec3::from).collect();
                same("NORMAL", prim.normals.len())?;
            }
            for set in 0..2 {
                if let Some(a) = p.get(&Semantic::TexCoords(set)) {
                    let uvs: Vec<[f64; 2]> = b
                        .floats::<2>(&a, n)?
                        .into_iter()
                        .map(|[u, v]| [u, 1.0 - v])
                        .collect();
                    same(&format!("TEXCOORD_{set}"), uvs.len())?;
                    prim.uvs[set as usize] = uvs;
                }
            }
            if let Some(a) = p.get(&Semantic::Colors(0)) {
                if a.dimensions() == gltf::accessor::Dimensions::Vec4 {
                    let rgba = b.floats::<4>(&a, n)?;
                    prim.colors = rgba
                        .iter()
                        .map(|&[r, g, b, _]| DVec3::new(r, g, b))
                        .collect();
                    prim.alphas = rgba.iter().map(|&[_, _, _, a]| a as f32).collect();
                } else {
                    prim.colors = b.floats::<3>(&a, n)?.into_iter().map(DVec3::from).collect();
                }
                same("COLOR_0", prim.colors.len())?;
            }
            if let Some(a) = p.get(&Semantic::Joints(0)) {
                prim.joints = b.indices::<4>(&a, n, u64::from(u32::MAX))?;
                same("JOINTS_0", prim.joints.len())?;
                prim.max_joint = prim.joints.iter().flatten().copied().max().unwrap_or(0);
                match p.get(&Semantic::Weights(0)) {
                    Some(w) => {
                        prim.weights = b.floats::<4>(&w, n)?;
                        same("WEIGHTS_0", prim.weights.len())?;
                    }
                    None => rig.warn(format!(
                        "{}: {path} has JOINTS_0 without WEIGHTS_0: drawn unskinned",
                        rig.file
                    )),
                }
            }
            for s in p.attributes().map(|(s, _)| s) {
                let used = matches!(
                    s,
                    Semantic::Positions
                        | Semantic::Normals
                        | Semantic::TexCoords(0 | 1)
                        | Semantic::Colors(0)
                        | Semantic::Joints(0)
                        | Semantic::Weights(0)
                );
                if !used {
                    rig.warn(format!(
                        "{}: the attribute {} is not used",
                        rig.file,
                        s.to_string()
                    ));
                }
            }
            for (k, t) in p.morph_targets().enumerate() {
                let mut target = super::rig::Target::default();
                if let Some(a) = t.positions() {
                    target.positions = b.floats::<3>(&a, n)?.into_iter().map(DVec3::from).collect();
                    same(&format!("targets[{k}].POSITION"), target.positions.len())?;
                }
                if let Some(a) = t.normals() {
                    target.normals = b.floats::<3>(&a, n)?.into_iter().map(DVec3::from).collect();
                    same(&format!("targets[{k}].NORMAL"), target.normals.len())?;
                }
                prim.targets.push(target);
            }
            let corners: Vec<u32> = match p.indices() {
                Some(a) => b
                    .indices::<1>(&a, 3 * MAX_MESH_TRIANGLES, n)?
                    .into_iter()
                    .map(|[i]| i)
                    .collect(),
                None => (0..n as u32).collect(),
            };
            prim.triangles = cut(p.mode(), &corners);
            triangles += prim.triangles.len() as u64;
            if triangles > MAX_MESH_TRIANGLES {
                return Err(at(
                    &rig.file,
                    path,
                    format!("the file's triangles pass the limit of {MAX_MESH_TRIANGLES}"),
                ));
            }
            prims.push(prim);
        }
        rig.meshes.push(prims);
        rig.mesh_weights.push(
            mesh.weights()
                .map_or_else(Vec::new, |w| w.iter().map(|&x| f64::from(x)).collect()),
        );
    }
    Ok(())
}

/// The triangles of a primitive's corners in `mode` (glTF 2.0 §3.7.2.1's orders).
pub fn cut(mode: Mode, c: &[u32]) -> Vec<[u32; 3]> {
    match mode {
        Mode::Triangles => c.chunks_exact(3).map(|t| [t[0], t[1], t[2]]).collect(),
        Mode::TriangleStrip => (0..c.len().saturating_sub(2))
            .map(|i| {
                if i % 2 == 0 {
                    [c[i], c[i + 1], c[i + 2]]
                } else {
                    [c[i + 1], c[i], c[i + 2]]
                }
            })
            .collect(),
        Mode::TriangleFan => (1..c.len().saturating_sub(1))
            .map(|i| [c[i], c[i + 1], c[0]])
            .collect(),
        _ => Vec::new(),
    }
}
