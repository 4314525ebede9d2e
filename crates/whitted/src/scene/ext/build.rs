//! Drawn objects from the extension's shape records (SPEC §16): each `ExtObject` becomes
//! one `Object` and its `ShapeSpec::Ext`, in file order, after the report's objects. A
//! sphere without modifiers stays the report's sphere (and joins the spheres' tree);
//! planes and triangles take their frame by moving their points; every other shape is a
//! `Placed` shape in its frame (scale, then rotate x, y, z in degrees, then translate).
//! A CSG block becomes one object (`csg`), its children drawn in the block's frame.
//!
//! Not built yet: meshes, refused with a located error naming them.

use super::{ExtItem, ExtObject, ExtShape, Extension, Modifiers};
use crate::object::Object;
use crate::scene::{FileLoc, SceneError, ShapeSpec};
use crate::shapes::{
    AaBox, Capped, Disc, Frame, Local, Placed, Plane, Shape, Sphere, Torus, Triangle,
};
use glam::DVec3;

/// The objects of `ext.objects`, in file order, each with its spec (`item` is its index
/// in `ext.objects`: what `Scene::object_names` looks its `name` up by).
pub fn objects(ext: &Extension) -> Result<Vec<(Object, ShapeSpec)>, SceneError> {
    let mut out = Vec::with_capacity(ext.objects.len());
    for (item, obj) in ext.objects.iter().enumerate() {
        match obj {
            ExtItem::Shape(o) => {
                let shape = shape(o)?;
                let spec = ShapeSpec::Ext {
                    item: item as u32,
                    kind: o.shape.keyword(),
                    shape: shape.clone(),
                    anchor: anchor(&o.shape, &o.mods),
                };
                let object = Object {
                    shape,
                    texture: o.texture,
                    material: o.material,
                };
                out.push((object, spec));
            }
            ExtItem::Csg(c) => {
                let (object, anchor) = csg::object(c)?;
                let spec = ShapeSpec::Ext {
                    item: item as u32,
                    kind: "csg",
                    shape: object.shape.clone(),
                    anchor,
                };
                out.push((object, spec));
            }
        }
    }
    Ok(out)
}

pub(super) fn refused(loc: &FileLoc, what: &str, message: &str) -> SceneError {
    SceneError::Syntax {
        loc: loc.clone(),
        message: message.to_string(),
        context: format!("the `{what}` record"),
    }
}

/// The frame the modifiers give (the identity without any).
pub fn frame(m: &Modifiers) -> Option<Frame> {
    if !m.has_transform() {
        return Some(Frame::IDENTITY);
    }
    Frame::new(
        m.scale.unwrap_or(DVec3::ONE),
        m.rotate.unwrap_or(DVec3::ZERO),
        m.translate.unwrap_or(DVec3::ZERO),
    )
}

/// The point a camera looks at for this object: its defining centre, moved by its frame.
pub(super) fn anchor(s: &ExtShape, m: &Modifiers) -> DVec3 {
    let p = match *s {
        ExtShape::Sphere { center, .. }
        | ExtShape::Disc { center, .. }
        | ExtShape::Torus { center, .. } => center,
        ExtShape::Plane { point, .. } => point,
        ExtShape::Box { min, max } => 0.5 * (min + max),
        ExtShape::Cylinder { a, b, .. } | ExtShape::Cone { a, b, .. } => 0.5 * (a + b),
        ExtShape::Triangle { corners: [a, b, c] } => (a + b + c) / 3.0,
        ExtShape::Mesh { .. } => DVec3::ZERO,
    };
    frame(m).map_or(p, |f| f.point_to_world(p))
}

/// The drawn shape of one record (its bounds were checked by the reader; what still
/// fails here, e.g. a frame that rounding made singular, is a located error).
pub fn shape(o: &ExtObject) -> Result<Shape, SceneError> {
    shape_in(o, &Frame::IDENTITY)
}

/// `shape`, its frame followed by `outer` (the frame of the CSG blocks around it).
pub(super) fn shape_in(o: &ExtObject, outer: &Frame) -> Result<Shape, SceneError> {
    let bad = |why: &str| refused(&o.loc, o.shape.keyword(), why);
    let singular = || bad("the scale, rotate and translate make a singular frame");
    let own = frame(&o.mods).ok_or_else(singular)?;
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
        ExtShape::Sphere { center, radius } => {
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
        ExtShape::Plane { point, normal } => {
            let n =
                crate::scene::direction(normal).ok_or_else(|| bad("the normal has zero length"))?;
            let p = f.point_to_world(point);
            let n = f.normal_to_world(n.normalize());
            Ok(Shape::Plane(Plane::new(p, n)))
        }
        ExtShape::Box { min, max } => placed(AaBox::new(min, max).map(Local::Box)),
        ExtShape::Cylinder { a, b, radius } => {
            placed(Capped::new(a, radius, b, radius, !o.mods.open).map(Local::Capped))
        }
        ExtShape::Cone { a, ra, b, rb } => {
            placed(Capped::new(a, ra, b, rb, !o.mods.open).map(Local::Capped))
        }
        ExtShape::Disc {
            center,
            normal,
            radius,
            hole,
        } => placed(Disc::new(center, normal, radius, hole).map(Local::Disc)),
        ExtShape::Torus {
            center,
            axis,
            major,
            minor,
        } => placed(Torus::new(center, axis, major, minor).map(Local::Torus)),
        ExtShape::Triangle { corners } => {
            let [a, b, c] = corners.map(|p| f.point_to_world(p));
            Triangle::new(a, b, c)
                .map(Shape::Triangle)
                .ok_or_else(|| bad("the triangle is degenerate"))
        }
        ExtShape::Mesh { .. } => Err(bad("meshes are not drawn yet")),
    }
}

#[path = "build_csg.rs"]
mod csg;

#[cfg(test)]
#[path = "build_tests.rs"]
mod tests;
