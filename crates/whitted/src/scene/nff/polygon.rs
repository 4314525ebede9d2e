//! Cutting an NFF polygon (any number of coplanar vertices, convex or not, such as the
//! gears' 144-vertex faces) into triangles by ear clipping (Meisters, 1975).
//!
//! The polygon is projected onto the coordinate plane its normal (Newell's, from every
//! vertex) is most nearly perpendicular to. An ear is a corner turning the polygon's way
//! whose triangle holds no other remaining vertex; it is cut off and the walk goes on
//! from its neighbour. Repeated and collinear vertices make zero-area corners, which are
//! dropped without a triangle. Every triangle keeps the polygon's winding, so its
//! normal faces the polygon's front. Should no ear be found (a self-intersecting
//! polygon), what remains is cut as a fan from its first vertex. O(n²) for the usual
//! polygons: a 144-vertex face takes a few thousand corner tests. A strictly convex
//! polygon is cut in O(n) (`convex_fan`: the same triangles, found without testing
//! every remaining vertex at every corner): 40,000 vertices took 2.4 s, the limit of
//! a million about 25 minutes.

use glam::{DVec2, DVec3};

/// The polygon's normal by Newell's method (not normalised; zero for a degenerate one).
pub fn newell(v: &[DVec3]) -> DVec3 {
    let mut n = DVec3::ZERO;
    for (i, a) in v.iter().enumerate() {
        let b = v[(i + 1) % v.len()];
        n += DVec3::new(
            (a.y - b.y) * (a.z + b.z),
            (a.z - b.z) * (a.x + b.x),
            (a.x - b.x) * (a.y + b.y),
        );
    }
    n
}

/// Twice the signed area of the 2-D triangle a, b, c (positive counter-clockwise).
fn cross(a: DVec2, b: DVec2, c: DVec2) -> f64 {
    (b - a).perp_dot(c - a)
}

/// Whether p lies inside or on the counter-clockwise triangle a, b, c.
fn inside(p: DVec2, a: DVec2, b: DVec2, c: DVec2) -> bool {
    cross(a, b, p) >= 0.0 && cross(b, c, p) >= 0.0 && cross(c, a, p) >= 0.0
}

/// The triangles (as index triples into `v`, in the polygon's winding) of the polygon
/// `v`; empty when it has no area.
pub fn triangulate(v: &[DVec3]) -> Vec<[usize; 3]> {
    let n = newell(v);
    if v.len() < 3 || n.length_squared().partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
        return Vec::new();
    }
    // Drop the axis the normal is largest along; keep the winding counter-clockwise by
    // flipping the other two when that component is negative.
    let a = n.abs();
    let (axis, sign) = if a.x >= a.y && a.x >= a.z {
        (0, n.x)
    } else if a.y >= a.z {
        (1, n.y)
    } else {
        (2, n.z)
    };
    let flat: Vec<DVec2> = v
        .iter()
        .map(|p| {
            let q = match axis {
                0 => DVec2::new(p.y, p.z),
                1 => DVec2::new(p.z, p.x),
                _ => DVec2::new(p.x, p.y),
            };
            if sign < 0.0 {
                DVec2::new(q.y, q.x)
            } else {
                q
            }
        })
        .collect();
    if let Some(fan) = convex_fan(&flat) {
        return fan;
    }
    let mut left: Vec<usize> = (0..v.len()).collect();
    let mut out = Vec::with_capacity(v.len() - 2);
    let mut i = 0;
    let mut misses = 0;
    while left.len() > 3 {
        let m = left.len();
        let (ia, ib, ic) = (left[(i + m - 1) % m], left[i % m], left[(i + 1) % m]);
        let (pa, pb, pc) = (flat[ia], flat[ib], flat[ic]);
        let turn = cross(pa, pb, pc);
        if turn == 0.0 {
            // A repeated or collinear vertex: no triangle, just drop it.
            left.remove(i % m);
            misses = 0;
            continue;
        }
        let ear = turn > 0.0
            && left.iter().all(|&k| {
                k == ia
                    || k == ib
                    || k == ic
                    || flat[k] == pa
                    || flat[k] == pb
                    || flat[k] == pc
                    || !inside(flat[k], pa, pb, pc)
            });
        if ear {
            out.push([ia, ib, ic]);
            left.remove(i % m);
            misses = 0;
            i %= left.len();
        } else {
            i = (i + 1) % m;
            misses += 1;
            if misses > m {
                break; // no ear: not a simple polygon
            }
        }
    }
    if left.len() > 3 {
        for k in 1..left.len() - 1 {
            out.push([left[0], left[k], left[k + 1]]);
        }
    } else if left.len() == 3 && cross(flat[left[0]], flat[left[1]], flat[left[2]]) != 0.0 {
        out.push([left[0], left[1], left[2]]);
    }
    out
}

