//! Unit tests of the extension's lights as built from their records
//! (`scene::ext::build::lights`) and through the tracer: each value by hand on a floor
//! lit from above.

use super::*;
use crate::scene::ext::build::lights as build;
use crate::scene::ext::{ExtLight, Extension, LightKind, Modifiers};
use crate::trace::{RayCount, Tracer};
use crate::Scene;

fn record(kind: LightKind, fade: Option<(f64, f64)>) -> ExtLight {
    ExtLight {
        kind,
        color: Color::new(1.0, 0.5, 0.25),
        intensity: 0.5,
        mods: Modifiers {
            fade,
            ..Modifiers::default()
        },
        loc: Default::default(),
    }
}

/// A white floor (Kd = 1: no specular) seen from the side, no report light, and
/// `lights` as the extension's: the colour of the centre pixel's hit at the origin.
fn floor_colour(lights: Vec<ExtLight>, blocker: bool) -> (Color, RayCount) {
    let (n, ball) = if blocker {
        (1, "0.6 0 3 0  1 1 1 1  1 0 0 1 0 0\n")
    } else {
        (0, "")
    };
    let src =
        format!("1 1  0 1 10  0 0 0  0 0  {n} 1 0 0\n{ball}0 0 0  0 1 0  1 1 1 1  1 0 0 1 0 0\n");
    let mut scene = Scene::parse(&src, "t.txt").unwrap();
    scene.ext.lights = lights;
    let tracer = Tracer::new(&scene);
    let mut count = RayCount::default();
    let c = tracer.primary(&scene.camera().ray(0.5, 0.5), &mut count);
    (c, count)
}

#[test]
fn build_keeps_order_kinds_and_fade() {
    let ext = Extension {
        lights: vec![
            record(
                LightKind::Directional {
                    direction: DVec3::new(0.0, -3.0, 0.0),
                },
                None,
            ),
            record(LightKind::Point { position: DVec3::Y }, Some((2.0, 1.0))),
        ],
        ..Extension::default()
    };
    let built = build(&ext);
    assert_eq!(built.len(), 2);
    assert!(matches!(built[0].kind, Kind::Directional(d) if d.to_light == DVec3::Y));
    assert_eq!(
        built[1].fade,
        Some(Fade {
            distance: 2.0,
            power: 1.0
        })
    );
    // Point at distance 4 with fade 2, 1: 0.5 · 2/(1 + 2) = 1/3.
    let inc = built[1].incident(DVec3::new(0.0, -3.0, 0.0)).unwrap();
    assert!((inc.intensity - 1.0 / 3.0).abs() < 1e-15);
    assert_eq!(built[1].color(), Color::new(1.0, 0.5, 0.25));
}

#[test]
fn directional_light_on_a_floor_by_hand() {
    // Light travelling along (1, −1, 0): N·L = cos 45°; white floor, Kd = 1:
    // 0.2 + 0.5·cos45°·Lc.
    let d = record(
        LightKind::Directional {
            direction: DVec3::new(1.0, -1.0, 0.0),
        },
        None,
    );
    let (c, count) = floor_colour(vec![d], false);
    let k = 0.5 * std::f64::consts::FRAC_1_SQRT_2;
    let want = Color::splat(0.2) + k * Color::new(1.0, 0.5, 0.25);
    assert!((c - want).length() < 1e-12, "{c}");
    assert_eq!(count.shadow, 1);
}

#[test]
fn a_directional_shadow_is_unbounded() {
    // A ball straight above the floor point blocks the light from above, however far.
    let d = record(
        LightKind::Directional {
            direction: DVec3::new(0.0, -1.0, 0.0),
        },
        None,
    );
    let (c, _) = floor_colour(vec![d], true);
    assert_eq!(c, Color::splat(0.2));
}

