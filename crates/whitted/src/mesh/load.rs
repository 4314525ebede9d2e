//! A mesh file made into a `Mesh`: read by its loader (chosen by the extension), placed
//! in the world by the record's frame (normals by the inverse transpose), its zero-area
//! triangles dropped, its normals as the record asks (SPEC §18: the file's, `smooth
//! Angle` computed in the world, or `flat`), and each vertex's texture coordinates and
//! colour carried to the copies smoothing makes of it. `fit` and `pivot` (§18's placing)
//! move the file's vertices first, in its own units.

use super::{normals, Mesh, MeshError, Pivot, Placing, Raw, Shading, DEFAULT_SMOOTH};
use crate::limits::MAX_MESH_BYTES;
use crate::shapes::{Transform, Triangle};
use glam::DVec3;
use std::path::Path;

/// Applies `fit` and `pivot` to the file's vertices (in its own units): with f the fit's
/// scale (1 without) and c the centre of the triangles' bounds, p becomes c + f·(p − c)
/// without a pivot, and f·(p − q) with pivot q (c for `center`): the pivot, fitted, at
/// the origin. `Err` when `fit` meets a mesh of no extent.
pub fn place(raw: &mut Raw, placing: &Placing) -> Result<(), String> {
    if *placing == Placing::default() {
        return Ok(());
    }
    let (mut lo, mut hi) = (DVec3::INFINITY, DVec3::NEG_INFINITY);
    for t in &raw.triangles {
        for &i in t {
            let p = raw.positions[i as usize];
            (lo, hi) = (lo.min(p), hi.max(p));
        }
    }
    if raw.triangles.is_empty() {
        return Ok(());
    }
    let c = 0.5 * (lo + hi);
    let side = (hi - lo).max_element();
    let f = match placing.fit {
        Some(size) if side > 0.0 => size / side,
        Some(_) => return Err("fit: the mesh has no extent to scale".into()),
        None => 1.0,
    };
    let moved = |p: DVec3| match placing.pivot {
        None => c + f * (p - c),
        Some(Pivot::Center) => f * (p - c),
        Some(Pivot::Point(q)) => f * (p - q),
    };
    raw.positions.iter_mut().for_each(|p| *p = moved(*p));
    Ok(())
}

impl Mesh {
    /// Reads the mesh file at `path`, places it by `frame` and shades it as `shading` asks
    /// (none: the file's normals, else `smooth 30`).
    pub fn load(
        path: &Path,
        frame: &Transform,
        shading: Option<Shading>,
    ) -> Result<Mesh, MeshError> {
        Mesh::load_placed(path, frame, shading, &Placing::default())
    }

    /// `load`, the file's vertices first fitted and pivoted as `placing` asks.
    pub fn load_placed(
        path: &Path,
        frame: &Transform,
        shading: Option<Shading>,
        placing: &Placing,
    ) -> Result<Mesh, MeshError> {
        let name = path.display().to_string();
        let ext = path
            .extension()
            .and_then(|e| e.to_str())
            .map(str::to_ascii_lowercase);
        let ext = match ext.as_deref() {
            Some(e @ ("obj" | "ply")) => e.to_string(),
            _ => return Err(MeshError::Format { path: name }),
        };
        let bytes =
            crate::input::read_regular(path, MAX_MESH_BYTES, "mesh file").map_err(|source| {
                MeshError::Io {
                    path: name.clone(),
                    source,
                }
            })?;
        let mut raw = read(&ext, &bytes, &name, path)?;
        place(&mut raw, placing).map_err(|message| MeshError::Malformed {
            path: name.clone(),
            line: None,
            format: if ext == "obj" { "OBJ" } else { "PLY" },
            message,
        })?;
        if raw.over_limit() {
            let count = raw.triangles.len() as u64;
            return Err(MeshError::TooMany { path: name, count });
        }
        let count = raw.triangles.len();
        let mesh = Mesh::from_raw(raw, frame, shading)
            .ok_or(MeshError::Degenerate { path: name, count })?;
        Ok(Mesh {
            source: crate::input::digest(&bytes),
            ..mesh
        })
    }

    /// The mesh of `raw` placed by `frame`, its zero-area triangles dropped, its normals
    /// as `shading` asks (computed in the world, after the frame); `None` when no
    /// triangle is left.
    pub fn from_raw(raw: Raw, frame: &Transform, shading: Option<Shading>) -> Option<Mesh> {
        let vertices: Vec<DVec3> = raw
            .positions
            .iter()
            .map(|&p| frame.point_to_world(p))
            .collect();
        // A zero or non-finite normal makes its mesh flat: no corner is left without one.
        let normals: Vec<DVec3> = raw
            .normals
            .iter()
            .map_while(|&n| frame.normal_to_world(n).try_normalize())
            .collect();
        let normals = if normals.len() == vertices.len() {
            normals
        } else {
            Vec::new()
        };
        let keep: Vec<bool> = raw
            .triangles
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(|i| vertices[i as usize]);
                Triangle::new(a, b, c).is_some()
            })
            .collect();
        let kept = |k: &usize| keep[*k];
        let mut triangles: Vec<[u32; 3]> = (0..keep.len())
            .filter(kept)
            .map(|k| raw.triangles[k])
            .collect();
        let face_looks: Vec<u32> = (0..raw.face_looks.len().min(keep.len()))
            .filter(kept)
            .map(|k| raw.face_looks[k])
            .collect();
        if triangles.is_empty() {
            return None;
        }
        let mut mesh = Mesh {
            vertices,
            normals,
            triangles: Vec::new(),
            uvs: raw.uvs,
            colors: raw.colors,
            looks: raw.looks,
            face_looks,
            warnings: raw.warnings,
            source: [0; 32],
            single_sided: false,
            extra: None,
        };
        let angle = match (shading, mesh.normals.is_empty()) {
            (Some(Shading::Flat), _) => {
                mesh.normals.clear();
                None
            }
            (Some(Shading::Smooth(a)), _) => Some(a),
            (None, true) => Some(DEFAULT_SMOOTH),
            (None, false) => None,
        };
        if let Some(angle) = angle {
            let s = normals::smooth(&mesh.vertices, &triangles, angle);
            let copy = |o: &u32| *o as usize;
            mesh.vertices = s.origin.iter().map(|o| mesh.vertices[copy(o)]).collect();
            if !mesh.uvs.is_empty() {
                mesh.uvs = s.origin.iter().map(|o| mesh.uvs[copy(o)]).collect();
            }
            if !mesh.colors.is_empty() {
                mesh.colors = s.origin.iter().map(|o| mesh.colors[copy(o)]).collect();
            }
            mesh.normals = s.normals;
            triangles = s.triangles;
        }
        triangles.shrink_to_fit();
        mesh.triangles = triangles;
        Some(mesh)
    }
}

/// The file's own data, by its format (`ext`: `obj` or `ply`).
#[cfg(feature = "mesh")]
fn read(ext: &str, bytes: &[u8], name: &str, path: &Path) -> Result<Raw, MeshError> {
    if ext == "obj" {
        let dir = path.parent().unwrap_or(Path::new(""));
        super::obj::read(bytes, name, dir)
    } else {
        super::ply::read(bytes, name)
    }
}

/// A lean build (without the tracer's `mesh` feature) reads no mesh file.
#[cfg(not(feature = "mesh"))]
fn read(_ext: &str, _bytes: &[u8], name: &str, _path: &Path) -> Result<Raw, MeshError> {
    Err(MeshError::NotBuilt { path: name.into() })
}
