//! Wavefront OBJ through `tobj`: every object and group of the file in one mesh, its
//! polygons fanned here (tobj's `face_arities`), one index per corner (`single_index`,
//! so positions, `vt` coordinates, normals and `v x y z r g b` colours pair up); each
//! kind counts only when every vertex has it. `mtllib` files are read beside the OBJ
//! through tobj's `.mtl` reader (`mtl`), and each face takes its `usemtl` material.
//!
//! Before tobj allocates, one pass (`obj_scan`) counts the file's vertices and faces
//! against the budgets and names the statements read past (one warning per kind). A
//! UTF-8 byte-order mark is skipped. tobj names what is wrong but not where: the reader
//! it reads from counts lines, so a line it refuses is the line just read; an index past
//! its list, which tobj finds only at the end of an object, is found by one more pass.

use super::obj_scan::{self, Counts};
use super::{mtl, MeshError, Raw};
use glam::DVec3;
use std::cell::RefCell;
use std::io::{BufRead, Read};
use std::path::Path;

fn options() -> tobj::LoadOptions {
    tobj::LoadOptions {
        single_index: true,
        triangulate: false,
        ignore_points: true,
        ignore_lines: true,
    }
}

/// The file's bytes handed to tobj one line at a time, counting lines as they go.
struct Lines<'b> {
    bytes: &'b [u8],
    at: usize,
    /// The 1-based line of the last byte handed over.
    line: usize,
}

impl Read for Lines<'_> {
    fn read(&mut self, out: &mut [u8]) -> std::io::Result<usize> {
        let n = self.fill_buf()?.len().min(out.len());
        out[..n].copy_from_slice(&self.bytes[self.at..self.at + n]);
        self.consume(n);
        Ok(n)
    }
}

impl BufRead for Lines<'_> {
    fn fill_buf(&mut self) -> std::io::Result<&[u8]> {
        let rest = &self.bytes[self.at..];
        let end = rest
            .iter()
            .position(|&b| b == b'\n')
            .map_or(rest.len(), |i| i + 1);
        Ok(&rest[..end])
    }

    fn consume(&mut self, n: usize) {
        if n > 0 && (self.at == 0 || self.bytes[self.at - 1] == b'\n') {
            self.line += 1;
        }
        self.at += n;
    }
}

fn malformed(path: &str, line: Option<usize>, message: String) -> MeshError {
    MeshError::Malformed {
        path: path.to_string(),
        line,
        format: "OBJ",
        message,
    }
}

/// Where tobj's `error` is in the file: the line it stopped at, or for an index past its
/// list, the face that holds it.
fn locate(e: tobj::LoadError, bytes: &[u8], counts: &Counts, stopped: usize) -> (usize, String) {
    use tobj::LoadError::*;
    match e {
        FaceVertexOutOfBounds | FaceTexCoordOutOfBounds | FaceNormalOutOfBounds => {
            obj_scan::bad_index(bytes, counts).unwrap_or((stopped, e.to_string()))
        }
        FaceColorOutOfBounds => (
            stopped,
            "some vertices have a colour (v x y z r g b) and others not".into(),
        ),
        _ => (stopped, e.to_string()),
    }
}

