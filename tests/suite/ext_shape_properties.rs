//! Properties of the extension's shapes (box, capped cylinder and truncated cone, disc,
//! torus, scaled sphere), each in a random frame, on random rays aimed near them, against
//! a brute-force reference that knows nothing of the solvers: the ray (ahead of its origin) is
//! sampled on a fine grid, each change of an independent inside test (or, for the disc, of the
//! side of its plane) is a crossing, refined by bisection. Every reference crossing must
//! be a root of the shape and every root a reference crossing (up to the slivers the grid
//! cannot see: a root pair closer than two grid steps, an inside stretch shorter than
//! 1e-5), `hit` must be the first root past the epsilon, and the normal at a root must be
//! unit and point out (a step along it leaves the solid).

use glam::{DAffine3, DMat3, DVec3};
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;
use whitted::optics::{Ray, T_MIN};
use whitted::shapes::{AaBox, Capped, Disc, Local, Placed, Shape, Sphere, Torus, Transform};

/// Grid steps along the sampled stretch of the line.
const STEPS: usize = 20_000;

fn vec3(half: f64) -> impl Strategy<Value = DVec3> {
    (-half..half, -half..half, -half..half).prop_map(|(x, y, z)| DVec3::new(x, y, z))
}

fn unit() -> impl Strategy<Value = DVec3> {
    (-1.0f64..=1.0, 0.0f64..std::f64::consts::TAU).prop_map(|(z, phi)| {
        let s = (1.0 - z * z).sqrt();
        DVec3::new(s * phi.cos(), s * phi.sin(), z)
    })
}

/// A frame (scale, rotate, translate) or none, with the test's own affine map.
fn frame() -> impl Strategy<Value = Option<(DVec3, DVec3, DVec3)>> {
    prop::option::of((
        (0.3f64..2.0, 0.3f64..2.0, 0.3f64..2.0).prop_map(|(x, y, z)| DVec3::new(x, y, z)),
        vec3(180.0),
        vec3(3.0),
    ))
}

/// The test's own object-to-world map: T · Rz · Ry · Rx · S.
fn affine(f: Option<(DVec3, DVec3, DVec3)>) -> DAffine3 {
    let Some((s, r, t)) = f else {
        return DAffine3::IDENTITY;
    };
    let r = r.to_radians_vec();
    let rot =
        DMat3::from_rotation_z(r.z) * DMat3::from_rotation_y(r.y) * DMat3::from_rotation_x(r.x);
    DAffine3::from_mat3_translation(rot * DMat3::from_diagonal(s), t)
}

trait Radians {
    fn to_radians_vec(self) -> DVec3;
}
impl Radians for DVec3 {
    fn to_radians_vec(self) -> DVec3 {
        self * (std::f64::consts::PI / 180.0)
    }
}

/// The sign the reference tracks along the line: inside a solid, or in front of a disc's
/// plane (where the annulus test then decides).
type Side<'a> = &'a dyn Fn(DVec3) -> bool;

/// Reference crossings of `side` (in object space through `to_local`) on [−span, span].
fn reference(ray: &Ray, span: f64, to_local: &DAffine3, side: Side) -> Vec<(f64, f64)> {
    let at = |t: f64| side(to_local.transform_point3(ray.at(t)));
    let step = 2.0 * span / STEPS as f64;
    let mut out = Vec::new();
    let mut prev = at(-span);
    for i in 1..=STEPS {
        let t = -span + i as f64 * step;
        let now = at(t);
        if now != prev {
            let (mut a, mut b) = (t - step, t);
            for _ in 0..80 {
                let m = 0.5 * (a + b);
                if at(m) == prev {
                    a = m;
                } else {
                    b = m;
                }
            }
            out.push((0.5 * (a + b), if prev { 1.0 } else { -1.0 }));
        }
        prev = now;
    }
    out
}