#[test]
fn faded_spot_on_a_floor_by_hand() {
    // Spot 4 above, aimed down: c = 1, full; fade 2, 2 at d = 4: 2/(1 + 4) = 0.4.
    let s = record(
        LightKind::Spot {
            position: DVec3::new(0.0, 4.0, 0.0),
            target: DVec3::ZERO,
            radius: 10.0,
            falloff: 20.0,
            tightness: 3.0,
        },
        Some((2.0, 2.0)),
    );
    let (c, _) = floor_colour(vec![s], false);
    let want = Color::splat(0.2) + 0.5 * 0.4 * Color::new(1.0, 0.5, 0.25);
    assert!((c - want).length() < 1e-12, "{c}");
}

#[test]
fn area_light_half_hidden_by_hand() {
    // A 4 × 1 grid 6 wide at y = 6: points x = −3, −1, 1, 3. The ball of radius 0.6 at
    // y = 3 hides x = −1 and 1 (the rays pass 3/√37 ≈ 0.49 from its centre) but not ±3
    // (1.34 from it):
    // half the light, 4 shadow rays; shading takes the centre, straight above.
    let a = record(
        LightKind::Area {
            position: DVec3::new(0.0, 6.0, 0.0),
            a1: DVec3::new(6.0, 0.0, 0.0),
            a2: DVec3::new(0.0, 0.0, 1.0),
            n1: 4,
            n2: 1,
        },
        None,
    );
    let (c, count) = floor_colour(vec![a], true);
    let want = Color::splat(0.2) + 0.5 * 0.5 * Color::new(1.0, 0.5, 0.25);
    assert!((c - want).length() < 1e-12, "{c}");
    assert_eq!(count.shadow, 4);
}

/// 40 white balls of radius 0.3 on a 8 × 5 lattice at y = 1, over the floor y = 0, and
/// a wall x = 8.
fn balls_over_a_floor() -> Scene {
    let mut src = String::from("1 1  0 1 10  0 0 0  0 0  40 2 0 0\n");
    for i in 0..8 {
        for j in 0..5 {
            let (x, z) = (f64::from(i) - 3.5, f64::from(j) - 2.0);
            src += &format!("0.3 {x} 1 {z}  1 1 1 1  1 0 0 1 0 0\n");
        }
    }
    src += "0 0 0  0 1 0  1 1 1 1  1 0 0 1 0 0\n8 0 0  1 0 0  1 1 1 1  1 0 0 1 0 0\n";
    Scene::parse(&src, "t.txt").unwrap()
}

/// A 4 × 4 area light of unit colour and intensity at `position`, spanned by `a1`, `a2`.
fn grid4(position: DVec3, a1: DVec3, a2: DVec3) -> Area {
    Area::new(position, a1, a2, 4, 4, Color::ONE, 1.0)
}

/// The shadow of `light` at `p` through the tracer (and its shafts) and through the
/// linear scan (no shafts): the same bits and ray counts, asserted. What the tracer's
/// shaft said, or `None` where the light does not reach `p`.
fn shadow_both(scene: &Scene, tracer: &Tracer, light: &Area, p: DVec3) -> Option<Clearance> {
    let inc = light.incident(p)?;
    let (mut fast, mut slow) = (0, 0);
    let a = light.shadow(0, tracer, p, &inc, &mut fast);
    let b = light.shadow(0, scene.objects.as_slice(), p, &inc, &mut slow);
    let bits = |c: Color| c.to_array().map(f64::to_bits);
    assert_eq!(bits(a), bits(b), "{p}");
    assert_eq!(fast, slow, "{p}");
    Some(tracer.clearance(p, &light.corners))
}

