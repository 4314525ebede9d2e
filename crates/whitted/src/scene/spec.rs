//! The one record form of a shape, as every reader hands it over: Scene.txt's report
//! records (a sphere's centre and radius, a plane's point and normal, an infinite
//! cylinder's axis, point and radius), its extension records (SPEC §16: box, capped
//! cylinder and cone, disc, torus, triangle, mesh), an NFF's (a polygon's triangles, a
//! patch's corners and normals, an open cone's end circles) and glTF's primitives. The
//! tracer draws `Shape`s built from these: a record without modifiers (the report's,
//! an NFF's) by `ShapeSpec::build`, an extension record with its modifiers, TEXTURE and
//! MATERIAL (`ext::ExtObject`) by `ext::build`. Animation tracks change a value here
//! and build the shape again, exactly as the reader would from the changed file.
//!
//! `ObjectSpec` says where an object's record is: held by the object itself (a report
//! or NFF record) or in the extension's list (`Scene::ext.objects`: a shape record, a
//! CSG block or a glTF primitive).

use crate::shapes::{Cone, Plane, Quadric, Shape, SmoothTriangle, Sphere, Triangle};
use glam::DVec3;
use std::path::PathBuf;

/// A shape record's geometry, as its reader gives it (checked by that reader).
#[derive(Clone, Debug, PartialEq)]
pub enum ShapeSpec {
    /// `sphere C(3) Radius` (the report's and the extension's; an NFF `s`).
    Sphere {
        /// The centre C.
        center: DVec3,
        /// The radius, > 0.
        radius: f64,
    },
    /// `plane P(3) N(3)` (the report's and the extension's); N non-zero as written.
    Plane {
        /// A point P on the plane.
        point: DVec3,
        /// The normal N as written (non-zero; normalised when the shape is built);
        /// inside CSG the solid is the half-space behind it.
        normal: DVec3,
    },
    /// The report's infinite cylinder (kind `cylinder`).
    InfiniteCylinder {
        /// The axis direction as written (non-zero).
        axis: DVec3,
        /// A point on the axis.
        point: DVec3,
        /// The radius, > 0.
        radius: f64,
    },
    /// `box Min(3) Max(3)`, Min < Max on each axis.
    Box {
        /// The corner Min.
        min: DVec3,
        /// The corner Max, above Min on each axis.
        max: DVec3,
    },
    /// `cylinder A(3) B(3) Radius`, capped unless `open`.
    Cylinder {
        /// The centre A of one end.
        a: DVec3,
        /// The centre B of the other end (B ≠ A).
        b: DVec3,
        /// The radius, > 0.
        radius: f64,
    },
    /// `cone A(3) Ra B(3) Rb`, capped unless `open`.
    Cone {
        /// The centre A of one end.
        a: DVec3,
        /// The radius Ra at A, ≥ 0.
        ra: f64,
        /// The centre B of the other end (B ≠ A).
        b: DVec3,
        /// The radius Rb at B, ≥ 0 (not both 0).
        rb: f64,
    },
    /// An NFF `c` open cone or cylinder (kind `cone`).
    OpenCone {
        /// The base circle's centre and radius.
        base: (DVec3, f64),
        /// The apex circle's centre and radius.
        apex: (DVec3, f64),
    },
    /// `disc C(3) N(3) Radius Hole`, 0 ≤ Hole < Radius.
    Disc {
        /// The centre C.
        center: DVec3,
        /// The normal N (non-zero).
        normal: DVec3,
        /// The outer radius, > 0.
        radius: f64,
        /// The hole's radius, 0 ≤ Hole < Radius.
        hole: f64,
    },
    /// `torus C(3) Axis(3) R r`, 0 < r < R.
    Torus {
        /// The centre C.
        center: DVec3,
        /// The axis (non-zero) the ring turns about.
        axis: DVec3,
        /// The ring's radius R (track field `major`).
        major: f64,
        /// The tube's radius r, 0 < r < R (track field `minor`).
        minor: f64,
    },
    /// `triangle P1(3) P2(3) P3(3)`, or one triangle of an NFF polygon: not degenerate.
    Triangle {
        /// P1, P2, P3, counter-clockwise seen from the front.
        corners: [DVec3; 3],
    },
    /// An NFF `pp` patch.
    Patch {
        /// The corners.
        corners: [DVec3; 3],
        /// The normal at each corner.
        normals: [DVec3; 3],
    },
    /// `mesh "file"`: `path` resolved against the scene's folder, `written` as quoted.
    Mesh {
        /// The file, resolved against the scene file's folder.
        path: PathBuf,
        /// The file name as the record quotes it.
        written: String,
    },
    /// A glTF primitive (SPEC §18): the glTF reader's, never written in a Scene.txt.
    Gltf {
        /// Its node in the file.
        node: u32,
        /// Its primitive in the node's mesh.
        primitive: u32,
    },
}

