//! Triangle meshes from files (SPEC §16's `mesh "file" TEXTURE MATERIAL`): one loader per
//! format behind one interface (`obj`: Wavefront OBJ through `tobj`; `ply`: PLY, ASCII
//! and binary, through `ply-rs-bw`), chosen by the file's extension (`.obj`, `.ply`, any
//! case). A loader gives the file's vertices, its vertex normals when it has one for
//! every vertex, and its polygons fanned into triangles (v0, vi, vi+1). `Mesh::load` then
//! moves the vertices into the world by the record's frame (normals by the inverse
//! transpose), drops the triangles of zero area, and stores the rest compactly: three
//! indices into one shared vertex array per triangle.
//!
//! Shading (SPEC §18): a mesh is smooth (the barycentric interpolation of its corners'
//! normals, normalised: `SmoothTriangle`) with the file's vertex normals, or with normals
//! computed from its faces (`normals`: `smooth Angle`, and `smooth 30` for a file without
//! normals), or flat (`flat`: each face's own normal). The triangles are two-sided, as
//! every surface of the tracer is.
//!
//! Limits: the file's bytes (`limits::MAX_MESH_BYTES`) and its triangles after fanning
//! (`limits::MAX_MESH_TRIANGLES`). Every failure is a `MeshError` naming the mesh file
//! (and its line where the format has lines and the crate, or `obj`'s search, finds it).

pub mod normals;
mod obj;
mod ply;

use crate::limits::{MAX_MESH_BYTES, MAX_MESH_TRIANGLES};
use crate::optics::Ray;
use crate::shapes::{Frame, Shape, SmoothTriangle, Triangle};
use glam::DVec3;
use std::path::Path;

/// Why a mesh file could not be drawn; every message starts with the file's name (and
/// `:line` where known).
#[derive(Debug, thiserror::Error)]
pub enum MeshError {
    /// Missing, unreadable, not a regular file, or over `MAX_MESH_BYTES`.
    #[error("{path}: cannot read the mesh file: {source}")]
    Io {
        /// The file as the record resolved it.
        path: String,
        /// The system's reason.
        #[source]
        source: std::io::Error,
    },
    /// Neither `.obj` nor `.ply`.
    #[error("{path}: unknown mesh format (the file name must end in .obj or .ply)")]
    Format {
        /// The file.
        path: String,
    },
    /// The crate refused the file, or an index or number in it is out of range.
    #[error("{path}{}: malformed {format} file: {message}", line.map(|l| format!(":{l}")).unwrap_or_default())]
    Malformed {
        /// The file.
        path: String,
        /// Its 1-based line, where known.
        line: Option<usize>,
        /// `OBJ` or `PLY`.
        format: &'static str,
        /// The reason.
        message: String,
    },
    /// More triangles than `MAX_MESH_TRIANGLES` after fanning.
    #[error(
        "{path}: the mesh has {count} triangles or more, over the limit of {MAX_MESH_TRIANGLES}"
    )]
    TooMany {
        /// The file.
        path: String,
        /// How many were counted before the loader stopped.
        count: u64,
    },
    /// No triangle of non-zero area (or no triangle at all).
    #[error("{path}: the mesh has no triangle of non-zero area")]
    Degenerate {
        /// The file.
        path: String,
    },
}

/// How a mesh record asks for its normals (SPEC §18); without either, the file's normals,
/// or `Smooth(DEFAULT_SMOOTH)` for a file that has none.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Shading {
    /// `flat`: each face's own normal, even where the file has normals.
    Flat,
    /// `smooth Angle`: normals from the faces, split where faces meet at more than Angle
    /// degrees (0 < Angle ≤ 180).
    Smooth(f64),
}

/// The crease angle of a mesh file without normals and without `smooth` or `flat`.
pub const DEFAULT_SMOOTH: f64 = 30.0;

/// What a loader reads: positions, per-vertex normals (empty, or one per position) and
/// triangles (indices checked to be in range).
#[derive(Clone, Debug, Default)]
pub struct Raw {
    /// The vertices, in the file's own space.
    pub positions: Vec<DVec3>,
    /// One normal per vertex, or none.
    pub normals: Vec<DVec3>,
    /// The triangles, polygons fanned.
    pub triangles: Vec<[u32; 3]>,
}

impl Raw {
    /// Fans the polygon `face` (vertex indices) into triangles (v0, vi, vi+1), checking
    /// each index against `vertices` and the total against the limit. A face of fewer
    /// than three vertices adds nothing.
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

    /// True when the triangles are past the limit.
    pub fn over_limit(&self) -> bool {
        self.triangles.len() as u64 > MAX_MESH_TRIANGLES
    }
}

/// A mesh in world space: a shared vertex array, a normal per vertex (smooth) or none
/// (flat), and three vertex indices per triangle. (Its `Debug` gives the counts only.)
#[derive(Clone, Default, PartialEq)]
pub struct Mesh {
    /// The vertices, in the world.
    pub vertices: Vec<DVec3>,
    /// Unit normals, one per vertex; empty for a flat mesh.
    pub normals: Vec<DVec3>,
    /// The triangles of non-zero area, in file order.
    pub triangles: Vec<[u32; 3]>,
    /// The SHA-256 of the file it was read from (zeros for one made in memory).
    pub source: [u8; 32],
}

