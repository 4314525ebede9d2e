//! Acceleration structures, built once per scene (in `Tracer::new`) and shared by every
//! frame and thread: a BVH over the spheres, a second BVH over the other bounded shapes
//! (an NFF's triangles and cones, the extension's shapes, and every triangle of every
//! mesh, stored as a small reference into its mesh; empty for a report scene) and plain
//! lists of the unbounded ones (planes, cylinders), which every query tests. Shadow rays
//! are `shadow`'s, nearest hits `nearest`'s; a leaf of triangles is first tested four at
//! a time in f32 lanes (`packet`), a filter that only spares the exact test the
//! triangles a ray clearly misses.
//!
//! Every query answers exactly what the linear scans over `Scene::objects` answer, bit for
//! bit (the linear versions are kept as the reference, and the tests compare them):
//! - `nearest`: the hit with the smallest t, and on equal t the object that comes first in
//!   the file, as the linear scan (which only replaces its best on a strictly smaller t)
//!   keeps it (on a mesh, one object, the triangle first in its file; a mesh is met only
//!   through the tree: its `Shape::Mesh` answers no ray by itself);
//! - `transmission`: black when an opaque object blocks the shadow ray, otherwise the
//!   product of `Kt·C` over the crossings of transparent objects, multiplied in object
//!   order and, within an object, in t order — the linear scan's order, so that the
//!   rounding of the product is the same.

mod bvh;
mod clearance;
mod dirgrid;
mod lightbuf;
mod nearest;
mod packet;
mod shadow;
mod shadow_cache;
mod tiles;
mod unique;

use bvh::Shaft;
pub use bvh::{Bounded, Bvh, Prim, ShapePrim};
pub use dirgrid::DirGrid;
pub use lightbuf::LightBuffer;
pub use tiles::{Hint, TileView};

use crate::mesh::Mesh;
use crate::object::Object;
use crate::optics::T_MIN;
use crate::shapes::{Shape, SmoothTriangle, Sphere};
use glam::DVec3;
use std::sync::Arc;

/// Up to this many transparent objects, shadow rays test them all in order after the
/// tree, as the linear scan does; past it they collect the crossings the tree finds.
const GLASS_LINEAR_MAX: usize = 4;
/// Crossings a shadow ray collects before it gives up and falls back to the linear loop
/// over every transparent object (no allocation either way).
const CROSSINGS_MAX: usize = 32;

/// The scene's objects sorted for fast ray queries.
#[derive(Clone, Debug, Default)]
pub struct Accel {
    /// Every bounded object: nearest hits, and shadow rays (which stop at the first
    /// opaque hit, and note the transparent crossings on the way).
    tree: Bvh,
    /// Every other bounded object (triangles, smooth triangles, cones, extension shapes)
    /// and every triangle of every mesh.
    shapes: Bvh<ShapePrim>,
    /// The shapes `shapes`' solo primitives name (`ShapePrim::part`).
    solo: Vec<Shape>,
    /// The triangles its `TRI` primitives name, in the tree's order (`in_tree_order`):
    /// corner A, then B − A and C − A, as `Triangle` holds them (the same test on the
    /// same numbers, without going through `Shape`: 72 bytes a triangle, read in the
    /// tree's leaves).
    tris: Vec<[DVec3; 3]>,
    /// The triangles of meshes its other primitives name (`ShapePrim::slot`), in the
    /// tree's order, as `tris` (B − A and C − A computed as `Mesh::line_hit` computes
    /// them): a leaf's are neighbours in memory, read without the vertex indices.
    mesh_tris: Vec<[DVec3; 3]>,
    /// Leaves of triangles rounded to f32 for the lanes' filter (`packet`), and for
    /// each of `shapes`' primitive slots the packet of the leaf starting there.
    packets: Vec<packet::TriPacket>,
    packet_at: Vec<u32>,
    /// The spheres its `SPHERE` primitives name, in the tree's order (`shares_tree`:
    /// empty when the spheres have a tree of their own).
    spheres: Vec<Sphere>,
    /// The scene's meshes (`Scene::meshes`; `ShapePrim::mesh` and `MeshRef::id` index it).
    meshes: Vec<Arc<Mesh>>,
    /// The scene's epsilon, given to the shadow rays (`Scene::t_min`).
    t_min: f64,
    /// Unbounded objects, in object order, with their indices.
    unbounded: Vec<(u32, Shape)>,
    unbounded_opaque: Vec<Shape>,
    unbounded_glass: Vec<u32>,
    /// Every object with Kt > 0, in object order.
    glass_all: Vec<u32>,
    /// Whether one of them is a mesh.
    glass_mesh: bool,
    /// This build's name in the threads' shadow caches (`shadow_cache`; 0 for none).
    id: u64,
    /// Whether shadow rays walk a tree (not only flat lists), where the shadow cache
    /// is worth its look-up.
    cached: bool,
}

/// A nearest hit: its t, its object and, on a mesh, the triangle (`NO_PART` elsewhere).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    /// The ray parameter.
    pub t: f64,
    /// The object's index in the scene.
    pub index: usize,
    /// The mesh triangle hit, or `NO_PART`.
    pub part: u32,
}

