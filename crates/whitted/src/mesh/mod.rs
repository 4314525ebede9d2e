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

pub mod extra;
mod load;
#[cfg(feature = "mesh")]
mod mtl;
pub mod normals;
#[cfg(feature = "mesh")]
mod obj;
#[cfg(feature = "mesh")]
mod obj_scan;
#[cfg(feature = "mesh")]
mod ply;
#[cfg(feature = "mesh")]
mod ply_records;
mod raw;
mod surface;

pub use load::place;
pub use raw::{Look, Raw, RECORD_LOOK};

use crate::limits::MAX_MESH_TRIANGLES;
use crate::optics::Ray;
use crate::shapes::Triangle;
use glam::DVec3;

/// Why a mesh file could not be drawn; every message starts with the file's name (and
/// `:line` where known).
#[derive(Debug, thiserror::Error)]
pub enum MeshError {
    /// This build of the tracer reads no mesh files (its `mesh` feature is off).
    #[error("{path}: this build reads no mesh files (the tracer's `mesh` feature)")]
    NotBuilt {
        /// The file as the record resolved it.
        path: String,
    },
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
    /// No triangle at all, and why (no faces, faces of fewer than three corners, …).
    #[error("{path}: the mesh has no triangle: {why}")]
    Empty {
        /// The file.
        path: String,
        /// The cause, in the file's terms.
        why: String,
    },
    /// Triangles, but none of non-zero area.
    #[error("{path}: the mesh has no triangle of non-zero area (its {count} triangles are all degenerate)")]
    Degenerate {
        /// The file.
        path: String,
        /// How many triangles the file gave.
        count: usize,
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

/// `pivot` (SPEC §18): the point of the file that becomes the mesh's origin.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Pivot {
    /// `pivot center`: the centre of the mesh's bounds.
    Center,
    /// `pivot x y z`: a point in the file's units.
    Point(DVec3),
}

/// `fit Size` and `pivot` of a mesh record: applied to the file's vertices before the
/// record's `scale`, `rotate` and `translate` (`load::place`).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Placing {
    /// `fit Size`: a uniform scale about the bounds' centre making the largest side Size.
    pub fit: Option<f64>,
    /// `pivot`: the point moved to the origin (after `fit`).
    pub pivot: Option<Pivot>,
}

/// The crease angle of a mesh file without normals and without `smooth` or `flat`.
pub const DEFAULT_SMOOTH: f64 = 30.0;

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
    /// One (u, v) per vertex (the file's `vt`, PLY `u v`), or none.
    pub uvs: Vec<[f64; 2]>,
    /// One colour per vertex (OBJ `v x y z r g b`, PLY `red green blue`), or none.
    pub colors: Vec<DVec3>,
    /// The file's materials (`.mtl`).
    pub looks: Vec<Look>,
    /// One entry of `looks` per triangle (`RECORD_LOOK`: the record's), or none.
    pub face_looks: Vec<u32>,
    /// What the file holds and the tracer does not use, one line per kind.
    pub warnings: Vec<String>,
    /// The SHA-256 of the file it was read from (zeros for one made in memory).
    pub source: [u8; 32],
    /// Camera rays do not see its back faces (a glTF material that is not
    /// `doubleSided`); false for every other mesh, whose triangles are two-sided.
    pub single_sided: bool,
    /// A glTF primitive's coverage and emissive texture (`extra`), when its material
    /// has either; `None` for every other mesh.
    pub extra: Option<std::sync::Arc<extra::Extra>>,
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

#[cfg(all(test, feature = "mesh"))]
mod data_tests;
#[cfg(all(test, feature = "mesh"))]
mod tests;
