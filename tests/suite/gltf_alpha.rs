//! glTF coverage and emission through `raytrace` (SPEC §18), on the generated files of
//! tests/data/gltf (make_generated.py): BLEND's α = factor × texture × COLOR_0 alpha and
//! MASK's cutoff read from a float EXR's linear beauty; an `emissiveTexture` on
//! TEXCOORD_1 with its strength; the EXR light split of a scene in linear light stored
//! linear, with an `emission` layer, summing to the beauty; no warning for MASK or
//! BLEND, and one for a picture of another shape than the camera's `aspectRatio`.

use crate::support::{exr_channels, raytrace};
use std::collections::HashMap;
use std::path::{Path, PathBuf};

fn data(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/gltf/generated")
        .join(name)
}

/// `raytrace FILE -o DIR/x.exr --exr-depth float ARGS`: the EXR's channels and the
/// standard error.
fn exr_of(file: &str, dir: &Path, args: &[&str]) -> (HashMap<String, Vec<f32>>, String) {
    let exr = dir.join("x.exr");
    let out = raytrace()
        .arg(data(file))
        .arg("-o")
        .arg(&exr)
        .args(["--exr-depth", "float"])
        .args(args)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr).to_string();
    assert!(out.status.success(), "{stderr}");
    (exr_channels(&exr), stderr)
}

/// The value of channel `name` at pixel (x, y) of a 960-pixel-wide frame.
fn at(ch: &HashMap<String, Vec<f32>>, name: &str, x: usize, y: usize) -> f64 {
    f64::from(ch[name][y * 960 + x])
}

#[test]
fn blend_is_factor_times_texture_times_vertex_alpha_and_mask_cuts() {
    // Three quads at 960 × 480 (centre column 480, 164 pixels a unit): "Whole", BLEND at
    // alpha 1, the reference S around x = 192; "Blend", factor 0.8 × texture (1 on its
    // left half, 51/255 = 0.2 on its right) × COLOR_0 alpha 0.5: α = 0.4 at x = 418 and
    // 0.08 at x = 542, over black; "Mask", the same alpha with cutoff 0.3: drawn whole
    // at x = 706 (0.4 ≥ 0.3), absent at x = 829 (0.08).
    let dir = tempfile::tempdir().unwrap();
    let (ch, stderr) = exr_of("alpha_blend.gltf", dir.path(), &[]);
    assert!(!stderr.contains("alphaMode"), "{stderr}");
    let s = at(&ch, "R", 192, 240);
    assert!(s > 0.1, "the reference is lit: {s}");
    let ratio = |x| at(&ch, "R", x, 240) / s;
    assert!((ratio(418) - 0.4).abs() < 1e-5, "{}", ratio(418));
    assert!((ratio(542) - 0.08).abs() < 1e-5, "{}", ratio(542));
    assert!((ratio(706) - 1.0).abs() < 1e-6, "{}", ratio(706));
    assert_eq!(at(&ch, "R", 829, 240), 0.0);
    // Coverage counts a sample that meets the BLEND surface; the masked-out part none.
    assert_eq!((at(&ch, "A", 542, 240), at(&ch, "A", 829, 240)), (1.0, 0.0));
}

/// The sRGB EOTF (IEC 61966-2-1), written here from the standard.
fn decode(v: f64) -> f64 {
    if v <= 0.04045 {
        v / 12.92
    } else {
        ((v + 0.055) / 1.055).powf(2.4)
    }
}

