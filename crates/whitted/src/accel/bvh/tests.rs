//! The wide tree's own parts: f32 rounding outward, the collapse, and the lanes'
//! range; the whole queries are checked against the linear scans in `accel::tests`.

use super::node8::{down, up};
use super::*;

#[test]
fn rounding_to_f32_goes_outward() {
    // 0.1 is not an f32: the nearest one, 0.100000001490116..., lies above it.
    assert_eq!(up(0.1), 0.1f32);
    assert_eq!(down(0.1), 0.099_999_994_f32);
    assert_eq!(down(-0.1), -0.1f32);
    assert_eq!(up(-0.1), -0.099_999_994_f32);
    // Exact values stay; past f32's range the low side saturates at its largest value.
    assert_eq!((down(0.5), up(0.5)), (0.5, 0.5));
    assert_eq!((down(1e39), up(1e39)), (f32::MAX, f32::INFINITY));
    assert_eq!((down(-1e39), up(-1e39)), (f32::NEG_INFINITY, -f32::MAX));
}

/// A row of `n` unit spheres along x, one every 3 units, from `x0`.
fn row(n: usize, x0: f64) -> Bvh<Prim> {
    let prims = (0..n)
        .map(|i| Prim {
            sphere: Sphere::new(DVec3::new(x0 + 3.0 * i as f64, 0.0, 0.0), 1.0),
            index: i as u32,
            glass: false,
            opaque: true,
        })
        .collect();
    Bvh::build(prims, Prim::bounds)
}

/// The primitives `traverse` offers, in its order, with no limit.
fn offered(bvh: &Bvh<Prim>, ray: &Ray) -> Vec<u32> {
    let mut seen = Vec::new();
    bvh.traverse(ray, f64::INFINITY, |p, l| {
        seen.push(p.index);
        Some(l)
    });
    seen
}

#[test]
fn the_collapse_keeps_every_primitive_once() {
    let bvh = row(1000, 0.0);
    // 250 to 1000 leaves, eight to a node: at least three levels (8² < 250).
    assert!(bvh.depth() >= 3 && bvh.depth() <= 5, "{}", bvh.depth());
    // A ray along the row meets every box: each sphere is offered exactly once,
    // nearest first.
    let seen = offered(&bvh, &Ray::new(DVec3::new(-5.0, 0.0, 0.0), DVec3::X));
    assert_eq!(seen, (0..1000).collect::<Vec<u32>>());
    // The other way round, the leaves farthest first (a leaf's spheres in its order).
    let mut back = offered(&bvh, &Ray::new(DVec3::new(3005.0, 0.0, 0.0), -DVec3::X));
    assert!(back[0] >= 1000 - LEAF_SAH_MAX as u32 && back[999] < LEAF_SAH_MAX as u32);
    back.sort();
    assert_eq!(back, (0..1000).collect::<Vec<u32>>());
}

