//! Shafts by hand, and against the brute force: where a shaft is clear, no shadow ray
//! from its point to any point of its light meets a primitive.

use super::*;
use crate::accel::bvh::Prim;
use crate::optics::Ray;
use crate::shapes::Sphere;
use proptest::prelude::*;

/// The square light of side 2 at height 5 over the origin, its corners in order.
pub(super) fn square() -> [DVec3; 4] {
    [
        DVec3::new(-1.0, 5.0, -1.0),
        DVec3::new(1.0, 5.0, -1.0),
        DVec3::new(1.0, 5.0, 1.0),
        DVec3::new(-1.0, 5.0, 1.0),
    ]
}

#[test]
fn a_box_is_missed_beyond_the_hull_or_outside_a_face() {
    let s = Shaft::new(DVec3::ZERO, &square()).unwrap();
    assert_eq!(s.planes.len(), 4);
    let d = 1e-5;
    // Beyond the hull's box (x up to 1): missed.
    assert!(s.misses(DVec3::new(9.5, 1.5, -0.5), DVec3::new(10.5, 2.5, 0.5), d));
    // Around the axis: met.
    assert!(!s.misses(DVec3::new(-0.1, 2.0, -0.1), DVec3::new(0.1, 2.1, 0.1), d));
    // Inside the hull's box but outside the face through the origin, (1, 5, −1) and
    // (1, 5, 1), which is the plane x = y/5: at y ≤ 1.5 the hull reaches x = 0.3, the
    // box starts at x = 0.5. Missed by the plane alone.
    assert!(s.misses(DVec3::new(0.5, 1.0, -0.1), DVec3::new(0.6, 1.5, 0.1), d));
    // The same box moved to x = 0.25 crosses the face: met.
    assert!(!s.misses(DVec3::new(0.25, 1.0, -0.1), DVec3::new(0.35, 1.5, 0.1), d));
    // An empty slot's box (+∞ to −∞) is always missed.
    assert!(s.misses(DVec3::INFINITY, DVec3::NEG_INFINITY, d));
}

#[test]
fn a_grid_one_point_wide_and_a_point_in_the_lights_plane() {
    // Corners pairwise equal (a light of 1 × n points): two planes, both holding the
    // flat hull, and boxes off that plane missed.
    let c = square();
    let line = [c[0], c[1], c[1], c[0]];
    let s = Shaft::new(DVec3::ZERO, &line).unwrap();
    assert_eq!(s.planes.len(), 2);
    assert!(s.misses(DVec3::new(-0.1, 2.0, 0.5), DVec3::new(0.1, 2.1, 0.6), 1e-5));
    // The point in the light's plane: a flat hull, the same.
    let s = Shaft::new(DVec3::new(3.0, 5.0, 0.0), &c).unwrap();
    assert!(s.misses(DVec3::new(0.0, 5.5, 0.0), DVec3::new(0.5, 6.0, 0.5), 1e-5));
    assert!(!s.misses(DVec3::new(1.5, 4.9, -0.1), DVec3::new(1.6, 5.1, 0.1), 1e-5));
    // Out of range: no shaft.
    assert!(Shaft::new(DVec3::splat(1e19), &c).is_none());
    assert!(Shaft::new(DVec3::NAN, &c).is_none());
}

/// `n` spheres at the given centres and radii, as a tree.
fn tree(balls: &[(DVec3, f64)]) -> Bvh<Prim> {
    let prims = balls
        .iter()
        .enumerate()
        .map(|(i, &(c, r))| Prim {
            sphere: Sphere::new(c, r),
            index: i as u32,
            glass: false,
            opaque: true,
        })
        .collect();
    Bvh::build(prims, Prim::bounds)
}

fn v3() -> impl Strategy<Value = DVec3> {
    (-4.0f64..4.0, -4.0f64..4.0, -4.0f64..4.0).prop_map(|(x, y, z)| DVec3::new(x, y, z))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    /// Random spheres, a random point and a random parallelogram light of 5 × 5 points:
    /// where the tree says the shaft is clear, none of the 25 shadow rays meets any
    /// sphere (each tested exactly, one by one).
    #[test]
    fn a_clear_shaft_holds_no_hit(
        balls in proptest::collection::vec((v3(), 0.05f64..0.3), 13..30),
        p in v3(),
        centre in v3(),
        a1 in v3(),
        a2 in v3(),
    ) {
        let bvh = tree(&balls);
        let at = |i: f64, j: f64| centre + a1 * (i - 0.5) + a2 * (j - 0.5);
        let corners = [at(0.0, 0.0), at(1.0, 0.0), at(1.0, 1.0), at(0.0, 1.0)];
        let shaft = Shaft::new(p, &corners).unwrap();
        if bvh.shaft_clear(&shaft, |_| false) {
            for i in 0..5 {
                for j in 0..5 {
                    let q = at(f64::from(i) / 4.0, f64::from(j) / 4.0);
                    let to = q - p;
                    let dist = to.length();
                    prop_assume!(dist > 1e-9);
                    let ray = Ray::new(p, to / dist).with_t_min(1e-9);
                    for (k, &(c, r)) in balls.iter().enumerate() {
                        let hit = Sphere::new(c, r).hit(&ray, dist);
                        prop_assert!(hit.is_none(), "ball {k} hit at {hit:?} towards {q}");
                    }
                }
            }
        }
    }
}