/// `Hit::part` of a hit on anything but a mesh.
pub const NO_PART: u32 = u32::MAX;

/// Kt > 0: shadow rays cross it (the linear scan's second loop).
fn is_glass(o: &Object) -> bool {
    o.material.kt > 0.0
}

/// A mesh some of whose triangles shadow rays cross: the record's Kt > 0 where a
/// triangle takes the record's material, a file material's (`.mtl` `d`) where it takes
/// its own; or a glTF mesh with coverage (MASK, BLEND), every triangle of which is
/// crossed, each crossing letting through what its point's alpha lets (`Mesh::filter`).
fn mesh_glass(o: &Object, mesh: &Mesh) -> bool {
    if mesh.face_looks.is_empty() {
        return is_glass(o) || mesh.has_coverage();
    }
    let glass = |k| mesh.face_material(k, &o.material).kt > 0.0;
    mesh.has_coverage() || (0..mesh.triangles.len() as u32).any(glass)
}

/// An object shadow rays may cross: Kt > 0, or a mesh with a triangle of Kt > 0.
fn glass_object(o: &Object, meshes: &[Arc<Mesh>]) -> bool {
    match o.shape {
        Shape::Mesh(m) => meshes
            .get(m.id as usize)
            .is_some_and(|mesh| mesh_glass(o, mesh)),
        _ => is_glass(o),
    }
}

/// Kt ≤ 0: it stops shadow rays (the linear scan's first loop). Not simply `!is_glass`:
/// an object with a NaN Kt is in neither loop.
fn is_opaque(o: &Object) -> bool {
    o.material.kt <= 0.0
}

/// `table` (the triangles or the spheres, as `kind` says) laid out in the order the
/// tree's leaves hold their primitives of that kind, which are renumbered to match: a
/// leaf's triangles are then neighbours in memory.
fn in_tree_order<T: Copy>(shapes: &mut Bvh<ShapePrim>, kind: u32, table: &[T]) -> Vec<T> {
    let mut ordered = Vec::with_capacity(table.len());
    for prim in shapes.prims_mut() {
        if prim.mesh == kind {
            ordered.push(table[prim.part as usize]);
            prim.part = (ordered.len() - 1) as u32;
        }
    }
    ordered
}

/// Whether the spheres go into the shapes' tree rather than a tree of their own: when
/// each kind is numerous enough for a tree (the SPD's rings and tree, where each
/// cylinder joins two spheres: walking two trees over the same space cost every ray two
/// descents, 21 to 24 % of their instructions). Balls, 7,381 spheres over a floor of two
/// triangles, counted 3 % more in one tree; a report scene (a flat list of spheres, no
/// other bounded shape) keeps its own path.
fn shares_tree(objects: &[Object]) -> bool {
    let (mut spheres, mut others) = (0, 0);
    for o in objects {
        match o.shape {
            Shape::Sphere(_) => spheres += 1,
            ref shape if shape.is_bounded() => others += 1,
            _ => {}
        }
    }
    spheres > bvh::FLAT_MAX && others > bvh::FLAT_MAX
}

impl Accel {
    /// Builds the accelerator over `objects` (a BVH over the spheres from 13 spheres up,
    /// shared with the other bounded shapes when those are many too; the unbounded
    /// shapes in a flat list), for rays with the report's epsilon.
    pub fn new(objects: &[Object]) -> Accel {
        Accel::with_t_min(objects, T_MIN)
    }

    /// The accelerator of `scene`'s objects and meshes, for rays with its epsilon.
    pub fn for_scene(scene: &crate::scene::Scene) -> Accel {
        Accel::with_meshes(&scene.objects, &scene.meshes, scene.t_min)
    }

    /// `new`, casting shadow rays with the epsilon `t_min` (`Scene::t_min`).
    pub fn with_t_min(objects: &[Object], t_min: f64) -> Accel {
        Accel::with_meshes(objects, &[], t_min)
    }