#[test]
fn emissive_textures_and_the_exr_layers_of_a_linear_scene_sum_to_the_beauty() {
    // "Glow": black, emissiveFactor (1, 0.5, 0.25) × strength 2 × a 2 × 1 texture read on
    // TEXCOORD_1, which mirrors TEXCOORD_0: its left half (x = 279) shows the right
    // texel (128, 64, 255), its right half (x = 402) the white one. "Lit": base 0.5 lit by
    // the default light, emissiveFactor (0.1, 0.2, 0.3), at x = 620.
    let dir = tempfile::tempdir().unwrap();
    let (ch, _) = exr_of("emissive.gltf", dir.path(), &["--passes", "all"]);
    let texel = [decode(128.0 / 255.0), decode(64.0 / 255.0), 1.0];
    let factor = [2.0, 1.0, 0.5];
    for (k, c) in ["R", "G", "B"].into_iter().enumerate() {
        let left = at(&ch, &format!("emission.{c}"), 279, 240);
        assert!((left - factor[k] * texel[k]).abs() < 1e-5, "{c}: {left}");
        let right = at(&ch, &format!("emission.{c}"), 402, 240);
        assert!((right - factor[k]).abs() < 1e-5, "{c}: {right}");
        // A black base colour emits and reflects nothing else: the beauty is the
        // emission, linear and unclamped (2 in red).
        assert!((at(&ch, c, 402, 240) - factor[k]).abs() < 1e-5);
        let lit = at(&ch, &format!("emission.{c}"), 620, 240);
        assert!((lit - [0.1, 0.2, 0.3][k]).abs() < 1e-6, "{c}: {lit}");
    }
    // The light split is stored linear: the ambient term 0.2 × 0.5 = 0.1 as it is.
    assert!((at(&ch, "ambient.R", 620, 240) - 0.1).abs() < 1e-6);
    assert_layers_sum(&ch);
}

#[test]
fn exr_layers_sum_to_the_beauty_through_blend_and_mask() {
    // Behind a BLEND surface what lies behind goes to the transmission layer; two by
    // two samples average layers and beauty alike.
    let dir = tempfile::tempdir().unwrap();
    let args = ["--passes", "all", "--samples", "2", "--size", "320x240"];
    let (ch, _) = exr_of("alpha_modes.gltf", dir.path(), &args);
    assert!(!ch.contains_key("emission.R") && !ch.contains_key("background.R"));
    assert_layers_sum(&ch);
}

/// Every pixel's light split (and `emission`, `background` where written) sums to the
/// beauty in each channel, to 1e-5 relative (1e-6 absolute near black).
fn assert_layers_sum(ch: &HashMap<String, Vec<f32>>) {
    let layers = [
        "ambient",
        "diffuse",
        "specular",
        "reflection",
        "transmission",
        "fog",
        "emission",
        "background",
    ];
    for c in ["R", "G", "B"] {
        for (k, &want) in ch[c].iter().enumerate() {
            let sum: f64 = (layers.iter())
                .filter_map(|l| ch.get(&format!("{l}.{c}")))
                .map(|v| f64::from(v[k]))
                .sum();
            let want = f64::from(want);
            assert!(
                (sum - want).abs() <= 1e-5 * want.abs() + 1e-6,
                "pixel {k} {c}: layers {sum} vs beauty {want}"
            );
        }
    }
}

#[test]
fn a_picture_of_another_shape_than_the_cameras_aspect_ratio_is_warned_about() {
    // alpha_modes' camera has aspectRatio 4/3: 400 × 400 is warned about (with the size
    // that keeps it), 320 × 240 is not, and neither warns about MASK or BLEND.
    let dir = tempfile::tempdir().unwrap();
    let png = dir.path().join("x.png");
    let stderr = |size: &str| {
        let out = raytrace()
            .arg(data("alpha_modes.gltf"))
            .arg("-o")
            .arg(&png)
            .args(["--size", size])
            .output()
            .unwrap();
        assert!(out.status.success());
        String::from_utf8_lossy(&out.stderr).to_string()
    };
    let square = stderr("400x400");
    assert!(
        square.contains("the camera `Cam` has aspectRatio 1.3333 and the picture is 400×400")
            && square.contains("533×400 keeps the camera's"),
        "{square}"
    );
    let same = stderr("320x240");
    assert!(
        !same.contains("aspectRatio") && !same.contains("alphaMode"),
        "{same}"
    );
}
