//! NFF scenes (SPEC §17) through the built binaries: `raytrace` reads `*.nff`, says where
//! a bad one is wrong (file:line:column, exit 2), `--stats` prints its JSON line after the
//! image, `--spd` draws 512 × 512 from 513 × 513 corner rays, the same bytes on any
//! thread count; `animate` takes an NFF scene and turns its circle about NFF's up. The
//! seven databases themselves are `spd_table`'s.

use crate::shipped;
use crate::skip;
use crate::support::{animate, pixels, raytrace};
use std::path::{Path, PathBuf};

/// The repository's own NFF scene (tests/data/nff/still-life.nff, 160 × 120).
fn still_life() -> PathBuf {
    shipped::root().join("tests/data/nff/still-life.nff")
}

/// The SPD beside the repository, or `None` (the test skips; fails under CI).
pub fn spd_dir() -> Option<PathBuf> {
    let dir = shipped::root().join("../shared/spd");
    if dir.join("balls.nff").is_file() {
        Some(dir)
    } else {
        skip::skip(&format!("{} (the SPD databases) is absent", dir.display()));
        None
    }
}

/// The stats line of a `raytrace ... --stats` run: the last line of standard error.
pub fn stats(stderr: &[u8]) -> serde_json::Value {
    let text = String::from_utf8_lossy(stderr);
    let last = text.lines().last().unwrap_or_default();
    serde_json::from_str(last).unwrap_or_else(|e| panic!("{e}: {text}"))
}

fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path
}

#[test]
fn an_nff_scene_renders_at_its_resolution_with_its_background() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("s.png");
    let run = raytrace()
        .arg(still_life())
        .arg("-o")
        .arg(&out)
        .arg("--stats")
        .output()
        .unwrap();
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let img = image::open(&out).unwrap().to_rgb8();
    assert_eq!(img.dimensions(), (160, 120));
    // The top-left corner sees the background b 0.2 0.3 0.5: 51, 77, 128.
    assert_eq!(img.get_pixel(0, 0).0, [51, 77, 128]);
    let s = stats(&run.stderr);
    assert_eq!(s["eye"], 160 * 120);
    let hits = s["eye_hits"].as_u64().unwrap();
    assert!(hits > 5000 && hits < 160 * 120, "{s}");
    // A mirror, a glass sphere and a reflective cone: all three kinds of secondary rays.
    for key in ["reflect", "refract", "shadow"] {
        assert!(s[key].as_u64().unwrap() > 1000, "{key}: {s}");
    }
    assert!(s["wall_s"].as_f64().unwrap() >= 0.0 && s["cpu_s"].as_f64().unwrap() >= 0.0);
}

#[test]
fn bad_nff_files_say_where_and_exit_2() {
    let dir = tempfile::tempdir().unwrap();
    let view = "v\nfrom 0 -5 1\nat 0 0 1\nup 0 0 1\nangle 40\nhither 1\nresolution 8 8\n";
    let f = "f 1 1 1 1 0 1 0 1\n";
    let cases = [
        (
            "unknown.nff",
            format!("{view}{f}q 1 2 3\n"),
            ":9:1:",
            "unknown record 'q'",
        ),
        (
            "short.nff",
            format!("{view}{f}p 4\n0 0 0\n1 0 0\n1 1 0\ns 0 0 0 1\n"),
            ":13:1:",
            "vertex 4 of 4",
        ),
        (
            "nof.nff",
            format!("{view}s 0 0 0 1\n"),
            ":8:1:",
            "before any 'f'",
        ),
        (
            "nov.nff",
            format!("{f}s 0 0 0 1\n"),
            ":3:1:",
            "no 'v' record",
        ),
        (
            "nan.nff",
            format!("{view}{f}s 0 nan 0 1\n"),
            ":9:5:",
            "finite number",
        ),
    ];
    for (name, text, at, says) in cases {
        let path = write(dir.path(), name, &text);
        let out = dir.path().join("x.png");
        let run = raytrace().arg(&path).arg("-o").arg(&out).output().unwrap();
        let err = String::from_utf8_lossy(&run.stderr);
        assert_eq!(run.status.code(), Some(2), "{name}: {err}");
        assert!(
            err.contains(&format!("{name}{at}")) && err.contains(says),
            "{name}: {err}"
        );
        assert!(!out.exists(), "{name}: an image was written");
    }
}

#[test]
fn spd_mode_casts_513_by_513_corner_rays_for_512_by_512_the_same_on_any_thread_count() {
    let dir = tempfile::tempdir().unwrap();
    let mut seen = Vec::new();
    for threads in ["1", "2"] {
        let out = dir.path().join(format!("t{threads}.png"));
        let run = raytrace()
            .arg(still_life())
            .args(["--spd", "--stats", "--threads", threads, "-o"])
            .arg(&out)
            .output()
            .unwrap();
        assert!(
            run.status.success(),
            "{}",
            String::from_utf8_lossy(&run.stderr)
        );
        let s = stats(&run.stderr);
        assert_eq!(s["eye"], 513 * 513);
        assert_eq!(
            image::open(&out).unwrap().to_rgb8().dimensions(),
            (512, 512)
        );
        let counts: Vec<u64> = ["eye_hits", "reflect", "refract", "shadow"]
            .iter()
            .map(|k| s[k].as_u64().unwrap())
            .collect();
        seen.push((pixels(&out), counts));
    }
    assert!(seen[0] == seen[1], "one and two threads differ");
    // --spd fixes the size: --size with it is refused.
    let run = raytrace()
        .arg(still_life())
        .args(["--spd", "--size", "64x64", "-o"])
        .arg(dir.path().join("no.png"))
        .output()
        .unwrap();
    assert_eq!(run.status.code(), Some(2));
}

