//! A shape as Scene.txt states it: a sphere's centre and radius, a plane's point and
//! normal, a cylinder's axis, point and radius; or as an NFF does: a triangle of a
//! polygon, a patch's corners and normals, a cone's end circles. The tracer draws `Shape`s built from these
//! (a cylinder becomes a quadric and forgets its axis); animation tracks change a value
//! here and build the shape again, exactly as the parser would from the changed file.

use crate::shapes::{Cone, Plane, Quadric, Shape, SmoothTriangle, Sphere, Triangle};
use glam::DVec3;

/// The values one shape record of Scene.txt gives.
// `Ext` carries its built shape so that specs stay `Copy` (tracks copy them per frame);
// boxing it would end that.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Debug, PartialEq)]
pub enum ShapeSpec {
    /// A sphere record.
    Sphere {
        /// The centre.
        center: DVec3,
        /// The radius, > 0.
        radius: f64,
    },
    /// A plane record.
    Plane {
        /// A point on the plane.
        point: DVec3,
        /// The normal as written (non-zero; normalised when the shape is built).
        normal: DVec3,
    },
    /// An infinite cylinder record.
    Cylinder {
        /// The axis direction as written (non-zero).
        axis: DVec3,
        /// A point on the axis.
        point: DVec3,
        /// The radius, > 0.
        radius: f64,
    },
    /// One triangle of an NFF polygon (valid: the reader checked it).
    Triangle {
        /// The corners, counter-clockwise seen from the front.
        corners: [DVec3; 3],
    },
    /// An NFF `pp` patch (valid: the reader checked it).
    Patch {
        /// The corners.
        corners: [DVec3; 3],
        /// The normal at each corner.
        normals: [DVec3; 3],
    },
    /// An NFF `c` open cone or cylinder (valid: the reader checked it).
    Cone {
        /// The base circle's centre and radius.
        base: (DVec3, f64),
        /// The apex circle's centre and radius.
        apex: (DVec3, f64),
    },
    /// A shape record of the extension (SPEC §16), built by `ext::build`.
    Ext {
        /// Its index in `Scene::ext.objects` (where its fields and `name` are).
        item: u32,
        /// Its keyword (`box`, `torus`, …): its kind for numbering.
        kind: &'static str,
        /// The drawn shape.
        shape: Shape,
        /// The point a camera looks at for it.
        anchor: DVec3,
    },
}

impl ShapeSpec {
    /// The shape the tracer draws.
    pub fn build(&self) -> Shape {
        match *self {
            ShapeSpec::Sphere { center, radius } => Shape::Sphere(Sphere::new(center, radius)),
            ShapeSpec::Plane { point, normal } => Shape::Plane(Plane::new(point, normal)),
            ShapeSpec::Cylinder {
                axis,
                point,
                radius,
            } => Shape::Quadric(Quadric::cylinder(axis, point, radius)),
            ShapeSpec::Triangle { corners: [a, b, c] } => {
                Shape::Triangle(Triangle::new(a, b, c).expect("the NFF reader checks triangles"))
            }
            ShapeSpec::Patch { corners, normals } => Shape::Smooth(
                SmoothTriangle::new(corners, normals).expect("the NFF reader checks patches"),
            ),
            ShapeSpec::Cone { base, apex } => Shape::Cone(
                Cone::new(base.0, base.1, apex.0, apex.1).expect("the NFF reader checks cones"),
            ),
            ShapeSpec::Ext { ref shape, .. } => shape.clone(),
        }
    }

    /// The record's kind as Scene.txt and the manifest name it.
    pub fn kind(&self) -> &'static str {
        match self {
            ShapeSpec::Sphere { .. } => "sphere",
            ShapeSpec::Plane { .. } => "plane",
            ShapeSpec::Cylinder { .. } => "cylinder",
            ShapeSpec::Triangle { .. } => "triangle",
            ShapeSpec::Patch { .. } => "patch",
            ShapeSpec::Cone { .. } => "cone",
            ShapeSpec::Ext { kind, .. } => kind,
        }
    }

    /// The point a camera looks at when told to look at this object: a sphere's centre,
    /// a plane's or a cylinder's point, a triangle's or a patch's centroid, the middle of
    /// a cone's axis.
    pub fn anchor(&self) -> DVec3 {
        match *self {
            ShapeSpec::Sphere { center, .. } => center,
            ShapeSpec::Plane { point, .. } | ShapeSpec::Cylinder { point, .. } => point,
            ShapeSpec::Triangle { corners: [a, b, c] }
            | ShapeSpec::Patch {
                corners: [a, b, c], ..
            } => (a + b + c) / 3.0,
            ShapeSpec::Cone { base, apex } => 0.5 * (base.0 + apex.0),
            ShapeSpec::Ext { anchor, .. } => anchor,
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
        let c = ShapeSpec::Cylinder {
            axis: DVec3::Y,
            point: DVec3::X,
            radius: 1.0,
        };
        assert_eq!((c.kind(), c.anchor()), ("cylinder", DVec3::X));
        assert!(matches!(c.build(), Shape::Quadric(_)));
    }
}