impl std::fmt::Debug for Mesh {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Mesh")
            .field("vertices", &self.vertices.len())
            .field("normals", &self.normals.len())
            .field("triangles", &self.triangles.len())
            .finish()
    }
}

impl Mesh {
    /// Reads the mesh file at `path`, places it by `frame` and shades it as `shading` asks
    /// (none: the file's normals, else `smooth 30`).
    pub fn load(path: &Path, frame: &Frame, shading: Option<Shading>) -> Result<Mesh, MeshError> {
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
        let raw = if ext == "obj" {
            obj::read(&bytes, &name)?
        } else {
            ply::read(&bytes, &name)?
        };
        if raw.over_limit() {
            let count = raw.triangles.len() as u64;
            return Err(MeshError::TooMany { path: name, count });
        }
        let mesh =
            Mesh::from_raw(raw, frame, shading).ok_or(MeshError::Degenerate { path: name })?;
        Ok(Mesh {
            source: crate::input::digest(&bytes),
            ..mesh
        })
    }

    /// The mesh of `raw` placed by `frame`, its zero-area triangles dropped, its normals
    /// as `shading` asks (computed in the world, after the frame); `None` when no
    /// triangle is left.
    pub fn from_raw(raw: Raw, frame: &Frame, shading: Option<Shading>) -> Option<Mesh> {
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
        let mut triangles = raw.triangles;
        triangles.retain(|&[a, b, c]| {
            Triangle::new(
                vertices[a as usize],
                vertices[b as usize],
                vertices[c as usize],
            )
            .is_some()
        });
        triangles.shrink_to_fit();
        if triangles.is_empty() {
            return None;
        }
        let angle = match (shading, normals.is_empty()) {
            (Some(Shading::Flat), _) => None,
            (Some(Shading::Smooth(a)), _) => Some(a),
            (None, true) => Some(DEFAULT_SMOOTH),
            (None, false) => {
                return Some(Mesh {
                    vertices,
                    normals,
                    triangles,
                    source: [0; 32],
                })
            }
        };
        let Some(angle) = angle else {
            return Some(Mesh {
                vertices,
                normals: Vec::new(),
                triangles,
                source: [0; 32],
            });
        };
        let s = normals::smooth(&vertices, &triangles, angle);
        Some(Mesh {
            vertices: s.origin.iter().map(|&o| vertices[o as usize]).collect(),
            normals: s.normals,
            triangles: s.triangles,
            source: [0; 32],
        })
    }

    /// The corners of triangle `k`.
    #[inline(always)]
    pub fn corners(&self, k: u32) -> [DVec3; 3] {
        let [a, b, c] = self.triangles[k as usize];
        let v = &self.vertices;
        [v[a as usize], v[b as usize], v[c as usize]]
    }

    /// Where the ray's line crosses triangle `k` (any sign), by `Triangle`'s own arithmetic.
    #[inline(always)]
    pub fn line_hit(&self, k: u32, ray: &Ray) -> Option<f64> {
        let [a, b, c] = self.corners(k);
        Triangle::uvt_of(a, b - a, c - a, ray).map(|(_, _, t)| t)
    }

    /// The hit on triangle `k` with `ray.t_min` < t < t_max, if any.
    #[inline(always)]
    pub fn hit(&self, k: u32, ray: &Ray, t_max: f64) -> Option<f64> {
        self.line_hit(k, ray)
            .filter(|&t| t > ray.t_min && t < t_max)
    }

    /// Triangle `k` as a shape of its own: smooth where the mesh has normals, flat
    /// otherwise (what shading asks for the normal at a hit).
    pub fn shape(&self, k: u32) -> Shape {
        let corners = self.corners(k);
        let flat = Triangle::new(corners[0], corners[1], corners[2])
            .expect("Mesh::from_raw keeps only triangles of non-zero area");
        if self.normals.is_empty() {
            return Shape::Triangle(flat);
        }
        let [a, b, c] = self.triangles[k as usize];
        let n = &self.normals;
        Shape::Smooth(SmoothTriangle {
            flat,
            normals: [n[a as usize], n[b as usize], n[c as usize]],
        })
    }

    /// The box of triangle `k`.
    #[inline]
    pub fn bounds(&self, k: u32) -> (DVec3, DVec3) {
        let [a, b, c] = self.corners(k);
        (a.min(b).min(c), a.max(b).max(c))
    }

    /// The box of the whole mesh (of its triangles' corners).
    pub fn extent(&self) -> (DVec3, DVec3) {
        (0..self.triangles.len() as u32).fold(
            (DVec3::INFINITY, DVec3::NEG_INFINITY),
            |(lo, hi), k| {
                let (a, b) = self.bounds(k);
                (lo.min(a), hi.max(b))
            },
        )
    }
}

#[cfg(test)]
mod tests;
