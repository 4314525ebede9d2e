//! Points 1 and 2 of reliability round three: a step past its range, and sizes, depths
//! and counts bounded before anything is allocated.

use super::{run, text, PROMPT};
use crate::support::*;
use std::path::Path;

// 1. A step spins forever.

#[test]
fn a_step_larger_than_the_range_returns_at_once() {
    let (dir, m) = project(&circle_manifest(""));
    let out = dir.path().join("frames");
    let spec = "0-11:9999999999";
    // Coarse to fine: every frame, the first and the last first.
    let (code, _, err) = run(&[&m, &"--frames", &spec, &"-q"]);
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(files(&out).len(), 12);
    let (code, table, err) = run(&[&"status", &m, &"--frames", &spec]);
    assert_eq!(code, Some(0), "{table}{err}");
    // `xN`: the first frame only.
    let (code, json, err) = run(&[&"status", &m, &"--frames", &"0-11x9999999999", &"--json"]);
    assert_eq!(code, Some(0), "{err}");
    let doc: serde_json::Value = serde_json::from_str(&json).unwrap();
    let predicted = doc["predicted_rays"].as_object().unwrap();
    assert_eq!(predicted.keys().collect::<Vec<_>>(), ["0"], "{json}");
}

#[test]
fn a_huge_step_in_check_frames_loads_at_once() {
    let check = "\n[check]\nframes = \"0-11:9999999999\"\nreferences = \"refs\"\n";
    let (dir, m) = project(&circle_manifest(check));
    let (code, _, err) = run(&[&"bless", &m, &"-q"]);
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(files(&dir.path().join("refs")).len(), 12);
    // `view` loads the manifest too: it must print its address.
    let viewer = crate::view_common::Viewer::start(&m, &[]);
    assert_eq!(viewer.get("/api/status").status, 200);
}

// 2. Sizes are checked before the memory is taken.

/// Writes an `side`×`side` EXR of one grey (ZIP: a few hundred kilobytes on disk).
fn big_exr(path: &Path, side: usize) {
    use exr::prelude::*;
    let encoding = Encoding {
        compression: Compression::ZIP16,
        ..Encoding::default()
    };
    let channels = SpecificChannels::rgb(|_: Vec2<usize>| (0.5f32, 0.5f32, 0.5f32));
    let layer = Layer::new((side, side), LayerAttributes::default(), encoding, channels);
    Image::from_layer(layer).write().to_file(path).unwrap();
}

#[test]
fn a_huge_exr_reference_is_refused_from_its_header() {
    let extra = "\n[check]\nframes = [0]\nreferences = \"refs\"\n";
    let manifest = circle_manifest(extra).replace("format = \"png\"", "format = \"exr\"");
    let (dir, m) = project(&manifest);
    std::fs::create_dir(dir.path().join("refs")).unwrap();
    big_exr(&dir.path().join("refs/frame_0000.exr"), 8192);
    let child = std::process::Command::new(assert_cmd::cargo::cargo_bin("animate"))
        .arg("check")
        .arg(&m)
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let (peak_kib, status) = peak_kib_until_exit(child);
    assert_eq!(status.code(), Some(2));
    // Before: the whole picture was decoded, 1.98 GB, then the process aborted.
    assert!(peak_kib < 200 << 10, "peak {peak_kib} KiB");
    let (code, _, err) = run(&[&"check", &m]);
    assert_eq!(code, Some(2));
    assert!(err.contains("is 8192×8192, the frame is 64×48"), "{err}");
}

#[test]
fn adaptive_depth_and_size_are_bounded_before_rendering() {
    // The manifest: 2048² at depth 6 needs 17 GB in the worst case.
    let render = "\n[render]\nwidth = 2048\nheight = 2048\n\
                  antialias = { mode = \"adaptive\", depth = 6 }\n";
    let (_dir, m) = project(&circle_manifest(render));
    let (code, _, err) = run(&[&"status", &m]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("anim.toml:21:13") && err.contains("more than the limit of 2048 MiB"),
        "{err}"
    );
    // The scene's own size with the manifest's depth: refused when the project loads.
    let render = "\n[render]\nantialias = { mode = \"adaptive\", depth = 6 }\n";
    let (dir, m) = project(&circle_manifest(render));
    std::fs::write(
        dir.path().join("scene.txt"),
        scene_with_eye([0.0, 3.0, 8.0]).replacen("64 48", "4096 2048", 1),
    )
    .unwrap();
    let (code, _, err) = run(&[&"status", &m]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("more than the limit of 2048 MiB"), "{err}");
    // raytrace --aa adaptive:0:6 --size 4096x2048: 33 GB, then an abort, before.
    let scene = dir.path().join("scene.txt");
    let out = raytrace()
        .arg(&scene)
        .args(["--aa", "adaptive:0:6", "--size", "4096x2048", "-o"])
        .arg(dir.path().join("big.png"))
        .timeout(PROMPT)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2), "{}", text(&out.stderr));
    let err = text(&out.stderr);
    assert!(
        err.contains("depth 6 on 4096×2048") && err.contains("limit of 2048 MiB"),
        "{err}"
    );
    assert!(!dir.path().join("big.png").exists());
}

#[test]
fn shard_counts_are_bounded_before_anything_is_split() {
    let (_dir, m) = project(&circle_manifest(""));
    // Before: gigabytes of shard bounds, then an abort.
    for args in [
        vec!["estimate", "--shards", "4294967295"],
        vec!["estimate", "--shards", "0"],
        vec!["estimate", "--shards", "1000001"],
    ] {
        let (code, _, err) = run(&[&args[0], &m, &args[1], &args[2]]);
        assert_eq!(code, Some(2), "{args:?}: {err}");
        assert!(err.contains("1..=1000000"), "{args:?}: {err}");
    }
    let (code, _, err) = run(&[&m, &"--shard", &"1/4294967295", &"--balance", &"-q"]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("from 1 to 1000000, the limit of shards"),
        "{err}"
    );
    // A Slurm count past u32 used to wrap to another count.
    let out = animate()
        .arg(&m)
        .args(["--shard", "auto", "-q"])
        .env("SLURM_ARRAY_TASK_ID", "0")
        .env("SLURM_ARRAY_TASK_MIN", "0")
        .env("SLURM_ARRAY_TASK_COUNT", "4294967297")
        .timeout(PROMPT)
        .output()
        .unwrap();
    let err = text(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("SLURM_ARRAY_TASK_COUNT=4294967297"), "{err}");
}
