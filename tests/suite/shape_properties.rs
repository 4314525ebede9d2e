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

proptest! {
    #![proptest_config(ProptestConfig::with_cases(3000))]

    #[test]
    fn sphere_hits_are_on_the_surface_and_nearest(
        c in point(50.0),
        r in 0.05f64..20.0,
        origin in point(60.0),
        towards in unit(),
        spread in 0.0f64..1.3,
        aimed in prop::bool::weighted(0.8),
        random_dir in unit(),
    ) {
        // Aimed at a point inside or just around the sphere, or anywhere.
        let dir = if aimed {
            (c + towards * r * spread - origin).try_normalize()
        } else {
            Some(random_dir)
        };
        prop_assume!(dir.is_some());
        let ray = Ray::new(origin, dir.unwrap());
        let hit = check_sphere(c, r, &ray)?;
        // From outside, the first hit enters: the outward normal faces the ray. Only from
        // farther than the epsilon: an origin within T_MIN of the surface has its entry
        // taken for a self-intersection, and its first hit is the exit (found with an
        // origin 0.005 outside, saved in shape_properties.proptest-regressions).
        if let Some(t) = hit {
            if (origin - c).length() > r + 2.0 * T_MIN {
                let n = Shape::Sphere(Sphere::new(c, r)).normal(ray.at(t));
                prop_assert!(n.dot(ray.dir) <= 1e-6, "entering, yet n·d = {}", n.dot(ray.dir));
            }
        }
    }

    #[test]
    fn a_ray_from_inside_a_sphere_always_leaves_it(
        c in point(50.0),
        r in 0.5f64..20.0,
        towards in unit(),
        depth in 0.0f64..0.9,
        dir in unit(),
    ) {
        // At least 0.05 inside the surface, so the exit is past the epsilon.
        let origin = c + towards * r * depth;
        let ray = Ray::new(origin, dir);
        let hit = check_sphere(c, r, &ray)?;
        prop_assert!(hit.is_some(), "no exit from inside");
        let t = hit.unwrap();
        let n = Shape::Sphere(Sphere::new(c, r)).normal(ray.at(t));
        prop_assert!(n.dot(dir) > 0.0, "leaving, yet n·d = {}", n.dot(dir));
        prop_assert!(t <= 2.0 * r * (1.0 + 1e-9));
    }

    #[test]
    fn plane_hits_are_on_the_plane(
        p0 in point(50.0),
        normal_dir in unit(),
        normal_len in 0.01f64..100.0,
        origin in point(60.0),
        offset in unit(),
        reach in 0.0f64..40.0,
        aimed in prop::bool::weighted(0.8),
        random_dir in unit(),
    ) {
        let given = normal_dir * normal_len;
        let n = normal_dir; // the given normal, normalised
        let shape = Shape::Plane(Plane::new(p0, given));
        // Aim at a point of the plane, or anywhere.
        let target = p0 + (offset - n * offset.dot(n)) * reach;
        let dir = if aimed { (target - origin).try_normalize() } else { Some(random_dir) };
        prop_assume!(dir.is_some());
        let ray = Ray::new(origin, dir.unwrap());
        let denom = n.dot(ray.dir);
        let scale = 1.0 + origin.abs().max_element() + p0.abs().max_element() + reach;
        let t_ref = n.dot(p0 - origin) / denom;
        // Near-parallel rays may count as parallel (no root): both are right.
        let roots = if denom.abs() < 1e-9 { (vec![], true) } else { (vec![t_ref], false) };
        let e = Expect {
            surface_error: &|p| n.dot(p - p0),
            outward: &|_| n,
            roots,
            scale: scale + if denom.abs() < 1e-9 { 0.0 } else { t_ref.abs() },
            t_tol: 1e-9 * scale / denom.abs().max(1e-300),
            radius: f64::INFINITY,
        };
        check(&shape, &ray, &e)?;
        // Two-sided: the normal given, normalised, whichever side the ray comes from.
        prop_assert!((shape.normal(origin) - given.normalize()).length() < 1e-15);
    }

    #[test]
    fn cylinder_hits_are_on_the_surface_and_nearest(
        axis in unit(),
        q in point(50.0),
        r in 0.05f64..10.0,
        origin in point(60.0),
        along in -30.0f64..30.0,
        around in unit(),
        spread in 0.0f64..1.3,
        aimed in prop::bool::weighted(0.8),
        random_dir in unit(),
    ) {
        let side = perpendicular(axis, around);
        prop_assume!(side.is_some());
        let target = q + axis * along + side.unwrap() * r * spread;
        let dir = if aimed { (target - origin).try_normalize() } else { Some(random_dir) };
        prop_assume!(dir.is_some());
        let ray = Ray::new(origin, dir.unwrap());
        let hit = check_cylinder(axis, q, r, &ray)?;
        if let Some(t) = hit {
            let shape = Shape::Quadric(Quadric::cylinder(axis, q, r));
            let n = shape.normal(ray.at(t));
            // Perpendicular to the axis.
            prop_assert!(n.dot(axis).abs() < 1e-9, "n·axis = {}", n.dot(axis));
            // From outside, the first hit enters; only from farther than the epsilon, as
            // for the sphere (found with an origin 0.0068 outside).
            let o = (origin - q) - axis * (origin - q).dot(axis);
            if o.length() > r + 2.0 * T_MIN {
                prop_assert!(n.dot(ray.dir) <= 1e-6, "entering, yet n·d = {}", n.dot(ray.dir));
            }
        }
    }

    #[test]
    fn a_cylinder_given_a_long_axis_is_the_same_cylinder(
        axis in unit(),
        len in 0.001f64..1000.0,
        q in point(50.0),
        r in 0.05f64..10.0,
        origin in point(60.0),
        dir in unit(),
    ) {
        // The axis need not be unit: the surface and normal do not depend on its length.
        let a = Quadric::cylinder(axis, q, r);
        let b = Quadric::cylinder(axis * len, q, r);
        let ray = Ray::new(origin, dir);
        let (ta, tb) = (Shape::Quadric(a).hit(&ray, f64::INFINITY), Shape::Quadric(b).hit(&ray, f64::INFINITY));
        match (ta, tb) {
            (Some(x), Some(y)) => prop_assert!((x - y).abs() <= 1e-9 * (1.0 + x.abs()), "{} vs {}", x, y),
            (None, None) => {}
            // Only a grazing ray may be found by one and not the other.
            (x, y) => {
                let t = x.or(y).unwrap();
                let p = ray.at(t);
                let radial = (p - q) - axis * (p - q).dot(axis);
                prop_assert!(radial.normalize().dot(dir).abs() < 1e-5, "{:?} vs {:?}", x, y);
            }
        }
    }

    #[test]
    fn a_ray_from_inside_a_cylinder_always_leaves_it(
        axis in unit(),
        q in point(50.0),
        r in 0.5f64..10.0,
        along in -30.0f64..30.0,
        around in unit(),
        depth in 0.0f64..0.9,
        dir in unit(),
    ) {
        let side = perpendicular(axis, around);
        prop_assume!(side.is_some());
        // Not along the axis (that ray never meets the surface).
        let d_perp = (dir - axis * dir.dot(axis)).length();
        prop_assume!(d_perp > 1e-3);
        let origin = q + axis * along + side.unwrap() * r * depth;
        let ray = Ray::new(origin, dir);
        let hit = check_cylinder(axis, q, r, &ray)?;
        prop_assert!(hit.is_some(), "no exit from inside");
        let t = hit.unwrap();
        let n = Shape::Quadric(Quadric::cylinder(axis, q, r)).normal(ray.at(t));
        prop_assert!(n.dot(dir) > 0.0, "leaving, yet n·d = {}", n.dot(dir));
        // The exit is within the chord across the cylinder's section.
        prop_assert!(t * d_perp <= 2.0 * r * (1.0 + 1e-9));
    }

    // Secondary rays start on a surface: the epsilon keeps them from finding that surface
    // again at t ≈ 0, and from a convex surface they meet it again only across a chord.
    #[test]
    fn a_ray_leaving_a_sphere_surface_finds_only_the_far_side(
        c in point(50.0),
        r in 0.05f64..20.0,
        at in unit(),
        dir in unit(),
    ) {
        let origin = c + at * r;
        let ray = Ray::new(origin, dir);
        let hit = Shape::Sphere(Sphere::new(c, r)).hit(&ray, f64::INFINITY);
        // The chord from a surface point along d is −2r·(d·at) long.
        let chord = -2.0 * r * dir.dot(at);
        if chord > T_MIN + 1e-6 {
            let t = hit.ok_or_else(|| TestCaseError::fail(format!("no far side at {chord}")))?;
            prop_assert!((t - chord).abs() <= 1e-6 * (1.0 + chord), "t = {}, chord = {}", t, chord);
        } else if chord < T_MIN - 1e-6 {
            prop_assert_eq!(hit, None, "outward or short chord {}", chord);
        }
    }

    #[test]
    fn a_ray_leaving_a_cylinder_surface_finds_only_the_far_side(
        axis in unit(),
        q in point(50.0),
        r in 0.05f64..10.0,
        along in -30.0f64..30.0,
        around in unit(),
        dir in unit(),
    ) {
        let side = perpendicular(axis, around);
        prop_assume!(side.is_some());
        let u = side.unwrap();
        let d_perp = dir - axis * dir.dot(axis);
        prop_assume!(d_perp.length_squared() > 1e-6);
        let origin = q + axis * along + u * r;
        let ray = Ray::new(origin, dir);
        let hit = Shape::Quadric(Quadric::cylinder(axis, q, r)).hit(&ray, f64::INFINITY);
        // |r·u + t·d⊥|² = r² gives t = −2r·(d⊥·u)/|d⊥|².
        let chord = -2.0 * r * d_perp.dot(u) / d_perp.length_squared();
        if chord > T_MIN + 1e-6 {
            let t = hit.ok_or_else(|| TestCaseError::fail(format!("no far side at {chord}")))?;
            prop_assert!((t - chord).abs() <= 1e-6 * (1.0 + chord), "t = {}, chord = {}", t, chord);
        } else if chord < T_MIN - 1e-6 {
            prop_assert_eq!(hit, None, "outward or short chord {}", chord);
        }
    }

    #[test]
    fn a_ray_leaving_a_plane_does_not_hit_it(
        p0 in point(50.0),
        n in unit(),
        offset in unit(),
        reach in 0.0f64..40.0,
        dir in unit(),
    ) {
        let origin = p0 + (offset - n * offset.dot(n)) * reach;
        let hit = Shape::Plane(Plane::new(p0, n)).hit(&Ray::new(origin, dir), f64::INFINITY);
        // The only root is at t ≈ 0 (rounding aside), far below the epsilon.
        prop_assert_eq!(hit, None);
    }
}

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
