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
//! polygons: a 144-vertex face takes a few thousand corner tests.

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
