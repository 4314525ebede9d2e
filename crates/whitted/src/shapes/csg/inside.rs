//! Inside tests of the solids a CSG block takes, strict (a point on the surface is not
//! inside): a sphere |p − C| < r; a plane's half-space behind its normal, (p − P)·N < 0;
//! in an object frame (`Placed`), the point carried to object space and tested there
//! against the sphere, the box (Min < p < Max), the capped cylinder or cone (0 < s < h
//! along the axis from A, and a distance to the axis below r_A + (r_B − r_A)·s/h) or the
//! torus ((ρ − R)² + y² < r², y along the axis and ρ the distance to it).

use crate::shapes::{Local, Shape};
use glam::DVec3;

/// True when the shape is a solid a block takes: a sphere, a plane, or a `Placed`
/// sphere, box, capped cylinder or cone, or torus (not an open one, not a disc).
pub fn is_solid(shape: &Shape) -> bool {
    match shape {
        Shape::Sphere(_) | Shape::Plane(_) => true,
        Shape::Placed(p) => match p.local {
            Local::Sphere(_) | Local::Box(_) | Local::Torus(_) => true,
            Local::Capped(c) => c.caps,
            Local::Disc(_) => false,
        },
        Shape::Csg(_) => true,
        Shape::Quadric(_)
        | Shape::Triangle(_)
        | Shape::Smooth(_)
        | Shape::Cone(_)
        | Shape::Mesh(_) => false,
    }
}

/// True when `p` lies strictly inside the solid `shape` (false for a shape that is not
/// a solid).
pub fn shape(shape: &Shape, p: DVec3) -> bool {
    match shape {
        Shape::Sphere(s) => (p - s.center).length_squared() < s.radius * s.radius,
        Shape::Plane(pl) => (p - pl.point).dot(pl.normal()) < 0.0,
        Shape::Placed(pl) => local(&pl.local, pl.frame.point_to_local(p)),
        Shape::Csg(c) => c.inside(p),
        Shape::Quadric(_)
        | Shape::Triangle(_)
        | Shape::Smooth(_)
        | Shape::Cone(_)
        | Shape::Mesh(_) => false,
    }
}

/// The inside test in object space.
fn local(l: &Local, p: DVec3) -> bool {
    match l {
        Local::Sphere(s) => (p - s.center).length_squared() < s.radius * s.radius,
        Local::Box(b) => p.cmpgt(b.min).all() && p.cmplt(b.max).all(),
        Local::Capped(c) => {
            let side = &c.side;
            let w = p - side.base;
            let s = w.dot(side.axis());
            let h = side.height();
            if !(c.caps && s > 0.0 && s < h) {
                return false;
            }
            let r = side.base_radius + (side.apex_radius - side.base_radius) * s / h;
            (w - s * side.axis()).length_squared() < r * r
        }
        Local::Torus(t) => {
            let w = p - t.center;
            let y = w.dot(t.axis);
            let rho = (w - y * t.axis).length();
            (rho - t.major).powi(2) + y * y < t.minor * t.minor
        }
        Local::Disc(_) => false,
    }
}
