//! The records `ply` reads one PLY element at a time into (`ply-rs-bw`'s
//! `PropertyAccess`): a vertex's position, normal, texture coordinates (`u v`, `s t` or
//! `texture_u texture_v`) and colour (`red green blue`: 8-bit values over 255, 16-bit
//! over 65535, floats as they are); a face's or strip's vertex index list (any integer
//! type, kept signed for strips' −1); and `Skip` for elements the tracer does not read.

use ply_rs_bw::ply::{PropertyAccess, PropertyAccessResult};

/// The vertex properties read, by slot: x y z, nx ny nz, u v, red green blue.
pub fn vertex_slot(name: &str) -> Option<usize> {
    Some(match name {
        "x" => 0,
        "y" => 1,
        "z" => 2,
        "nx" => 3,
        "ny" => 4,
        "nz" => 5,
        "u" | "s" | "texture_u" => 6,
        "v" | "t" | "texture_v" => 7,
        "red" => 8,
        "green" => 9,
        "blue" => 10,
        _ => return None,
    })
}

/// One vertex: its slots and which were seen.
#[derive(Default)]
pub struct Vertex {
    /// The values by slot (`vertex_slot`).
    pub values: [f64; 11],
}

impl Vertex {
    fn set(&mut self, name: &str, v: f64, colour_scale: f64) -> PropertyAccessResult {
        match vertex_slot(name) {
            Some(slot) => {
                self.values[slot] = if slot >= 8 { v / colour_scale } else { v };
                PropertyAccessResult::Set
            }
            None => PropertyAccessResult::Ignored,
        }
    }
}

impl PropertyAccess for Vertex {
    fn new() -> Self {
        Vertex::default()
    }
    fn set_char(&mut self, name: &str, v: i8) -> PropertyAccessResult {
        self.set(name, f64::from(v), 127.0)
    }
    fn set_uchar(&mut self, name: &str, v: u8) -> PropertyAccessResult {
        self.set(name, f64::from(v), 255.0)
    }
    fn set_short(&mut self, name: &str, v: i16) -> PropertyAccessResult {
        self.set(name, f64::from(v), 32767.0)
    }
    fn set_ushort(&mut self, name: &str, v: u16) -> PropertyAccessResult {
        self.set(name, f64::from(v), 65535.0)
    }
    fn set_int(&mut self, name: &str, v: i32) -> PropertyAccessResult {
        self.set(name, f64::from(v), 1.0)
    }
    fn set_uint(&mut self, name: &str, v: u32) -> PropertyAccessResult {
        self.set(name, f64::from(v), 1.0)
    }
    fn set_float(&mut self, name: &str, v: f32) -> PropertyAccessResult {
        self.set(name, f64::from(v), 1.0)
    }
    fn set_double(&mut self, name: &str, v: f64) -> PropertyAccessResult {
        self.set(name, v, 1.0)
    }
}

/// True for the name of a face's or strip's index list.
pub fn is_index_list(name: &str) -> bool {
    name == "vertex_indices" || name == "vertex_index"
}

/// A face's or strip's vertex indices, as written: the list `ply_rs_bw` read, kept as
/// it came (no copy per face: a million-face file made three allocations a face).
#[derive(Default)]
pub struct Face {
    list: List,
}

/// An index list in its file's integer type.
#[derive(Default)]
enum List {
    #[default]
    None,
    I8(Vec<i8>),
    U8(Vec<u8>),
    I16(Vec<i16>),
    U16(Vec<u16>),
    I32(Vec<i32>),
    U32(Vec<u32>),
}

impl Face {
    /// Puts the indices, signed, into `out` (emptied first).
    pub fn indices(&self, out: &mut Vec<i64>) {
        out.clear();
        match &self.list {
            List::None => {}
            List::I8(v) => out.extend(v.iter().map(|&i| i64::from(i))),
            List::U8(v) => out.extend(v.iter().map(|&i| i64::from(i))),
            List::I16(v) => out.extend(v.iter().map(|&i| i64::from(i))),
            List::U16(v) => out.extend(v.iter().map(|&i| i64::from(i))),
            List::I32(v) => out.extend(v.iter().map(|&i| i64::from(i))),
            List::U32(v) => out.extend(v.iter().map(|&i| i64::from(i))),
        }
    }

    fn take(&mut self, name: &str, list: List) -> PropertyAccessResult {
        if !is_index_list(name) {
            return PropertyAccessResult::Ignored;
        }
        self.list = list;
        PropertyAccessResult::Set
    }
}

impl PropertyAccess for Face {
    fn new() -> Self {
        Face::default()
    }
    fn set_list_char(&mut self, name: &str, v: Vec<i8>) -> PropertyAccessResult {
        self.take(name, List::I8(v))
    }
    fn set_list_uchar(&mut self, name: &str, v: Vec<u8>) -> PropertyAccessResult {
        self.take(name, List::U8(v))
    }
    fn set_list_short(&mut self, name: &str, v: Vec<i16>) -> PropertyAccessResult {
        self.take(name, List::I16(v))
    }
    fn set_list_ushort(&mut self, name: &str, v: Vec<u16>) -> PropertyAccessResult {
        self.take(name, List::U16(v))
    }
    fn set_list_int(&mut self, name: &str, v: Vec<i32>) -> PropertyAccessResult {
        self.take(name, List::I32(v))
    }
    fn set_list_uint(&mut self, name: &str, v: Vec<u32>) -> PropertyAccessResult {
        self.take(name, List::U32(v))
    }
}

/// An element the tracer does not read.
pub struct Skip;

impl PropertyAccess for Skip {
    fn new() -> Self {
        Skip
    }
}
