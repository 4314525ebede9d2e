//! Tracks: random `[[track]]` tables, resolved against a real scene.

use super::*;
#[allow(unused_imports)]
use super::{findings::*, manifest_properties::*, manifests::*, properties::*, seeds::*};
use whitted_anim::Manifest;

use whitted_anim::Timeline;

/// A scene with one object of each kind, fog and two lights, for track targets.
pub(super) const TRACK_SCENE: &str = "8 6  0 2 10  0 1 0  2 30  2 1 1 2
1.0  0 1 0   1 0.9 0.1 0.1   0.7 0.3 0 1 1 0.1
0.5  2 0.5 0   2 2 0.1 0.2 0.3 0.4 0.5 0.6 0.7 0.8 0.9   0.8 0 0.5 1.5 0 0
0 0 0  0 1 0   2 1 1 1 1 0 0 0 0 0 0   0.9 0 0 1 0 0
0 1 0  -2 0 -2  0.3   1 0.2 0.5 0.8   0.7 0 0 1 0 0
5 10 5  1 1 1  0.9
-6 8 4  0.6 0.6 0.8  0.6";

/// Every track feature at once, as a seed.
pub(super) const TRACKS: &str = r#"scene = "s.txt"
frames = 30
[camera]
look_at = "sphere 2"
[render]
motion_blur = { shutter = 0.75, samples = 3 }
[[track]]
target = "sphere 1 center"
interpolation = "smooth"
ease = "in-out"
keys = [{ frame = 0, value = [0, 1, 0] }, { frame = 10, value = [0, 3, 0], ease = "out" }, { frame = 29, value = [1, 1, 0] }]
[[track]]
target = "light 1 position"
path = "circle"
center = [0, 0, 0]
radius = 5.0
height = 8.0
turns = -2.0
[[track]]
target = "plane 1 color1"
interpolation = "step"
keys = [{ frame = 0, value = [1, 1, 1] }, { frame = 15, value = [0.2, 0.3, 0.4] }]
[[track]]
target = "fog distance"
keys = [{ frame = 3, value = 30 }, { frame = 20, value = 5.5 }]
"#;

pub(super) fn track_target() -> BoxedStrategy<String> {
    let kinds = [
        "sphere 1",
        "sphere 2",
        "sphere 3",
        "plane 1",
        "cylinder 1",
        "light 1",
        "light 2",
        "cube 1",
        "fog",
        "",
    ];
    let fields = [
        "center",
        "radius",
        "point",
        "normal",
        "axis",
        "color",
        "color1",
        "color2",
        "color3",
        "kd",
        "kr",
        "kt",
        "ior",
        "bump",
        "position",
        "intensity",
        "distance",
        "size",
    ];
    (
        prop::sample::select(kinds.to_vec()),
        prop::sample::select(fields.to_vec()),
    )
        .prop_map(|(k, f)| format!("\"{k} {f}\""))
        .boxed()
}

pub(super) fn track_value() -> BoxedStrategy<String> {
    prop_oneof![
        3 => (-3.0f64..3.0).prop_map(|x| format!("{x:?}")),
        3 => ((-3.0f64..3.0), (-0.5f64..1.5), (-3.0f64..3.0)).prop_map(|(x, y, z)| format!("[{x:?}, {y:?}, {z:?}]")),
        2 => (0.0f64..1.0).prop_map(|x| format!("{x:?}")),
        2 => ((0.0f64..1.0), (0.0f64..1.0), (0.0f64..1.0)).prop_map(|(x, y, z)| format!("[{x:?}, {y:?}, {z:?}]")),
        1 => float(),
        1 => point(),
    ]
    .boxed()
}