    /// `with_t_min` over objects that may hold meshes (`Shape::Mesh` ids index
    /// `meshes`; a mesh object whose id is past them hits nothing).
    pub fn with_meshes(objects: &[Object], meshes: &[Arc<Mesh>], t_min: f64) -> Accel {
        let mut solo = Vec::new();
        let mut tris = Vec::new();
        let mut spheres = Vec::new();
        let mut shapes: Vec<ShapePrim> = Vec::new();
        let unify = shares_tree(objects);
        // Which objects shadow rays may cross (a mesh's faces looked at once here).
        let glass: Vec<bool> = objects.iter().map(|o| glass_object(o, meshes)).collect();
        for (i, o) in objects.iter().enumerate() {
            let prim = |part: u32, mesh: u32| ShapePrim {
                index: i as u32,
                part,
                mesh,
                slot: 0,
                glass: is_glass(o),
                opaque: is_opaque(o),
            };
            match &o.shape {
                Shape::Sphere(sphere) if unify => {
                    shapes.push(prim(spheres.len() as u32, ShapePrim::SPHERE));
                    spheres.push(*sphere);
                }
                Shape::Sphere(_) => {}
                Shape::Mesh(m) => {
                    let Some(mesh) = meshes.get(m.id as usize) else {
                        continue;
                    };
                    // A glass mesh keeps its copies: each crossing of a shadow ray counts.
                    // Its triangles stop or cross shadow rays by their own Kt (`.mtl`).
                    let parts = if glass[i] {
                        (0..mesh.triangles.len() as u32).collect()
                    } else {
                        unique::triangles(mesh)
                    };
                    let covered = mesh.has_coverage();
                    shapes.extend(parts.into_iter().map(|k| {
                        let kt = mesh.face_material(k, &o.material).kt;
                        ShapePrim {
                            glass: kt > 0.0 || covered,
                            opaque: kt <= 0.0 && !covered,
                            ..prim(k, m.id)
                        }
                    }));
                }
                // A smooth triangle is hit as its flat one (`SmoothTriangle::hit`).
                Shape::Triangle(t) | Shape::Smooth(SmoothTriangle { flat: t, .. }) => {
                    shapes.push(prim(tris.len() as u32, ShapePrim::TRI));
                    tris.push([t.a, t.e1, t.e2]);
                }
                shape if shape.is_bounded() => {
                    shapes.push(prim(solo.len() as u32, ShapePrim::SOLO));
                    solo.push(shape.clone());
                }
                _ => {}
            }
        }
        let prims: Vec<Prim> = objects
            .iter()
            .enumerate()
            .filter_map(|(i, o)| match &o.shape {
                Shape::Sphere(sphere) if !unify => Some(Prim {
                    sphere: *sphere,
                    index: i as u32,
                    glass: is_glass(o),
                    opaque: is_opaque(o),
                }),
                _ => None,
            })
            .collect();
        let unbounded = |keep: &dyn Fn(&Object) -> bool| -> Vec<(u32, Shape)> {
            objects
                .iter()
                .enumerate()
                .filter(|(_, o)| !o.shape.is_bounded() && keep(o))
                .map(|(i, o)| (i as u32, o.shape.clone()))
                .collect()
        };
        // Leaves of triangles alone take four: the packets test four at once.
        let leaf_max = if shapes
            .iter()
            .all(|p| p.mesh != ShapePrim::SOLO && p.mesh != ShapePrim::SPHERE)
        {
            4
        } else {
            2
        };
        let mut shapes = Bvh::build_leaves(
            shapes,
            |p| {
                let (lo, hi) = if p.mesh == ShapePrim::SOLO {
                    solo[p.part as usize]
                        .bounds()
                        .expect("solo shapes are bounded")
                } else if p.mesh == ShapePrim::TRI {
                    let [a, e1, e2] = tris[p.part as usize];
                    let (b, c) = (a + e1, a + e2);
                    (a.min(b).min(c), a.max(b).max(c))
                } else if p.mesh == ShapePrim::SPHERE {
                    spheres[p.part as usize].bounds()
                } else {
                    meshes[p.mesh as usize].bounds(p.part)
                };
                (lo, hi, 0.5 * (lo + hi))
            },
            leaf_max,
        );
        let tris = in_tree_order(&mut shapes, ShapePrim::TRI, &tris);
        // Sized first: grown by doubling, a million triangles' 72 MB were copied and
        // their pages touched twice over.
        let mut mesh_tris =
            Vec::with_capacity(shapes.prims().iter().filter(|p| !p.is_own()).count());
        for prim in shapes.prims_mut().iter_mut().filter(|p| !p.is_own()) {
            let [a, b, c] = meshes[prim.mesh as usize].corners(prim.part);
            prim.slot = mesh_tris.len() as u32;
            mesh_tris.push([a, b - a, c - a]);
        }
        let spheres = in_tree_order(&mut shapes, ShapePrim::SPHERE, &spheres);
        let tree = Bvh::build(prims, Prim::bounds);
        let mut accel = Accel {
            id: shadow_cache::new_id(),
            cached: !tree.is_flat() || !shapes.is_flat(),
            tree,
            shapes,
            solo,
            tris,
            mesh_tris,
            spheres,
            meshes: meshes.to_vec(),
            t_min,
            unbounded: unbounded(&|_| true),
            unbounded_opaque: unbounded(&is_opaque).into_iter().map(|(_, s)| s).collect(),
            unbounded_glass: unbounded(&is_glass).into_iter().map(|(i, _)| i).collect(),
            glass_all: (0..objects.len() as u32)
                .filter(|&i| glass[i as usize])
                .collect(),
            glass_mesh: objects
                .iter()
                .zip(&glass)
                .any(|(o, &g)| g && matches!(o.shape, Shape::Mesh(_))),
            packets: Vec::new(),
            packet_at: Vec::new(),
        };
        accel.build_packets();
        accel
    }
}

#[cfg(test)]
mod grid_tests;

#[cfg(test)]
mod tests;

#[cfg(test)]
mod face_tests;
#[cfg(test)]
mod mesh_tests;
#[cfg(test)]
mod packet_tests;
