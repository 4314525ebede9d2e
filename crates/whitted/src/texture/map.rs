//! Where an image texture's map puts a surface point (SPEC §16): the point in the map's
//! frame, then its (u, v), one image per Size of the frame (u and v wrap later).
//!
//! - `planar`: u = x/Size, v = y/Size. On a plane or a disc the frame has its origin at
//!   the plane's point (the disc's centre), x along normalize(up × N) with up = (0,1,0),
//!   or (0,0,−1) when N is vertical, and y along N × x; on any other object it is the
//!   object's own frame (world axes moved by its `scale`, `rotate`, `translate`).
//! - `spherical`: from the unit direction (x, y, z) of the point seen from the centre
//!   (a sphere's; the object frame's origin on other shapes): v = ½ + asin(y)/π,
//!   θ = acos(x/√(x²+z²)), 2π − θ where z < 0, u = θ/2π (Size unused).
//! - `cylindrical`: the frame's origin at the cylinder's point A, y along its axis,
//!   x = normalize(up × y) with up as for planes, z = x × y; u as spherical's from x and
//!   z, v = y/Size. Other shapes use their object frame (y up).
//!
//! - `uv` (SPEC §18): a mesh's own (u, v), interpolated over the triangle hit, over
//!   Size; the mesh maps them (`Mesh::surface`), here it is (0, 0).
//!
//! The frames are read from the drawn shape, so an animated shape carries its image. A
//! flat face on a tile boundary reads the tile on its solid's side (`faces`).

use super::map_kind::MapKind;
use crate::shapes::{Local, Shape};
use glam::DVec3;
use std::f64::consts::{PI, TAU};

/// The x of a frame whose third axis is `n` (unit): normalize(up × n), up = (0,1,0), or
/// (0,0,−1) when n is vertical.
fn side(n: DVec3) -> DVec3 {
    let x = DVec3::Y.cross(n);
    if x.length_squared() > 1e-18 {
        x.normalize()
    } else {
        DVec3::NEG_Z.cross(n).normalize()
    }
}

/// The point `p` in the frame of origin `o` whose y is `y` (planar: normal `n` as z).
fn planar_frame(p: DVec3, o: DVec3, n: DVec3) -> DVec3 {
    let x = side(n);
    let y = n.cross(x);
    let d = p - o;
    DVec3::new(d.dot(x), d.dot(y), d.dot(n))
}

/// The point `p` in the cylindrical frame of origin `o` and unit axis `a`.
fn axis_frame(p: DVec3, o: DVec3, a: DVec3) -> DVec3 {
    let x = side(a);
    let z = x.cross(a);
    let d = p - o;
    DVec3::new(d.dot(x), d.dot(a), d.dot(z))
}

/// A world point in the shape's own frame (object space for a placed shape, else the
/// world).
fn object_point(shape: &Shape, p: DVec3) -> DVec3 {
    match shape {
        Shape::Placed(pl) => pl.frame.point_to_local(p),
        _ => p,
    }
}

/// θ/2π of (x, z): the angle from +x towards +z, 0 where x = z = 0.
fn turn(x: f64, z: f64) -> f64 {
    let len = (x * x + z * z).sqrt();
    if len == 0.0 {
        return 0.0;
    }
    let theta = (x / len).clamp(-1.0, 1.0).acos();
    let theta = if z < 0.0 { TAU - theta } else { theta };
    theta / TAU
}

/// (u, v) of the world point `p` of `shape` under `map`, before wrapping; on a face
/// that lies on a tile boundary, the coordinate it holds constant is read just inside
/// the solid's tile (`faces`).
pub fn uv(map: MapKind, size: f64, shape: &Shape, p: DVec3) -> (f64, f64) {
    let uv = unsettled(map, size, shape, p);
    super::faces::settle(map, size, shape, p, uv)
}

