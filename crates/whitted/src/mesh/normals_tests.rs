use super::*;
use proptest::prelude::*;
use std::f64::consts::FRAC_PI_2;

fn v(x: f64, y: f64, z: f64) -> DVec3 {
    DVec3::new(x, y, z)
}

/// The normal `s` gives corner `k` of triangle `f`.
fn at(s: &Smoothed, f: usize, k: usize) -> DVec3 {
    s.normals[s.triangles[f][k] as usize]
}

#[test]
fn two_faces_weighted_by_their_angles_by_hand() {
    // Two faces at the origin O, sharing the edge from O to (1, 0, 0): A lies in the
    // plane z = 0 with a right angle at O, B rises to (1, 1, 1) and its angle at O is
    // acos(1/√3) = 54.7356°; their normals are 45° apart.
    let verts = [
        v(0.0, 0.0, 0.0),
        v(1.0, 0.0, 0.0),
        v(0.0, -1.0, 0.0),
        v(1.0, 1.0, 1.0),
    ];
    // A = (0, 2, 1): normal (0,-1,0)×(1,0,0) = (0,0,1); its angle at O is 90°.
    // B = (0, 1, 3): normal (1,0,0)×(1,1,1) = (0,−1,1)/√2; angle at O acos(1/√3).
    let tris = [[0, 2, 1], [0, 1, 3]];
    let s = smooth(&verts, &tris, 60.0);
    let (wa, wb) = (FRAC_PI_2, (1.0 / 3f64.sqrt()).acos());
    let nb = v(0.0, -1.0, 1.0) / 2f64.sqrt();
    let want = (wa * DVec3::Z + wb * nb).normalize();
    // By hand: wa = 1.5707963, wb = 0.9553166; sum = (0, −0.67551, 2.24631), length 2.34568 → (0, −0.28798, 0.95764).
    assert!(
        (want - v(0.0, -0.287_98, 0.957_64)).length() < 1e-5,
        "{want}"
    );
    assert!((at(&s, 0, 0) - want).length() < 1e-12);
    assert!((at(&s, 1, 0) - want).length() < 1e-12);
    // The faces meet at 45°: at 44° they are split, each corner its face's normal.
    let s = smooth(&verts, &tris, 44.0);
    assert_eq!(at(&s, 0, 0), DVec3::Z);
    assert!((at(&s, 1, 0) - nb).length() < 1e-15);
    assert_eq!(s.normals.len(), 6); // O and (1,0,0) copied, two lone corners
    assert_eq!(s.origin.iter().filter(|&&o| o == 0).count(), 2);
}

/// A unit cube of six quads, each fanned into two triangles.
fn cube() -> (Vec<DVec3>, Vec<[u32; 3]>) {
    let verts = (0..8)
        .map(|i| v((i & 1) as f64, (i >> 1 & 1) as f64, (i >> 2 & 1) as f64))
        .collect();
    let quads = [
        [0, 2, 3, 1],
        [4, 5, 7, 6],
        [0, 1, 5, 4],
        [2, 6, 7, 3],
        [0, 4, 6, 2],
        [1, 3, 7, 5],
    ];
    let tris = quads
        .iter()
        .flat_map(|q| [[q[0], q[1], q[2]], [q[0], q[2], q[3]]])
        .collect();
    (verts, tris)
}

#[test]
fn a_cube_keeps_its_edges_at_30_and_rounds_at_180() {
    let (verts, tris) = cube();
    let s = smooth(&verts, &tris, 30.0);
    // Every corner has its face's normal; each vertex is copied once per side: 24.
    for (f, t) in tris.iter().enumerate() {
        let (n, _) = face(
            verts[t[0] as usize],
            verts[t[1] as usize],
            verts[t[2] as usize],
        );
        for k in 0..3 {
            assert_eq!(at(&s, f, k), n);
        }
    }
    assert_eq!(s.normals.len(), 24);
    // At 180° every corner is the vertex's diagonal: 90° of each of the three sides.
    let s = smooth(&verts, &tris, 180.0);
    assert_eq!(s.normals.len(), 8);
    let third = 1.0 / 3f64.sqrt();
    assert!((at(&s, 0, 0) - v(-third, -third, -third)).length() < 1e-15);
}

/// The reference: for each corner, the faces around its vertex (by position) reached by
/// crossing edges of exactly two faces within the angle, found by scanning every face.
fn brute(verts: &[DVec3], tris: &[[u32; 3]], angle_deg: f64) -> Vec<[DVec3; 3]> {
    let cos_max = if angle_deg >= 180.0 {
        -1.0
    } else {
        angle_deg.to_radians().cos()
    };
    let p = |i: u32| verts[i as usize];
    let faces: Vec<_> = tris
        .iter()
        .map(|t| face(p(t[0]), p(t[1]), p(t[2])))
        .collect();
    let has = |f: usize, x: DVec3| tris[f].iter().any(|&i| p(i) == x);
    let shared = |f: usize, g: usize| tris[f].iter().filter(|&&i| has(g, p(i))).count() == 2;
    let edge_faces = |f: usize, g: usize| {
        // The faces holding both ends of the edge f and g share.
        let ends: Vec<DVec3> = tris[f]
            .iter()
            .map(|&i| p(i))
            .filter(|&x| has(g, x))
            .collect();
        (0..tris.len())
            .filter(|&h| ends.iter().all(|&x| has(h, x)))
            .count()
    };
    tris.iter()
        .enumerate()
        .map(|(f, t)| {
            [0, 1, 2].map(|k| {
                let x = p(t[k]);
                let mut group = vec![f];
                let mut grew = true;
                while grew {
                    grew = false;
                    for g in 0..tris.len() {
                        if group.contains(&g) || !has(g, x) {
                            continue;
                        }
                        let joins = group.iter().any(|&h| {
                            shared(g, h)
                                && edge_faces(g, h) == 2
                                && joined(faces[g].0, faces[h].0, cos_max)
                        });
                        if joins {
                            group.push(g);
                            grew = true;
                        }
                    }
                }
                let sum: DVec3 = group
                    .iter()
                    .map(|&g| {
                        let j = (0..3).find(|&j| p(tris[g][j]) == x).unwrap();
                        faces[g].1[j] * faces[g].0
                    })
                    .sum();
                sum.try_normalize().unwrap_or(faces[f].0)
            })
        })
        .collect()
}

