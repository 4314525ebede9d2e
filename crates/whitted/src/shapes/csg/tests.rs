//! Hand-computed CSG hits: which surfaces each operation keeps, which leaf shades them,
//! the reversed normals of cut surfaces (nested too), bounds and inside tests.

use super::*;
use crate::bump::Bump;
use crate::object::{Highlight, Material};
use crate::shapes::{AaBox, Capped, Local, Placed, Plane, Sphere, Torus, Transform};
use crate::texture::Texture;

fn leaf(shape: Shape, grey: f64) -> Node {
    Node::Leaf(Object {
        shape,
        texture: Texture::Uniform(DVec3::splat(grey)),
        material: Material {
            kd: 1.0,
            kr: 0.0,
            kt: 0.0,
            ior: 1.0,
            bump: Bump::None,
            highlight: Highlight::Report,
        },
    })
}

fn ball(x: f64, r: f64, grey: f64) -> Node {
    leaf(Shape::Sphere(Sphere::new(DVec3::new(x, 0.0, 0.0), r)), grey)
}

fn cube(min: DVec3, max: DVec3, grey: f64) -> Node {
    let b = AaBox::new(min, max).unwrap();
    leaf(
        Shape::Placed(Placed::new(Local::Box(b), Transform::IDENTITY)),
        grey,
    )
}

fn grey(o: &Object) -> f64 {
    match o.texture {
        Texture::Uniform(c) => c.x,
        _ => unreachable!(),
    }
}

fn ray(o: [f64; 3], d: [f64; 3]) -> Ray {
    Ray::new(DVec3::from(o), DVec3::from(d))
}

#[test]
fn a_difference_shows_the_cut_with_the_cutters_texture_and_a_reversed_normal() {
    // The unit ball minus the box x ≥ 0: a half ball, flat face at x = 0.
    let half = DVec3::new(2.0, 2.0, 2.0);
    let c = Csg::new(
        Op::Difference,
        vec![
            ball(0.0, 1.0, 0.1),
            cube(DVec3::new(0.0, -2.0, -2.0), half, 0.2),
        ],
    )
    .unwrap();
    // From −x: the ball's own surface at x = −1 (t = 4), normal −x, the ball's texture.
    let s = c
        .surface(&ray([-5.0, 0.0, 0.0], [1.0, 0.0, 0.0]), f64::INFINITY)
        .unwrap();
    assert_eq!((s.t, s.normal, grey(s.leaf)), (4.0, -DVec3::X, 0.1));
    // From +x: the box's face x = 2 is outside the ball and the ball's x = 1 inside the
    // box: the first kept point is the cut x = 0 (t = 5), the box's −x normal reversed.
    let s = c
        .surface(&ray([5.0, 0.0, 0.0], [-1.0, 0.0, 0.0]), f64::INFINITY)
        .unwrap();
    assert_eq!((s.t, s.normal, grey(s.leaf)), (5.0, DVec3::X, 0.2));
    assert_eq!(
        c.roots(&ray([5.0, 0.0, 0.0], [-1.0, 0.0, 0.0])).as_slice(),
        &[5.0, 6.0]
    );
    // Past the ball on the box's side: nothing.
    assert_eq!(
        c.hit(&ray([5.0, 1.5, 0.0], [-1.0, 0.0, 0.0]), f64::INFINITY),
        None
    );
    // The normal without the ray agrees at both points.
    assert_eq!(c.normal(DVec3::new(0.0, 0.3, 0.2)), DVec3::X);
    assert_eq!(c.normal(DVec3::new(-1.0, 0.0, 0.0)), -DVec3::X);
    assert_eq!(c.bounds(), Some((DVec3::splat(-1.0), DVec3::splat(1.0))));
}

