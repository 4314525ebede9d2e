//! Vertex normals computed from a mesh's faces (SPEC §18's `smooth Angle`): each corner
//! of a face takes the sum of the unit normals of the faces in its smoothing group at
//! that vertex, each weighted by the face's angle at the vertex, normalised.
//!
//! A smoothing group is split at creases: two faces that share an edge are joined across
//! it when exactly two faces share that edge and their normals are at most Angle apart;
//! the faces around a vertex that such joins connect (walking from face to face across
//! the vertex's edges) form one group. Vertices are compared by position (welded), so
//! the copies a file makes of a vertex for its texture coordinates or colours smooth
//! together. An edge of three or more faces, or faces that only touch at the vertex, are
//! creases.
//!
//! Time: near-linear at any vertex valence. Edges are bucketed by their lower vertex
//! (a counting sort), each bucket sorted by the other end (n log n in a fan of 300 k
//! faces around one vertex), and the joins merge corners in a union-find.

use glam::DVec3;
use std::collections::HashMap;

/// A mesh's triangles re-indexed so that each vertex has one normal: a vertex whose
/// corners fall in several smoothing groups is copied once per group.
#[derive(Clone, Debug, PartialEq)]
pub struct Smoothed {
    /// The triangles, indexing the new vertices.
    pub triangles: Vec<[u32; 3]>,
    /// The unit normal of each new vertex.
    pub normals: Vec<DVec3>,
    /// For each new vertex, the vertex of the input it copies.
    pub origin: Vec<u32>,
}

/// Each vertex's welded id: the first vertex of the same position (−0 and +0 equal),
/// found by sorting the vertices by position (no hash a file could flood).
fn weld(vertices: &[DVec3]) -> Vec<u32> {
    let key = |i: u32| {
        (vertices[i as usize] + DVec3::ZERO)
            .to_array()
            .map(f64::to_bits)
    };
    let mut order: Vec<([u64; 3], u32)> = (0..vertices.len() as u32).map(|i| (key(i), i)).collect();
    order.sort_unstable();
    let mut welded = vec![0u32; vertices.len()];
    let mut first = 0;
    for k in 0..order.len() {
        if order[k].0 != order[first].0 {
            first = k;
        }
        welded[order[k].1 as usize] = order[first].1;
    }
    welded
}

/// The angle between `u` and `v` (robust near 0 and π).
fn angle(u: DVec3, v: DVec3) -> f64 {
    u.cross(v).length().atan2(u.dot(v))
}

/// A face's unit normal and its angles at its three corners (the face has non-zero area).
pub fn face(a: DVec3, b: DVec3, c: DVec3) -> (DVec3, [f64; 3]) {
    let n = (b - a).cross(c - a).normalize_or_zero();
    (
        n,
        [
            angle(b - a, c - a),
            angle(c - b, a - b),
            angle(a - c, b - c),
        ],
    )
}

/// Whether two faces of unit normals `n` and `m` are joined at `cos_max` (the cosine of
/// the crease angle; −1 or less joins any two).
#[inline]
pub fn joined(n: DVec3, m: DVec3, cos_max: f64) -> bool {
    cos_max <= -1.0 || n.dot(m) >= cos_max
}

/// The union-find root of `x`, halving the path.
fn find(parent: &mut [u32], mut x: u32) -> u32 {
    while parent[x as usize] != x {
        let up = parent[parent[x as usize] as usize];
        parent[x as usize] = up;
        x = up;
    }
    x
}

/// Sorts `v` ascending: by insertion where it is short (a vertex's few edges; the
/// standard sort's set-up cost more than the sorting on a million-triangle mesh), by
/// `sort_unstable` otherwise. The entries are distinct, so the order is the same.
fn sort_small(v: &mut [(u32, u32)]) {
    if v.len() > 16 {
        v.sort_unstable();
        return;
    }
    for i in 1..v.len() {
        let x = v[i];
        let mut j = i;
        while j > 0 && v[j - 1] > x {
            v[j] = v[j - 1];
            j -= 1;
        }
        v[j] = x;
    }
}

