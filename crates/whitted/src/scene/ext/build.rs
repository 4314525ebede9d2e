//! Drawn objects from the extension's shape records (SPEC §16): each `ExtObject` becomes
//! one `Object` and its `ObjectSpec::Ext`, in file order, after the report's objects. A
//! sphere without modifiers stays the report's sphere (and joins the spheres' tree);
//! planes and triangles take their frame by moving their points; every other shape is a
//! `Placed` shape in its frame (scale, then rotate x, y, z in degrees, then translate).
//! A `mesh` is read from its file (`crate::mesh`), its vertices moved by its frame, and
//! becomes one object (`Shape::Mesh`, its box) whose triangles the scene keeps in
//! `Scene::meshes`; a file that cannot be drawn is an error at the record. A CSG block
//! becomes one object (`csg`), its children drawn in the block's frame.

use super::{ExtItem, ExtObject, Extension, Modifiers};
use crate::limits::MAX_SCENE_TRIANGLES;
use crate::mesh::Mesh;
use crate::object::Object;
use crate::scene::{FileLoc, ObjectSpec, Scene, SceneError, ShapeSpec};
use crate::shapes::{
    AaBox, Capped, Disc, Local, MeshRef, Placed, Plane, Shape, Sphere, Torus, Transform, Triangle,
};
use crate::texture::{MapKind, Texture};
use glam::DVec3;
use std::sync::Arc;

/// What the extension's records draw: the objects with their specs, and the meshes
/// their `Shape::Mesh` ids index.
#[derive(Debug, Default)]
pub struct Drawn {
    /// The objects, in file order, each with its spec.
    pub objects: Vec<(Object, ObjectSpec)>,
    /// The meshes, in file order.
    pub meshes: Vec<Arc<Mesh>>,
}

/// Draws `scene.ext`'s objects after the report's, and keeps their meshes.
pub fn draw(scene: &mut Scene) -> Result<(), SceneError> {
    let drawn = objects(&scene.ext)?;
    for (object, spec) in drawn.objects {
        scene.objects.push(object);
        scene.specs.push(spec);
    }
    scene.meshes = drawn.meshes;
    Ok(())
}

/// The objects of `ext.objects`, in file order, each with its spec (`item` is its index
/// in `ext.objects`: what `Scene::object_names` looks its `name` up by).
pub fn objects(ext: &Extension) -> Result<Drawn, SceneError> {
    let mut out = Drawn::default();
    for (item, obj) in ext.objects.iter().enumerate() {
        match obj {
            ExtItem::Shape(o) => {
                let (shape, anchor) = match &o.shape {
                    ShapeSpec::Mesh { path, .. } => {
                        let (handle, mesh) = mesh(o, path, out.meshes.len())?;
                        let before: u64 = out.meshes.iter().map(|m| m.triangles.len() as u64).sum();
                        let total = before + mesh.triangles.len() as u64;
                        if total > MAX_SCENE_TRIANGLES {
                            let why = format!(
                                "its {} triangles and the {before} of the meshes before it make {total}: a scene's meshes may have {MAX_SCENE_TRIANGLES} triangles in all",
                                mesh.triangles.len()
                            );
                            return Err(refused(&o.loc, "mesh", &why));
                        }
                        out.meshes.push(Arc::new(mesh));
                        (Shape::Mesh(handle), 0.5 * (handle.lo + handle.hi))
                    }
                    _ => (shape(o)?, anchor(o)),
                };
                let spec = ObjectSpec::Ext {
                    item: item as u32,
                    kind: o.shape.kind(),
                    anchor,
                };
                let object = Object {
                    shape,
                    texture: o.texture.clone(),
                    material: o.material,
                };
                out.objects.push((object, spec));
            }
            ExtItem::Csg(c) => {
                let (object, anchor) = csg::object(c)?;
                let spec = ObjectSpec::Ext {
                    item: item as u32,
                    kind: "csg",
                    anchor,
                };
                out.objects.push((object, spec));
            }
        }
    }
    Ok(out)
}

/// The mesh of a `mesh` record (the `id`-th of its scene) and its handle.
fn mesh(o: &ExtObject, path: &std::path::Path, id: usize) -> Result<(MeshRef, Mesh), SceneError> {
    let bad = |why: &str| refused(&o.loc, "mesh", why);
    let f = frame(&o.mods)
        .ok_or_else(|| bad("the scale, rotate and translate make a singular frame"))?;
    let mesh = Mesh::load_placed(path, &f, o.mods.shading, &o.mods.placing)
        .map_err(|e| bad(&e.to_string()))?;
    let uv = matches!(&o.texture, Texture::Image(i) if i.map == MapKind::Uv);
    if uv && mesh.uvs.is_empty() {
        return Err(bad(&format!(
            "{}: the uv map needs the file's texture coordinates (OBJ vt, PLY u v), and it has none",
            path.display()
        )));
    }
    let (lo, hi) = mesh.extent();
    let id = id as u32;
    Ok((MeshRef { id, lo, hi }, mesh))
}

