//! Wavefront OBJ through `tobj`: every object and group of the file in one mesh, its
//! polygons fanned here (tobj's `face_arities`), one index per corner (`single_index`,
//! so positions and normals pair up), points and lines ignored, materials not read (the
//! record's TEXTURE and MATERIAL colour the mesh). Normals count only when every vertex
//! has one.
//!
//! tobj names what is wrong but not where; on an error the line is found by reading
//! ever shorter prefixes of the file (a binary search over its lines: the first prefix
//! that fails ends at the line to blame).

use super::{MeshError, Raw};
use glam::DVec3;

fn options() -> tobj::LoadOptions {
    tobj::LoadOptions {
        single_index: true,
        triangulate: false,
        ignore_points: true,
        ignore_lines: true,
    }
}

fn load(text: &[u8]) -> Result<Vec<tobj::Model>, tobj::LoadError> {
    let mut reader = std::io::BufReader::new(text);
    let (models, _materials) = tobj::load_obj_buf(&mut reader, &options(), |_| {
        Err(tobj::LoadError::OpenFileFailed)
    })?;
    Ok(models)
}

/// The line (1-based) whose addition makes tobj fail, when the file's prefixes show it.
fn locate(bytes: &[u8]) -> Option<usize> {
    let ends: Vec<usize> = bytes
        .iter()
        .enumerate()
        .filter(|(_, &b)| b == b'\n')
        .map(|(i, _)| i + 1)
        .chain((bytes.last() != Some(&b'\n')).then_some(bytes.len()))
        .collect();
    let fails = |lines: usize| load(&bytes[..ends[lines - 1]]).is_err();
    // The smallest number of lines whose prefix fails.
    let (mut lo, mut hi) = (1usize, ends.len());
    if hi == 0 || !fails(hi) {
        return None;
    }
    while lo < hi {
        let mid = lo + (hi - lo) / 2;
        if fails(mid) {
            hi = mid;
        } else {
            lo = mid + 1;
        }
    }
    Some(lo)
}

/// The vertices, normals and fanned triangles of an OBJ file's bytes.
pub fn read(bytes: &[u8], path: &str) -> Result<Raw, MeshError> {
    let models = load(bytes).map_err(|e| MeshError::Malformed {
        path: path.to_string(),
        line: locate(bytes),
        format: "OBJ",
        message: e.to_string(),
    })?;
    let mut raw = Raw::default();
    let mut smooth = true;
    for model in &models {
        let m = &model.mesh;
        let base = raw.positions.len() as u32;
        let count = m.positions.len() / 3;
        raw.positions.extend(
            m.positions
                .chunks_exact(3)
                .map(|p| DVec3::new(p[0], p[1], p[2])),
        );
        if m.normals.len() == m.positions.len() {
            raw.normals.extend(
                m.normals
                    .chunks_exact(3)
                    .map(|n| DVec3::new(n[0], n[1], n[2])),
            );
        } else {
            smooth = false;
        }
        let mut face = Vec::new();
        let mut start = 0usize;
        let arities: Box<dyn Iterator<Item = usize>> = if m.face_arities.is_empty() {
            Box::new(std::iter::repeat_n(3, m.indices.len() / 3))
        } else {
            Box::new(m.face_arities.iter().map(|&a| a as usize))
        };
        for arity in arities {
            let Some(corners) = m.indices.get(start..start + arity) else {
                break;
            };
            start += arity;
            face.clear();
            face.extend(corners.iter().map(|&i| i + base));
            raw.fan(&face, base as usize + count)
                .map_err(|message| MeshError::Malformed {
                    path: path.to_string(),
                    line: None,
                    format: "OBJ",
                    message,
                })?;
            if raw.over_limit() {
                break;
            }
        }
    }
    if !smooth {
        raw.normals.clear();
    }
    Ok(raw)
}
