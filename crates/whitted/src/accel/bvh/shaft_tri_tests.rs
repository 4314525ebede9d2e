//! `Shaft::misses_triangle` by hand (a point's own triangle, a convex and a concave
//! neighbour) and against the exact test: where it says "missed", none of 25 rays from
//! the point to the light's grid meets the triangle as `Triangle::uvt_of` tests it.

use super::super::tests::square;
use super::*;
use crate::optics::Ray;
use crate::shapes::Triangle;
use proptest::prelude::*;

/// Whether a ray from `p` towards one of the 5 × 5 points of the light `at` meets the
/// triangle, exactly.
fn some_ray_meets(p: DVec3, at: impl Fn(f64, f64) -> DVec3, tri: [DVec3; 3], t_min: f64) -> bool {
    let [a, e1, e2] = tri;
    (0..25).any(|k| {
        let to = at(f64::from(k % 5) / 4.0, f64::from(k / 5) / 4.0) - p;
        let dist = to.length();
        let ray = Ray::new(p, to / dist).with_t_min(t_min);
        dist > 0.0
            && Triangle::uvt_of(a, e1, e2, &ray).is_some_and(|(_, _, t)| t > t_min && t < dist)
    })
}

#[test]
fn the_points_own_triangle_and_a_convex_neighbour_are_missed() {
    // A ridge along z: T = (−1, 0, −1), (0, 0, −1), (0, 0, 1) flat, T' beyond x = 0
    // sloping down. The point on T near the ridge, the light above the origin.
    let (a, b, c) = (
        DVec3::new(-1.0, 0.0, -1.0),
        DVec3::new(0.0, 0.0, -1.0),
        DVec3::new(0.0, 0.0, 1.0),
    );
    let p = a + 0.6 * (b - a) + 0.3 * (c - a);
    let s = Shaft::new(p, &square()).unwrap();
    assert!(s.misses_triangle(a, b - a, c - a, 1e-9));
    // The same with its corners in the other order (the determinant's other sign).
    assert!(s.misses_triangle(a, c - a, b - a, 1e-9));
    let d = DVec3::new(1.0, -0.5, 0.0);
    assert!(s.misses_triangle(b, d - b, c - b, 1e-9));
    // A concave neighbour rising steeply towards the light, which it partly hides.
    let up = DVec3::new(0.5, 8.0, 0.0);
    assert!(!s.misses_triangle(b, up - b, c - b, 1e-9));
    assert!(some_ray_meets(
        p,
        |i, j| square()[0] + DVec3::new(2.0 * i, 0.0, 2.0 * j),
        [b, up - b, c - b],
        1e-9
    ));
}

#[test]
fn a_light_across_the_triangles_plane_is_never_cleared_by_its_edges_alone() {
    // The light's square straddles the plane y = 5 of a big triangle around it: the
    // determinant takes both signs, so nothing is said.
    let s = Shaft::new(DVec3::new(0.0, 5.0, 3.0), &square()).unwrap();
    let (a, e1, e2) = (
        DVec3::new(-10.0, 5.0, -10.0),
        DVec3::new(30.0, 0.0, 0.0),
        DVec3::new(0.0, 0.0, 30.0),
    );
    assert!(!s.misses_triangle(a, e1, e2, 1e-9));
}

fn v3(r: f64) -> impl Strategy<Value = DVec3> {
    (-r..r, -r..r, -r..r).prop_map(|(x, y, z)| DVec3::new(x, y, z))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    /// Two triangles sharing an edge (A, B), the point on the first (as rounding leaves
    /// a computed point of it) or off it, a random parallelogram light: where either is
    /// said to be missed, no ray to the light's grid meets it.
    #[test]
    fn a_missed_triangle_is_met_by_no_ray(
        a in v3(2.0), b in v3(2.0), c in v3(2.0), d in v3(2.0),
        (u, v) in (0.0f64..1.0, 0.0f64..1.0),
        off in prop_oneof![Just(0.0), -1e-3f64..1e-3, -1.0f64..1.0],
        centre in v3(6.0), a1 in v3(3.0), a2 in v3(3.0),
        t_min in prop_oneof![Just(0.0), Just(1e-9), Just(1e-6), Just(1e-3)],
    ) {
        let (u, v) = if u + v > 1.0 { (1.0 - u, 1.0 - v) } else { (u, v) };
        let n = (b - a).cross(c - a).try_normalize().unwrap_or(DVec3::Y);
        let p = a + u * (b - a) + v * (c - a) + off * n;
        let at = |i: f64, j: f64| centre + a1 * (i - 0.5) + a2 * (j - 0.5);
        let corners = [at(0.0, 0.0), at(1.0, 0.0), at(1.0, 1.0), at(0.0, 1.0)];
        let shaft = Shaft::new(p, &corners).unwrap();
        for tri in [[a, b - a, c - a], [b, a - b, d - b], [a, d - a, b - a]] {
            if shaft.misses_triangle(tri[0], tri[1], tri[2], t_min) {
                prop_assert!(!some_ray_meets(p, at, tri, t_min), "{tri:?} from {p}");
            }
        }
    }
}