#[test]
fn spd_mode_stops_at_depth_5_and_never_cuts_by_weight() {
    // Two facing mirrors with Ks = 0.01 (a weight of 1e-4 after two bounces, which the
    // report's 1/256 cut-off would drop): every eye ray that hits spawns exactly 4
    // reflections (depth 5 counting the eye ray), and no shadow ray without a light.
    let dir = tempfile::tempdir().unwrap();
    let nff = "v\nfrom 0 0 0\nat 0 1 0\nup 0 0 1\nangle 10\nhither 1\nresolution 8 8\n\
               f 1 1 1 0.5 0.01 10 0 1\np 4\n-50 5 -50\n50 5 -50\n50 5 50\n-50 5 50\n\
               p 4\n-50 -5 -50\n-50 -5 50\n50 -5 50\n50 -5 -50\n";
    let path = write(dir.path(), "mirrors.nff", nff);
    let run = raytrace()
        .arg(&path)
        .args(["--spd", "--stats", "-o"])
        .arg(dir.path().join("m.png"))
        .output()
        .unwrap();
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let s = stats(&run.stderr);
    assert_eq!(s["eye_hits"], 263_169);
    assert_eq!(s["reflect"], 4 * 263_169);
    assert_eq!(
        (s["refract"].as_u64(), s["shadow"].as_u64()),
        (Some(0), Some(0))
    );
    // Without --spd: the report's rules, 5 bounces but the weight cut-off after one.
    let run = raytrace()
        .arg(&path)
        .args(["--stats", "-o"])
        .arg(dir.path().join("r.png"))
        .output()
        .unwrap();
    let s = stats(&run.stderr);
    assert_eq!(
        (s["eye"].as_u64(), s["reflect"].as_u64()),
        (Some(64), Some(64))
    );
}

#[test]
fn the_sphereflake_manifest_orbits_about_z() {
    let Some(_) = spd_dir() else { return };
    let manifest = shipped::root().join("animations/sphereflake.toml");
    let project = whitted_anim::Project::load(&manifest).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(project.timeline.base.lens.up, glam::DVec3::Z);
    // Every eye stays at the NFF view's height z = 1.7 and distance 2.47 from the z axis.
    for frame in [0.0, 13.0, 50.0, 99.0] {
        let eye = project.timeline.at(frame).eye;
        assert!((eye.z - 1.7).abs() < 1e-12, "{eye}");
        assert!((eye.truncate().length() - 2.47).abs() < 1e-12, "{eye}");
    }
    let dir = tempfile::tempdir().unwrap();
    let run = animate()
        .arg(&manifest)
        .args(["--frames", "0", "-q", "-o"])
        .arg(dir.path())
        .output()
        .unwrap();
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    assert!(dir.path().join("frame_0000.png").is_file());
}

#[test]
fn tracks_move_nff_spheres_and_lights_and_the_circle_keeps_z_up() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::copy(still_life(), dir.path().join("still-life.nff")).unwrap();
    let manifest = write(
        dir.path(),
        "m.toml",
        r#"scene = "still-life.nff"
frames = 4
fps = 25
[camera]
path = "circle"
center = [0.0, 0.0, 0.8]
radius = 6.0
height = 2.5
turns = 0.25
[[track]]
target = "sphere 1 center"
keys = [ { frame = 0, value = [-1.2, 0.5, 1.0] }, { frame = 3, value = [-1.2, 0.5, 2.5] } ]
[[track]]
target = "light 1 intensity"
keys = [ { frame = 0, value = 0.35 }, { frame = 3, value = 1.0 } ]
[output]
dir = "out"
"#,
    );
    let project = whitted_anim::Project::load(&manifest).unwrap_or_else(|e| panic!("{e}"));
    let last = project.timeline.at(3.0);
    // The floor's two triangles come first: sphere 1 is the third object.
    assert_eq!(last.scene.specs[2].kind(), "sphere");
    assert_eq!(
        last.scene.specs[2].anchor(),
        glam::DVec3::new(-1.2, 0.5, 2.5)
    );
    assert_eq!(last.scene.lights[0].intensity, 1.0);
    // Frame 3 of 4 on a quarter turn is θ = 67.5° about z from the −y side, at z = 2.5:
    // (6·sin θ, −6·cos θ, 2.5).
    let (sin, cos) = 67.5f64.to_radians().sin_cos();
    let want = glam::DVec3::new(6.0 * sin, -6.0 * cos, 2.5);
    assert!((last.eye - want).length() < 1e-12, "{}", last.eye);
    let run = animate().arg(&manifest).arg("-q").output().unwrap();
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let out = dir.path().join("out");
    assert_ne!(
        pixels(&out.join("frame_0000.png")),
        pixels(&out.join("frame_0003.png"))
    );
}
