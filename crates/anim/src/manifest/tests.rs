//! Unit tests of the manifest: the SPEC's examples, defaults, paths and file names.

use super::*;
use crate::timeline::{CameraPath, Circle, Key};
use glam::DVec3;

/// SPEC §5's first example, verbatim.
pub(super) const ORBIT: &str = r#"scene = "../scenes/orbit.txt"   # the base Scene.txt; the tracer is the same as raytrace's
frames = 250
fps = 25

[camera]                         # circle: the report's 10 s orbit
path = "circle"
center = [0.0, 1.0, 0.0]         # the camera turns around this point and looks at it
radius = 12.0
height = 3.0                     # camera y
start_angle = 0.0                # degrees; 0 puts the camera on the +z side of center
turns = 1.0                      # negative turns go the other way
# look_at = [x, y, z]            # optional, defaults to center

[output]
dir = "../out/orbit"
name = "frame_####"              # #### = zero-padded frame number (Blender's convention)
format = "png"                   # png | jpeg | ppm | raw
jpeg_quality = 90

[render]                         # optional overrides of the scene file
# width = 1280
# height = 960
# samples = 2

[check]                          # regression on selected frames (OpenImageIO idiff's rules)
frames = [0, 62, 125, 187, 249]
references = "../tests/golden/orbit"
fail = 2                         # a pixel fails when a channel differs by more (0..255)
fail_percent = 0.1               # a frame fails when more than this % of its pixels fail
hard_fail = 64                   # ... or when any channel differs by more than this
"#;

/// SPEC §5's spline `[camera]`, verbatim, after the two keys it needs.
pub(super) const TOUR: &str = r#"scene = "orbit.txt"
frames = 250
[camera]
path = "spline"                  # centripetal Catmull-Rom through the keys
closed = false                   # true: the path loops back to the first key
constant_speed = false           # true: even speed by arc length between the first and last key
look_at = [0.0, 1.0, 0.0]        # or a look_at on each key, interpolated the same way
keys = [
  { frame = 0,   position = [0.0, 3.0, 12.0] },
  { frame = 120, position = [10.0, 6.0, 0.0] },
  { frame = 249, position = [0.0, 2.0, -12.0] },
]
"#;

pub(super) const CIRCLE: &str =
    "[camera]\npath = \"circle\"\ncenter = [0, 1, 0]\nradius = 2\nheight = 1\n";

pub(super) fn parse(src: &str) -> Result<Manifest, ManifestError> {
    Manifest::parse(src, Path::new("anims/m.toml"))
}

/// The `line:column: message` of a refused manifest (one line per unknown name).
pub(super) fn refusal(src: &str) -> String {
    match parse(src) {
        Err(e @ (ManifestError::Invalid { .. } | ManifestError::Unknown(_))) => {
            let text = e.to_string();
            let lines: Vec<&str> = text
                .lines()
                .map(|l| l.strip_prefix("anims/m.toml:").unwrap_or(l))
                .collect();
            lines.join("\n")
        }
        other => panic!("expected a refusal, got {other:?}"),
    }
}

/// A circle manifest with `extra` lines at the top level.
pub(super) fn with(extra: &str) -> String {
    format!("scene = \"s.txt\"\nframes = 10\n{extra}\n{CIRCLE}")
}

#[test]
fn the_spec_orbit_parses_with_its_values() {
    let m = Manifest::parse(ORBIT, Path::new("/work/anims/orbit.toml")).unwrap();
    assert_eq!(m.path, Path::new("/work/anims/orbit.toml"));
    assert_eq!(m.scene, Path::new("/work/anims/../scenes/orbit.txt"));
    assert_eq!((m.frames, m.fps), (250, 25.0));
    let circle = CameraPath::Circle {
        circle: Circle {
            center: DVec3::new(0.0, 1.0, 0.0),
            radius: 12.0,
            height: 3.0,
            start_angle: 0.0,
            turns: 1.0,
        },
        look_at: None,
    };
    assert_eq!(m.camera, Some(circle));
    let output = OutputSpec {
        dir: PathBuf::from("/work/anims/../out/orbit"),
        name: "frame_####".into(),
        format: ImageFormat::Png,
    };
    assert_eq!(m.output, output);
    let render = RenderSpec {
        width: None,
        height: None,
        samples: 1,
        motion_blur: None,
        antialias: None,
    };
    assert_eq!(m.render, render);
    let check = CheckSpec {
        frames: vec![0, 62, 125, 187, 249],
        references: PathBuf::from("/work/anims/../tests/golden/orbit"),
        fail: 2,
        fail_percent: 0.1,
        hard_fail: 64,
        flip: None,
    };
    assert_eq!(m.check, Some(check));
}