fn check(
    shape: &Shape,
    ray: &Ray,
    span: f64,
    to_local: &DAffine3,
    side: Side,
    on_surface: &dyn Fn(DVec3) -> bool,
    solid: bool,
) -> Result<(), TestCaseError> {
    // Only what lies ahead: a sphere reports no roots behind a ray moving away from it.
    let roots: Vec<f64> = shape
        .roots(ray)
        .as_slice()
        .iter()
        .copied()
        .filter(|&t| t > 0.0)
        .collect();
    let crossings: Vec<f64> = reference(ray, span, to_local, side)
        .into_iter()
        .map(|(t, _)| t)
        .filter(|&t| t > 1e-9)
        .filter(|&t| on_surface(to_local.transform_point3(ray.at(t))))
        .collect();
    let step = 2.0 * span / STEPS as f64;
    let tol = 1e-7 * (1.0 + span);
    for (i, &r) in crossings.iter().enumerate() {
        // A stretch inside shorter than 1e-5 is a corner clipped by rounding either way.
        let sliver = crossings
            .iter()
            .enumerate()
            .any(|(j, &o)| j != i && (o - r).abs() < 1e-5);
        prop_assert!(
            sliver || roots.iter().any(|&t| (t - r).abs() <= tol),
            "reference crossing {} is none of the roots {:?} (reference {:?})",
            r,
            roots,
            crossings
        );
    }
    for (i, &t) in roots.iter().enumerate() {
        if t.abs() > span * 0.999 {
            continue;
        }
        let thin = roots
            .iter()
            .enumerate()
            .any(|(j, &o)| j != i && (o - t).abs() < 2.0 * step);
        prop_assert!(
            thin || crossings.iter().any(|&r| (t - r).abs() <= tol),
            "root {} is no reference crossing {:?} (roots {:?})",
            t,
            crossings,
            roots
        );
        let p = ray.at(t);
        let n = shape.normal(p);
        prop_assert!((n.length() - 1.0).abs() < 1e-9, "|n| = {}", n.length());
        if solid && !thin {
            let out = to_local.transform_point3(p + 1e-6 * (1.0 + span) * n);
            prop_assert!(!side(out), "the normal {} at {} points inwards", n, p);
        }
    }
    let first = roots.iter().copied().find(|&t| t > T_MIN);
    prop_assert_eq!(shape.hit(ray, f64::INFINITY), first);
    Ok(())
}

/// A ray from a random point towards a random point near `target` (sometimes from
/// inside: the origin drawn close to the target).
fn ray_near(origin: DVec3, aim: DVec3, target: DVec3, inside: bool) -> Ray {
    let o = if inside {
        target + 0.1 * origin
    } else {
        origin
    };
    let d = (target + aim - o).try_normalize().unwrap_or(DVec3::X);
    Ray::new(o, d)
}

fn placed(local: Local, f: Option<(DVec3, DVec3, DVec3)>) -> (Shape, DAffine3) {
    let m = affine(f);
    let frame = Transform::from_affine(m).unwrap();
    (Shape::Placed(Placed::new(local, frame)), m.inverse())
}