#[test]
fn holder_leaves_offers_the_leaves_of_one_node() {
    let bvh = row(1000, 0.0);
    // Every primitive's holder has the leaf that holds it in one of its slots.
    for i in 0..1000 {
        let n = &bvh.nodes[bvh.holder[i] as usize];
        assert!(
            (0..WIDTH).any(|s| n.child[s] & LEAF != 0
                && ((n.child[s] & !LEAF) as usize
                    ..(n.child[s] & !LEAF) as usize + n.count[s] as usize)
                    .contains(&i)),
            "{i}"
        );
    }
    // Along the row, sphere 500's node offers its leaves' spheres, 500 among them, in
    // a run of neighbours around it (at most eight leaves of up to four); off the row,
    // none.
    let along = Ray::new(DVec3::new(-5.0, 0.0, 0.0), DVec3::X);
    let mut seen = Vec::new();
    bvh.holder_leaves(500, &along, f64::INFINITY, |first, count, l| {
        seen.extend(bvh.prims[first..first + count].iter().map(|p| p.index));
        Some(l)
    });
    assert!(
        seen.contains(&500) && seen.len() <= WIDTH * LEAF_SAH_MAX,
        "{seen:?}"
    );
    assert!(seen.windows(2).all(|w| w[1] == w[0] + 1), "{seen:?}");
    // The limit stops it short of sphere 500 (at x = 1500, entered at t = 1504).
    let mut short = 0;
    bvh.holder_leaves(500, &along, 1400.0, |_, count, l| {
        short += count;
        Some(l)
    });
    assert_eq!(short, 0);
    let beside = Ray::new(DVec3::new(-5.0, 5.0, 0.0), DVec3::X);
    bvh.holder_leaves(500, &beside, f64::INFINITY, |_, _, _| panic!("offered"));
    // A primitive's place, from a reference into the tree; one from elsewhere lies past
    // the end.
    assert!((0..1000).all(|i| bvh.place(&bvh.prims[i]) == i as u32));
    let elsewhere = bvh.prims[500];
    assert!(bvh.place(&elsewhere) as usize >= 1000);
    // A place past the end: nothing.
    bvh.holder_leaves(1000, &along, f64::INFINITY, |_, _, _| panic!("offered"));
    bvh.holder_leaves(u32::MAX as usize, &along, f64::INFINITY, |_, _, _| {
        panic!("offered")
    });
}

#[test]
fn a_ray_beside_the_row_is_offered_nothing() {
    let bvh = row(1000, 0.0);
    let beside = Ray::new(DVec3::new(-5.0, 1.5, 0.0), DVec3::X);
    assert!(offered(&bvh, &beside).is_empty());
    // Parallel to a box's face, just inside its margin (|o| + scale ≈ 3000, δ ≈ 0.03):
    // offered, since the widened box contains the line.
    let inside = Ray::new(DVec3::new(-5.0, 1.0 + 0.02, 0.0), DVec3::X);
    assert_eq!(offered(&bvh, &inside).len(), 1000);
}

#[test]
fn beyond_the_lanes_range_every_primitive_is_offered() {
    // Coordinates near 1e18 and more: the lanes decline and the traversal falls back
    // to every primitive, which loses nothing.
    let bvh = row(40, 1e18);
    let beside = Ray::new(DVec3::new(1e18, 5.0, 0.0), DVec3::Y);
    assert_eq!(offered(&bvh, &beside).len(), 40);
    // Within the range the same shape of query is pruned.
    let near = row(40, 1e6);
    let beside = Ray::new(DVec3::new(1e6 + 1.5, 5.0, 0.0), DVec3::Y);
    assert!(offered(&near, &beside).len() < 40);
}

#[test]
fn zero_and_negative_zero_directions_enter_by_their_own_corners() {
    let bvh = row(100, 0.0);
    for d in [
        DVec3::new(1.0, 0.0, 0.0),
        DVec3::new(1.0, -0.0, -0.0),
        DVec3::new(-1.0, 0.0, -0.0),
    ] {
        let o = if d.x > 0.0 { -5.0 } else { 400.0 };
        let seen = offered(&bvh, &Ray::new(DVec3::new(o, 0.5, -0.5), d));
        assert_eq!(seen.len(), 100, "{d:?}");
    }
}

#[test]
fn a_deep_tree_is_walked_whole() {
    // Spheres at x = 1.2^i: each split peels the farthest one off, so the tree is as
    // deep as the build allows; every sphere is still offered, in order.
    let prims = (0..200)
        .map(|i| Prim {
            sphere: Sphere::new(DVec3::new(1.2f64.powi(i), 0.0, 0.0), 0.01),
            index: i as u32,
            glass: false,
            opaque: true,
        })
        .collect();
    let bvh = Bvh::build(prims, Prim::bounds);
    assert!(bvh.depth() > 8, "{}", bvh.depth());
    let seen = offered(&bvh, &Ray::new(DVec3::new(-1.0, 0.0, 0.0), DVec3::X));
    assert_eq!(seen, (0..200).collect::<Vec<u32>>());
}