/// A grid of (n+1)² heights, each cell cut along a chosen diagonal; heights from a few
/// levels so that neighbouring faces meet at many angles, creases included. Some
/// vertices are written twice (as a file does for its texture coordinates).
fn terrain(
    n: usize,
    heights: &[u8],
    cuts: &[bool],
    copies: &[bool],
) -> (Vec<DVec3>, Vec<[u32; 3]>) {
    let idx = |i: usize, j: usize| (i * (n + 1) + j) as u32;
    let mut verts: Vec<DVec3> = (0..(n + 1) * (n + 1))
        .map(|k| {
            v(
                (k / (n + 1)) as f64,
                (k % (n + 1)) as f64,
                heights[k] as f64 * 0.7,
            )
        })
        .collect();
    let mut tris = Vec::new();
    for i in 0..n {
        for j in 0..n {
            let (a, b, c, d) = (idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1));
            let cell = i * n + j;
            let (mut t1, t2) = if cuts[cell] {
                ([a, b, c], [a, c, d])
            } else {
                ([a, b, d], [b, c, d])
            };
            if copies[cell] {
                verts.push(verts[t1[0] as usize]);
                t1[0] = verts.len() as u32 - 1;
            }
            tris.extend([t1, t2]);
        }
    }
    (verts, tris)
}

proptest! {
    #[test]
    fn smooth_matches_the_brute_force_reference(
        heights in prop::collection::vec(0u8..4, 25),
        cuts in prop::collection::vec(any::<bool>(), 16),
        copies in prop::collection::vec(any::<bool>(), 16),
        angle in 1.0f64..=180.0,
    ) {
        let (verts, tris) = terrain(4, &heights, &cuts, &copies);
        let tris: Vec<[u32; 3]> = tris; // every face of a grid has non-zero area
        let s = smooth(&verts, &tris, angle);
        let want = brute(&verts, &tris, angle);
        prop_assert_eq!(s.triangles.len(), tris.len());
        for (f, w) in want.iter().enumerate() {
            for k in 0..3 {
                let got = at(&s, f, k);
                prop_assert!((got - w[k]).length() < 1e-9, "face {} corner {}: {} vs {}", f, k, got, w[k]);
                prop_assert_eq!(s.origin[s.triangles[f][k] as usize], tris[f][k]);
            }
        }
    }
}

#[test]
fn a_fan_of_many_faces_and_a_fin_of_three() {
    // 1000 faces around one vertex (a flat disc): one normal, +z, everywhere.
    let n = 1000;
    let mut verts = vec![DVec3::ZERO];
    verts.extend((0..n).map(|k| {
        let a = k as f64 / n as f64 * std::f64::consts::TAU;
        v(a.cos(), a.sin(), 0.0)
    }));
    let tris: Vec<[u32; 3]> = (0..n as u32)
        .map(|k| [0, k + 1, (k + 1) % n as u32 + 1])
        .collect();
    let s = smooth(&verts, &tris, 30.0);
    assert_eq!(s.normals.len(), n + 1);
    assert!(s.normals.iter().all(|m| (*m - DVec3::Z).length() < 1e-12));
    // Three faces on one edge: a crease, whatever the angle.
    let verts = [
        v(0.0, 0.0, 0.0),
        v(0.0, 1.0, 0.0),
        v(1.0, 0.0, 0.0),
        v(-1.0, 0.0, 0.0),
        v(1.0, 0.0, 0.01),
    ];
    let tris = [[0, 1, 2], [1, 0, 3], [0, 1, 4]];
    let s = smooth(&verts, &tris, 180.0);
    assert_eq!(at(&s, 0, 0), DVec3::new(0.0, 0.0, -1.0));
    assert_eq!(s.normals.len(), 9);
}

#[test]
fn short_and_long_lists_sort_as_the_standard_sort() {
    // By hand: [(2, 5), (1, 9), (2, 1)] → [(1, 9), (2, 1), (2, 5)].
    let mut v = [(2, 5), (1, 9), (2, 1)];
    sort_small(&mut v);
    assert_eq!(v, [(1, 9), (2, 1), (2, 5)]);
    // Lengths 0 to 40 (both sides of the insertion limit), pseudo-random entries.
    let mut x = 0x9e37_79b9_u32;
    for n in 0..40 {
        let mut v: Vec<(u32, u32)> = (0..n)
            .map(|k| {
                x ^= x << 13;
                x ^= x >> 17;
                x ^= x << 5;
                (x % 7, k)
            })
            .collect();
        let mut want = v.clone();
        want.sort_unstable();
        sort_small(&mut v);
        assert_eq!(v, want, "{n}");
    }
}