fn span_of(ray: &Ray, m: &DAffine3, reach: f64) -> f64 {
    // Far enough to see every crossing: the origin's distance plus the scaled reach.
    let world_reach = reach
        * m.inverse()
            .matrix3
            .to_cols_array()
            .iter()
            .map(|v| v.abs())
            .sum::<f64>();
    ray.origin.length() + m.inverse().translation.length() + world_reach + 1.0
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn boxes(c in vec3(2.0), h in (0.2f64..2.0, 0.2f64..2.0, 0.2f64..2.0), f in frame(),
             o in vec3(8.0), aim in vec3(2.0), inside in any::<bool>()) {
        let h = DVec3::new(h.0, h.1, h.2);
        let b = AaBox::new(c - h, c + h).unwrap();
        let (shape, to_local) = placed(Local::Box(b), f);
        let ray = ray_near(o, aim, to_local.inverse().transform_point3(c), inside);
        let side = |p: DVec3| ((p - c).abs() - h).max_element() <= 0.0;
        let span = span_of(&ray, &to_local, c.length() + h.length());
        check(&shape, &ray, span, &to_local, &side, &|_| true, true)?;
    }

    #[test]
    fn capped_cones(a in vec3(2.0), b in vec3(2.0), ra in 0.0f64..1.5, rb in 0.0f64..1.5,
                    open in any::<bool>(), f in frame(), o in vec3(8.0), aim in vec3(1.5),
                    inside in any::<bool>()) {
        prop_assume!((a - b).length() > 0.3 && ra.max(rb) > 0.1);
        let c = Capped::new(a, ra, b, rb, !open).unwrap();
        let (shape, to_local) = placed(Local::Capped(c), f);
        let mid = 0.5 * (a + b);
        let ray = ray_near(o, aim, to_local.inverse().transform_point3(mid), inside);
        let (axis, h) = ((b - a).normalize(), (b - a).length());
        let inside_cone = move |p: DVec3| {
            let s = (p - a).dot(axis);
            let radial = (p - a - s * axis).length();
            (0.0..=h).contains(&s) && radial <= ra + (rb - ra) * s / h
        };
        let span = span_of(&ray, &to_local, a.length() + b.length() + ra + rb);
        // Open: only crossings through the side count (not where the line passes an end).
        let on_side = move |p: DVec3| {
            let s = (p - a).dot(axis);
            !open || (s > 1e-7 && s < h - 1e-7)
        };
        check(&shape, &ray, span, &to_local, &inside_cone, &on_side, !open)?;
    }

    #[test]
    fn tori(c in vec3(2.0), axis in unit(), big in 1.0f64..3.0, ratio in 0.05f64..0.9,
            f in frame(), o in vec3(8.0), aim in vec3(3.0), inside in any::<bool>()) {
        let small = big * ratio;
        let t = Torus::new(c, axis, big, small).unwrap();
        let (shape, to_local) = placed(Local::Torus(t), f);
        let ray = ray_near(o, aim, to_local.inverse().transform_point3(c), inside);
        let side = move |p: DVec3| {
            let w = p - c;
            let y = w.dot(axis);
            let rho = (w - y * axis).length();
            (rho - big).powi(2) + y * y <= small * small
        };
        let span = span_of(&ray, &to_local, c.length() + big + small);
        check(&shape, &ray, span, &to_local, &side, &|_| true, true)?;
    }

    #[test]
    fn discs(c in vec3(2.0), n in unit(), radius in 0.2f64..2.0, hole in 0.0f64..1.0,
             f in frame(), o in vec3(8.0), aim in vec3(2.0)) {
        let hole = hole * radius * 0.9;
        let d = Disc::new(c, n, radius, hole).unwrap();
        let (shape, to_local) = placed(Local::Disc(d), f);
        let ray = ray_near(o, aim, to_local.inverse().transform_point3(c), false);
        let front = move |p: DVec3| (p - c).dot(n) >= 0.0;
        let on = move |p: DVec3| {
            let r = (p - c - (p - c).dot(n) * n).length();
            r <= radius && r >= hole
        };
        let span = span_of(&ray, &to_local, c.length() + radius);
        check(&shape, &ray, span, &to_local, &front, &on, false)?;
    }

    #[test]
    fn ellipsoids(c in vec3(2.0), r in 0.2f64..2.0, f in frame(), o in vec3(8.0),
                  aim in vec3(2.0), inside in any::<bool>()) {
        let (shape, to_local) = placed(Local::Sphere(Sphere::new(c, r)), f);
        let ray = ray_near(o, aim, to_local.inverse().transform_point3(c), inside);
        let side = move |p: DVec3| (p - c).length() <= r;
        let span = span_of(&ray, &to_local, c.length() + r);
        check(&shape, &ray, span, &to_local, &side, &|_| true, true)?;
    }
}