impl ShapeSpec {
    /// The shape the tracer draws for a record without modifiers (the report's, an
    /// NFF's); `None` for the records only the extension gives (box, capped cylinder and
    /// cone, disc, torus, mesh, glTF primitive), which `ext::build` draws with theirs.
    pub fn build(&self) -> Option<Shape> {
        Some(match *self {
            ShapeSpec::Sphere { center, radius } => Shape::Sphere(Sphere::new(center, radius)),
            ShapeSpec::Plane { point, normal } => Shape::Plane(Plane::new(point, normal)),
            ShapeSpec::InfiniteCylinder {
                axis,
                point,
                radius,
            } => Shape::Quadric(Quadric::cylinder(axis, point, radius)),
            ShapeSpec::Triangle { corners: [a, b, c] } => {
                Shape::Triangle(Triangle::new(a, b, c).expect("the readers check triangles"))
            }
            ShapeSpec::Patch { corners, normals } => Shape::Smooth(
                SmoothTriangle::new(corners, normals).expect("the NFF reader checks patches"),
            ),
            ShapeSpec::OpenCone { base, apex } => Shape::Cone(
                Cone::new(base.0, base.1, apex.0, apex.1).expect("the NFF reader checks cones"),
            ),
            ShapeSpec::Box { .. }
            | ShapeSpec::Cylinder { .. }
            | ShapeSpec::Cone { .. }
            | ShapeSpec::Disc { .. }
            | ShapeSpec::Torus { .. }
            | ShapeSpec::Mesh { .. }
            | ShapeSpec::Gltf { .. } => return None,
        })
    }

    /// The record's kind as Scene.txt and the manifest name it: its keyword (`box`,
    /// `torus`, …), its kind for numbering and tracks (the report's and the extension's
    /// cylinders are both `cylinder`, an NFF's open cone a `cone`).
    pub fn kind(&self) -> &'static str {
        match self {
            ShapeSpec::Sphere { .. } => "sphere",
            ShapeSpec::Plane { .. } => "plane",
            ShapeSpec::InfiniteCylinder { .. } | ShapeSpec::Cylinder { .. } => "cylinder",
            ShapeSpec::Box { .. } => "box",
            ShapeSpec::Cone { .. } | ShapeSpec::OpenCone { .. } => "cone",
            ShapeSpec::Disc { .. } => "disc",
            ShapeSpec::Torus { .. } => "torus",
            ShapeSpec::Triangle { .. } => "triangle",
            ShapeSpec::Patch { .. } => "patch",
            ShapeSpec::Mesh { .. } => "mesh",
            ShapeSpec::Gltf { .. } => "gltf",
        }
    }

    /// True for the shapes CSG takes (a solid: sphere, plane, box, capped cylinder and
    /// cone, torus); `open` is the modifier that would make a cylinder or cone a shell.
    pub fn is_solid(&self, open: bool) -> bool {
        match self {
            ShapeSpec::Sphere { .. }
            | ShapeSpec::Plane { .. }
            | ShapeSpec::Box { .. }
            | ShapeSpec::Torus { .. } => true,
            ShapeSpec::Cylinder { .. } | ShapeSpec::Cone { .. } => !open,
            ShapeSpec::InfiniteCylinder { .. }
            | ShapeSpec::OpenCone { .. }
            | ShapeSpec::Disc { .. }
            | ShapeSpec::Triangle { .. }
            | ShapeSpec::Patch { .. }
            | ShapeSpec::Mesh { .. }
            | ShapeSpec::Gltf { .. } => false,
        }
    }

    /// The point a camera looks at when told to look at this record, in its own units
    /// (before any modifier moves it): a sphere's, disc's or torus's centre, a plane's
    /// or an infinite cylinder's point, a box's centre, the middle of a cylinder's or a
    /// cone's axis, a triangle's or a patch's centroid; the origin for a mesh and a glTF
    /// primitive (whose box's centre only their builder knows).
    pub fn anchor(&self) -> DVec3 {
        match *self {
            ShapeSpec::Sphere { center, .. }
            | ShapeSpec::Disc { center, .. }
            | ShapeSpec::Torus { center, .. } => center,
            ShapeSpec::Plane { point, .. } | ShapeSpec::InfiniteCylinder { point, .. } => point,
            ShapeSpec::Box { min, max } => 0.5 * (min + max),
            ShapeSpec::Cylinder { a, b, .. } | ShapeSpec::Cone { a, b, .. } => 0.5 * (a + b),
            ShapeSpec::OpenCone { base, apex } => 0.5 * (base.0 + apex.0),
            ShapeSpec::Triangle { corners: [a, b, c] }
            | ShapeSpec::Patch {
                corners: [a, b, c], ..
            } => (a + b + c) / 3.0,
            ShapeSpec::Mesh { .. } | ShapeSpec::Gltf { .. } => DVec3::ZERO,
        }
    }
}