#[test]
fn clear_and_met_shafts_both_occur() {
    // The property above must not pass vacuously: a row of balls along x at y = 2, the
    // light above; a point under the row's far end is shadowed, one far off is clear.
    let balls: Vec<(DVec3, f64)> = (0..20)
        .map(|i| (DVec3::new(3.0 * f64::from(i), 2.0, 0.0), 0.5))
        .collect();
    let bvh = tree(&balls);
    let clear = |p: DVec3| bvh.shaft_clear(&Shaft::new(p, &square()).unwrap(), |_| false);
    assert!(!clear(DVec3::ZERO));
    assert!(clear(DVec3::new(0.0, 0.0, 30.0)));
    // A flat list (too few primitives for a tree) is clear only when empty.
    assert!(!tree(&balls[..3]).shaft_clear(&Shaft::new(DVec3::ZERO, &square()).unwrap(), |_| false));
    assert!(tree(&[]).shaft_clear(&Shaft::new(DVec3::ZERO, &square()).unwrap(), |_| false));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1000))]

    /// A random plane, a shaft's point on it (up to rounding) or off it, and a random
    /// light: where `misses_plane` says so, none of the 25 rays meets the plane as
    /// `Plane::hit` tests it.
    #[test]
    fn a_missed_plane_is_met_by_no_ray(
        point in v3(),
        normal in v3(),
        along in v3(),
        off in prop_oneof![Just(0.0), -1.0f64..1.0],
        centre in v3(),
        a1 in v3(),
        a2 in v3(),
        t_min in prop_oneof![Just(0.0), Just(1e-9), Just(1e-6), Just(1e-3)],
    ) {
        prop_assume!(normal.length() > 1e-3);
        let plane = crate::shapes::Plane::new(point, normal);
        let n = plane.normal();
        // A point of the plane (as rounding leaves it), moved `off` along the normal.
        let p = point + (along - n * n.dot(along)) + n * off;
        let at = |i: f64, j: f64| centre + a1 * (i - 0.5) + a2 * (j - 0.5);
        let corners = [at(0.0, 0.0), at(1.0, 0.0), at(1.0, 1.0), at(0.0, 1.0)];
        let shaft = Shaft::new(p, &corners).unwrap();
        if shaft.misses_plane(plane.point, n, t_min) {
            for i in 0..5 {
                for j in 0..5 {
                    let to = at(f64::from(i) / 4.0, f64::from(j) / 4.0) - p;
                    let dist = to.length();
                    prop_assume!(dist > 0.0);
                    let ray = Ray::new(p, to / dist).with_t_min(t_min);
                    prop_assert_eq!(plane.hit(&ray, dist), None);
                }
            }
        }
    }
}

#[test]
fn a_floor_point_under_a_light_misses_the_floor() {
    // The floor y = 0 and the square light above: from a point on it (or a hair under
    // it, as rounding leaves hit points) every ray goes up and starts within t_min.
    let s = Shaft::new(DVec3::new(3.0, 0.0, 1.0), &square()).unwrap();
    assert!(s.misses_plane(DVec3::ZERO, DVec3::Y, 1e-6));
    let s = Shaft::new(DVec3::new(3.0, -1e-15, 1.0), &square()).unwrap();
    assert!(s.misses_plane(DVec3::ZERO, DVec3::Y, 1e-6));
    // With t_min 0 a point a hair under the floor would meet it: not missed.
    assert!(!s.misses_plane(DVec3::ZERO, DVec3::Y, 0.0));
    // A wall x = 2 between the point (x = 3) and the light (x ≤ 1): not missed.
    assert!(!s.misses_plane(DVec3::new(2.0, 0.0, 0.0), DVec3::X, 1e-6));
    // A wall x = 5 behind the point: missed (every ray moves away from it).
    assert!(s.misses_plane(DVec3::new(5.0, 0.0, 0.0), DVec3::X, 1e-6));
}

