//! Properties of CSG blocks (union, intersection, difference, one level nested) of random
//! spheres, turned boxes, capped cylinders and tori, on random rays aimed at them, against
//! a brute-force reference that knows nothing of the solvers nor of the block's rules of
//! its own: the test's inside tests of the solids, combined by the operations, sampled on
//! a fine grid along the ray; each change is a crossing, refined by bisection.
//!
//! Without a union in the tree the block's surface is exactly the boundary of its solid:
//! its crossings past the epsilon (the first four, `roots`) must be the reference's first
//! ones, one for one (up to slivers shorter than 1e-5). A union keeps its inner surfaces
//! too: there every reference crossing before the fourth root must be a root, and every
//! root a crossing of some solid. A stretch shorter than the grid's step can fall between
//! two samples: a root the reference lacks is still a crossing where the inside test
//! differs a tolerance before and after it. At every root the grid found the block's
//! normal is unit and points out of the combined solid (a step of 1e-6, 1e-7 or 1e-8 of
//! the span off the surface, the smaller where a crease is nearer than the larger);
//! `hit` is the first root.

use glam::{DAffine3, DMat3, DVec3};
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;
use std::rc::Rc;
use whitted::bump::Bump;
use whitted::object::{Highlight, Material, Object};
use whitted::optics::{Ray, T_MIN};
use whitted::shapes::csg::{Csg, Node, Op};
use whitted::shapes::{AaBox, Capped, Local, Placed, Shape, Sphere, Torus, Transform};
use whitted::texture::Texture;

/// Grid steps along the sampled stretch of the line.
const STEPS: usize = 20_000;

/// A solid as drawn and the test's own inside test.
type Solid = (Shape, Rc<dyn Fn(DVec3) -> bool>);

fn vec3(half: f64) -> impl Strategy<Value = DVec3> {
    (-half..half, -half..half, -half..half).prop_map(|(x, y, z)| DVec3::new(x, y, z))
}

/// One random solid near the origin, by kind 0..4.
fn solid(kind: u8, c: DVec3, size: DVec3, angles: DVec3) -> Solid {
    let (sx, sy, sz) = (0.4 + size.x.abs(), 0.4 + size.y.abs(), 0.4 + size.z.abs());
    match kind {
        0 => {
            let s = Shape::Sphere(Sphere::new(c, sx));
            (s, Rc::new(move |p: DVec3| (p - c).length() < sx))
        }
        1 => {
            // A box [−h, h] turned by `angles` (degrees, x then y then z) and moved to c.
            let h = DVec3::new(sx, sy, sz);
            let r = angles * (std::f64::consts::PI / 180.0);
            let rot = DMat3::from_rotation_z(r.z)
                * DMat3::from_rotation_y(r.y)
                * DMat3::from_rotation_x(r.x);
            let m = DAffine3::from_mat3_translation(rot, c);
            let f = Transform::from_affine(m).unwrap();
            let b = AaBox::new(-h, h).unwrap();
            let inv = m.inverse();
            let shape = Shape::Placed(Placed::new(Local::Box(b), f));
            (
                shape,
                Rc::new(move |p: DVec3| {
                    let q = inv.transform_point3(p).abs();
                    q.x < h.x && q.y < h.y && q.z < h.z
                }),
            )
        }
        2 => {
            // A capped cylinder of radius sx from c − (0, sy, 0) to c + (0, sy, 0).
            let (a, b) = (c - DVec3::Y * sy, c + DVec3::Y * sy);
            let cap = Capped::new(a, sx, b, sx, true).unwrap();
            let shape = Shape::Placed(Placed::new(Local::Capped(cap), Transform::IDENTITY));
            (
                shape,
                Rc::new(move |p: DVec3| {
                    let w = p - c;
                    w.y.abs() < sy && (w.x * w.x + w.z * w.z) < sx * sx
                }),
            )
        }
        _ => {
            // A torus about z, R = 1 + sx, r = 0.3 + sy/4.
            let (big, small) = (1.0 + sx, 0.3 + 0.25 * sy.min(2.0));
            let t = Torus::new(c, DVec3::Z, big, small).unwrap();
            let shape = Shape::Placed(Placed::new(Local::Torus(t), Transform::IDENTITY));
            (
                shape,
                Rc::new(move |p: DVec3| {
                    let w = p - c;
                    let rho = (w.x * w.x + w.y * w.y).sqrt();
                    (rho - big).powi(2) + w.z * w.z < small * small
                }),
            )
        }
    }
}

