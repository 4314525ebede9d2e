//! PLY (ASCII, binary little- and big-endian) through `ply-rs-bw`: its header, then one
//! element at a time (`ply_records`), so nothing is allocated for a count the file only
//! claims. Read: the `vertex` element's `x y z` and, when declared, `nx ny nz`, `u v`
//! (or `s t`, `texture_u texture_v`) and `red green blue`; the `face` element's
//! `vertex_indices` (or `vertex_index`) list of any integer type, fanned; the `tristrips`
//! element's lists, cut at −1 restarts. Every other element and property is named in one
//! warning.
//!
//! Before any element is read, the header is checked: a vertex element with x, y and z,
//! counts within the budgets (`MAX_MESH_VERTICES`, `MAX_MESH_TRIANGLES` faces), index
//! lists of integers, and a face or strip element at all; each refusal names its cause.
//! Errors in an ASCII file carry its line.

use super::ply_records::{is_index_list, vertex_slot, Face, Skip, Vertex};
use super::{MeshError, Raw};
use crate::limits::{MAX_MESH_TRIANGLES, MAX_MESH_VERTICES};
use glam::DVec3;
use ply_rs_bw::parser::{Parser, Reader};
use ply_rs_bw::ply::{ElementDef, Encoding, Header, PropertyAccess, PropertyType, ScalarType};
use std::io::{BufRead, Cursor};

fn malformed(path: &str, line: Option<usize>, message: String) -> MeshError {
    MeshError::Malformed {
        path: path.to_string(),
        line,
        format: "PLY",
        message,
    }
}

/// The elements' reader: the bytes after the header, the encoding, and the line of the
/// last element read (ASCII).
struct Elements<'b> {
    bytes: Cursor<&'b [u8]>,
    encoding: Encoding,
    line: usize,
    text: String,
}

impl Elements<'_> {
    /// The next element of `def`, or why not (with its line in an ASCII file).
    fn next<E: PropertyAccess>(
        &mut self,
        parser: &Parser<E>,
        def: &ElementDef,
    ) -> Result<E, (Option<usize>, String)> {
        let one_line = |e: ply_rs_bw::parser::ParseError| {
            let msg = e.to_string().replace(['\n', '\t'], " ");
            msg.chars().take(200).collect::<String>()
        };
        match self.encoding {
            Encoding::Ascii => {
                self.text.clear();
                self.line += 1;
                let read = self.bytes.read_line(&mut self.text);
                if read.map_err(|e| (Some(self.line), e.to_string()))? == 0 {
                    let msg = format!("the file ends inside the {} element", def.name);
                    return Err((Some(self.line), msg));
                }
                let text = self.text.trim_end_matches(['\n', '\r']);
                parser
                    .read_ascii_element(text, def)
                    .map_err(|e| (Some(self.line), one_line(e)))
            }
            Encoding::BinaryLittleEndian => parser
                .read_little_endian_element(&mut self.bytes, def)
                .map_err(|e| (None, one_line(e))),
            Encoding::BinaryBigEndian => parser
                .read_big_endian_element(&mut self.bytes, def)
                .map_err(|e| (None, one_line(e))),
        }
    }
}

/// The header's refusals and warnings: what must hold before any element is read.
fn check_header(header: &Header, path: &str, raw: &mut Raw) -> Result<(), MeshError> {
    let bad = |m: String| malformed(path, None, m);
    let Some(vertex) = header.elements.get("vertex") else {
        return Err(bad("the header declares no vertex element".into()));
    };
    let declared = |name: &str| vertex.properties.contains_key(name);
    if !(declared("x") && declared("y") && declared("z")) {
        return Err(bad("the vertex element lacks x, y or z".into()));
    }
    if vertex.count as u64 > MAX_MESH_VERTICES {
        return Err(bad(format!(
            "the header declares {} vertices, over the budget of {MAX_MESH_VERTICES} a mesh",
            vertex.count
        )));
    }
    let mut unused = Vec::new();
    for def in header.elements.values() {
        match def.name.as_str() {
            "vertex" => unused.extend(
                def.properties
                    .keys()
                    .filter(|p| vertex_slot(p).is_none())
                    .map(|p| format!("vertex property '{p}'")),
            ),
            "face" | "tristrips" => {
                let list = def.properties.values().find(|p| is_index_list(&p.name));
                let Some(list) = list else {
                    let msg = format!("the {} element has no vertex_indices list", def.name);
                    return Err(bad(msg));
                };
                match list.data_type {
                    PropertyType::List(_, ScalarType::Float | ScalarType::Double) => {
                        return Err(bad(format!(
                            "the {} element's {} is a list of floating-point numbers; vertex indices are integers",
                            def.name, list.name
                        )))
                    }
                    PropertyType::Scalar(_) => {
                        return Err(bad(format!(
                            "the {} element's {} is a single number, not a list of vertex indices",
                            def.name, list.name
                        )))
                    }
                    PropertyType::List(..) => {}
                }
                if def.name == "face" && def.count as u64 > MAX_MESH_TRIANGLES {
                    return Err(bad(format!(
                        "the header declares {} faces, over the budget of {MAX_MESH_TRIANGLES} triangles a mesh",
                        def.count
                    )));
                }
                unused.extend(
                    def.properties
                        .keys()
                        .filter(|p| !is_index_list(p))
                        .map(|p| format!("{} property '{p}'", def.name)),
                );
            }
            other => unused.push(format!("element '{other}' ({} of them)", def.count)),
        }
    }
    let faces = ["face", "tristrips"].map(|n| header.elements.get(n).map(|d| d.count));
    match faces {
        [None, None] => {
            return Err(MeshError::Empty {
                path: path.to_string(),
                why: "the PLY file has no face or tristrips element (points only)".into(),
            })
        }
        [Some(0) | None, Some(0) | None] => {
            return Err(MeshError::Empty {
                path: path.to_string(),
                why: "the PLY file declares 0 faces".into(),
            })
        }
        _ => {}
    }
    if !unused.is_empty() {
        raw.warnings
            .push(format!("{path}: not used: {}", unused.join(", ")));
    }
    Ok(())
}

