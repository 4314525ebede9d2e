//! Image textures against POV-Ray 3.7 on a scene of our own: a floor with a `planar` map
//! (`map_type 0`), a ball with a `spherical` one (`map_type 1`) and an upright cylinder
//! with a `cylindrical` one (`map_type 2`), all from one small PNG written by the test,
//! with `nearest` (POV-Ray's default, no interpolation) and `bilinear` (`interpolate 2`).
//! The POV-Ray side reads the image with `gamma 1.0` (its bytes as they are, like ours)
//! and has z negated (it is left-handed); each pigment is scaled by −1 along z back into
//! our frame and moved to the map frame's origin. Bound: under 1 % of the pixels more
//! than 6 levels apart on a channel. Skips without POV-Ray (fails under CI).

use crate::support::povray::{against_povray, assert_close, povray};
use whitted::Scene;

const W: u32 = 160;
const H: u32 = 120;

/// Ours: the floor (Size 2), a ball, a cylinder along y through (1.6, 0, −0.5) (Size
/// 1.5), one light. `{I}` is the interpolation.
const SCENE: &str = "160 120  0 4 8  0 0.5 0  0 0  1 1 1 1
1   -1.2 1 0   3 \"tex.png\" spherical {I} 1   0.7 0 0 1 0 0
0 0 0  0 1 0   3 \"tex.png\" planar {I} 2      1 0 0 1 0 0
0 1 0  1.6 0 -0.5  0.6   3 \"tex.png\" cylindrical {I} 1.5   0.7 0 0 1 0 0
5 8 6  1 1 1  1
";

/// The same in POV-Ray's language; `{I}` is `interpolate 2` or nothing (its default, no
/// interpolation).
const POV: &str = "#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 6 adc_bailout 1/256 }
camera { perspective location <0, 4, -8> direction <0, 0, 1> right <0.5, 0, 0>
  up <0, 0.35, 0> sky <0, 1, 0> look_at <0, 0.5, 0> }
#macro Fin(Kd) finish { ambient 0.2 diffuse Kd phong (1 - Kd) phong_size 20 } #end
#macro Img(T) image_map { png \"tex.png\" gamma 1.0 map_type T {I} } #end
sphere { <-1.2, 1, 0>, 1
  pigment { Img(1) scale <1, 1, -1> translate <-1.2, 1, 0> } Fin(0.7) }
plane { y, 0 pigment { Img(0) scale 2 rotate x*90 } Fin(1) }
cylinder { <1.6, -60, 0.5>, <1.6, 60, 0.5>, 0.6 open
  pigment { Img(2) scale <1, 1.5, -1> translate <1.6, 0, 0.5> } Fin(0.7) }
light_source { <5, 8, -6> color rgb 1 }
";

/// A 16 × 8 picture with a different colour in every pixel and no symmetry: red across,
/// green down, blue in a checker of 4 × 2 blocks.
pub(crate) fn texture_picture() -> image::RgbImage {
    image::RgbImage::from_fn(16, 8, |i, j| {
        let b = if (i / 4 + j / 2) % 2 == 0 { 40 } else { 230 };
        image::Rgb([(i * 16 + 8) as u8, (j * 30 + 10) as u8, b])
    })
}

/// Renders both; the share of pixels apart, or none without POV-Ray.
fn compare(ours_interp: &str, pov_interp: &str) -> Option<f64> {
    povray()?;
    let dir = tempfile::tempdir().unwrap();
    texture_picture().save(dir.path().join("tex.png")).unwrap();
    let scene_path = dir.path().join("scene.txt");
    std::fs::write(&scene_path, SCENE.replace("{I}", ours_interp)).unwrap();
    let scene = Scene::load(&scene_path).unwrap();
    let pov = dir.path().join("scene.pov");
    std::fs::write(&pov, POV.replace("{I}", pov_interp)).unwrap();
    let keep = ("IMAGE_POVRAY_KEEP", ours_interp);
    Some(against_povray(&scene, &pov, (W, H), keep))
}

#[test]
fn nearest_maps_match_image_map_without_interpolation() {
    assert_close(compare("nearest", ""));
}

#[test]
fn bilinear_maps_match_image_map_interpolate_2() {
    assert_close(compare("bilinear", "interpolate 2"));
}
