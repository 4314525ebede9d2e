//! `--info`'s values by hand: bounds, triangle counts, the camera's angles, the pixels an
//! object spans, and the two warnings.

use super::show::num;
use super::*;

/// A 32 × 24 scene, eye at z = 5 looking at the origin: a sphere of radius `r` at the
/// origin, a floor plane, one light.
fn scene(r: &str) -> Scene {
    let text = format!(
        "32 24  0 0 5  0 0 0  0 0  1 1 0 1
{r} 0 0 0  1 1 0 0  1 0 0 1 0 0
0 -2 0  0 1 0  1 1 1 1  1 0 0 1 0 0
0 5 5  1 1 1  1
box 1 2 3  2 4 6  1 1 1 1  1 0 0 1 0 0  name crate translate 0 0 -10
directional 0 -1 0  1 1 1  1
"
    );
    Scene::parse(&text, "t.txt").unwrap()
}

fn info(s: &Scene) -> Info {
    Info::of(s, (32, 24), (32, 24), &Lens::default())
}

#[test]
fn numbers_keep_four_decimals_or_their_digits() {
    assert_eq!(num(1.0), "1");
    assert_eq!(num(-0.25), "-0.25");
    assert_eq!(num(12.345_678), "12.3457");
    assert_eq!(num(-0.00001), "-1e-5");
    assert_eq!(num(0.000_025), "2.5e-5");
    assert_eq!(num(-0.0), "0");
    assert_eq!(num(0.0), "0");
}

#[test]
fn objects_lights_and_camera_by_hand() {
    let i = info(&scene("1"));
    let o = &i.objects;
    assert_eq!(o.len(), 3);
    assert_eq!(
        (o[0].number, o[0].name.as_str(), o[0].kind),
        (1, "sphere 1", "sphere")
    );
    assert_eq!(o[0].bounds, Some((DVec3::splat(-1.0), DVec3::splat(1.0))));
    assert_eq!(
        (o[1].kind, o[1].bounds, o[1].triangles),
        ("plane", None, None)
    );
    // The box moved 10 back by its translate: z from 3 − 10 to 6 − 10.
    assert_eq!(
        (o[2].number, o[2].name.as_str(), o[2].kind),
        (3, "crate", "box")
    );
    let (lo, hi) = o[2].bounds.unwrap();
    assert!(
        (lo - DVec3::new(1.0, 2.0, -7.0)).abs().max_element() < 1e-12,
        "{lo}"
    );
    assert!(
        (hi - DVec3::new(2.0, 4.0, -4.0)).abs().max_element() < 1e-12,
        "{hi}"
    );
    let l = &i.lights;
    assert_eq!((l[0].name.as_str(), l[0].kind), ("light 1", "point"));
    assert_eq!(l[0].place, LightPlace::At(DVec3::new(0.0, 5.0, 5.0)));
    assert_eq!((l[1].number, l[1].name.as_str()), (2, "directional 1"));
    assert_eq!(l[1].place, LightPlace::Towards(DVec3::new(0.0, -1.0, 0.0)));
    // The report's plane, 0.5 × 0.35 at distance 1: 2·atan(0.175) and 2·atan(0.25).
    assert!((i.camera.fov() - 19.852_491).abs() < 1e-6);
    assert!((i.camera.fov_horizontal() - 28.072_487).abs() < 1e-6);
    assert!(i.warnings.is_empty(), "{:?}", i.warnings);
    let text = i.to_string();
    assert!(
        text.contains("  1  sphere 1  sphere  -          [-1, -1, -1] to [1, 1, 1]\n"),
        "{text}"
    );
    assert!(
        text.contains("  3  crate     box     -          [1, 2, -7] to [2, 4, -4]\n"),
        "{text}"
    );
    assert!(
        text.contains("  2  directional 1  directional  towards [0, -1, 0]\n"),
        "{text}"
    );
    assert!(
        text.ends_with("camera: eye [0, 0, 5], look-at [0, 0, 0], 32×24 pixels, field of view 19.8525° vertical (28.0725° horizontal)\n"),
        "{text}"
    );
}

#[test]
fn pixels_spanned_by_hand() {
    // The unit sphere's box: diagonal 2√3 at distance 5; a pixel is 0.35 / 24 at
    // distance 1: 2√3 / (5 · 0.35 / 24) = 47.5077 pixels.
    let i = info(&scene("1"));
    let spans = i.camera.pixels_spanned(2.0 * 3f64.sqrt(), 5.0);
    assert!((spans - 47.507_679).abs() < 1e-5, "{spans}");
}

#[test]
fn a_speck_and_a_camera_inside_are_warned_about() {
    // Radius 0.001: 0.0475 pixel.
    let i = info(&scene("0.001"));
    assert_eq!(i.warnings.len(), 1, "{:?}", i.warnings);
    let w = &i.warnings[0];
    assert!(
        w.starts_with("object 1 (sphere 1) would cover less than one pixel"),
        "{w}"
    );
    assert!(w.contains("spans 0.0475 pixel"), "{w}");
    // Radius 6 holds the eye at z = 5.
    let i = info(&scene("6"));
    assert_eq!(i.warnings.len(), 1, "{:?}", i.warnings);
    let w = &i.warnings[0];
    assert!(
        w.starts_with("the camera at [0, 0, 5] is inside the bounds of object 1 (sphere 1), [-6, -6, -6] to [6, 6, 6]"),
        "{w}"
    );
}
