//! What a frame's provenance covers beyond the report's records, through the binary:
//! after a first render, editing an extension light, adding a `focus` record, or changing
//! the bytes of a mesh file or of an image texture's file (same names) makes `animate
//! status` call the frames stale (exit 1), and putting the old input back makes them up
//! to date again.

use crate::support::animate;
use std::path::Path;

const SCENE: &str = "48 36
0 2 8
0 0.5 0
0 1
0 1 0 1
0 0 0  0 1 0   3 \"tex.png\" planar nearest 2   0.8 0 0 1 0 0
5 8 6  1 1 1  0.5
mesh \"tri.obj\"   1 0.8 0.3 0.2   0.7 0 0 1 0 0
spot 0 6 0  0 0 0  1 1 1 1  10 20 2
";

const MANIFEST: &str = "scene = \"s.txt\"\nframes = 2\nfps = 25\n[output]\ndir = \"out\"\n";

/// A 2×2 PNG of two colours.
fn write_png(path: &Path, a: [u8; 3], b: [u8; 3]) {
    let img = image::RgbImage::from_fn(2, 2, |i, j| {
        image::Rgb(if (i + j) % 2 == 0 { a } else { b })
    });
    img.save(path).unwrap();
}

/// A triangle whose apex is at x = `apex` (its box the same for any apex in -1..1).
fn write_obj(path: &Path, apex: f64) {
    let obj = format!("v -1 0 0\nv 1 0 0\nv {apex} 1.5 0.5\nf 1 2 3\n");
    std::fs::write(path, obj).unwrap();
}

/// What an edit is called, the edit, and its undoing.
type Edit<'a> = (&'a str, Box<dyn Fn() + 'a>, Box<dyn Fn() + 'a>);

/// `animate status`'s exit code and its stale range.
fn status(manifest: &Path) -> (Option<i32>, String) {
    let out = animate()
        .args(["status", "--json"])
        .arg(manifest)
        .output()
        .unwrap();
    let doc: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap_or_default();
    (
        out.status.code(),
        doc["stale"].as_str().unwrap_or("?").to_string(),
    )
}

#[test]
fn edits_to_extension_records_and_read_files_make_frames_stale() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let (scene, manifest) = (d.join("s.txt"), d.join("m.toml"));
    std::fs::write(&scene, SCENE).unwrap();
    std::fs::write(&manifest, MANIFEST).unwrap();
    write_png(&d.join("tex.png"), [200, 30, 30], [30, 30, 200]);
    write_obj(&d.join("tri.obj"), 0.0);
    let out = animate().arg(&manifest).arg("-q").output().unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let fresh = (Some(0), "-".to_string());
    let stale = (Some(1), "0-1".to_string());
    assert_eq!(status(&manifest), fresh);

    // Each edit alone, then undone.
    let edits: [Edit; 4] = [
        (
            "the spot's cone",
            Box::new(|| std::fs::write(&scene, SCENE.replace("10 20 2", "5 8 2")).unwrap()),
            Box::new(|| std::fs::write(&scene, SCENE).unwrap()),
        ),
        (
            "a focus record",
            Box::new(|| std::fs::write(&scene, format!("{SCENE}focus 8 0.2 2\n")).unwrap()),
            Box::new(|| std::fs::write(&scene, SCENE).unwrap()),
        ),
        (
            "the mesh file's bytes",
            Box::new(|| write_obj(&d.join("tri.obj"), 0.25)),
            Box::new(|| write_obj(&d.join("tri.obj"), 0.0)),
        ),
        (
            "the image file's bytes",
            Box::new(|| write_png(&d.join("tex.png"), [200, 30, 30], [30, 200, 30])),
            Box::new(|| write_png(&d.join("tex.png"), [200, 30, 30], [30, 30, 200])),
        ),
    ];
    for (what, edit, undo) in &edits {
        edit();
        assert_eq!(status(&manifest), stale, "after editing {what}");
        undo();
        assert_eq!(status(&manifest), fresh, "after undoing {what}");
    }
}