/// The vertices, their data and the triangles of a PLY file's bytes.
pub fn read(bytes: &[u8], path: &str) -> Result<Raw, MeshError> {
    let crate_error = |e: ply_rs_bw::parser::ParseError| malformed(path, e.line(), e.to_string());
    let mut reader = Reader::new(Cursor::new(bytes));
    let header = Parser::<Skip>::new()
        .read_header(&mut reader)
        .map_err(crate_error)?;
    let mut raw = Raw::default();
    check_header(&header, path, &mut raw)?;
    let cursor = reader.into_inner();
    let start = cursor.position() as usize;
    let mut elements = Elements {
        line: bytes[..start].iter().filter(|&&b| b == b'\n').count(),
        bytes: cursor,
        encoding: header.encoding,
        text: String::new(),
    };
    let vertex = &header.elements["vertex"];
    let has = |names: &[&str]| names.iter().all(|n| vertex.properties.contains_key(*n));
    let normals = has(&["nx", "ny", "nz"]);
    let uvs = has(&["u", "v"]) || has(&["s", "t"]) || has(&["texture_u", "texture_v"]);
    let colors = has(&["red", "green", "blue"]);
    let (mut faces, mut strips, mut short) = (0u64, 0u64, 0u64);
    for def in header.elements.values() {
        let located = |(line, msg): (Option<usize>, String)| malformed(path, line, msg);
        match def.name.as_str() {
            "vertex" => {
                let parser = Parser::<Vertex>::new();
                for k in 0..def.count {
                    let v = elements.next(&parser, def).map_err(located)?.values;
                    let p = DVec3::new(v[0], v[1], v[2]);
                    if !p.is_finite() {
                        let line = (header.encoding == Encoding::Ascii).then_some(elements.line);
                        let msg = format!(
                            "vertex {k} is at ({} {} {}): not three finite numbers",
                            v[0], v[1], v[2]
                        );
                        return Err(malformed(path, line, msg));
                    }
                    raw.positions.push(p);
                    if normals {
                        raw.normals.push(DVec3::new(v[3], v[4], v[5]));
                    }
                    if uvs {
                        raw.uvs.push([v[6], v[7]]);
                    }
                    if colors {
                        raw.colors.push(DVec3::new(v[8], v[9], v[10]));
                    }
                }
            }
            kind @ ("face" | "tristrips") => {
                let parser = Parser::<Face>::new();
                let vertices = raw.positions.len();
                // One buffer each for every face's indices, signed and checked.
                let (mut indices, mut face) = (Vec::new(), Vec::new());
                for k in 0..def.count {
                    let f = elements.next(&parser, def).map_err(located)?;
                    f.indices(&mut indices);
                    let line = (header.encoding == Encoding::Ascii).then_some(elements.line);
                    let why = |m: String| malformed(path, line, format!("{kind} {k}: {m}"));
                    if kind == "face" {
                        faces += 1;
                        short += u64::from(indices.len() < 3);
                        face.clear();
                        for &i in &indices {
                            let i = u32::try_from(i)
                                .map_err(|_| why(format!("the vertex index {i} is negative")))?;
                            face.push(i);
                        }
                        raw.fan(&face, vertices).map_err(why)?;
                    } else {
                        strips += 1;
                        raw.strip(&indices, vertices).map_err(why)?;
                    }
                    if raw.over_limit() {
                        let count = raw.triangles.len() as u64;
                        return Err(MeshError::TooMany {
                            path: path.to_string(),
                            count,
                        });
                    }
                }
            }
            _ => {
                let parser = Parser::<Skip>::new();
                for _ in 0..def.count {
                    elements.next(&parser, def).map_err(located)?;
                }
            }
        }
    }
    if raw.triangles.is_empty() {
        let why = if strips > 0 && faces == short {
            format!(
                "its {strips} triangle strips hold no three vertices in a row (−1 restarts only?)"
            )
        } else {
            format!("each of its {faces} faces has fewer than three vertices")
        };
        return Err(MeshError::Empty {
            path: path.to_string(),
            why,
        });
    }
    Ok(raw)
}
