//! Writes a finely tessellated torus as a binary PLY (with ply-rs-bw, the crate the
//! tracer reads PLY with): the mesh of the performance goal, a million triangles by
//! default, with a unit normal per vertex (smooth shading).
//!
//!     cargo run --release --features examples --example torus_ply -- OUT.ply [MAJOR_STEPS MINOR_STEPS]
//!
//! A torus of radii 1 and 0.4 about the y axis, MAJOR_STEPS × MINOR_STEPS quads (default
//! 1000 × 500) cut into two triangles each: 2 · MAJOR_STEPS · MINOR_STEPS triangles.

use ply_rs_bw::ply::{
    Addable, ElementDef, Encoding, Ply, PropertyAccess, PropertyDef, PropertyType, ScalarType,
};
use ply_rs_bw::writer::Writer;
use std::f64::consts::TAU;

/// A vertex or a face (the writer takes one element type for the whole file).
#[derive(Default)]
struct El {
    v: [f32; 6],
    face: Vec<u32>,
}

impl PropertyAccess for El {
    fn new() -> Self {
        El::default()
    }
    fn get_float(&self, name: &str) -> Option<f32> {
        let k = ["x", "y", "z", "nx", "ny", "nz"]
            .iter()
            .position(|&n| n == name)?;
        Some(self.v[k])
    }
    fn get_list_uint(&self, name: &str) -> Option<&[u32]> {
        (name == "vertex_indices").then_some(&self.face[..])
    }
}

fn main() -> std::io::Result<()> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let out = args
        .first()
        .expect("usage: torus_ply OUT.ply [MAJOR_STEPS MINOR_STEPS]");
    let steps = |i: usize, d: u32| args.get(i).map_or(d, |s| s.parse().expect("a count"));
    let (nu, nv) = (steps(1, 1000), steps(2, 500));
    let (big, small) = (1.0f64, 0.4f64);
    let mut ply = Ply::<El>::new();
    ply.header.encoding = Encoding::BinaryLittleEndian;
    let mut vertex = ElementDef::new("vertex".to_string());
    for name in ["x", "y", "z", "nx", "ny", "nz"] {
        let def = PropertyDef::new(name.to_string(), PropertyType::Scalar(ScalarType::Float));
        vertex.properties.add(def);
    }
    let mut face = ElementDef::new("face".to_string());
    let list = PropertyType::List(ScalarType::UChar, ScalarType::UInt);
    face.properties
        .add(PropertyDef::new("vertex_indices".to_string(), list));
    ply.header.elements.add(vertex);
    ply.header.elements.add(face);
    let mut vertices = Vec::with_capacity((nu * nv) as usize);
    for i in 0..nu {
        let u = TAU * f64::from(i) / f64::from(nu);
        for j in 0..nv {
            let w = TAU * f64::from(j) / f64::from(nv);
            let n = [u.cos() * w.cos(), w.sin(), u.sin() * w.cos()];
            let p = [
                (big + small * w.cos()) * u.cos(),
                small * w.sin(),
                (big + small * w.cos()) * u.sin(),
            ];
            let v = [p[0], p[1], p[2], n[0], n[1], n[2]].map(|c| c as f32);
            vertices.push(El {
                v,
                face: Vec::new(),
            });
        }
    }
    let at = |i: u32, j: u32| (i % nu) * nv + (j % nv);
    let mut faces = Vec::with_capacity(2 * (nu * nv) as usize);
    for i in 0..nu {
        for j in 0..nv {
            let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
            faces.push(El {
                v: [0.0; 6],
                face: vec![a, c, b],
            });
            faces.push(El {
                v: [0.0; 6],
                face: vec![a, d, c],
            });
        }
    }
    ply.payload.insert("vertex".to_string(), vertices);
    ply.payload.insert("face".to_string(), faces);
    let mut file = std::io::BufWriter::new(std::fs::File::create(out)?);
    Writer::new().write_ply(&mut file, &mut ply)?;
    eprintln!("{out}: {} triangles", 2 * nu * nv);
    Ok(())
}
