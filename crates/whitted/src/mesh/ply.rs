//! PLY (ASCII, binary little- and big-endian) through `ply-rs-bw`, read element by
//! element into compact records of our own (no per-vertex maps): the `vertex` element's
//! `x y z` (float or double) and, when every vertex has them, `nx ny nz`; the `face`
//! element's `vertex_indices` (or `vertex_index`) list, of any integer type, fanned into
//! triangles. Other elements and properties are read past and ignored. The crate's
//! errors carry the file's line in an ASCII file; ours say which face is wrong.

use super::{MeshError, Raw};
use glam::DVec3;
use ply_rs_bw::parser::{Parser, Reader};
use ply_rs_bw::ply::{PropertyAccess, PropertyAccessResult};

#[derive(Default)]
struct Vertex {
    p: [f64; 3],
    n: [f64; 3],
    /// Bits 0..2: x y z seen; bits 3..5: nx ny nz seen.
    seen: u8,
}

impl Vertex {
    fn set(&mut self, name: &str, v: f64) -> PropertyAccessResult {
        let slot = match name {
            "x" => 0,
            "y" => 1,
            "z" => 2,
            "nx" => 3,
            "ny" => 4,
            "nz" => 5,
            _ => return PropertyAccessResult::Ignored,
        };
        if slot < 3 {
            self.p[slot] = v;
        } else {
            self.n[slot - 3] = v;
        }
        self.seen |= 1 << slot;
        PropertyAccessResult::Set
    }
}

impl PropertyAccess for Vertex {
    fn new() -> Self {
        Vertex::default()
    }
    fn set_float(&mut self, name: &str, v: f32) -> PropertyAccessResult {
        self.set(name, f64::from(v))
    }
    fn set_double(&mut self, name: &str, v: f64) -> PropertyAccessResult {
        self.set(name, v)
    }
}

/// A face's vertex indices; `bad` when one was negative.
#[derive(Default)]
struct Face {
    indices: Vec<u32>,
    bad: bool,
}

impl Face {
    fn take<T: TryInto<u32> + Copy>(&mut self, name: &str, v: &[T]) -> PropertyAccessResult {
        if name != "vertex_indices" && name != "vertex_index" {
            return PropertyAccessResult::Ignored;
        }
        self.indices.clear();
        for &i in v {
            match i.try_into() {
                Ok(i) => self.indices.push(i),
                Err(_) => self.bad = true,
            }
        }
        PropertyAccessResult::Set
    }
}

impl PropertyAccess for Face {
    fn new() -> Self {
        Face::default()
    }
    fn set_list_char(&mut self, name: &str, v: Vec<i8>) -> PropertyAccessResult {
        self.take(name, &v)
    }
    fn set_list_uchar(&mut self, name: &str, v: Vec<u8>) -> PropertyAccessResult {
        self.take(name, &v)
    }
    fn set_list_short(&mut self, name: &str, v: Vec<i16>) -> PropertyAccessResult {
        self.take(name, &v)
    }
    fn set_list_ushort(&mut self, name: &str, v: Vec<u16>) -> PropertyAccessResult {
        self.take(name, &v)
    }
    fn set_list_int(&mut self, name: &str, v: Vec<i32>) -> PropertyAccessResult {
        self.take(name, &v)
    }
    fn set_list_uint(&mut self, name: &str, v: Vec<u32>) -> PropertyAccessResult {
        self.take(name, &v)
    }
}

/// An element we do not read.
struct Skip;

impl PropertyAccess for Skip {
    fn new() -> Self {
        Skip
    }
}

fn malformed(path: &str, line: Option<usize>, message: String) -> MeshError {
    MeshError::Malformed {
        path: path.to_string(),
        line,
        format: "PLY",
        message,
    }
}

/// The vertices, normals and fanned triangles of a PLY file's bytes.
pub fn read(bytes: &[u8], path: &str) -> Result<Raw, MeshError> {
    let crate_error = |e: ply_rs_bw::parser::ParseError| malformed(path, e.line(), e.to_string());
    let mut reader = Reader::new(std::io::BufReader::new(bytes));
    let header = Parser::<Skip>::new()
        .read_header(&mut reader)
        .map_err(crate_error)?;
    let mut raw = Raw::default();
    let mut faces: Vec<Face> = Vec::new();
    for def in header.elements.values() {
        match def.name.as_str() {
            "vertex" => {
                let vs = Parser::<Vertex>::new()
                    .read_payload_for_element(&mut reader, def, &header)
                    .map_err(crate_error)?;
                if let Some(k) = vs.iter().position(|v| v.seen & 7 != 7) {
                    return Err(malformed(path, None, format!("vertex {k} lacks x, y or z")));
                }
                raw.positions = vs.iter().map(|v| DVec3::from_array(v.p)).collect();
                if vs.iter().all(|v| v.seen >> 3 == 7) {
                    raw.normals = vs.iter().map(|v| DVec3::from_array(v.n)).collect();
                }
            }
            "face" => {
                faces = Parser::<Face>::new()
                    .read_payload_for_element(&mut reader, def, &header)
                    .map_err(crate_error)?;
            }
            _ => {
                Parser::<Skip>::new()
                    .read_payload_for_element(&mut reader, def, &header)
                    .map_err(crate_error)?;
            }
        }
    }
    let vertices = raw.positions.len();
    for (k, face) in faces.iter().enumerate() {
        if face.bad {
            return Err(malformed(
                path,
                None,
                format!("face {k} has a negative vertex index"),
            ));
        }
        raw.fan(&face.indices, vertices)
            .map_err(|why| malformed(path, None, format!("face {k}: {why}")))?;
        if raw.over_limit() {
            break;
        }
    }
    Ok(raw)
}
