//! Provenance and incremental re-rendering (SPEC §8) through the binary: `--resume`
//! renders exactly the missing and stale frames and touches nothing else; `animate
//! status` reads the frames' records and reports ranges with exit 0 / 1 / 2.

use crate::support;

use std::path::Path;
use std::time::SystemTime;
use support::*;

/// Modification times of the visible files of a folder, by name.
fn mtimes(dir: &Path) -> Vec<(String, SystemTime)> {
    let mut out: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap())
        .filter(|e| !e.file_name().to_string_lossy().starts_with('.'))
        .map(|e| {
            let name = e.file_name().to_string_lossy().into_owned();
            (name, e.metadata().unwrap().modified().unwrap())
        })
        .collect();
    out.sort();
    out
}

fn status_json(manifest: &Path) -> (Option<i32>, serde_json::Value) {
    let out = animate()
        .arg("status")
        .arg(manifest)
        .arg("--json")
        .output()
        .unwrap();
    let doc = serde_json::from_slice(&out.stdout).unwrap_or(serde_json::Value::Null);
    (out.status.code(), doc)
}

fn resume(manifest: &Path) -> String {
    let out = animate().arg(manifest).arg("--resume").output().unwrap();
    assert!(out.status.success());
    String::from_utf8_lossy(&out.stderr).into_owned()
}

#[test]
fn an_up_to_date_folder_is_left_untouched() {
    let (dir, manifest) = project(&circle_manifest(""));
    animate().arg(&manifest).assert().success();
    let frames = dir.path().join("frames");
    let (before, times) = (files(&frames), mtimes(&frames));
    std::thread::sleep(std::time::Duration::from_millis(20));
    let err = resume(&manifest);
    assert!(err.contains("0 frames rendered, 12 up to date in"), "{err}");
    assert_eq!(files(&frames), before);
    assert_eq!(mtimes(&frames), times);
    let (code, doc) = status_json(&manifest);
    assert_eq!(code, Some(0));
    assert_eq!(doc["up_to_date"], "0-11");
    assert_eq!(
        (doc["stale"].as_str(), doc["missing"].as_str()),
        (Some("-"), Some("-"))
    );
}

/// A 50-frame still with a 5-key smooth track on sphere 1's centre.
fn smooth_track(second_key: &str) -> String {
    format!(
        "scene = \"scene.txt\"\nframes = 50\n[output]\ndir = \"frames\"\n\
         [render]\nwidth = 16\nheight = 12\n\
         [[track]]\ntarget = \"sphere 1 center\"\ninterpolation = \"smooth\"\nkeys = [\n\
         {{ frame = 0, value = [-1.3, 1.0, 0.0] }},\n\
         {{ frame = 10, value = {second_key} }},\n\
         {{ frame = 20, value = [-1.3, 2.0, 0.0] }},\n\
         {{ frame = 30, value = [0.0, 1.5, 0.5] }},\n\
         {{ frame = 40, value = [-1.3, 1.0, 0.0] }},\n]\n"
    )
}

#[test]
fn moving_one_key_of_a_smooth_track_renders_only_the_frames_it_moved() {
    let (dir, manifest) = project(&smooth_track("[-0.5, 1.5, 0.0]"));
    animate().arg(&manifest).assert().success();
    let frames = dir.path().join("frames");
    let times = mtimes(&frames);
    std::fs::write(&manifest, smooth_track("[-0.5, 1.8, 0.0]")).unwrap();
    // Catmull-Rom has local support: the key at frame 10 shapes the segments 0-10, 10-20
    // and 20-30 only, and the curve still passes exactly through the other keys.
    let (code, doc) = status_json(&manifest);
    assert_eq!(code, Some(1));
    assert_eq!(doc["stale"], "1-19,21-29", "{doc}");
    assert_eq!(doc["up_to_date"], "0,20,30-49", "{doc}");
    std::thread::sleep(std::time::Duration::from_millis(20));
    let err = resume(&manifest);
    assert!(err.contains("28 frames rendered, 22 up to date"), "{err}");
    let after = mtimes(&frames);
    for ((name, t0), (_, t1)) in times.iter().zip(&after) {
        let frame: u32 = name[6..10].parse().unwrap();
        let moved = (1..=19).contains(&frame) || (21..=29).contains(&frame);
        assert_eq!(t0 != t1, moved, "{name}");
    }
    // The folder is now exactly a fresh render of the edited manifest.
    render_into(&manifest, &dir.path().join("fresh"), &[]);
    assert_eq!(files(&frames), files(&dir.path().join("fresh")));
    assert_eq!(status_json(&manifest).0, Some(0));
}

