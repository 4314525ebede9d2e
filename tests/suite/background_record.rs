//! The `background R G B` record through `raytrace`: rays that hit nothing take the
//! colour (a PNG's corner is its bytes), fog still whitens it, an EXR of the light split
//! gains a `background` layer (decoded to linear light like the beauty) and its layers sum
//! to the beauty; a bad or second record is a located error.

use crate::support::{exr_channels, raytrace, render_scene};

/// A 32 × 24 view with a small sphere in the middle; `fog` is FogType FogDistance.
fn scene(fog: &str, records: &str) -> String {
    format!(
        "32 24  0 0 10  0 0 0  {fog}  1 0 0 1
0.5 0 0 0  1 1 0 0  0.8 0 0 1 0 0
5 5 5  1 1 1  1
{records}"
    )
}

/// The RGB of pixel (x, y) of a PNG's bytes.
fn pixel(png: &[u8], x: u32, y: u32) -> [u8; 3] {
    let img = image::load_from_memory(png).unwrap().to_rgb8();
    img.get_pixel(x, y).0
}

#[test]
fn misses_take_the_colour_and_fog_still_applies() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let black = render_scene(d, &scene("0 0", "")).unwrap();
    assert_eq!(pixel(&black, 0, 0), [0, 0, 0]);
    let png = render_scene(d, &scene("0 0", "background 0.2 0.4 0.6\n")).unwrap();
    // round(255·0.2, 0.4, 0.6) in the corner; the sphere in the middle is unchanged.
    assert_eq!(pixel(&png, 0, 0), [51, 102, 153]);
    assert_eq!(pixel(&png, 16, 12), pixel(&black, 16, 12));
    // Exponential fog over 20 (type 2): a miss is at infinity, wholly fogged to white,
    // as the black background is.
    let fogged = render_scene(d, &scene("2 20", "background 0.2 0.4 0.6\n")).unwrap();
    assert_eq!(pixel(&fogged, 0, 0), [255, 255, 255]);
}

#[test]
fn an_exr_of_the_light_split_gains_a_background_layer_that_sums() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let exr = d.join("x.exr");
    for (records, layer) in [("", false), ("background 0.2 0.4 0.6\n", true)] {
        let path = d.join("scene.txt");
        std::fs::write(&path, scene("0 0", records)).unwrap();
        raytrace()
            .arg(&path)
            .args(["--passes", "all", "-o"])
            .arg(&exr)
            .assert()
            .success();
        let ch = exr_channels(&exr);
        assert_eq!(ch.contains_key("background.R"), layer, "{:?}", ch.keys());
        let light = [
            "ambient",
            "diffuse",
            "specular",
            "reflection",
            "transmission",
            "fog",
        ];
        for (k, want) in ch["R"].iter().enumerate() {
            let mut sum: f32 = light.iter().map(|l| ch[&format!("{l}.R")][k]).sum();
            sum += ch.get("background.R").map_or(0.0, |b| b[k]);
            assert!(
                (sum - want).abs() <= 1e-3 * want.abs().max(1e-2),
                "pixel {k}: {sum} vs {want}"
            );
        }
        if layer {
            // The corner sees the background alone: 0.2 decoded from sRGB to linear
            // light, ((0.2 + 0.055) / 1.055)^2.4 = 0.033105, as the beauty is.
            let r = ch["background.R"][0];
            assert!((r - 0.033105).abs() < 2e-5, "{r}");
        }
    }
}

#[test]
fn bad_background_records_are_located_errors() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let e = render_scene(d, &scene("0 0", "background 0.2 1.4 0.6\n")).unwrap_err();
    assert!(e.contains("DIR/scene.txt:4:16:"), "{e}");
    let two = "background 0 0 0\nbackground 1 1 1\n";
    let e = render_scene(d, &scene("0 0", two)).unwrap_err();
    assert!(
        e.contains("DIR/scene.txt:5:1:") && e.contains("second background record"),
        "{e}"
    );
    let e = render_scene(d, &scene("0 0", "backgrund 0 0 0\n")).unwrap_err();
    assert!(e.contains("did you mean 'background'?"), "{e}");
}
