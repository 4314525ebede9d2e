//! Direction grids against direct tests of the shapes.

use super::*;
use crate::base::Color;
use crate::bump::Bump;
use crate::object::Material;
use crate::shapes::{Plane, Sphere};
use crate::texture::Texture;

fn obj(shape: Shape) -> Object {
    Object {
        shape,
        texture: Texture::Uniform(Color::ONE),
        material: Material {
            kd: 1.0,
            kr: 0.0,
            kt: 0.0,
            ior: 1.0,
            bump: Bump::None,
            highlight: Default::default(),
        },
    }
}

fn set(o: Objects) -> Vec<usize> {
    o.collect()
}

#[test]
fn bit_sets_iterate_in_object_order() {
    assert_eq!(set(Objects(0b1010_0101)), vec![0, 2, 5, 7]);
    assert_eq!(set(Objects(1 << 63)), vec![63]);
    assert_eq!(set(Objects(0)), Vec::<usize>::new());
}

#[test]
fn cylinder_recovered_from_its_coefficients() {
    let q = Quadric::cylinder(DVec3::new(0.0, 2.0, 0.0), DVec3::new(1.0, 0.0, 2.0), 0.35);
    let (a, p, r) = cylinder_of(&q).unwrap();
    assert_eq!((a, p), (DVec3::Y, DVec3::new(1.0, 0.0, 2.0)));
    assert!((r - 0.35).abs() < 1e-15);
    let slant = DVec3::new(1.0, 2.0, -2.0) / 3.0;
    let (a, _, _) = cylinder_of(&Quadric::cylinder(slant, DVec3::ZERO, 1.0)).unwrap();
    assert!((a - slant).length() < 1e-15, "{a}");
    // A sphere as a quadric (x² + y² + z² − 1) is no cylinder.
    let mut ball = q;
    ball.coef = [1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0];
    assert_eq!(cylinder_of(&ball), None);
}

#[test]
fn cells_keep_only_what_their_directions_can_meet() {
    // From the origin: a sphere of radius 1 at (10, 0, 0) (seen within asin(0.1),
    // 5.7°, of +x), the floor y = −2, and a vertical cylinder of radius 0.5 through
    // (0, 0, −10) (within asin(0.05), 2.9°, of −z azimuthally, at every height).
    let objects = [
        obj(Shape::Sphere(Sphere::new(DVec3::new(10.0, 0.0, 0.0), 1.0))),
        obj(Shape::Plane(Plane::new(
            DVec3::new(0.0, -2.0, 0.0),
            DVec3::Y,
        ))),
        obj(Shape::Quadric(Quadric::cylinder(
            DVec3::Y,
            DVec3::new(0.0, 0.0, -10.0),
            0.5,
        ))),
    ];
    let g = DirGrid::build(DVec3::ZERO, &objects, |_| Some(true)).unwrap();
    let at = |d: DVec3| set(g.cell(d).unwrap().0);
    // +x, level: the sphere, and the floor (the horizon runs through the cell).
    assert_eq!(at(DVec3::X), vec![0, 1]);
    assert_eq!(at(DVec3::new(1.0, 0.5, 0.0)), Vec::<usize>::new()); // above the sphere
                                                                    // Slightly down: the floor.
    assert_eq!(at(DVec3::new(1.0, -0.01, 0.02)), vec![0, 1]);
    // Straight up or down, the cell holds directions parallel to the cylinder's axis:
    // it is kept (the test is by bounding cones), as the floor is below.
    assert_eq!(at(DVec3::Y), vec![2]);
    assert_eq!(at(-DVec3::Y), vec![1, 2]);
    assert_eq!(at(-DVec3::Z), vec![1, 2]); // towards the cylinder, at the horizon
    assert_eq!(at(DVec3::new(0.01, 0.3, -1.0)), vec![2]); // towards it, above
    assert_eq!(at(DVec3::new(0.0, 0.9, -1.0)), vec![2]); // up along it, still
    assert_eq!(at(DVec3::new(1.0, 0.5, -1.0)), Vec::<usize>::new()); // beside it
    assert_eq!(g.cell(DVec3::ZERO), None);
    assert_eq!(g.cell(DVec3::new(-1e-310, 0.0, 0.0)), None);
    assert_eq!(g.cell(DVec3::new(f64::INFINITY, 0.0, 0.0)), None);
    assert_eq!(g.cell(-DVec3::X * 1e-299), g.cell(-DVec3::X));
    assert_eq!(g.cell(DVec3::Y * f64::MAX), g.cell(DVec3::Y));
    assert_eq!(g.cell(DVec3::new(f64::NAN, 1.0, 0.0)), None);
}
