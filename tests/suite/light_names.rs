//! The extension's lights by name and in the light split: each kind is numbered on its
//! own (`point` records are `light N` after the report's, then `spot 1`, `area 1`,
//! `directional 1`), a `name` replaces the number; and the EXR's light split (ambient,
//! diffuse, specular, reflection, transmission, fog) still sums to the beauty when
//! every kind of light shines, with fade, shadows through glass and fog.

use whitted::passes::{Pass, PassSet};
use whitted::render::{render, Layered, Options};
use whitted::trace::Tracer;
use whitted::Scene;

const SCENE: &str = "40 30  0 3 9  0 0.8 0  1 30  2 1 0 2
1    -1 1 0    1 0.9 0.3 0.2     0.6 0.3 0 1 0 0
0.7   1.2 0.7 0.8  1 0.9 0.9 1   0.1 0.1 0.8 1.4 0 0
0 0 0  0 1 0   2 1 1 1 1 0.2 0.2 0.2 0 0 0   0.9 0.1 0 1 0 0
5 9 6  1 1 1  0.5
-6 7 4  0.6 0.7 1  0.4
point 2 4 3   1 0.9 0.8  0.8   fade 3 2
spot 0 7 2  0 0 0   1 1 0.9  0.9  15 30 2
area 1 6 1  2 0 0  0 0 2  3 3  1 1 1  0.5   name key
directional -1 -2 -1  0.9 0.9 1  0.4
point -3 3 3  0.5 1 0.5  0.3
";

#[test]
fn lights_are_numbered_per_kind_after_the_reports() {
    let scene = Scene::parse(SCENE, "lights.txt").unwrap();
    let names = scene.light_names();
    let want = [
        "light 1",
        "light 2",
        "light 3",
        "spot 1",
        "key",
        "directional 1",
        "light 4",
    ];
    assert_eq!(names, want);
}

#[test]
fn the_light_split_sums_to_the_beauty_with_every_kind_of_light() {
    let scene = Scene::parse(SCENE, "lights.txt").unwrap();
    let tracer = Tracer::new(&scene);
    let (w, h) = (scene.width, scene.height);
    let grid = Options::grid(w, h, 2);
    let light = Layered(PassSet::of(&Pass::LIGHT));
    let (layers, _) = render(&tracer, &scene.camera(), &grid, light);
    let mut lit = 0;
    for (k, c) in layers.beauty.iter().enumerate() {
        for (axis, ch) in ["R", "G", "B"].iter().enumerate() {
            let sum: f64 = [
                "ambient",
                "diffuse",
                "specular",
                "reflection",
                "transmission",
                "fog",
            ]
            .iter()
            .map(|l| f64::from(layers.channel(&format!("{l}.{ch}")).unwrap().values[k]))
            .sum();
            let want = c[axis];
            assert!(
                (sum - want).abs() <= 1e-5 * want.abs().max(1e-3),
                "pixel {k} {ch}: split {sum}, beauty {want}"
            );
        }
        lit += usize::from(layers.channel("diffuse.R").unwrap().values[k] > 0.0);
    }
    assert!(lit > (w * h / 2) as usize, "only {lit} pixels lit");
}