#[test]
fn an_intersection_keeps_the_points_inside_the_others() {
    // Balls of radius 1 at x = ±0.5: the lens between x = −0.5 and 0.5.
    let c = Csg::new(
        Op::Intersection,
        vec![ball(-0.5, 1.0, 0.1), ball(0.5, 1.0, 0.2)],
    )
    .unwrap();
    let r = ray([-5.0, 0.0, 0.0], [1.0, 0.0, 0.0]);
    // Candidates 3.5 and 5.5 (first ball), 4.5 and 6.5 (second): 4.5 and 5.5 are kept.
    assert_eq!(c.roots(&r).as_slice(), &[4.5, 5.5]);
    let s = c.surface(&r, f64::INFINITY).unwrap();
    assert_eq!((s.t, s.normal, grey(s.leaf)), (4.5, -DVec3::X, 0.2));
    assert_eq!(c.hit(&r, 4.5), None, "t_max is exclusive");
    let (lo, hi) = c.bounds().unwrap();
    assert_eq!((lo.x, hi.x, lo.y, hi.y), (-0.5, 0.5, -1.0, 1.0));
    assert!(c.inside(DVec3::ZERO) && !c.inside(DVec3::new(0.7, 0.0, 0.0)));
}

#[test]
fn a_union_keeps_every_surface() {
    let c = Csg::new(Op::Union, vec![ball(-0.5, 1.0, 0.1), ball(0.5, 1.0, 0.2)]).unwrap();
    let r = ray([-5.0, 0.0, 0.0], [1.0, 0.0, 0.0]);
    assert_eq!(c.roots(&r).as_slice(), &[3.5, 4.5, 5.5, 6.5]);
    let s = c.surface(&r, f64::INFINITY).unwrap();
    assert_eq!((s.t, grey(s.leaf)), (3.5, 0.1));
    // From inside the overlap (t_min 0): the first ball's far side at x = 0.5.
    assert_eq!(
        c.hit(&ray([0.0, 0.0, 0.0], [1.0, 0.0, 0.0]), f64::INFINITY),
        Some(0.5)
    );
    let (lo, hi) = c.bounds().unwrap();
    assert_eq!((lo.x, hi.x), (-1.5, 1.5));
}

#[test]
fn a_plane_is_the_half_space_behind_its_normal() {
    // The unit ball cut by the plane y = 0 (normal +y): the lower half ball.
    let floor = leaf(Shape::Plane(Plane::new(DVec3::ZERO, DVec3::Y)), 0.3);
    let c = Csg::new(Op::Intersection, vec![ball(0.0, 1.0, 0.1), floor]).unwrap();
    // From above: the ball's top (t = 4) is outside the half-space; the plane at t = 5.
    let s = c
        .surface(&ray([0.0, 5.0, 0.0], [0.0, -1.0, 0.0]), f64::INFINITY)
        .unwrap();
    assert_eq!((s.t, s.normal, grey(s.leaf)), (5.0, DVec3::Y, 0.3));
    // Beside the ball the plane is outside it: nothing.
    assert_eq!(
        c.hit(&ray([3.0, 5.0, 0.0], [0.0, -1.0, 0.0]), f64::INFINITY),
        None
    );
    // Bounded by the ball alone.
    assert_eq!(c.bounds(), Some((DVec3::splat(-1.0), DVec3::splat(1.0))));
    let u = Csg::new(
        Op::Union,
        vec![
            ball(0.0, 1.0, 0.1),
            leaf(Shape::Plane(Plane::new(DVec3::ZERO, DVec3::Y)), 0.3),
        ],
    );
    assert_eq!(u.unwrap().bounds(), None);
}

