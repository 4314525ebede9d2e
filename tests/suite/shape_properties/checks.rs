//! The checks themselves: a skipped root is caught, the reference quadratic by hand.

use super::*;

/// The checker itself must be able to fail: a "shape" whose hit is the far root.
#[test]
fn the_checks_catch_a_skipped_root() {
    // Sphere of radius 1 at (0,0,−5) seen from the origin: roots 4 and 6.
    let c = DVec3::new(0.0, 0.0, -5.0);
    let ray = Ray::new(DVec3::ZERO, -DVec3::Z);
    let e = Expect {
        surface_error: &|p| (p - c).length() - 1.0,
        outward: &|p| (p - c).normalize(),
        roots: (vec![4.0, 6.0], false),
        scale: 10.0,
        t_tol: 1e-6,
        radius: 1.0,
    };
    // The real sphere passes.
    assert!(check(&Shape::Sphere(Sphere::new(c, 1.0)), &ray, &e).is_ok());
    // A sphere whose roots are claimed to be 2 and 6 "skipped" the one at 2.
    let wrong_roots = Expect {
        roots: (vec![2.0, 6.0], false),
        ..e
    };
    assert!(check(&Shape::Sphere(Sphere::new(c, 1.0)), &ray, &wrong_roots).is_err());
    // A surface that the hit point is not on.
    let off = Expect {
        surface_error: &|p| (p - c).length() - 1.5,
        outward: &|p| (p - c).normalize(),
        roots: (vec![4.0, 6.0], false),
        scale: 10.0,
        t_tol: 1e-6,
        radius: 1.0,
    };
    assert!(check(&Shape::Sphere(Sphere::new(c, 1.0)), &ray, &off).is_err());
    // An inward normal.
    let inward = Expect {
        surface_error: &|p| (p - c).length() - 1.0,
        outward: &|p| (c - p).normalize(),
        roots: (vec![4.0, 6.0], false),
        scale: 10.0,
        t_tol: 1e-6,
        radius: 1.0,
    };
    assert!(check(&Shape::Sphere(Sphere::new(c, 1.0)), &ray, &inward).is_err());
}

#[test]
fn the_reference_quadratic_by_hand() {
    // t² − 10t + 24 = 0: 4 and 6.
    assert_eq!(quadratic(1.0, -5.0, 24.0, 1.0), (vec![4.0, 6.0], false));
    // t² + 1 = 0: none.
    assert_eq!(quadratic(1.0, 0.0, 1.0, 1.0).0, Vec::<f64>::new());
    // 2t² − 2 = 0: ±1.
    assert_eq!(quadratic(2.0, 0.0, -2.0, 1.0).0, vec![-1.0, 1.0]);
}
