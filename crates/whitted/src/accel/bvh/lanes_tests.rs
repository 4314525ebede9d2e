//! The two lanes give the same bits: for random nodes (empty slots, flat boxes, boxes
//! behind the ray) and rays (zero, negative-zero and tiny direction components), the
//! AVX2 lanes' mask and entry parameters equal the narrow lanes', and so do their masks
//! of the boxes beyond a random shaft. Skipped, and said so,
//! on a processor without AVX2 (and not built without the `avx2` feature).

use super::lanes::{Avx2, Choice, Lanes, Narrow};
use super::node8::{down, up, WideNode, WIDTH};
use super::raybox::RayBox;
use super::Shaft;
use crate::optics::Ray;
use glam::DVec3;
use proptest::prelude::*;

/// A node of random boxes in [-50, 50]³; slots past `used` are empty.
fn node(corners: &[(f64, f64, f64, f64, f64, f64)], used: usize) -> WideNode {
    let mut n = WideNode {
        b: [[[f32::INFINITY; WIDTH]; 3], [[f32::NEG_INFINITY; WIDTH]; 3]],
        child: [0; WIDTH],
        count: [0; WIDTH],
    };
    for (s, c) in corners.iter().enumerate().take(used) {
        let (a, b) = ([c.0, c.1, c.2], [c.3, c.4, c.5]);
        for axis in 0..3 {
            // Every third box is flat on x (a polygon's), the rest proper.
            let (lo, hi) = if s % 3 == 0 && axis == 0 {
                (a[0], a[0])
            } else {
                (a[axis].min(b[axis]), a[axis].max(b[axis]))
            };
            n.b[0][axis][s] = down(lo);
            n.b[1][axis][s] = up(hi);
        }
    }
    n
}

/// A direction component: ordinary, zero, negative zero or tiny.
fn component() -> impl Strategy<Value = f64> {
    prop_oneof![
        6 => -1.0..1.0f64,
        1 => Just(0.0),
        1 => Just(-0.0),
        1 => Just(1e-30),
    ]
}

/// The corners of a node's eight boxes, in [-50, 50]³.
fn boxes() -> impl Strategy<Value = Vec<(f64, f64, f64, f64, f64, f64)>> {
    let c = || -50.0..50.0f64;
    proptest::collection::vec((c(), c(), c(), c(), c(), c()), WIDTH)
}

/// The AVX2 lanes, or `None` (and a line saying the test is skipped) on a processor
/// without AVX2.
fn avx2() -> Option<Avx2> {
    let lanes = pulp::x86::V3::try_new().map(Avx2);
    if lanes.is_none() {
        eprintln!("skipped: this processor has no AVX2");
    }
    lanes
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]
    #[test]
    fn avx2_lanes_give_the_narrow_lanes_bits(
        corners in boxes(),
        used in 1..=WIDTH,
        o in (-80.0..80.0f64, -80.0..80.0f64, -80.0..80.0f64),
        d in (component(), component(), component()),
        t_max in prop_oneof![Just(f32::INFINITY), 0.0..200.0f32],
    ) {
        let Some(avx2) = avx2() else {
            return Ok(());
        };
        let n = node(&corners, used);
        let ray = Ray::new(DVec3::new(o.0, o.1, o.2), DVec3::new(d.0, d.1, d.2));
        let rb = RayBox::new(&ray, 50.0).expect("within the lanes' range");
        let (m0, t0) = Narrow.enter(&Narrow.ray(&rb), &n, t_max);
        let (m1, t1) = avx2.0.vectorize(|| avx2.enter(&avx2.ray(&rb), &n, t_max));
        prop_assert_eq!(m0, m1);
        prop_assert_eq!(t0.map(f32::to_bits), t1.map(f32::to_bits));
        // Empty slots are never entered.
        prop_assert_eq!(m0 >> used, 0);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]
    /// The shaft test too: random boxes, a random point and parallelogram, the same
    /// mask from both lanes.
    #[test]
    fn avx2_lanes_miss_a_shaft_as_the_narrow_lanes_do(
        corners in boxes(),
        used in 1..=WIDTH,
        p in (-60.0..60.0f64, -60.0..60.0f64, -60.0..60.0f64),
        c in (-60.0..60.0f64, -60.0..60.0f64, -60.0..60.0f64),
        e in (-20.0..20.0f64, -20.0..20.0f64, -20.0..20.0f64, -20.0..20.0f64),
    ) {
        let Some(avx2) = avx2() else {
            return Ok(());
        };
        let n = node(&corners, used);
        let (c0, e1, e2) = (
            DVec3::new(c.0, c.1, c.2),
            DVec3::new(e.0, e.1, 0.0),
            DVec3::new(0.0, e.2, e.3),
        );
        let quad = [c0, c0 + e1, c0 + e1 + e2, c0 + e2];
        let Some(shaft) = Shaft::new(DVec3::new(p.0, p.1, p.2), &quad) else {
            return Ok(());
        };
        let q = shaft.in_lanes(1e-3, 50.0);
        let m0 = Narrow.misses(&Narrow.shaft(&q), &n);
        let m1 = avx2.0.vectorize(|| avx2.misses(&avx2.shaft(&q), &n));
        prop_assert_eq!(m0, m1);
        // Empty slots are always missed.
        prop_assert_eq!(m0 >> used, (1u32 << (WIDTH - used)) - 1);
    }
}

#[test]
fn the_setting_narrow_chooses_the_narrow_lanes() {
    let wide = |c: Choice| matches!(c, Choice::Avx2(_));
    assert!(!wide(Choice::from_setting(Some("narrow"))));
    let has_avx2 = pulp::x86::V3::is_available();
    assert_eq!(wide(Choice::from_setting(None)), has_avx2);
    assert_eq!(wide(Choice::from_setting(Some("auto"))), has_avx2);
}