pub(super) fn track_table() -> BoxedStrategy<String> {
    let names = |v: &'static [&'static str]| prop::option::of(prop::sample::select(v));
    let key = (
        int(-2..14),
        track_value(),
        names(&["none", "in", "out", "in-out", "inout"]),
    )
        .prop_map(|(f, v, e)| match e {
            Some(e) => format!("{{ frame = {f}, value = {v}, ease = \"{e}\" }}"),
            None => format!("{{ frame = {f}, value = {v} }}"),
        });
    let keys =
        prop::collection::vec(key, 0..5).prop_map(|k| format!("keys = [{}]\n", k.join(", ")));
    let circle = (point(), float(), float()).prop_map(|(c, r, h)| {
        format!("path = \"circle\"\ncenter = {c}\nradius = {r}\nheight = {h}\n")
    });
    (
        track_target(),
        names(&["linear", "smooth", "step", "cubic"]),
        names(&["none", "in", "out", "in-out"]),
        prop_oneof![4 => keys, 1 => circle],
    )
        .prop_map(|(t, i, e, motion)| {
            let mut s = format!("[[track]]\ntarget = {t}\n");
            if let Some(i) = i {
                s += &format!("interpolation = \"{i}\"\n");
            }
            if let Some(e) = e {
                s += &format!("ease = \"{e}\"\n");
            }
            s + &motion
        })
        .boxed()
}

/// A manifest with random tracks over `TRACK_SCENE`: the timeline either accepts it,
/// and then every value at every sampled time is finite and every frame's scene draws
/// a camera, or refuses it with a location inside the text.
pub(super) fn timeline_ok_or_located(src: String) -> Result<(), String> {
    let shown = src.clone();
    bounded(move || {
        let m = match Manifest::parse(&src, Path::new(MANIFEST_PATH)) {
            Ok(m) => m,
            Err(e) => return check_manifest_error(&src, &e),
        };
        let scene = Scene::parse(TRACK_SCENE, "s.txt").map_err(|e| e.to_string())?;
        let timeline = match Timeline::new(scene, &m) {
            Ok(t) => t,
            Err(e) => return check_manifest_error(&src, &e),
        };
        for frame in 0..m.frames {
            for t in timeline.times(frame) {
                let s = timeline.at(t);
                let values_ok = s
                    .scene
                    .objects
                    .iter()
                    .all(|o| format!("{o:?}").find("NaN").is_none())
                    && s.scene
                        .lights
                        .iter()
                        .all(|l| l.position.is_finite() && l.intensity.is_finite());
                if !values_ok || !s.eye.is_finite() || !s.look_at.is_finite() {
                    return Err(format!("frame {frame} (t = {t}): a value is not finite"));
                }
            }
        }
        Ok(())
    })
    .and_then(|r| r)
    .map_err(|e| format!("{e}\n--- manifest ---\n{shown}\n---"))
}

#[test]
fn the_tracks_seed_resolves_against_its_scene() {
    timeline_ok_or_located(TRACKS.to_string()).unwrap();
    let m = Manifest::parse(TRACKS, Path::new(MANIFEST_PATH)).unwrap();
    let timeline = Timeline::new(Scene::parse(TRACK_SCENE, "s.txt").unwrap(), &m).unwrap();
    assert_eq!(timeline.tracks.len(), 4);
    assert_eq!(timeline.times(0).len(), 3);
}

proptest! {
    #![proptest_config(config(600))]

    #[test]
    fn random_tracks_resolve_or_are_located(
        frames in 1u32..16,
        blur in prop::option::of((0.05f64..1.0, 1u32..5)),
        tracks in prop::collection::vec(track_table(), 1..4),
    ) {
        let mut src = format!("scene = \"s.txt\"\nframes = {frames}\n");
        if let Some((shutter, samples)) = blur {
            src += &format!("[render]\nmotion_blur = {{ shutter = {shutter:?}, samples = {samples} }}\n");
        }
        src += &tracks.concat();
        timeline_ok_or_located(src).map_err(TestCaseError::fail)?;
    }

    #[test]
    fn mutated_tracks_seed(edits in prop::collection::vec(manifest_edit(), 1..4)) {
        let bytes = apply_manifest(TRACKS, &edits);
        let src = String::from_utf8_lossy(&bytes).into_owned();
        timeline_ok_or_located(src).map_err(TestCaseError::fail)?;
    }
}
