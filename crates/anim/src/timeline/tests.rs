use super::*;
use crate::manifest::Manifest;
use crate::refusal::ManifestError;
use std::path::Path;

const SCENE: &str = "8 6  0 2 10  0 1 0  1 30  2 1 0 1
1.0  0 1 0   1 0.9 0.1 0.1   0.7 0.3 0 1 0 0
0.5  2 0.5 0   1 0.2 0.2 0.9   0.8 0 0 1 0 0
0 0 0  0 1 0   2 1 1 1 1 0 0 0 0 0 0   0.9 0 0 1 0 0
5 10 5  1 1 1  0.9";

fn timeline(manifest: &str) -> Result<Timeline, ManifestError> {
    let text = format!("scene = \"s.txt\"\nframes = 81\n{manifest}");
    let m = Manifest::parse(&text, Path::new("m.toml"))?;
    Timeline::new(Scene::parse(SCENE, "s.txt").unwrap(), &m)
}

fn refusal(manifest: &str) -> String {
    timeline(manifest).unwrap_err().to_string()
}

const BOUNCE: &str = "[[track]]
target = \"sphere 1 center\"
keys = [
  { frame = 0, value = [0.0, 1.0, 0.0] },
  { frame = 40, value = [0.0, 4.0, 0.0], ease = \"out\" },
  { frame = 80, value = [0.0, 1.0, 0.0] },
]
";

#[test]
fn without_a_camera_the_scene_holds_still() {
    let t = timeline("").unwrap();
    let s = t.at(17.0);
    assert_eq!((s.eye, s.look_at), (DVec3::new(0.0, 2.0, 10.0), DVec3::Y));
    assert!(matches!(s.scene, Cow::Borrowed(_)));
}

#[test]
fn tracks_put_their_values_into_the_scene() {
    let t = timeline(BOUNCE).unwrap();
    let center = |f: f64| match t.at(f).scene.specs[0] {
        whitted::scene::ObjectSpec::Record(whitted::scene::ShapeSpec::Sphere {
            center, ..
        }) => center,
        _ => unreachable!(),
    };
    assert_eq!(center(0.0), DVec3::new(0.0, 1.0, 0.0));
    assert_eq!(center(20.0), DVec3::new(0.0, 2.5, 0.0));
    // From frame 40 the key's own ease (out): u = 0.5 → e = 0.75 → 4 − 3·0.75 = 1.75.
    assert_eq!(center(60.0), DVec3::new(0.0, 1.75, 0.0));
    // The shape the tracer draws moved too.
    let shape = t.at(40.0).scene.objects[0].shape.clone();
    assert_eq!(
        Some(shape),
        whitted::scene::ShapeSpec::Sphere {
            center: DVec3::new(0.0, 4.0, 0.0),
            radius: 1.0
        }
        .build()
    );
    assert!(t.moves_geometry());
    assert_eq!(t.tracked_positions()[0].1[40], DVec3::new(0.0, 4.0, 0.0));
}

#[test]
fn the_camera_follows_an_object_tracked_or_not() {
    let t = timeline(&format!("[camera]\nlook_at = \"sphere 1\"\n{BOUNCE}")).unwrap();
    assert_eq!(t.at(40.0).look_at, DVec3::new(0.0, 4.0, 0.0));
    assert_eq!(t.at(40.0).eye, DVec3::new(0.0, 2.0, 10.0));
    let t = timeline("[camera]\npath = \"circle\"\ncenter = [0.0, 1.0, 0.0]\nradius = 5.0\nheight = 2.0\nlook_at = \"sphere 2\"\n").unwrap();
    assert_eq!(t.at(3.0).look_at, DVec3::new(2.0, 0.5, 0.0));
    let t = timeline("[camera]\nlook_at = [1.0, 2.0, 3.0]\n").unwrap();
    assert_eq!(t.at(3.0).look_at, DVec3::new(1.0, 2.0, 3.0));
}

#[test]
fn colour_and_light_tracks_leave_geometry_alone() {
    let t = timeline("[[track]]\ntarget = \"sphere 2 color\"\nkeys = [{ frame = 0, value = [0.0, 0.0, 0.0] }, { frame = 80, value = [1.0, 1.0, 1.0] }]\n[[track]]\ntarget = \"light 1 position\"\npath = \"circle\"\ncenter = [0.0, 0.0, 0.0]\nradius = 8.0\nheight = 10.0\n").unwrap();
    assert!(!t.moves_geometry());
    assert_eq!(
        t.at(40.0).scene.objects[1].texture,
        whitted::texture::Texture::Uniform(DVec3::splat(0.5))
    );
    assert!(
        t.at(0.0).scene.lights[0]
            .position
            .distance(DVec3::new(0.0, 10.0, 8.0))
            < 1e-12
    );
}

#[test]
fn motion_blur_times_straddle_the_frame() {
    let t = timeline("[render]\nmotion_blur = { shutter = 0.5, samples = 4 }\n").unwrap();
    // t_k = 10 + 0.5·((k + ½)/4 − ½): 9.8125, 9.9375, 10.0625, 10.1875.
    assert_eq!(t.times(10), vec![9.8125, 9.9375, 10.0625, 10.1875]);
    let t = timeline("[render]\nmotion_blur = {}\n").unwrap();
    assert_eq!(t.times(0).len(), 8);
    assert_eq!(timeline("").unwrap().times(7), vec![7.0]);
}

#[test]
fn every_value_at_every_time_is_checked() {
    // The radius reaches 0 at frame 80: refused at the key that starts the segment.
    let e = refusal("[[track]]\ntarget = \"sphere 1 radius\"\nkeys = [{ frame = 0, value = 1.0 }, { frame = 80, value = 0.0 }]\n");
    assert!(e.starts_with("m.toml:5:"), "{e}");
    assert!(
        e.contains("track 1 (`sphere 1 radius`): at frame 80 its value 0 is out of bounds"),
        "{e}"
    );
    // A smooth colour dips below 0 between keys that are all within 0..1 (the curve's
    // knots come from distances in all three channels).
    let e = refusal("[[track]]\ntarget = \"sphere 1 color\"\ninterpolation = \"smooth\"\nkeys = [{ frame = 0, value = [0.0, 0.0, 0.0] }, { frame = 10, value = [0.0, 0.0, 0.5] }, { frame = 20, value = [0.0, 0.5, 0.0] }]\n");
    assert!(e.contains("at frame 1 its value [0, -0.00"), "{e}");
    assert!(
        e.contains("out of bounds: each colour channel must be from 0 to 1"),
        "{e}"
    );
    // The same dip between keys one frame apart: only motion-blur times see it.
    let keys = "keys = [{ frame = 0, value = [0.0, 0.0, 0.0] }, { frame = 1, value = [0.0, 0.0, 0.5] }, { frame = 2, value = [0.0, 0.5, 0.0] }]";
    let track =
        format!("[[track]]\ntarget = \"sphere 1 color\"\ninterpolation = \"smooth\"\n{keys}\n");
    assert!(timeline(&track).is_ok());
    let e = refusal(&format!(
        "[render]\nmotion_blur = {{ shutter = 0.5, samples = 4 }}\n{track}"
    ));
    assert!(e.contains("at frame 0 (motion-blur time 0.0625)"), "{e}");
}

#[test]
fn targets_are_refused_at_their_line() {
    let e = refusal(
        "[[track]]\ntarget = \"sphere 9 center\"\nkeys = [{ frame = 0, value = [0, 0, 0] }]\n",
    );
    assert!(e.starts_with("m.toml:4:10: sphere 9 does not exist"), "{e}");
    let e = refusal(
        "[[track]]\ntarget = \"sphere 1 radius\"\nkeys = [{ frame = 0, value = [1, 1, 1] }]\n",
    );
    assert!(e.contains("takes a number"), "{e}");
    let e = refusal("[[track]]\ntarget = \"sphere 1 kd\"\npath = \"circle\"\ncenter = [0, 0, 0]\nradius = 1.0\nheight = 0.0\n");
    assert!(e.contains("is not a position"), "{e}");
    let e = refusal(&format!("{BOUNCE}{BOUNCE}"));
    assert!(
        e.contains("track 2: its target `sphere 1 center` is already animated by track 1"),
        "{e}"
    );
    let e = refusal("[camera]\nlook_at = \"sphere 7\"\n");
    assert!(
        e.starts_with("m.toml:4:11: look_at: sphere 7 does not exist"),
        "{e}"
    );
}
