//! What a mesh loader hands over (`Raw`): the file's vertices with what it gives per
//! vertex (normals, texture coordinates, colours), its triangles (polygons fanned, strips
//! cut), the materials it names (`Look`, one per `.mtl` material) and which triangle
//! takes which, and the warnings for what it holds and the tracer does not use. Fanning
//! and strips check every index and the triangle budget as they go.

use crate::limits::MAX_MESH_TRIANGLES;
use crate::object::Material;
use crate::texture::Texture;
use glam::DVec3;

/// A material of the file (an `.mtl` entry): the TEXTURE and MATERIAL it stands for.
#[derive(Clone, Debug, PartialEq)]
pub struct Look {
    /// The colour: Kd, or the map_Kd image on the `uv` map.
    pub texture: Texture,
    /// The coefficients §2 shades with.
    pub material: Material,
}

/// A triangle that takes the record's own TEXTURE and MATERIAL (`Raw::face_looks`).
pub const RECORD_LOOK: u32 = u32::MAX;

/// What a loader reads, in the file's own space; every per-vertex list is empty or holds
/// one entry per position.
#[derive(Clone, Debug, Default)]
pub struct Raw {
    /// The vertices.
    pub positions: Vec<DVec3>,
    /// One normal per vertex, or none.
    pub normals: Vec<DVec3>,
    /// One (u, v) per vertex, or none.
    pub uvs: Vec<[f64; 2]>,
    /// One colour (0..1) per vertex, or none.
    pub colors: Vec<DVec3>,
    /// The triangles, polygons fanned and strips cut.
    pub triangles: Vec<[u32; 3]>,
    /// The file's materials.
    pub looks: Vec<Look>,
    /// One entry of `looks` per triangle (`RECORD_LOOK`: the record's), or none.
    pub face_looks: Vec<u32>,
    /// One line per kind of thing the file holds and the tracer does not use.
    pub warnings: Vec<String>,
}

impl Raw {
    /// Fans the polygon `face` (vertex indices) into triangles (v0, vi, vi+1), checking
    /// each index against `vertices`. A face of fewer than three vertices adds nothing.
    pub fn fan(&mut self, face: &[u32], vertices: usize) -> Result<(), String> {
        if let Some(bad) = face.iter().find(|&&i| i as usize >= vertices) {
            return Err(format!(
                "vertex index {bad} out of range ({vertices} vertices)"
            ));
        }
        for k in 1..face.len().saturating_sub(1) {
            self.triangles.push([face[0], face[k], face[k + 1]]);
        }
        Ok(())
    }

    /// Cuts the triangle strip `strip` (−1 restarts it) into triangles, every other one
    /// turned so that all keep the strip's winding: (a, b, c), then (c, b, d), …
    pub fn strip(&mut self, strip: &[i64], vertices: usize) -> Result<(), String> {
        let mut run: Vec<u32> = Vec::new();
        let flush = |run: &mut Vec<u32>, raw: &mut Raw| {
            for k in 0..run.len().saturating_sub(2) {
                let (a, b, c) = (run[k], run[k + 1], run[k + 2]);
                raw.triangles
                    .push(if k % 2 == 0 { [a, b, c] } else { [b, a, c] });
            }
            run.clear();
        };
        for &i in strip {
            match i {
                -1 => flush(&mut run, self),
                0.. if (i as u64) < vertices as u64 => run.push(i as u32),
                _ => {
                    return Err(format!(
                        "vertex index {i} out of range ({vertices} vertices; −1 restarts a strip)"
                    ))
                }
            }
        }
        flush(&mut run, self);
        Ok(())
    }

    /// True when the triangles are past the limit.
    pub fn over_limit(&self) -> bool {
        self.triangles.len() as u64 > MAX_MESH_TRIANGLES
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn strips_keep_their_winding_and_restart_at_minus_one() {
        let mut raw = Raw::default();
        raw.strip(&[0, 1, 2, 3, -1, 4, 5, 6, -1, -1, 7], 8).unwrap();
        assert_eq!(raw.triangles, vec![[0, 1, 2], [2, 1, 3], [4, 5, 6]]);
        let mut raw = Raw::default();
        raw.strip(&[-1, -1, -1], 8).unwrap();
        assert!(raw.triangles.is_empty());
        assert!(raw.strip(&[0, 1, 8], 8).unwrap_err().contains("index 8"));
        assert!(raw.strip(&[0, -2, 1], 8).unwrap_err().contains("index -2"));
    }
}