#[test]
fn an_area_lights_shafts_give_the_linear_scans_answers() {
    // Floor points and ball points near a 4 × 4 area light: through the tracer (whose
    // shafts skip the trees where nothing bounded is in the way, and every ray where
    // the floor cannot be met either) and through the linear scan (no shafts), the same
    // bits and the same ray counts.
    let scene = balls_over_a_floor();
    let tracer = Tracer::new(&scene);
    let light = grid4(DVec3::new(0.0, 6.0, 0.0), 2.0 * DVec3::X, 2.0 * DVec3::Z);
    let mut seen = [0; 3];
    let floor = (0..41).flat_map(|i| (0..41).map(move |j| (i, j)));
    let points = floor
        .map(|(i, j)| DVec3::new(f64::from(i) * 0.6 - 12.0, 0.0, f64::from(j) * 0.5 - 10.0))
        .chain((0..40).map(|k| DVec3::new(f64::from(k % 8) - 3.5, 1.3, f64::from(k / 8) - 2.0)));
    for p in points {
        let clear = shadow_both(&scene, &tracer, &light, p).expect("every point is lit");
        seen[clear as usize] += 1;
    }
    // Not vacuous: open shafts (the floor between the balls and the wall), shafts the
    // wall may cut (the floor beyond it, and left of the light: each ray asks the
    // planes) and shafts with balls in them.
    assert!(seen[Clearance::Open as usize] > 300, "{seen:?}");
    assert!(seen[Clearance::Unbounded as usize] > 300, "{seen:?}");
    assert!(seen[Clearance::Unknown as usize] > 100, "{seen:?}");
}

/// A bumpy terrain of 2 × 12 × 12 triangles, y = 0.4 + 0.5·sin(1.3x)·cos(1.1z) over
/// x, z in −3..3 (hills and hollows), over the floor y = 0.
fn terrain() -> (Scene, Vec<[DVec3; 3]>) {
    let h = |x: f64, z: f64| DVec3::new(x, 0.4 + 0.5 * (1.3 * x).sin() * (1.1 * z).cos(), z);
    let mut tris = Vec::new();
    for i in 0..12 {
        for j in 0..12 {
            let (x, z) = (f64::from(i) * 0.5 - 3.0, f64::from(j) * 0.5 - 3.0);
            let (a, b) = (h(x, z), h(x + 0.5, z));
            let (c, d) = (h(x + 0.5, z + 0.5), h(x, z + 0.5));
            tris.push([a, d, c]);
            tris.push([a, c, b]);
        }
    }
    let mut src = String::from("1 1  0 1 10  0 0 0  0 0  0 1 0 0\n");
    src += "0 0 0  0 1 0  1 1 1 1  1 0 0 1 0 0\n";
    for [a, b, c] in &tris {
        let v = [a, b, c]
            .map(|p| format!("{} {} {}", p.x, p.y, p.z))
            .join("  ");
        src += &format!("triangle {v}   1 1 1 1   1 0 0 1 0 0\n");
    }
    (Scene::parse(&src, "t.txt").unwrap(), tris)
}

#[test]
fn a_surfaces_own_triangles_clear_their_shafts_with_the_linear_scans_answers() {
    // Points on each triangle of the terrain (as rounding leaves them), under a 4 × 4
    // area light low on one side: through the tracer (whose shafts ask the triangles of
    // the leaves they meet) and through the linear scan, the same bits and ray counts;
    // and the points facing the light see it through open shafts, though their own
    // leaves' boxes hold them, while hills hide it from others.
    let (scene, tris) = terrain();
    let tracer = Tracer::new(&scene);
    let light = grid4(DVec3::new(5.0, 1.5, 0.5), DVec3::Y, 2.0 * DVec3::Z);
    let mut seen = [0; 3];
    for [a, b, c] in &tris {
        for (u, v) in [(0.2, 0.3), (0.6, 0.1), (0.05, 0.9)] {
            let p = *a + u * (*b - *a) + v * (*c - *a);
            if let Some(clear) = shadow_both(&scene, &tracer, &light, p) {
                seen[clear as usize] += 1;
            }
        }
    }
    assert!(seen[Clearance::Open as usize] > 60, "{seen:?}");
    assert!(seen[Clearance::Unknown as usize] > 200, "{seen:?}");
}
