//! The packets' lanes against the exact test: a worked example, rays aimed at the edges
//! and corners of random triangles at many scales (every triangle the exact test hits
//! must pass its lane), rays that clearly miss (their lanes must not pass: the filter
//! filters), and the bounds that keep a triangle out of any packet.

use super::packet::{Ray32, TriPacket};
use super::tests::Rng;
use crate::optics::Ray;
use crate::shapes::Triangle;
use glam::DVec3;
use proptest::prelude::*;

/// The right triangle (0,0,0), (1,0,0), (0,1,0) as corner and edges.
const UNIT: [DVec3; 3] = [DVec3::ZERO, DVec3::X, DVec3::Y];

/// A number in [0, 1).
fn unit(rng: &mut Rng) -> f64 {
    0.5 * (rng.next() + 1.0)
}

fn ray(o: DVec3, towards: DVec3) -> Ray {
    Ray::new(o, (towards - o).normalize())
}

#[test]
fn a_ray_through_the_triangle_passes_and_one_beside_it_does_not() {
    let p = TriPacket::new(&[UNIT, UNIT]).unwrap();
    // Straight down through (0.25, 0.25): det = 1, u′ = v′ = 0.25 by hand.
    let down = Ray::new(DVec3::new(0.25, 0.25, 1.0), DVec3::NEG_Z);
    assert_eq!(p.candidates(&Ray32::new(&down).unwrap()), 0b11);
    // Through (2, 2, 0): u′ = v′ = 2, u′ + v′ = 4 > det = 1 far beyond the margin
    // (2⁻¹⁴·1·1·3 ≈ 1.8e-4).
    let beside = Ray::new(DVec3::new(2.0, 2.0, 1.0), DVec3::NEG_Z);
    assert_eq!(p.candidates(&Ray32::new(&beside).unwrap()), 0);
    // Through (-0.001, 0.5): u′ = −0.001, 5.5 margins below zero.
    let off = Ray::new(DVec3::new(-0.001, 0.5, 1.0), DVec3::NEG_Z);
    assert_eq!(p.candidates(&Ray32::new(&off).unwrap()), 0);
    // Exactly on the edge u = 0: the exact test hits (edges count), so the lane passes.
    let edge = Ray::new(DVec3::new(0.0, 0.5, 1.0), DVec3::NEG_Z);
    assert!(Triangle::uvt_of(UNIT[0], UNIT[1], UNIT[2], &edge).is_some());
    assert_eq!(p.candidates(&Ray32::new(&edge).unwrap()), 0b11);
}

#[test]
fn only_the_lanes_that_hold_a_triangle_answer() {
    let far = [DVec3::new(5.0, 5.0, 0.0), DVec3::X, DVec3::Y];
    let p = TriPacket::new(&[far, UNIT, far]).unwrap();
    let down = Ray::new(DVec3::new(0.25, 0.25, 1.0), DVec3::NEG_Z);
    // Lane 1 alone; lane 3 is empty (its zeros must not pass whatever they compute).
    assert_eq!(p.candidates(&Ray32::new(&down).unwrap()), 0b010);
}

#[test]
fn triangles_and_rays_beyond_the_lanes_bounds_take_the_exact_test() {
    let huge = [DVec3::splat(2e12), DVec3::X, DVec3::Y];
    let tiny = [DVec3::ZERO, DVec3::X * 1e-13, DVec3::Y * 1e-13];
    assert!(TriPacket::new(&[UNIT, huge]).is_none());
    assert!(TriPacket::new(&[UNIT, tiny]).is_none());
    assert!(TriPacket::new(&[]).is_none());
    assert!(TriPacket::new(&[UNIT; 5]).is_none());
    let far = Ray::new(DVec3::new(0.0, 0.0, 2e12), DVec3::NEG_Z);
    assert!(Ray32::new(&far).is_none());
}

/// A random triangle of size `size` around `centre`.
fn triangle(rng: &mut Rng, centre: DVec3, size: f64) -> [DVec3; 3] {
    let a = centre + rng.vec(size);
    let (b, c) = (a + rng.vec(size), a + rng.vec(size));
    [a, b - a, c - a]
}

/// A point on the boundary of `tri` (an edge or a corner), nudged by `nudge` in
/// barycentric terms (a few ulps either way).
fn boundary(rng: &mut Rng, [a, e1, e2]: [DVec3; 3], nudge: f64) -> DVec3 {
    let w = unit(rng);
    let (u, v) = match (unit(rng) * 4.0) as u32 {
        0 => (0.0, w),
        1 => (w, 0.0),
        2 => (w, 1.0 - w),
        _ => [(0.0, 0.0), (1.0, 0.0), (0.0, 1.0)][(w * 2.99) as usize],
    };
    a + (u + nudge) * e1 + (v - nudge) * e2
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    /// Every triangle the exact test hits passes its lane: rays at the triangles'
    /// edges and corners (where the lanes' rounding matters), from near and far, at
    /// scales from 1e-6 to 1e6 and away from the origin.
    #[test]
    fn no_exact_hit_is_filtered_out(seed in any::<u64>(), scale in -6i32..7, shift in -3i32..4) {
        let mut rng = Rng(seed | 1);
        let size = 10f64.powi(scale);
        let centre = rng.vec(size * 10f64.powi(shift));
        let tris: Vec<[DVec3; 3]> = (0..4).map(|_| triangle(&mut rng, centre, size)).collect();
        let Some(packet) = TriPacket::new(&tris) else {
            return Ok(());
        };
        for k in 0..4 {
            for _ in 0..8 {
                let nudge = (unit(&mut rng) - 0.5) * 1e-15;
                let target = boundary(&mut rng, tris[k], nudge);
                let reach = size * 10f64.powi((unit(&mut rng) * 4.0) as i32 - 1);
                let o = target + rng.vec(reach);
                let r = ray(o, target);
                let Some(r32) = Ray32::new(&r) else { continue };
                let mask = packet.candidates(&r32);
                for (j, &[a, e1, e2]) in tris.iter().enumerate() {
                    if Triangle::uvt_of(a, e1, e2, &r).is_some() {
                        prop_assert!(mask & (1 << j) != 0, "lane {j} dropped an exact hit");
                    }
                }
            }
        }
    }

    /// Rays aimed a tenth of the triangle's size outside it, from within ten sizes of
    /// it, never pass: the margin is far narrower than that.
    #[test]
    fn clear_misses_are_filtered_out(seed in any::<u64>(), scale in -3i32..4) {
        let mut rng = Rng(seed | 1);
        let size = 10f64.powi(scale);
        // A well-shaped triangle: the right triangle scaled, at a random place.
        let a = rng.vec(size);
        let tri = [a, DVec3::X * size, DVec3::Y * size];
        let packet = TriPacket::new(&[tri]).unwrap();
        let target = a + DVec3::new(-0.1 * size, unit(&mut rng) * size, 0.0);
        let o = target + DVec3::new(unit(&mut rng) - 0.5, unit(&mut rng) - 0.5, 1.0) * size * 5.0;
        let r32 = Ray32::new(&ray(o, target)).unwrap();
        prop_assert_eq!(packet.candidates(&r32), 0);
    }
}
