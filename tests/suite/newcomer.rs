//! Issue 16, "a newcomer's hour with the tool", items 1, 4 and 5, through the built
//! binaries: the formats' reference is in the repository and `animate --help` names it;
//! a scene whose counts do not match its records is refused at the count; every unknown
//! table and key of a manifest is located, in file order, with the nearest known name.

use crate::support;

use std::path::Path;
use support::*;

/// Standard error of a run that must refuse its input with exit status 2.
fn refused(cmd: &mut assert_cmd::Command) -> String {
    let out = cmd.output().unwrap();
    assert_eq!(out.status.code(), Some(2), "{out:?}");
    String::from_utf8(out.stderr).unwrap()
}

#[test]
fn animate_help_names_the_reference_pages_and_they_exist() {
    let out = animate().arg("--help").output().unwrap();
    assert!(out.status.success());
    let help = String::from_utf8(out.stdout).unwrap();
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    for page in ["docs/manifest.md", "docs/scene-format.md"] {
        assert!(help.contains(page), "--help does not name {page}");
        assert!(root.join(page).is_file(), "{page} is not in the repository");
    }
}

#[test]
fn every_unknown_table_and_key_is_located_with_the_nearest_name() {
    // Before: `[camra]` was reported as an unknown top-level field (or, earlier, as a
    // missing [camera] at 1:1), and only the first unknown name of the file was reported.
    let manifest = "scene = \"scene.txt\"\nframes = 4\n\n[camra]\npath = \"circle\"\n\n\
                    [outptu]\ndir = \"frames\"\n\n[render]\nsamles = 2\n\n\
                    [check]\nframes = [0]\nreferences = \"golden\"\nfail_percnt = 1\n";
    let (dir, path) = project(manifest);
    let stderr = refused(animate().arg(&path));
    let file = path.display().to_string();
    let located: Vec<&str> = stderr
        .lines()
        .map(|l| l.strip_prefix("animate: ").unwrap_or(l))
        .filter(|l| l.starts_with(&file))
        .collect();
    let expected = [
        (4, 2, "unknown table `[camra]` (did you mean `[camera]`?)"),
        (7, 2, "unknown table `[outptu]` (did you mean `[output]`?)"),
        (
            11,
            1,
            "render: unknown key `samles` (did you mean `samples`?)",
        ),
        (
            16,
            1,
            "check: unknown key `fail_percnt` (did you mean `fail_percent`?)",
        ),
    ];
    assert_eq!(located.len(), expected.len(), "{stderr}");
    for (line, (l, c, message)) in located.iter().zip(expected) {
        let want = format!("{file}:{l}:{c}: {message}");
        assert!(line.starts_with(&want), "{line:?} is not {want:?}");
    }
    assert!(!dir.path().join("frames").exists(), "frames were rendered");
}

#[test]
fn a_key_of_another_camera_path_says_which_path_it_belongs_to() {
    let manifest = "scene = \"scene.txt\"\nframes = 4\n[camera]\nlook_at = [0, 1, 0]\nradius = 3\n";
    let (_dir, path) = project(manifest);
    let stderr = refused(animate().arg(&path));
    let want = format!(
        "{}:5:1: camera: unknown key `radius` (a key of path = \"circle\"); \
         [camera] without a path takes `path`, `name`, `look_at`, `fov`, `roll`",
        path.display()
    );
    assert!(stderr.contains(&want), "{stderr}");
}

/// A scene announcing `spheres` spheres, with four written, then a plane and a light,
/// each record on its own line.
fn four_spheres_announcing(spheres: u32) -> String {
    let sphere = |x: f64| format!("0.5 {x} 0.5 0   1 0.9 0.2 0.2   0.9 0 0 1 0 0\n");
    let mut s = format!("32 24\n0 2 10\n0 1 0\n0 1\n{spheres} 1 0 1\n");
    for x in [-3.0, -1.0, 1.0, 3.0] {
        s += &sphere(x);
    }
    s + "0 0 0  0 1 0   1 0.5 0.5 0.5   1 0 0 1 0 0\n5 10 5  1 1 1  1\n"
}

#[test]
fn a_count_that_announces_a_missing_record_is_where_the_error_is() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("five.txt"), four_spheres_announcing(5)).unwrap();
    let stderr = refused(
        raytrace()
            .current_dir(dir.path())
            .args(["five.txt", "-o", "five.png"]),
    );
    // Before: "five.txt:10:1: Radius must be greater than 0, found '0' (sphere 5 of 5,
    // field Radius)", on the plane's line.
    assert!(
        stderr.contains(
            "five.txt:5:1: the counts announce 5 spheres, but line 10, read as sphere 5 of 5, \
             holds 16 values, as a plane does: is a sphere missing, or should NSpheres be 4?"
        ),
        "{stderr}"
    );
    assert!(stderr.contains("(counts, field NSpheres)"), "{stderr}");
    assert!(!dir.path().join("five.png").exists());
    // The same scene with the right count renders.
    std::fs::write(dir.path().join("four.txt"), four_spheres_announcing(4)).unwrap();
    raytrace()
        .current_dir(dir.path())
        .args(["four.txt", "-o", "four.png"])
        .assert()
        .success();
}

#[test]
fn animate_reports_the_count_of_its_base_scene_too() {
    let (dir, path) = project(&circle_manifest(""));
    std::fs::write(dir.path().join("scene.txt"), four_spheres_announcing(5)).unwrap();
    let stderr = refused(animate().arg(&path));
    let scene = dir.path().join("scene.txt").display().to_string();
    assert!(
        stderr.contains(&format!("{scene}:5:1: the counts announce 5 spheres")),
        "{stderr}"
    );
}