#[test]
fn nested_cuts_reverse_their_normals_once_per_difference() {
    // A = the box [−2, 2]³ minus (the unit ball minus the box x ≥ 0): a cavity shaped
    // as the left half ball inside a solid box.
    let inner = Csg::new(
        Op::Difference,
        vec![
            ball(0.0, 1.0, 0.1),
            cube(DVec3::new(0.0, -3.0, -3.0), DVec3::splat(3.0), 0.2),
        ],
    )
    .unwrap();
    let c = Csg::new(
        Op::Difference,
        vec![
            cube(DVec3::splat(-2.0), DVec3::splat(2.0), 0.3),
            Node::Csg(inner),
        ],
    )
    .unwrap();
    // From the cavity towards −x: the ball's wall at x = −1, its −x normal reversed once
    // (the solid lies beyond it): +x, the ball's texture.
    let s = c
        .surface(&ray([-0.5, 0.0, 0.0], [-1.0, 0.0, 0.0]), f64::INFINITY)
        .unwrap();
    assert_eq!((s.t, s.normal, grey(s.leaf)), (0.5, DVec3::X, 0.1));
    // Towards +x: the inner box's face x = 0, reversed twice: its own −x.
    let s = c
        .surface(&ray([-0.5, 0.0, 0.0], [1.0, 0.0, 0.0]), f64::INFINITY)
        .unwrap();
    assert_eq!((s.t, s.normal, grey(s.leaf)), (0.5, -DVec3::X, 0.2));
    // From outside along x: the outer box at x = −2 (t = 3), then the cavity's walls.
    let r = ray([-5.0, 0.0, 0.0], [1.0, 0.0, 0.0]);
    assert_eq!(c.roots(&r).as_slice(), &[3.0, 4.0, 5.0, 7.0]);
    assert!(c.inside(DVec3::new(0.5, 0.0, 0.0)) && !c.inside(DVec3::new(-0.5, 0.0, 0.0)));
    assert_eq!(c.first_leaf().texture, Texture::Uniform(DVec3::splat(0.3)));
}

#[test]
fn inside_tests_of_each_solid() {
    let cyl = Capped::new(DVec3::ZERO, 1.0, DVec3::new(0.0, 2.0, 0.0), 1.0, true).unwrap();
    let cyl = Shape::Placed(Placed::new(Local::Capped(cyl), Transform::IDENTITY));
    assert!(inside::shape(&cyl, DVec3::new(0.9, 1.0, 0.0)));
    assert!(!inside::shape(&cyl, DVec3::new(1.1, 1.0, 0.0)));
    assert!(!inside::shape(&cyl, DVec3::new(0.0, 2.1, 0.0)));
    // A cone from radius 1 at y = 0 to 0 at y = 2: radius 0.5 at y = 1.
    let cone = Capped::new(DVec3::ZERO, 1.0, DVec3::new(0.0, 2.0, 0.0), 0.0, true).unwrap();
    let cone = Shape::Placed(Placed::new(Local::Capped(cone), Transform::IDENTITY));
    assert!(inside::shape(&cone, DVec3::new(0.0, 1.0, 0.49)));
    assert!(!inside::shape(&cone, DVec3::new(0.0, 1.0, 0.51)));
    // A torus R 2, r 0.5 about y: the tube's centre (2, 0, 0) is inside, the hub is not.
    let torus = Torus::new(DVec3::ZERO, DVec3::Y, 2.0, 0.5).unwrap();
    let torus = Shape::Placed(Placed::new(Local::Torus(torus), Transform::IDENTITY));
    assert!(inside::shape(&torus, DVec3::new(0.0, 0.4, -2.0)));
    assert!(!inside::shape(&torus, DVec3::ZERO));
    assert!(!inside::shape(&torus, DVec3::new(2.0, 0.6, 0.0)));
    // A box scaled by 2 along x and moved to x = 10: [8, 12] × [−1, 1]².
    let f = Transform::new(
        DVec3::new(2.0, 1.0, 1.0),
        DVec3::ZERO,
        DVec3::new(10.0, 0.0, 0.0),
    );
    let b = AaBox::new(DVec3::splat(-1.0), DVec3::splat(1.0)).unwrap();
    let b = Shape::Placed(Placed::new(Local::Box(b), f.unwrap()));
    assert!(inside::shape(&b, DVec3::new(11.9, 0.0, 0.0)));
    assert!(!inside::shape(&b, DVec3::new(12.1, 0.0, 0.0)));
    // Open shells are not solids; a point on a surface is not inside.
    let open = Capped::new(DVec3::ZERO, 1.0, DVec3::Y, 1.0, false).unwrap();
    assert!(!is_solid(&Shape::Placed(Placed::new(
        Local::Capped(open),
        Transform::IDENTITY
    ))));
    assert!(!inside::shape(
        &Shape::Sphere(Sphere::new(DVec3::ZERO, 1.0)),
        DVec3::X
    ));
}

#[test]
fn fewer_than_two_children_is_no_block() {
    assert_eq!(Csg::new(Op::Union, vec![ball(0.0, 1.0, 0.1)]), None);
}