pub(super) fn refused(loc: &FileLoc, what: &str, message: &str) -> SceneError {
    SceneError::Syntax {
        loc: loc.clone(),
        message: message.to_string(),
        context: format!("the `{what}` record"),
    }
}

/// The frame the modifiers give (the identity without any).
pub fn frame(m: &Modifiers) -> Option<Transform> {
    if !m.has_transform() {
        return Some(Transform::IDENTITY);
    }
    Transform::new(
        m.scale.unwrap_or(DVec3::ONE),
        m.rotate.unwrap_or(DVec3::ZERO),
        m.translate.unwrap_or(DVec3::ZERO),
    )
}

/// The point a camera looks at for this object: its defining centre, moved by its frame
/// (its placing included).
pub(super) fn anchor(o: &ExtObject) -> DVec3 {
    let p = o.shape.anchor();
    placed_frame(o).map_or(p, |f| f.point_to_world(p))
}

/// The frame of a record other than a mesh: its `fit` and `pivot` (`place::prefix`,
/// measured on the record as written), then its scale, rotate and translate.
fn placed_frame(o: &ExtObject) -> Result<Transform, SceneError> {
    let singular = || {
        refused(
            &o.loc,
            o.shape.kind(),
            "the scale, rotate and translate make a singular frame",
        )
    };
    let own = frame(&o.mods).ok_or_else(singular)?;
    if o.mods.placing == crate::mesh::Placing::default() {
        return Ok(own);
    }
    let written = ExtObject {
        mods: place::unplaced(&o.mods),
        ..o.clone()
    };
    let bounds = shape(&written)?.bounds();
    let before = place::prefix(&o.mods.placing, bounds, &o.loc, o.shape.kind())?;
    before.then(&own).ok_or_else(singular)
}

/// The drawn shape of one record (its bounds were checked by the reader; what still
/// fails here, e.g. a frame that rounding made singular, is a located error).
pub fn shape(o: &ExtObject) -> Result<Shape, SceneError> {
    shape_in(o, &Transform::IDENTITY)
}

/// `shape`, its frame followed by `outer` (the frame of the CSG blocks around it).
pub(super) fn shape_in(o: &ExtObject, outer: &Transform) -> Result<Shape, SceneError> {
    let bad = |why: &str| refused(&o.loc, o.shape.kind(), why);
    let singular = || bad("the scale, rotate and translate make a singular frame");
    let own = placed_frame(o)?;
    let f = if outer.is_identity() {
        own
    } else {
        own.then(outer).ok_or_else(singular)?
    };
    let placed = |local: Option<Local>| {
        local
            .map(|l| Shape::Placed(Placed::new(l, f)))
            .ok_or_else(|| bad("the shape's fields are out of bounds"))
    };
    match o.shape {
        ShapeSpec::Sphere { center, radius } => {
            if !(radius > 0.0 && radius.is_finite() && center.is_finite()) {
                return Err(bad("the radius must be greater than 0"));
            }
            let s = Sphere::new(center, radius);
            if f.is_identity() {
                Ok(Shape::Sphere(s))
            } else {
                placed(Some(Local::Sphere(s)))
            }
        }
        ShapeSpec::Plane { point, normal } => {
            let n =
                crate::scene::direction(normal).ok_or_else(|| bad("the normal has zero length"))?;
            let p = f.point_to_world(point);
            let n = f.normal_to_world(n.normalize());
            Ok(Shape::Plane(Plane::new(p, n)))
        }
        ShapeSpec::Box { min, max } => placed(AaBox::new(min, max).map(Local::Box)),
        ShapeSpec::Cylinder { a, b, radius } => {
            placed(Capped::new(a, radius, b, radius, !o.mods.open).map(Local::Capped))
        }
        ShapeSpec::Cone { a, ra, b, rb } => {
            placed(Capped::new(a, ra, b, rb, !o.mods.open).map(Local::Capped))
        }
        ShapeSpec::Disc {
            center,
            normal,
            radius,
            hole,
        } => placed(Disc::new(center, normal, radius, hole).map(Local::Disc)),
        ShapeSpec::Torus {
            center,
            axis,
            major,
            minor,
        } => placed(Torus::new(center, axis, major, minor).map(Local::Torus)),
        ShapeSpec::Triangle { corners } => {
            let [a, b, c] = corners.map(|p| f.point_to_world(p));
            Triangle::new(a, b, c)
                .map(Shape::Triangle)
                .ok_or_else(|| bad("the triangle is degenerate"))
        }
        ShapeSpec::Mesh { .. } | ShapeSpec::Gltf { .. } => {
            Err(bad("a mesh is drawn from its file by `objects`"))
        }
        // The report's and an NFF's own records, which no extension record gives.
        ShapeSpec::InfiniteCylinder { .. }
        | ShapeSpec::OpenCone { .. }
        | ShapeSpec::Patch { .. } => Err(bad("not a record of the extension")),
    }
}

#[path = "build_csg.rs"]
mod csg;
#[path = "build_lights.rs"]
mod lights;
pub use lights::lights;
#[path = "place.rs"]
mod place;

#[cfg(test)]
#[path = "build_tests.rs"]
mod tests;