/// The cuts ear clipping makes of a strictly convex polygon (every corner turning left,
/// the edges turning through one full turn), found in O(n): from the first corner on,
/// every corner is an ear (no other vertex can lie in a fan triangle of a convex
/// polygon), so the walk cuts (n−1, k, k+1) for k = 0, 1, … (dropping a corner its
/// rounding makes flat, as the walk does), then the last three. `None` for any other
/// polygon, or should a cut's rounding turn the wrong way: the walk decides those.
fn convex_fan(flat: &[DVec2]) -> Option<Vec<[usize; 3]>> {
    let n = flat.len();
    let turns_left = (0..n).all(|i| cross(flat[(i + n - 1) % n], flat[i], flat[(i + 1) % n]) > 0.0);
    if !turns_left {
        return None;
    }
    // With every turn to the left, the edge's direction wraps past ±π once per turn
    // round: once for a convex polygon, more for a star that winds several times.
    let angle = |i: usize| {
        let d = flat[(i + 1) % n] - flat[i];
        d.y.atan2(d.x)
    };
    let wraps = (0..n).filter(|&i| angle((i + 1) % n) < angle(i)).count();
    if wraps != 1 {
        return None;
    }
    let last = n - 1;
    let mut out = Vec::with_capacity(n - 2);
    let mut k = 0;
    while n - k > 3 {
        let turn = cross(flat[last], flat[k], flat[k + 1]);
        if turn < 0.0 {
            return None;
        }
        if turn > 0.0 {
            out.push([last, k, k + 1]);
        }
        k += 1;
    }
    if cross(flat[k], flat[k + 1], flat[k + 2]) != 0.0 {
        out.push([k, k + 1, k + 2]);
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn area(v: &[DVec3], tris: &[[usize; 3]]) -> f64 {
        tris.iter()
            .map(|t| (v[t[1]] - v[t[0]]).cross(v[t[2]] - v[t[0]]).length() / 2.0)
            .sum()
    }

    #[test]
    fn square_and_l_shape_by_hand() {
        let sq = [
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(1.0, 0.0, 0.0),
            DVec3::new(1.0, 1.0, 0.0),
            DVec3::new(0.0, 1.0, 0.0),
        ];
        assert_eq!(newell(&sq), DVec3::new(0.0, 0.0, 2.0));
        let t = triangulate(&sq);
        assert_eq!(t.len(), 2);
        assert_eq!(area(&sq, &t), 1.0);
        // An L of area 3 (a concave corner at (1, 1)), in the plane x = 2, seen from −x.
        let l: Vec<DVec3> = [
            (0.0, 0.0),
            (0.0, 2.0),
            (1.0, 2.0),
            (1.0, 1.0),
            (2.0, 1.0),
            (2.0, 0.0),
        ]
        .iter()
        .map(|&(y, z)| DVec3::new(2.0, y, z))
        .collect();
        assert!(newell(&l).x < 0.0);
        let t = triangulate(&l);
        assert_eq!(t.len(), 4);
        assert_eq!(area(&l, &t), 3.0);
        // Every triangle faces the polygon's way.
        for tri in &t {
            let n = (l[tri[1]] - l[tri[0]]).cross(l[tri[2]] - l[tri[0]]);
            assert!(n.x < 0.0, "{tri:?}");
        }
        // A repeated vertex and a collinear one: dropped.
        let d = [sq[0], sq[1], sq[1], DVec3::new(1.0, 0.5, 0.0), sq[2], sq[3]];
        assert_eq!(area(&d, &triangulate(&d)), 1.0);
        assert!(triangulate(&[sq[0], sq[1], 2.0 * sq[1]]).is_empty());
    }

    /// The walk alone (what `triangulate` did before `convex_fan`), for comparison.
    fn walk_only(v: &[DVec3]) -> Vec<[usize; 3]> {
        let flat: Vec<DVec2> = v.iter().map(|p| DVec2::new(p.x, p.y)).collect();
        let mut left: Vec<usize> = (0..v.len()).collect();
        let mut out = Vec::new();
        while left.len() > 3 {
            let m = left.len();
            let (ia, ib, ic) = (left[m - 1], left[0], left[1]);
            if cross(flat[ia], flat[ib], flat[ic]) > 0.0 {
                out.push([ia, ib, ic]);
            }
            left.remove(0);
        }
        out.push([left[0], left[1], left[2]]);
        out
    }

    #[test]
    fn a_convex_polygon_is_cut_as_the_walk_cuts_it() {
        // A regular hexagon, counter-clockwise in z = 0: (5,0,1) (5,1,2) (5,2,3) (3,4,5).
        let hex: Vec<DVec3> = (0..6)
            .map(|i| {
                let a = std::f64::consts::TAU * i as f64 / 6.0;
                DVec3::new(a.cos(), a.sin(), 0.0)
            })
            .collect();
        let want = vec![[5, 0, 1], [5, 1, 2], [5, 2, 3], [3, 4, 5]];
        assert_eq!(triangulate(&hex), want);
        assert_eq!(walk_only(&hex), want);
        // 40,000 vertices on a circle: 39,998 triangles of the circle's area.
        let n = 40_000;
        let big: Vec<DVec3> = (0..n)
            .map(|i| {
                let a = std::f64::consts::TAU * i as f64 / n as f64;
                DVec3::new(a.cos(), a.sin(), 0.0)
            })
            .collect();
        let t = triangulate(&big);
        assert_eq!(t.len(), n - 2);
        assert_eq!(t, walk_only(&big));
        let shoelace = newell(&big).z / 2.0;
        assert!((area(&big, &t) - shoelace).abs() < 1e-9);
        // A pentagram's outline walked twice round (every turn left, two wraps) is not
        // convex: the walk decides it.
        let star: Vec<DVec3> = (0..5)
            .map(|i| {
                let a = std::f64::consts::TAU * (2 * i) as f64 / 5.0;
                DVec3::new(a.cos(), a.sin(), 0.0)
            })
            .collect();
        let flat: Vec<DVec2> = star.iter().map(|p| DVec2::new(p.x, p.y)).collect();
        assert_eq!(convex_fan(&flat), None);
    }

    proptest! {
        /// Star-shaped polygons (a gear's outline: radii varying around a centre) of up to
        /// 150 vertices: n − 2 triangles (fewer for collinear corners), the polygon's area
        /// (by the shoelace formula), all facing its way.
        #[test]
        fn star_polygons(radii in proptest::collection::vec(0.2f64..1.0, 3..150)) {
            let n = radii.len();
            let v: Vec<DVec3> = radii.iter().enumerate().map(|(i, r)| {
                let a = std::f64::consts::TAU * i as f64 / n as f64;
                DVec3::new(r * a.cos(), r * a.sin(), 0.5)
            }).collect();
            let t = triangulate(&v);
            prop_assert!(t.len() <= n - 2);
            let shoelace = newell(&v).z / 2.0;
            prop_assert!((area(&v, &t) - shoelace).abs() < 1e-9 * shoelace.max(1.0), "{} {}", area(&v, &t), shoelace);
            for tri in &t {
                let nz = (v[tri[1]] - v[tri[0]]).cross(v[tri[2]] - v[tri[0]]).z;
                prop_assert!(nz > 0.0);
            }
        }
    }
}
