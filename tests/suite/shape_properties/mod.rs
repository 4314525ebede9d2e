//! Properties of the shapes (SPEC §2, report IV.1), on random rays aimed mostly at them:
//! whenever `hit` returns t, the point lies on the surface, t > 0.01, the normal there is
//! unit and outward, and no root in (0.01, t) was skipped. Roots are checked against an
//! independent solution of each surface's equation (sphere: |o + t·d − c|² = r²;
//! cylinder: the part of o + t·d perpendicular to the axis has length r; plane: one
//! division), not against the library's own formulas.
//!
//! Tolerances are relative to the size of the problem (the coordinates and distances
//! involved): 1e-9 on the surface equation, looser on t itself, which an almost-tangent
//! ray only determines to about the square root of the rounding error.

use glam::DVec3;
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;
use whitted::optics::{Ray, T_MIN};
use whitted::shapes::{Plane, Quadric, Shape, Sphere};

mod checks;
mod properties;

/// A uniformly distributed unit vector.
fn unit() -> impl Strategy<Value = DVec3> {
    (-1.0f64..=1.0, 0.0f64..std::f64::consts::TAU).prop_map(|(z, phi)| {
        let s = (1.0 - z * z).sqrt();
        DVec3::new(s * phi.cos(), s * phi.sin(), z)
    })
}

/// A point in the cube [−half, half]³.
fn point(half: f64) -> impl Strategy<Value = DVec3> {
    (-half..half, -half..half, -half..half).prop_map(|(x, y, z)| DVec3::new(x, y, z))
}

/// Roots of t² + 2·b·t + c = 0 (a unit-length direction makes the t² coefficient 1, or
/// `a` in general), ascending, and whether the line is so close to tangent that hitting
/// and missing are both right.
fn quadratic(a: f64, half_b: f64, c: f64, scale2: f64) -> (Vec<f64>, bool) {
    let disc = half_b * half_b - a * c;
    // Rounding in b² and a·c is about 1e-15 of the squared size of the problem.
    let grazing = disc.abs() <= 1e-12 * scale2;
    if disc < 0.0 {
        return (Vec::new(), grazing);
    }
    let q = -(half_b + disc.sqrt().copysign(half_b));
    if q == 0.0 {
        return (vec![0.0, 0.0], grazing);
    }
    let (t1, t2) = (q / a, c / q);
    (vec![t1.min(t2), t1.max(t2)], grazing)
}

/// What a hit must satisfy, shape by shape.
struct Expect<'a> {
    /// Signed distance-like error of a point from the surface (0 on it).
    surface_error: &'a dyn Fn(DVec3) -> f64,
    /// The outward unit normal at a surface point, computed independently.
    outward: &'a dyn Fn(DVec3) -> DVec3,
    /// The reference roots (any sign) and whether the ray grazes the surface.
    roots: (Vec<f64>, bool),
    /// The size of the problem: coordinates, radius, distances.
    scale: f64,
    /// How far t may be from a reference root.
    t_tol: f64,
    /// The radius: a hit point off the surface by e has a normal (C→P / R) whose length
    /// is off 1 by e / R, which for a small sphere far away exceeds 1e-9.
    radius: f64,
}

fn check(shape: &Shape, ray: &Ray, e: &Expect) -> Result<(), TestCaseError> {
    let (roots, grazing) = &e.roots;
    // Roots clearly past the epsilon; one within t_tol of it may go either way.
    let ahead: Vec<f64> = roots
        .iter()
        .copied()
        .filter(|&t| t > T_MIN + e.t_tol)
        .collect();
    let hit = shape.hit(ray, f64::INFINITY);
    // Shadow rays see the same first crossing as `hit`.
    prop_assert_eq!(shape.crossings(ray, f64::INFINITY).next(), hit);
    let Some(t) = hit else {
        prop_assert!(
            ahead.is_empty() || *grazing,
            "missed, but the surface is crossed at {:?}",
            ahead
        );
        return Ok(());
    };
    prop_assert!(t > T_MIN, "t = {} is not past the epsilon", t);
    let p = ray.at(t);
    let err = (e.surface_error)(p);
    prop_assert!(
        err.abs() <= 1e-9 * e.scale,
        "t = {}, p = {} is {} off the surface (scale {})",
        t,
        p,
        err,
        e.scale
    );
    // t is one of the roots, and no root clearly ahead of the epsilon comes before it.
    prop_assert!(
        roots.iter().any(|&r| (r - t).abs() <= e.t_tol) || *grazing,
        "t = {} is none of the roots {:?}",
        t,
        roots
    );
    if let Some(&first) = ahead.first() {
        prop_assert!(
            t <= first + e.t_tol,
            "t = {} skipped the nearer root {} (roots {:?})",
            t,
            first,
            roots
        );
    }
    // The normal is unit and outward, to within what the point's own error allows (found
    // with a sphere of radius 0.056 at 118 units: |n| − 1 = 1.08e-9).
    let n = shape.normal(p);
    let n_tol = 1e-9 + 2.0 * err.abs() / e.radius;
    prop_assert!((n.length() - 1.0).abs() <= n_tol, "|n| = {}", n.length());
    let want = (e.outward)(p);
    prop_assert!(
        (n - want).length() <= 1e-9 * e.scale + n_tol,
        "normal {} at {}, expected {}",
        n,
        p,
        want
    );
    Ok(())
}

/// The sphere's checks for one ray.
fn check_sphere(c: DVec3, r: f64, ray: &Ray) -> Result<Option<f64>, TestCaseError> {
    let shape = Shape::Sphere(Sphere::new(c, r));
    let oc = ray.origin - c;
    let scale = 1.0 + ray.origin.abs().max_element() + c.abs().max_element() + r;
    let roots = quadratic(
        1.0,
        oc.dot(ray.dir),
        oc.length_squared() - r * r,
        scale * scale,
    );
    let e = Expect {
        surface_error: &|p| (p - c).length() - r,
        outward: &|p| (p - c).normalize(),
        roots,
        scale,
        t_tol: 1e-6 * scale,
        radius: r,
    };
    check(&shape, ray, &e)?;
    Ok(shape.hit(ray, f64::INFINITY))
}

/// The cylinder's checks for one ray (`axis` unit).
fn check_cylinder(axis: DVec3, q: DVec3, r: f64, ray: &Ray) -> Result<Option<f64>, TestCaseError> {
    let shape = Shape::Quadric(Quadric::cylinder(axis, q, r));
    let perp = |v: DVec3| v - axis * v.dot(axis);
    let (o, d) = (perp(ray.origin - q), perp(ray.dir));
    let a = d.length_squared();
    let base = 1.0 + ray.origin.abs().max_element() + q.abs().max_element() + r;
    // Far hits (a ray nearly along the axis) are as far as 2·base/|d⊥|.
    let scale = base + 2.0 * base / a.sqrt().max(1e-300);
    let roots = if a < 1e-14 {
        // Along the axis: no crossing at all (or the whole line on the surface).
        (Vec::new(), true)
    } else {
        quadratic(a, o.dot(d), o.length_squared() - r * r, base * base)
    };
    let e = Expect {
        surface_error: &|p| perp(p - q).length() - r,
        outward: &|p| perp(p - q).normalize(),
        roots,
        scale,
        t_tol: 1e-6 * scale,
        radius: r,
    };
    check(&shape, ray, &e)?;
    Ok(shape.hit(ray, f64::INFINITY))
}

/// A unit vector perpendicular to `axis`, from any vector not parallel to it.
fn perpendicular(axis: DVec3, w: DVec3) -> Option<DVec3> {
    (w - axis * w.dot(axis)).try_normalize()
}
