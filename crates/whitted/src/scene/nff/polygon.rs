//! Cutting an NFF polygon (any number of coplanar vertices, convex or not, such as the
//! gears' 144-vertex faces) into triangles.
//!
//! The polygon is projected onto the coordinate plane its normal (Newell's, from every
//! vertex) is most nearly perpendicular to, turned counter-clockwise, and cut by ear
//! clipping, the smallest ear first (`ears`). Repeated and collinear vertices make
//! zero-area corners, which are dropped without a triangle. Every triangle keeps the
//! polygon's winding, so its normal faces the polygon's front. A convex polygon is cut
//! without testing vertices against ears: a million vertices on a circle take about a
//! second.

use super::ears::{self, cross};
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
    ears::clip(&flat, convex(&flat))
}

/// Whether every corner of `flat` turns left and its edges turn through one full turn
/// (a convex polygon, not a star that winds several times), so that every corner is an
/// ear until it is cut.
fn convex(flat: &[DVec2]) -> bool {
    let n = flat.len();
    let turns_left = (0..n).all(|i| cross(flat[(i + n - 1) % n], flat[i], flat[(i + 1) % n]) > 0.0);
    // With every turn to the left, the edge's direction wraps past ±π once per turn
    // round: once for a convex polygon, more for a star.
    let angle = |i: usize| {
        let d = flat[(i + 1) % n] - flat[i];
        d.y.atan2(d.x)
    };
    turns_left && (0..n).filter(|&i| angle((i + 1) % n) < angle(i)).count() == 1
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
        // The two small ears first, (0,2) (1,2) (1,1) and (1,1) (2,1) (2,0); the concave
        // corner (1,1) then lies on the line from (0,2) to (2,0) and goes without a
        // triangle, leaving (0,0) (0,2) (2,0).
        assert_eq!(t, vec![[1, 2, 3], [3, 4, 5], [0, 1, 5]]);
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

    fn box_area(v: &[DVec3], tris: &[[usize; 3]]) -> f64 {
        tris.iter()
            .map(|t| {
                let (lo, hi) = (
                    v[t[0]].min(v[t[1]]).min(v[t[2]]),
                    v[t[0]].max(v[t[1]]).max(v[t[2]]),
                );
                (hi.x - lo.x) * (hi.y - lo.y)
            })
            .sum()
    }

    #[test]
    fn the_smallest_ear_is_cut_first_by_hand() {
        // A convex pentagon in z = 0. The ears' boxes (width + height): at 0 and 1, 10 + 1;
        // at 2, (10,0) (10,1) (5,2): 5 + 2; at 3, 10 + 1; at 4, (5,2) (0,1) (0,0): 5 + 2.
        // 2 and 4 tie: 2 first. Then 1 and 3 are asked again (10 + 2 each), so 4 goes
        // next, and 0, 1, 3 are left.
        let p: Vec<DVec3> = [(0.0, 0.0), (10.0, 0.0), (10.0, 1.0), (5.0, 2.0), (0.0, 1.0)]
            .iter()
            .map(|&(x, y)| DVec3::new(x, y, 0.0))
            .collect();
        assert_eq!(triangulate(&p), vec![[1, 2, 3], [3, 4, 0], [0, 1, 3]]);
        // The same cuts when the polygon is not known to be convex (every vertex tested).
        let flat: Vec<DVec2> = p.iter().map(|q| q.truncate()).collect();
        assert_eq!(ears::clip(&flat, false), ears::clip(&flat, true));
    }

    /// A gear's face as the SPD draws one: `teeth` teeth of four vertices each, on a root
    /// circle of radius 0.8 and tips at 1.
    fn gear(teeth: usize) -> Vec<DVec3> {
        let n = 4 * teeth;
        (0..n)
            .map(|i| {
                let a = std::f64::consts::TAU * i as f64 / n as f64;
                let r = if i % 4 == 1 || i % 4 == 2 { 1.0 } else { 0.8 };
                DVec3::new(r * a.cos(), r * a.sin(), 0.0)
            })
            .collect()
    }

    #[test]
    fn a_gears_face_is_cut_into_compact_triangles() {
        // 36 teeth, 144 vertices: 142 triangles of the face's area whose boxes cover
        // under 3.5 times that area (the first ear met, a fan of slivers: about 8 times).
        let g = gear(36);
        let t = triangulate(&g);
        assert_eq!(t.len(), 142);
        let shoelace = newell(&g).z / 2.0;
        assert!((area(&g, &t) - shoelace).abs() < 1e-12);
        let boxes = box_area(&g, &t) / shoelace;
        assert!(boxes < 3.5, "{boxes}");
        let fan: Vec<[usize; 3]> = (1..143).map(|k| [0, k, k + 1]).collect();
        assert!(box_area(&g, &fan) / shoelace > 6.0);
    }

    #[test]
    fn a_large_convex_polygon_is_cut_quickly() {
        // 1,000,000 vertices on a circle: n − 2 triangles of the circle's area, without
        // testing vertices against ears.
        let n = 1_000_000;
        let big: Vec<DVec3> = (0..n)
            .map(|i| {
                let a = std::f64::consts::TAU * i as f64 / n as f64;
                DVec3::new(a.cos(), a.sin(), 0.0)
            })
            .collect();
        let t = triangulate(&big);
        assert_eq!(t.len(), n - 2);
        let shoelace = newell(&big).z / 2.0;
        assert!((area(&big, &t) - shoelace).abs() < 1e-9);
        // A pentagram's outline walked twice round (every turn left, two wraps) is not
        // convex: its vertices are tested, and it is cut as far as it has ears.
        let star: Vec<DVec2> = (0..5)
            .map(|i| {
                let a = std::f64::consts::TAU * (2 * i) as f64 / 5.0;
                DVec2::new(a.cos(), a.sin())
            })
            .collect();
        assert!(!convex(&star));
        assert!(convex(
            &big.iter().map(|q| q.truncate()).collect::<Vec<_>>()
        ));
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