#[test]
fn the_spec_spline_parses_with_defaults() {
    let m = Manifest::parse(TOUR, Path::new("anims/tour.toml")).unwrap();
    assert_eq!(m.scene, Path::new("anims/orbit.txt"));
    assert_eq!(m.fps, 25.0);
    let key = |frame, p: [f64; 3]| Key {
        frame,
        position: DVec3::from_array(p),
        look_at: None,
        ease: Default::default(),
    };
    let keys = vec![
        key(0, [0.0, 3.0, 12.0]),
        key(120, [10.0, 6.0, 0.0]),
        key(249, [0.0, 2.0, -12.0]),
    ];
    let Some(CameraPath::Spline(spline)) = &m.camera else {
        panic!("not a spline: {:?}", m.camera);
    };
    assert_eq!(spline.keys, keys);
    assert!(!spline.closed && !spline.constant_speed);
    assert_eq!(spline.look_at, Some(DVec3::new(0.0, 1.0, 0.0)));
    assert_eq!(m.output.dir, Path::new("anims/tour-frames"));
    assert_eq!(m.output.name, "frame_####");
    assert_eq!(m.output.format, ImageFormat::Png);
    assert_eq!(
        m.render,
        RenderSpec {
            samples: 1,
            ..RenderSpec::default()
        }
    );
    assert_eq!(m.check, None);
}

#[test]
fn paths_are_relative_to_the_manifest_folder() {
    let src = "scene = \"s.txt\"\nframes = 2\n[output]\ndir = \"out\"\n[check]\nframes = [1]\nreferences = \"../ref\"\n";
    let src = format!("{src}{CIRCLE}");
    let m = Manifest::parse(&src, Path::new("a/b/m.toml")).unwrap();
    assert_eq!(m.scene, Path::new("a/b/s.txt"));
    assert_eq!(m.output.dir, Path::new("a/b/out"));
    assert_eq!(m.check.unwrap().references, Path::new("a/b/../ref"));
    let m = Manifest::parse(&src, Path::new("m.toml")).unwrap();
    assert_eq!(m.scene, Path::new("s.txt"));
    let abs = src.replace("\"s.txt\"", "\"/scenes/s.txt\"");
    let m = Manifest::parse(&abs, Path::new("a/m.toml")).unwrap();
    assert_eq!(m.scene, Path::new("/scenes/s.txt"));
    let m = Manifest::parse(&with(""), Path::new("a/walk.anim")).unwrap();
    assert_eq!(m.output.dir, Path::new("a/walk.anim-frames"));
}

#[test]
fn per_key_look_at_points_are_read() {
    let src = TOUR
        .replace("look_at = [0.0, 1.0, 0.0]", "")
        .replace("position = [", "look_at = [1, 2, 3], position = [");
    let m = parse(&src).unwrap();
    let (_, look) = m.camera.unwrap().at(120.0, 250, DVec3::ZERO);
    assert_eq!(look, DVec3::new(1.0, 2.0, 3.0));
}

#[test]
fn the_name_pattern_is_cut_around_its_first_run_of_hashes() {
    let spec = |name: &str| OutputSpec {
        dir: PathBuf::new(),
        name: name.into(),
        format: ImageFormat::Png,
    };
    assert_eq!(spec("f_###x").parts(), ("f_".to_string(), 3, "x"));
    assert_eq!(spec("a#b##").parts(), ("a".to_string(), 1, "b##"));
    assert_eq!(spec("walk").parts(), ("walk_".to_string(), 4, ""));
}

#[test]
fn file_names_are_padded_so_that_they_sort() {
    let spec = |name: &str, format| OutputSpec {
        dir: PathBuf::new(),
        name: name.into(),
        format,
    };
    let png = spec("frame_####", ImageFormat::Png);
    assert_eq!(png.file_name(7, 250), "frame_0007.png");
    assert_eq!(png.file_name(7, 100_000), "frame_00007.png");
    assert_eq!(png.file_name(99_999, 100_000), "frame_99999.png");
    assert_eq!(png.file_name(9, 10_000), "frame_0009.png");
    assert_eq!(png.file_name(9, 10_001), "frame_00009.png");
    assert_eq!(
        spec("a#b##", ImageFormat::Ppm).file_name(7, 10),
        "a7b##.ppm"
    );
    assert_eq!(
        spec("shot##_v2", ImageFormat::Raw).file_name(3, 10),
        "shot03_v2.raw"
    );
    assert_eq!(spec("#", ImageFormat::Png).file_name(42, 1000), "042.png");
    assert_eq!(
        spec("walk", ImageFormat::Jpeg { quality: 90 }).file_name(7, 10),
        "walk_0007.jpg"
    );
    assert_eq!(
        spec("walk", ImageFormat::Jpeg { quality: 90 }).file_name(7, 123_456),
        "walk_000007.jpg"
    );
    assert_eq!(
        spec("walk", ImageFormat::Png).file_name(0, 0),
        "walk_0000.png"
    );
}

#[test]
fn load_reads_a_file_and_reports_a_missing_one() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("orbit.toml");
    std::fs::write(&path, ORBIT).unwrap();
    let m = Manifest::load(&path).unwrap();
    assert_eq!(m.scene, dir.path().join("../scenes/orbit.txt"));
    let missing = dir.path().join("none.toml");
    let err = Manifest::load(&missing).unwrap_err();
    assert!(matches!(err, ManifestError::Io { .. }));
    assert!(err
        .to_string()
        .contains("none.toml: cannot read the manifest"));
}