#[test]
fn a_comment_changes_nothing_and_a_colour_changes_everything() {
    let (dir, manifest) = project(&circle_manifest(""));
    animate().arg(&manifest).assert().success();
    let scene = dir.path().join("scene.txt");
    let text = std::fs::read_to_string(&scene).unwrap();
    let commented = format!(
        "# the test scene, reformatted\n{}",
        text.replace("  ", "   ")
    );
    std::fs::write(&scene, &commented).unwrap();
    assert_eq!(status_json(&manifest).0, Some(0));
    std::fs::write(&scene, commented.replace("1 0.2 0.5 0.8", "1 0.2 0.5 0.7")).unwrap();
    let (code, doc) = status_json(&manifest);
    assert_eq!(code, Some(1));
    assert_eq!(
        (doc["stale"].as_str(), doc["up_to_date"].as_str()),
        (Some("0-11"), Some("-"))
    );
}

#[test]
fn status_reports_missing_foreign_and_broken_frames() {
    let (dir, manifest) = project(&circle_manifest(""));
    animate().arg(&manifest).assert().success();
    let frames = dir.path().join("frames");
    let frame = |k: u32| frames.join(format!("frame_{k:04}.png"));
    std::fs::remove_file(frame(4)).unwrap();
    std::fs::remove_file(frame(5)).unwrap();
    // A frame of another manifest (another circle), a truncated one, a foreign PNG.
    let other = circle_manifest("").replace("radius = 8.0", "radius = 9.0");
    let (odir, omanifest) = project(&other);
    animate()
        .arg(&omanifest)
        .args(["--frames", "7"])
        .assert()
        .success();
    std::fs::copy(odir.path().join("frames/frame_0007.png"), frame(7)).unwrap();
    let bytes = std::fs::read(frame(9)).unwrap();
    std::fs::write(frame(9), &bytes[..bytes.len() / 2]).unwrap();
    let still = dir.path().join("still.png");
    raytrace()
        .arg(dir.path().join("scene.txt"))
        .arg("-o")
        .arg(&still)
        .assert()
        .success();
    std::fs::copy(&still, frame(10)).unwrap();
    std::fs::write(frame(11), b"not a png at all").unwrap();
    let (code, doc) = status_json(&manifest);
    assert_eq!(code, Some(1));
    assert_eq!(doc["missing"], "4-5");
    // The truncated frame still carries its record (text chunks precede the pixels), but
    // a PNG cut short is not a finished frame.
    assert_eq!(doc["stale"], "7,9-11");
    assert_eq!(doc["up_to_date"], "0-3,6,8");
    // The table, and --resume mends it all.
    let out = animate().arg("status").arg(&manifest).output().unwrap();
    let table = String::from_utf8_lossy(&out.stdout);
    assert!(table.contains("missing:       2  4-5"), "{table}");
    // The still under frame 10's name has no record: not the tool's, so --resume refuses
    // to replace it (reliability round three) until told to.
    let out = animate().arg(&manifest).arg("--resume").output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    let out = animate()
        .arg(&manifest)
        .args(["--resume", "--force"])
        .output()
        .unwrap();
    assert!(out.status.success());
    assert_eq!(status_json(&manifest).0, Some(0));
    // Bad input: exit 2.
    let out = animate()
        .arg("status")
        .arg(dir.path().join("none.toml"))
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn raw_and_jpeg_frames_keep_their_records_too() {
    for format in ["raw", "jpeg", "ppm"] {
        let text =
            circle_manifest("").replace("format = \"png\"", &format!("format = \"{format}\""));
        let (dir, manifest) = project(&text);
        animate()
            .arg(&manifest)
            .args(["--frames", "0-3"])
            .assert()
            .success();
        let (code, doc) = status_json(&manifest);
        assert_eq!(code, Some(1), "{format}");
        assert_eq!(
            (doc["up_to_date"].as_str(), doc["missing"].as_str()),
            (Some("0-3"), Some("4-11")),
            "{format}"
        );
        let err = resume(&manifest);
        assert!(
            err.contains("8 frames rendered, 4 up to date"),
            "{format}: {err}"
        );
        if format == "raw" {
            assert!(dir
                .path()
                .join("frames/.whitted-record/frame_0000.raw.txt")
                .exists());
        }
    }
}

#[test]
fn a_frame_does_not_depend_on_how_the_manifest_path_is_spelled() {
    let (dir, manifest) = project(&circle_manifest(""));
    animate()
        .arg(&manifest)
        .args(["--frames", "3", "-o"])
        .arg(dir.path().join("a"))
        .assert()
        .success();
    animate()
        .current_dir(dir.path())
        .args(["anim.toml", "--frames", "3", "-o", "b"])
        .assert()
        .success();
    assert_eq!(files(&dir.path().join("a")), files(&dir.path().join("b")));
}