/// The smooth normals of the triangles (of non-zero area) over `vertices`, split where
/// faces meet at more than `angle_deg` degrees.
pub fn smooth(vertices: &[DVec3], triangles: &[[u32; 3]], angle_deg: f64) -> Smoothed {
    let cos_max = if angle_deg >= 180.0 {
        -1.0
    } else {
        angle_deg.to_radians().cos()
    };
    let welded = weld(vertices);
    let w = |i: u32| welded[i as usize];
    let faces: Vec<(DVec3, [f64; 3])> = triangles
        .iter()
        .map(|t| {
            let [a, b, c] = t.map(|i| vertices[i as usize]);
            face(a, b, c)
        })
        .collect();
    // Edges (lo, hi, corner of lo's side) bucketed by lo.
    let mut start = vec![0u32; vertices.len() + 1];
    for t in triangles {
        for k in 0..3 {
            let (a, b) = (w(t[k]), w(t[(k + 1) % 3]));
            start[a.min(b) as usize + 1] += 1;
        }
    }
    for i in 0..vertices.len() {
        start[i + 1] += start[i];
    }
    let mut fill = start.clone();
    // (hi, face * 3 + k): the edge from corner k to corner k + 1 of face.
    let mut edges = vec![(0u32, 0u32); triangles.len() * 3];
    for (f, t) in triangles.iter().enumerate() {
        for k in 0..3 {
            let (a, b) = (w(t[k]), w(t[(k + 1) % 3]));
            let slot = &mut fill[a.min(b) as usize];
            edges[*slot as usize] = (a.max(b), (f * 3 + k) as u32);
            *slot += 1;
        }
    }
    let mut parent: Vec<u32> = (0..triangles.len() as u32 * 3).collect();
    let union = |parent: &mut Vec<u32>, x: u32, y: u32| {
        let (rx, ry) = (find(parent, x), find(parent, y));
        parent[rx.max(ry) as usize] = rx.min(ry);
    };
    let corner_at = |f: u32, v: u32| {
        let t = triangles[f as usize];
        let k = (0..3)
            .find(|&k| w(t[k]) == v)
            .expect("an edge's end is a corner");
        f * 3 + k as u32
    };
    for lo in 0..vertices.len() {
        let bucket = &mut edges[start[lo] as usize..start[lo + 1] as usize];
        sort_small(bucket);
        let mut i = 0;
        while i < bucket.len() {
            let mut j = i + 1;
            while j < bucket.len() && bucket[j].0 == bucket[i].0 {
                j += 1;
            }
            if j - i == 2 {
                let (hi, f, g) = (bucket[i].0, bucket[i].1 / 3, bucket[i + 1].1 / 3);
                if joined(faces[f as usize].0, faces[g as usize].0, cos_max) {
                    for v in [lo as u32, hi] {
                        union(&mut parent, corner_at(f, v), corner_at(g, v));
                    }
                }
            }
            i = j;
        }
    }
    // Each corner's root: the least corner of its group (a union points the greater root
    // at the lesser, and halving a path only moves a corner's parent lower).
    for c in 0..parent.len() as u32 {
        parent[c as usize] = find(&mut parent, c);
    }
    // Each group's angle-weighted sum, the groups numbered in the order of their roots
    // (in corner order a group's root comes first). Each corner's parent becomes its
    // group's number (a root's is written before any other corner of its group reads
    // it), and `roots` keeps each group's root: its face's normal stands in for a sum of
    // zero. The sums are those the roots' own slots kept before, in the same order.
    let (mut sums, mut roots) = (Vec::new(), Vec::new());
    for c in 0..parent.len() as u32 {
        let r = parent[c as usize];
        let g = if r == c {
            sums.push(DVec3::ZERO);
            roots.push(r);
            roots.len() as u32 - 1
        } else {
            parent[r as usize]
        };
        parent[c as usize] = g;
        let (n, angles) = faces[c as usize / 3];
        sums[g as usize] += angles[c as usize % 3] * n;
    }
    // One new vertex per (input vertex, group), in corner order.
    let mut first: Vec<Option<(u32, u32)>> = vec![None; vertices.len()];
    let mut more: HashMap<(u32, u32), u32> = HashMap::new();
    let mut out = Smoothed {
        triangles: Vec::with_capacity(triangles.len()),
        normals: Vec::with_capacity(vertices.len()),
        origin: Vec::with_capacity(vertices.len()),
    };
    for (f, t) in triangles.iter().enumerate() {
        let mut tri = [0u32; 3];
        for k in 0..3 {
            let (v, r) = (t[k], parent[f * 3 + k]);
            let add = |out: &mut Smoothed| {
                let n = sums[r as usize]
                    .try_normalize()
                    .unwrap_or(faces[roots[r as usize] as usize / 3].0);
                out.normals.push(n);
                out.origin.push(v);
                out.normals.len() as u32 - 1
            };
            tri[k] = match first[v as usize] {
                None => {
                    let id = add(&mut out);
                    first[v as usize] = Some((r, id));
                    id
                }
                Some((r0, id)) if r0 == r => id,
                Some(_) => *more.entry((v, r)).or_insert_with(|| add(&mut out)),
            };
        }
        out.triangles.push(tri);
    }
    out
}

#[cfg(test)]
#[path = "normals_tests.rs"]
mod tests;