/// A wide node holding the boxes `b` (low and high corners) in its first slots, the
/// rest empty.
pub(super) fn node_of(b: &[(DVec3, DVec3)]) -> WideNode {
    let mut n = WideNode {
        b: [[[f32::INFINITY; WIDTH]; 3], [[f32::NEG_INFINITY; WIDTH]; 3]],
        child: [0; WIDTH],
        count: [0; WIDTH],
    };
    for (s, (lo, hi)) in b.iter().enumerate() {
        for axis in 0..3 {
            n.b[0][axis][s] = down(lo[axis]);
            n.b[1][axis][s] = up(hi[axis]);
        }
    }
    n
}

#[test]
fn the_lanes_miss_the_boxes_by_hand_as_the_f64_test_does() {
    // The boxes of the first test, in slots 0 to 3: missed beyond the hull, met, missed
    // by a face alone, met; slots 4 to 7 empty, missed.
    let s = Shaft::new(DVec3::ZERO, &square()).unwrap();
    let n = node_of(&[
        (DVec3::new(9.5, 1.5, -0.5), DVec3::new(10.5, 2.5, 0.5)),
        (DVec3::new(-0.1, 2.0, -0.1), DVec3::new(0.1, 2.1, 0.1)),
        (DVec3::new(0.5, 1.0, -0.1), DVec3::new(0.6, 1.5, 0.1)),
        (DVec3::new(0.25, 1.0, -0.1), DVec3::new(0.35, 1.5, 0.1)),
    ]);
    let q = s.in_lanes(1e-5, 10.5);
    assert_eq!(Narrow.misses(&Narrow.shaft(&q), &n), 0b1111_0101);
}

#[test]
fn the_lanes_widen_the_shaft_by_delta_and_no_more_than_their_allowance() {
    // The face x = y/5 of the first test (unit normal (5, −1, 0)/√26, offset 0): a box
    // whose corner least far along it, (x, 1.5), lies 0.9δ outside is met (the f64 test
    // widens by δ, and so must the lanes: their own allowance, (scale + 1)·2⁻²⁰, is
    // 0.58δ here); one 4δ outside is missed. The same at the hull's far edge (x up to
    // 1 at y = 5): x from 1 + 0.9δ met, from 1 + 4δ missed.
    let s = Shaft::new(DVec3::ZERO, &square()).unwrap();
    let (delta, scale) = (1e-5, 5.1);
    let at = |k: f64| {
        let x = 0.3 + 26f64.sqrt() * k * delta / 5.0;
        (DVec3::new(x, 1.0, -0.1), DVec3::new(x + 0.1, 1.5, 0.1))
    };
    let beyond = |k: f64| {
        let x = 1.0 + k * delta;
        (DVec3::new(x, 4.9, -0.1), DVec3::new(x + 0.1, 5.0, 0.1))
    };
    let b = [at(0.9), at(4.0), beyond(0.9), beyond(4.0)];
    for (k, &(lo, hi)) in b.iter().enumerate() {
        assert_eq!(s.misses(lo, hi, delta), k % 2 == 1, "box {k}");
    }
    let q = s.in_lanes(delta, scale);
    assert_eq!(Narrow.misses(&Narrow.shaft(&q), &node_of(&b)), 0b1111_1010);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    /// Random boxes about a random shaft from a point to a parallelogram: every box the
    /// lanes find beyond the shaft, the f64 test (`Shaft::misses`, with the same δ)
    /// finds beyond it too; so a shaft is never called clear that the f64 walk would
    /// have found met. (The lanes may meet a box that the f64 test misses by less
    /// than their allowance.)
    #[test]
    fn a_box_the_lanes_miss_the_f64_test_misses(
        p in v3(),
        c in (v3(), v3(), v3()),
        boxes in proptest::collection::vec((v3(), 0.0f64..2.0, 0.0f64..2.0, 0.0f64..2.0), WIDTH),
        used in 1..=WIDTH,
    ) {
        let (c0, e1, e2) = c;
        let corners = [c0, c0 + e1, c0 + e1 + e2, c0 + e2];
        let Some(s) = Shaft::new(p, &corners) else { return Ok(()) };
        let b: Vec<(DVec3, DVec3)> = boxes[..used]
            .iter()
            .map(|&(lo, x, y, z)| (lo, lo + DVec3::new(x, y, z)))
            .collect();
        let n = node_of(&b);
        let scale = 12.0;
        let delta = PAD * (s.reach + scale + 1.0);
        let mask = Narrow.misses(&Narrow.shaft(&s.in_lanes(delta, scale)), &n);
        prop_assert_eq!(mask >> used, (1u32 << (WIDTH - used)) - 1);
        for k in (0..used).filter(|k| mask & (1 << k) != 0) {
            let corner = |c: usize| DVec3::from_array([0, 1, 2].map(|a| f64::from(n.b[c][a][k])));
            prop_assert!(s.misses(corner(0), corner(1), delta), "slot {}", k);
        }
    }
}
