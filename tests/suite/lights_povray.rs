//! The extension's lights against POV-Ray 3.7 on a scene of our own: a grey floor, a
//! red ball and a green one, lit in turn by a `directional` light (POV-Ray's `parallel`),
//! a `spot` (`spotlight`), a point light with `fade` (`fade_distance` / `fade_power`) and
//! a 4 × 4 `area` light (`area_light` without jitter). The lights are put in the scene's
//! extension by hand (as the reader hands them over) and drawn through the library; the
//! POV-Ray side is the same scene written in its language (z negated: POV-Ray is
//! left-handed). Bound: under 1 % of the pixels more than 6 levels apart on a channel.
//! Skips without POV-Ray (fails under CI).

use crate::support::povray::{against_povray, assert_close, povray};
use glam::DVec3;
use whitted::scene::ext::{ExtLight, LightKind, Modifiers};
use whitted::Scene;

const W: u32 = 160;
const H: u32 = 120;

/// The scene's report part: camera, floor, two balls, no report light.
const BASE: &str = "160 120  0 4 8  0 0.5 0  0 0  2 1 0 0
1   0 1 0      1 0.9 0.2 0.2   0.7 0 0 1 0 0
0.6 -2 0.6 1   1 0.2 0.8 0.3   0.7 0 0 1 0 0
0 0 0  0 1 0   1 0.8 0.8 0.8   1 0 0 1 0 0
";

/// The same in POV-Ray's language, the report's model as benches/pov/orbit.pov has it.
const POV_BASE: &str = "#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 6 adc_bailout 1/256 }
camera { perspective location <0, 4, -8> direction <0, 0, 1> right <0.5, 0, 0>
  up <0, 0.35, 0> sky <0, 1, 0> look_at <0, 0.5, 0> }
#macro Fin(Kd) finish { ambient 0.2 diffuse Kd phong (1 - Kd) phong_size 20 } #end
sphere { <0, 1, 0>, 1 pigment { color rgb <0.9, 0.2, 0.2> } Fin(0.7) }
sphere { <-2, 0.6, -1>, 0.6 pigment { color rgb <0.2, 0.8, 0.3> } Fin(0.7) }
plane { y, 0 pigment { color rgb <0.8, 0.8, 0.8> } Fin(1) }
";

fn light(kind: LightKind, color: [f64; 3], intensity: f64, fade: Option<(f64, f64)>) -> ExtLight {
    ExtLight {
        kind,
        color: DVec3::from(color),
        intensity,
        mods: Modifiers {
            fade,
            ..Modifiers::default()
        },
        loc: Default::default(),
    }
}

/// Draws `lights` on the base scene with us and `pov_light` with POV-Ray; the share of
/// pixels apart, or none when POV-Ray is missing.
fn compare(lights: Vec<ExtLight>, pov_light: &str) -> Option<f64> {
    povray()?;
    let dir = tempfile::tempdir().unwrap();
    let mut scene = Scene::parse(BASE, "lights.txt").unwrap();
    scene.ext.lights = lights;
    let pov = dir.path().join("scene.pov");
    std::fs::write(&pov, format!("{POV_BASE}{pov_light}\n")).unwrap();
    Some(against_povray(
        &scene,
        &pov,
        (W, H),
        ("LIGHTS_POVRAY_KEEP", "light"),
    ))
}

#[test]
fn directional_matches_parallel() {
    // POV-Ray's parallel light casts shadows only from objects in front of its location:
    // the location is put far back along the direction.
    let d = light(
        LightKind::Directional {
            direction: DVec3::new(-1.0, -2.0, -1.5),
        },
        [1.0, 0.9, 0.8],
        0.8,
        None,
    );
    assert_close(compare(
        vec![d],
        "light_source { <100, 200, -150> color rgb <1, 0.9, 0.8> * 0.8 parallel point_at <0, 0, 0> }",
    ));
}

#[test]
fn spot_matches_spotlight() {
    let s = light(
        LightKind::Spot {
            position: DVec3::new(3.0, 6.0, 2.0),
            target: DVec3::new(-0.5, 0.0, 0.0),
            radius: 12.0,
            falloff: 25.0,
            tightness: 4.0,
        },
        [1.0, 1.0, 1.0],
        1.0,
        None,
    );
    assert_close(compare(
        vec![s],
        "light_source { <3, 6, -2> color rgb 1 spotlight point_at <-0.5, 0, 0> \
         radius 12 falloff 25 tightness 4 }",
    ));
}

#[test]
fn faded_point_matches_fade_distance_and_power() {
    let p = light(
        LightKind::Point {
            position: DVec3::new(2.0, 3.0, 2.0),
        },
        [1.0, 1.0, 0.9],
        1.0,
        Some((2.5, 2.0)),
    );
    assert_close(compare(
        vec![p],
        "light_source { <2, 3, -2> color rgb <1, 1, 0.9> fade_distance 2.5 fade_power 2 }",
    ));
}

#[test]
fn area_matches_area_light() {
    // 4 × 4 points over a 3 × 3 square above the balls: soft shadow edges.
    let a = light(
        LightKind::Area {
            position: DVec3::new(1.0, 6.0, 1.0),
            a1: DVec3::new(3.0, 0.0, 0.0),
            a2: DVec3::new(0.0, 0.0, 3.0),
            n1: 4,
            n2: 4,
        },
        [1.0, 1.0, 1.0],
        0.9,
        None,
    );
    assert_close(compare(
        vec![a],
        "light_source { <1, 6, -1> color rgb 0.9 area_light <3, 0, 0>, <0, 0, -3>, 4, 4 }",
    ));
}