fn leaf(shape: Shape) -> Node {
    Node::Leaf(Object {
        shape,
        texture: Texture::Uniform(DVec3::ONE),
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

fn op(i: u8) -> Op {
    [Op::Union, Op::Intersection, Op::Difference][usize::from(i % 3)]
}

/// The reference's rule for an operation over the children's inside tests.
fn combine(op: Op, kids: Vec<Rc<dyn Fn(DVec3) -> bool>>) -> Rc<dyn Fn(DVec3) -> bool> {
    Rc::new(move |p| match op {
        Op::Union => kids.iter().any(|k| k(p)),
        Op::Intersection => kids.iter().all(|k| k(p)),
        Op::Difference => kids[0](p) && !kids[1..].iter().any(|k| k(p)),
    })
}

/// Reference crossings of `inside` along the ray on (0, span].
fn reference(ray: &Ray, span: f64, inside: &dyn Fn(DVec3) -> bool) -> Vec<f64> {
    let at = |t: f64| inside(ray.at(t));
    let step = span / STEPS as f64;
    let mut out = Vec::new();
    let mut prev = at(0.0);
    for i in 1..=STEPS {
        let t = i as f64 * step;
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
            out.push(0.5 * (a + b));
        }
        prev = now;
    }
    out
}

fn check(
    shape: &Shape,
    ray: &Ray,
    inside: &dyn Fn(DVec3) -> bool,
    leaves: &[Shape],
    exact: bool,
) -> Result<(), TestCaseError> {
    let span = ray.origin.length() + 12.0;
    let roots: Vec<f64> = shape.roots(ray).as_slice().to_vec();
    prop_assert!(roots.iter().all(|&t| t > T_MIN), "{:?}", roots);
    let crossings: Vec<f64> = reference(ray, span, inside)
        .into_iter()
        .filter(|&t| t > T_MIN + 1e-6)
        .collect();
    let tol = 1e-7 * (1.0 + span);
    let sliver = |list: &[f64], i: usize| {
        list.iter()
            .enumerate()
            .any(|(j, &o)| j != i && (o - list[i]).abs() < 1e-5)
    };
    let is_root = |r: f64| roots.iter().any(|&t| (t - r).abs() <= tol);
    // A stretch shorter than the grid's step can fall between two samples: a root the
    // list lacks is still a crossing where the inside test differs on its two sides.
    let flips = |t: f64| inside(ray.at(t - tol)) != inside(ray.at(t + tol));
    let listed = |t: f64| crossings.iter().any(|&r| (t - r).abs() <= tol);
    let is_crossing = |t: f64| listed(t) || flips(t);
    // Reference crossings the roots must show: all, or those before a full list's last.
    let horizon = if roots.len() == 4 {
        roots[3] + tol
    } else {
        f64::INFINITY
    };
    for (i, &r) in crossings.iter().enumerate() {
        if r <= horizon && !sliver(&crossings, i) {
            prop_assert!(
                is_root(r),
                "crossing {} is none of the roots {:?} (reference {:?})",
                r,
                roots,
                crossings
            );
        }
    }
    for (i, &t) in roots.iter().enumerate() {
        let thin = sliver(&roots, i);
        if exact && !thin {
            prop_assert!(
                is_crossing(t),
                "root {} is no crossing {:?} (roots {:?})",
                t,
                crossings,
                roots
            );
        }
        // Every root lies on some solid's surface.
        let on_leaf = leaves.iter().any(|l| {
            let mut probe = *ray;
            probe.t_min = f64::NEG_INFINITY;
            l.roots(&probe)
                .as_slice()
                .iter()
                .any(|&u| (u - t).abs() <= tol)
        });
        prop_assert!(on_leaf, "root {} is on no solid", t);
        // The normal is checked a step off the surface: on stretches the grid saw.
        if listed(t) && !thin {
            let p = ray.at(t);
            let n = shape.normal(p);
            prop_assert!((n.length() - 1.0).abs() < 1e-9, "|n| = {}", n.length());
            // A step off the surface, out then in; near a crease of the combined solid
            // the largest step can land beyond the crease, so a smaller one may answer.
            let points_out = |k: f64| {
                let e = k * (1.0 + span);
                !inside(p + e * n) && inside(p - e * n)
            };
            prop_assert!(
                [1e-6, 1e-7, 1e-8].into_iter().any(points_out),
                "normal {} at {} points in",
                n,
                p
            );
        }
    }
    prop_assert_eq!(shape.hit(ray, f64::INFINITY), roots.first().copied());
    Ok(())
}

#[derive(Clone, Debug)]
struct Spec {
    kind: u8,
    c: DVec3,
    size: DVec3,
    angles: DVec3,
}

fn spec() -> impl Strategy<Value = Spec> {
    (0u8..4, vec3(1.5), vec3(1.2), vec3(180.0)).prop_map(|(kind, c, size, angles)| Spec {
        kind,
        c,
        size,
        angles,
    })
}

fn build(s: &Spec) -> Solid {
    solid(s.kind, s.c, s.size, s.angles)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    #[test]
    fn blocks_of_two_or_three(outer in 0u8..3, a in spec(), b in spec(), c in prop::option::of(spec()),
                              o in vec3(9.0), aim in vec3(1.5), from_inside in any::<bool>()) {
        let mut solids = vec![build(&a), build(&b)];
        solids.extend(c.as_ref().map(build));
        let leaves: Vec<Shape> = solids.iter().map(|s| s.0.clone()).collect();
        let nodes: Vec<Node> = leaves.iter().cloned().map(leaf).collect();
        let tests: Vec<_> = solids.iter().map(|s| s.1.clone()).collect();
        let op = op(outer);
        let csg = Csg::new(op, nodes).unwrap();
        let shape = Shape::Csg(std::sync::Arc::new(csg));
        let inside = combine(op, tests);
        let origin = if from_inside { 0.1 * o } else { o };
        let dir = (aim - origin).try_normalize().unwrap_or(DVec3::X);
        let ray = Ray::new(origin, dir);
        check(&shape, &ray, &*inside, &leaves, op != Op::Union)?;
    }

    #[test]
    fn nested_blocks(outer in 0u8..3, inner in 0u8..3, a in spec(), b in spec(), c in spec(),
                     o in vec3(9.0), aim in vec3(1.5), swap in any::<bool>()) {
        let solids = [build(&a), build(&b), build(&c)];
        let leaves: Vec<Shape> = solids.iter().map(|s| s.0.clone()).collect();
        let (op1, op2) = (op(outer), op(inner));
        let nested = Csg::new(op2, vec![leaf(leaves[1].clone()), leaf(leaves[2].clone())]).unwrap();
        let nested_in = combine(op2, vec![solids[1].1.clone(), solids[2].1.clone()]);
        // The nested block first or second (a difference's cutter or its base).
        let (nodes, tests) = if swap {
            (vec![Node::Csg(nested), leaf(leaves[0].clone())], vec![nested_in, solids[0].1.clone()])
        } else {
            (vec![leaf(leaves[0].clone()), Node::Csg(nested)], vec![solids[0].1.clone(), nested_in])
        };
        let shape = Shape::Csg(std::sync::Arc::new(Csg::new(op1, nodes).unwrap()));
        let inside = combine(op1, tests);
        let dir = (aim - o).try_normalize().unwrap_or(DVec3::X);
        let ray = Ray::new(o, dir);
        let exact = op1 != Op::Union && op2 != Op::Union;
        check(&shape, &ray, &*inside, &leaves, exact)?;
    }
}