/// (u, v) as the formulas above give them.
fn unsettled(map: MapKind, size: f64, shape: &Shape, p: DVec3) -> (f64, f64) {
    match map {
        MapKind::Planar => {
            let q = match shape {
                Shape::Plane(pl) => planar_frame(p, pl.point, pl.normal()),
                Shape::Placed(pl) => match &pl.local {
                    Local::Disc(d) => planar_frame(pl.frame.point_to_local(p), d.center, d.normal),
                    _ => pl.frame.point_to_local(p),
                },
                _ => p,
            };
            (q.x / size, q.y / size)
        }
        MapKind::Spherical => {
            let d = match shape {
                Shape::Sphere(s) => p - s.center,
                Shape::Placed(pl) => match &pl.local {
                    Local::Sphere(s) => pl.frame.point_to_local(p) - s.center,
                    _ => pl.frame.point_to_local(p),
                },
                _ => p,
            };
            let len = d.length();
            if len == 0.0 || !len.is_finite() {
                return (0.0, 0.0);
            }
            let d = d / len;
            (turn(d.x, d.z), 0.5 + d.y.clamp(-1.0, 1.0).asin() / PI)
        }
        MapKind::Cylindrical => {
            let q = match shape {
                Shape::Quadric(q) if q.axis != DVec3::ZERO => axis_frame(p, q.origin, q.axis),
                Shape::Cone(c) => axis_frame(p, c.base, c.axis()),
                Shape::Placed(pl) => match &pl.local {
                    Local::Capped(c) => {
                        axis_frame(pl.frame.point_to_local(p), c.side.base, c.side.axis())
                    }
                    _ => pl.frame.point_to_local(p),
                },
                _ => object_point(shape, p),
            };
            (turn(q.x, q.z), q.y / size)
        }
        // Only a mesh has coordinates, and it maps them itself (`Mesh::surface`).
        MapKind::Uv => (0.0, 0.0),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::shapes::{Capped, Placed, Plane, Quadric, Sphere, Transform};

    fn close(a: (f64, f64), b: (f64, f64)) -> bool {
        (a.0 - b.0).abs() < 1e-12 && (a.1 - b.1).abs() < 1e-12
    }

    #[test]
    fn planar_on_a_floor_is_x_and_minus_z() {
        // N = y is vertical: x = (0,0,−1) × (0,1,0) = (1,0,0), y = N × x = (0,0,−1).
        let floor = Shape::Plane(Plane::new(DVec3::new(1.0, 0.0, 0.0), DVec3::Y));
        let (u, v) = uv(MapKind::Planar, 2.0, &floor, DVec3::new(2.0, 0.0, 3.0));
        assert!(close((u, v), (0.5, -1.5)), "{u} {v}");
    }

    #[test]
    fn planar_on_a_wall_uses_up_cross_n() {
        // N = z: x = (0,1,0) × (0,0,1) = (1,0,0), y = z × x = (0,1,0): the wall's x and y.
        let wall = Shape::Plane(Plane::new(DVec3::ZERO, DVec3::Z));
        assert!(close(
            uv(MapKind::Planar, 1.0, &wall, DVec3::new(0.25, 0.75, 0.0)),
            (0.25, 0.75)
        ));
        // N = x: x = (0,1,0) × (1,0,0) = (0,0,−1), y = x̂ × (0,0,−1) = (0,1,0).
        let wall = Shape::Plane(Plane::new(DVec3::ZERO, DVec3::X));
        assert!(close(
            uv(MapKind::Planar, 1.0, &wall, DVec3::new(0.0, 0.5, -0.25)),
            (0.25, 0.5)
        ));
    }

    #[test]
    fn planar_on_a_placed_shape_is_its_object_frame() {
        // Translated by (10, 0, 0): the world point (10.5, 0.25, 3) is (0.5, 0.25, 3).
        let frame = Transform::new(DVec3::ONE, DVec3::ZERO, DVec3::new(10.0, 0.0, 0.0)).unwrap();
        let ball = Local::Sphere(Sphere::new(DVec3::ZERO, 1.0));
        let placed = Shape::Placed(Placed::new(ball, frame));
        let p = DVec3::new(10.5, 0.25, 3.0);
        assert!(close(uv(MapKind::Planar, 0.5, &placed, p), (1.0, 0.5)));
    }

    #[test]
    fn spherical_by_hand() {
        let s = Shape::Sphere(Sphere::new(DVec3::new(0.0, 1.0, 0.0), 2.0));
        // +x at the equator: θ = 0, v = ½.
        let at = |x, y, z| uv(MapKind::Spherical, 7.0, &s, DVec3::new(x, y, z));
        assert!(close(at(2.0, 1.0, 0.0), (0.0, 0.5)));
        // +z: θ = π/2 → u = ¼; −z: 2π − π/2 → u = ¾; −x: u = ½.
        assert!(close(at(0.0, 1.0, 2.0), (0.25, 0.5)));
        assert!(close(at(0.0, 1.0, -2.0), (0.75, 0.5)));
        assert!(close(at(-2.0, 1.0, 0.0), (0.5, 0.5)));
        // The north pole: v = ½ + asin(1)/π = 1; 30° up: v = ½ + (π/6)/π = 2/3.
        assert!(close(at(0.0, 3.0, 0.0), (0.0, 1.0)));
        let (c, s30) = (3f64.sqrt(), 1.0);
        assert!(close(at(c, 1.0 + s30, 0.0), (0.0, 2.0 / 3.0)));
    }

    #[test]
    fn cylindrical_on_the_report_cylinder_and_a_capped_one() {
        // A vertical axis through (1, 0, 0): the frame is the world's axes moved to A.
        let q = Shape::Quadric(Quadric::cylinder(DVec3::Y, DVec3::new(1.0, 0.0, 0.0), 0.5));
        let at = |s: &Shape, x, y, z| uv(MapKind::Cylindrical, 2.0, s, DVec3::new(x, y, z));
        assert!(close(at(&q, 1.0, 3.0, 0.5), (0.25, 1.5)));
        assert!(close(at(&q, 1.5, -1.0, 0.0), (0.0, -0.5)));
        // Along x: y = x̂, x = normalize(ŷ × x̂) = −ẑ, z = x × y = (−ẑ) × x̂ = −ŷ.
        let q = Shape::Quadric(Quadric::cylinder(DVec3::X, DVec3::ZERO, 1.0));
        // The point (4, −1, 0): frame (0, 4, 1): θ = π/2, u = ¼; v = 4/2.
        assert!(close(at(&q, 4.0, -1.0, 0.0), (0.25, 2.0)));
        // A capped cylinder from A = (0,1,0) up: the same frame as the quadric's from A.
        let cap = Capped::new(DVec3::Y, 0.5, DVec3::new(0.0, 3.0, 0.0), 0.5, true).unwrap();
        let placed = Shape::Placed(Placed::new(Local::Capped(cap), Transform::IDENTITY));
        assert!(close(at(&placed, 0.0, 2.0, -0.5), (0.75, 0.5)));
    }
}