/// The vertices, their data, the fanned triangles and the materials of an OBJ file's
/// bytes; `dir` is the file's folder, where its `.mtl` files are.
pub fn read(bytes: &[u8], path: &str, dir: &Path) -> Result<Raw, MeshError> {
    let bytes = bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes);
    let counts = obj_scan::count(bytes);
    if let Some(why) = counts.over_budget() {
        return Err(malformed(path, None, why));
    }
    if counts.faces == 0 {
        let why = "the OBJ file has no faces ('f' lines)".to_string();
        return Err(MeshError::Empty {
            path: path.to_string(),
            why,
        });
    }
    if let Some(line) = obj_scan::non_finite(bytes) {
        let why = "the vertex has a coordinate that is not a finite number (NaN, or past ±1.8e308)"
            .to_string();
        return Err(malformed(path, Some(line), why));
    }
    let mut raw = Raw::default();
    let mtl_warnings = RefCell::new(Vec::new());
    let mut lines = Lines {
        bytes,
        at: 0,
        line: 0,
    };
    let (models, materials) = tobj::load_obj_buf(&mut lines, &options(), |name| {
        mtl::read(dir, name, path, &mut mtl_warnings.borrow_mut())
    })
    .map_err(|e| {
        let (line, message) = locate(e, bytes, &counts, lines.line);
        malformed(path, Some(line), message)
    })?;
    raw.warnings.extend(mtl_warnings.into_inner());
    for (name, n, line) in &counts.unused {
        raw.warnings.push(format!(
            "{path}:{line}: not used: {n} '{name}' statement(s) (the tracer reads v, vt, vn, f, o, g, mtllib, usemtl)"
        ));
    }
    if counts.others > 0 {
        raw.warnings.push(format!(
            "{path}: not used: {} 'l' and 'p' lines (lines and points are not drawn)",
            counts.others
        ));
    }
    let every = |f: &dyn Fn(&tobj::Mesh) -> bool| models.iter().all(|m| f(&m.mesh));
    let normals = every(&|m| m.normals.len() == m.positions.len());
    let uvs = every(&|m| m.texcoords.len() / 2 == m.positions.len() / 3);
    let colors = every(&|m| m.vertex_color.len() == m.positions.len());
    let materials = materials.unwrap_or_default();
    undefined_materials(bytes, &materials, path, &mut raw.warnings);
    raw.looks = mtl::looks(&materials, dir, path, uvs, &mut raw.warnings);
    let looks = models.iter().any(|m| m.mesh.material_id.is_some()) && !raw.looks.is_empty();
    for model in &models {
        let m = &model.mesh;
        let base = raw.positions.len() as u32;
        let count = m.positions.len() / 3;
        let triples = |v: &[f64]| -> Vec<DVec3> {
            v.chunks_exact(3)
                .map(|p| DVec3::new(p[0], p[1], p[2]))
                .collect()
        };
        raw.positions.extend(triples(&m.positions));
        if normals {
            raw.normals.extend(triples(&m.normals));
        }
        if colors {
            raw.colors.extend(triples(&m.vertex_color));
        }
        if uvs {
            raw.uvs
                .extend(m.texcoords.chunks_exact(2).map(|t| [t[0], t[1]]));
        }
        let look = m
            .material_id
            .filter(|&i| i < raw.looks.len())
            .map_or(super::raw::RECORD_LOOK, |i| i as u32);
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
            let before = raw.triangles.len();
            raw.fan(&face, base as usize + count)
                .map_err(|message| malformed(path, None, message))?;
            if looks {
                let added = raw.triangles.len() - before;
                raw.face_looks.extend(std::iter::repeat_n(look, added));
            }
        }
    }
    if raw.triangles.is_empty() {
        let why = format!(
            "each of its {} 'f' lines has fewer than three corners",
            counts.faces
        );
        return Err(MeshError::Empty {
            path: path.to_string(),
            why,
        });
    }
    Ok(raw)
}

/// A warning for the first `usemtl` of each name that no `.mtl` material has, or that
/// comes before every `mtllib` line (tobj looks the name up when it meets it): its faces
/// take the record's TEXTURE and MATERIAL. Each with its line.
fn undefined_materials(
    bytes: &[u8],
    materials: &[tobj::Material],
    path: &str,
    warnings: &mut Vec<String>,
) {
    let mut named: Vec<&[u8]> = Vec::new();
    let mut libraries = false;
    for (line, text) in obj_scan::lines(bytes) {
        let mut words = text
            .split(|b| b.is_ascii_whitespace())
            .filter(|w| !w.is_empty());
        let keyword = words.next();
        if keyword == Some(b"mtllib".as_slice()) {
            libraries = true;
        }
        if keyword != Some(b"usemtl".as_slice()) {
            continue;
        }
        let Some(name) = words.next() else { continue };
        let known = materials.iter().any(|m| m.name.as_bytes() == name);
        if (!known || !libraries) && !named.contains(&name) {
            named.push(name);
            let why = if known {
                "comes before every mtllib line"
            } else {
                "names no material of the .mtl files"
            };
            warnings.push(format!(
                "{path}:{line}: usemtl '{}' {why}: its faces take the record's TEXTURE and MATERIAL",
                String::from_utf8_lossy(name)
            ));
        }
    }
}