/// Where an object's record is.
#[derive(Clone, Debug, PartialEq)]
pub enum ObjectSpec {
    /// A report or NFF record, held here (its TEXTURE and MATERIAL are the object's).
    Record(ShapeSpec),
    /// The extension's record `Scene::ext.objects[item]`: a shape record, a CSG block or
    /// a glTF primitive, with its modifiers.
    Ext {
        /// Its index in `Scene::ext.objects` (where its fields and `name` are).
        item: u32,
        /// Its kind for numbering: the shape record's, or `csg` for a block.
        kind: &'static str,
        /// The point a camera looks at for it, as its builder placed it.
        anchor: DVec3,
    },
}

impl ObjectSpec {
    /// The object's kind as Scene.txt and the manifest name it (see `ShapeSpec::kind`).
    pub fn kind(&self) -> &'static str {
        match self {
            ObjectSpec::Record(r) => r.kind(),
            ObjectSpec::Ext { kind, .. } => kind,
        }
    }

    /// The point a camera looks at when told to look at this object.
    pub fn anchor(&self) -> DVec3 {
        match self {
            ObjectSpec::Record(r) => r.anchor(),
            ObjectSpec::Ext { anchor, .. } => *anchor,
        }
    }

    /// The record the object holds itself (a report or NFF record), if any.
    pub fn record(&self) -> Option<&ShapeSpec> {
        match self {
            ObjectSpec::Record(r) => Some(r),
            ObjectSpec::Ext { .. } => None,
        }
    }

    /// The object's index in `Scene::ext.objects`, for an extension object.
    pub fn item(&self) -> Option<usize> {
        match self {
            ObjectSpec::Record(_) => None,
            ObjectSpec::Ext { item, .. } => Some(*item as usize),
        }
    }
}

/// A direction (a normal or an axis) usable as given, or scaled by its largest component
/// when |v|² under- or overflows; `None` for a zero or non-finite vector.
pub fn direction(v: DVec3) -> Option<DVec3> {
    if !v.is_finite() {
        return None;
    }
    if v.try_normalize().is_some() {
        return Some(v);
    }
    let scaled = v / v.abs().max_element();
    scaled.try_normalize().map(|_| scaled)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn directions() {
        assert_eq!(
            direction(DVec3::new(0.0, 2.0, 0.0)),
            Some(DVec3::new(0.0, 2.0, 0.0))
        );
        assert_eq!(direction(DVec3::ZERO), None);
        assert_eq!(direction(DVec3::new(f64::NAN, 1.0, 0.0)), None);
        // 1e-200 squared underflows: scaled by its largest component it is (1, 0, 0).
        assert_eq!(direction(DVec3::new(1e-200, 0.0, 0.0)), Some(DVec3::X));
    }

    #[test]
    fn anchors_and_kinds() {
        let s = ShapeSpec::Sphere {
            center: DVec3::ONE,
            radius: 2.0,
        };
        assert_eq!((s.kind(), s.anchor()), ("sphere", DVec3::ONE));
        let c = ShapeSpec::InfiniteCylinder {
            axis: DVec3::Y,
            point: DVec3::X,
            radius: 1.0,
        };
        assert_eq!((c.kind(), c.anchor()), ("cylinder", DVec3::X));
        assert!(matches!(c.build(), Some(Shape::Quadric(_))));
        // The extension's capped cylinder is a `cylinder` too, drawn by `ext::build`.
        let capped = ShapeSpec::Cylinder {
            a: DVec3::ZERO,
            b: DVec3::Y,
            radius: 1.0,
        };
        assert_eq!(
            (capped.kind(), capped.anchor()),
            ("cylinder", 0.5 * DVec3::Y)
        );
        assert_eq!(capped.build(), None);
        let o = ObjectSpec::Ext {
            item: 3,
            kind: "csg",
            anchor: DVec3::Z,
        };
        assert_eq!((o.kind(), o.anchor(), o.item()), ("csg", DVec3::Z, Some(3)));
        assert_eq!(ObjectSpec::Record(c.clone()).record(), Some(&c));
    }
}
