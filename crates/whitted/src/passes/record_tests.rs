//! The per-pixel sums of the passes, by hand: the light split with fog, a partly
//! covering surface, a scene in linear light and emission.

use super::*;

#[test]
fn fogged_terms_and_fog_sum_to_the_fogged_colour() {
    // Terms 0.1..0.5 (sum 1.5) at fog f = 0.25: beauty 1.5·0.75 + 0.25 = 1.375.
    let s = Sample {
        hit: Some((0, 2.0)),
        terms: [0.1, 0.2, 0.3, 0.4, 0.5].map(Color::splat),
        fog: 0.25,
        ..Default::default()
    };
    let mut sum = PixelSum::default();
    let beauty = Color::splat(1.375);
    let dir = DVec3::new(0.6, 0.0, 0.8);
    sum.add(beauty, &s, dir, DVec3::Z, true);
    let total: Color = sum.light.iter().copied().sum();
    assert!((total - beauty).abs().max_element() < 1e-15, "{total}");
    // Depth along the view axis: t·(dir·forward) = 2·0.8.
    assert!((sum.depth - 1.6).abs() < 1e-15);
    assert_eq!(sum.objects, [(0, 1)]);
    // A second sample that misses: depth becomes +inf; the object is still counted
    // once, and one of the two samples covers the pixel.
    sum.add(Color::ONE, &Sample::default(), dir, DVec3::Z, true);
    assert_eq!(sum.depth, f64::INFINITY);
    assert_eq!(sum.objects, [(0, 1)]);
    assert_eq!((sum.hits, coverage(sum.hits, 2.0)), (1, 0.5));
}

#[test]
fn a_covering_surface_emission_and_linear_scale_sum_by_hand() {
    // A glTF BLEND surface of α = 0.25 with terms 0.4 (ambient) and 0.8 (diffuse),
    // emission 0.4, no fog, and 0.3 behind it (already times 1 − α): the linear colour
    // is 0.25·(0.4 + 0.8 + 0.4) + 0.3 = 0.7, stored as the display value 0.35 (a scale
    // of ½, as if encoded so): ambient 0.25·0.4·½ = 0.05, diffuse 0.1, emission 0.05,
    // transmission (behind) 0.15; they sum to 0.35.
    let s = Sample {
        hit: Some((0, 1.0)),
        terms: [0.4, 0.8, 0.0, 0.0, 0.0].map(Color::splat),
        emission: Color::splat(0.4),
        cover: Some(0.25),
        behind: Color::splat(0.3),
        scale: Some(Color::splat(0.5)),
        ..Default::default()
    };
    let mut sum = PixelSum::default();
    sum.add(Color::splat(0.35), &s, DVec3::Z, DVec3::Z, false);
    let want = [0.05, 0.1, 0.0, 0.0, 0.15, 0.0];
    for (got, want) in sum.light.iter().zip(want) {
        assert!((got.x - want).abs() < 1e-15, "{got} vs {want}");
    }
    assert!((sum.emission.x - 0.05).abs() < 1e-15);
    let total: Color = sum.light.iter().copied().sum::<Color>() + sum.emission;
    assert!((total.x - 0.35).abs() < 1e-15, "{total}");
    // `encoded` makes the scale from the linear colour and its display value, per
    // channel (1 where the linear colour is 0, whose parts are all 0).
    let mut s = Sample::default();
    s.encoded(Color::new(0.25, 0.0, 0.5), Color::new(0.625, 0.0, 0.75));
    assert_eq!(s.scale, Some(Color::new(2.5, 1.0, 1.5)));
}
