//! glTF scenes through the binaries (SPEC §18): `raytrace` draws a `.gltf` and a `.glb`
//! and refuses a hostile file with exit 2 at its JSON path; `--camera` picks the file's
//! camera by name; `animate` plays a file's animations (frames counted from the last key
//! when `frames` is left out, `[animation] name` picking some), a node track wins over
//! the file's channel, and a frame's digest covers the files the glTF file names.

use crate::support::{animate, raytrace};
use std::path::{Path, PathBuf};

fn data(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/gltf")
        .join(name)
}

/// `raytrace FILE -o DIR/out.png ARGS`: the PNG's bytes, or the standard error of a
/// refusal (exit 2, no image).
fn draw(file: &Path, dir: &Path, args: &[&str]) -> Result<Vec<u8>, String> {
    let png = dir.join("out.png");
    let _ = std::fs::remove_file(&png);
    let out = raytrace()
        .arg(file)
        .arg("-o")
        .arg(&png)
        .args(args)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr).to_string();
    match out.status.code() {
        Some(0) => Ok(std::fs::read(&png).unwrap()),
        Some(2) if !png.exists() && !stderr.contains("panicked") => Err(stderr),
        code => panic!("exit {code:?}: {stderr}"),
    }
}

#[test]
fn raytrace_draws_gltf_and_glb_files() {
    let dir = tempfile::tempdir().unwrap();
    for name in [
        "BoxTextured.gltf",
        "SimpleSkin.gltf",
        "generated/two_primitives.glb",
    ] {
        let png = draw(&data(name), dir.path(), &[]).unwrap();
        let img = image::load_from_memory(&png).unwrap().to_rgb8();
        assert_eq!(img.dimensions(), (640, 480), "{name}");
        // Something is drawn: not every pixel is the black background.
        assert!(img.pixels().any(|p| p.0 != [0, 0, 0]), "{name}");
    }
}

#[test]
fn hostile_gltf_files_exit_2_naming_file_and_json_path() {
    let dir = tempfile::tempdir().unwrap();
    let cases = [
        ("index_past.gltf", "accessors[0]"),
        ("huge_count.gltf", "accessors[0].count"),
        ("nan_position.gltf", "not a finite number"),
        ("missing_buffer.gltf", "buffers[0]"),
        ("skin_joint_outside.gltf", "skins[0].joints"),
    ];
    for (name, want) in cases {
        let e = draw(&data(&format!("bad/{name}")), dir.path(), &[]).unwrap_err();
        assert!(e.contains(want), "{name}: {e}");
    }
}

#[test]
fn camera_picks_the_files_camera_by_name() {
    let dir = tempfile::tempdir().unwrap();
    let file = data("generated/interpolation.gltf");
    let named = draw(&file, dir.path(), &["--camera", "Cam"]).unwrap();
    // "Cam" is the file's first camera: the default view.
    assert_eq!(named, draw(&file, dir.path(), &[]).unwrap());
    let e = draw(&file, dir.path(), &["--camera", "Nope"]).unwrap_err();
    assert!(e.contains("Nope") && e.contains("Cam"), "{e}");
    let txt = dir.path().join("s.txt");
    std::fs::write(&txt, crate::support::scene_with_eye([0.0, 3.0, 8.0])).unwrap();
    let e = draw(&txt, dir.path(), &["--camera", "Cam"]).unwrap_err();
    assert!(e.contains("glTF"), "{e}");
}

/// Writes `manifest` beside a copy of the interpolation file and runs `animate` on it
/// into DIR/frames: the frame files' names, or the refusal.
fn play(dir: &Path, gltf: &str, manifest: &str) -> Result<Vec<String>, String> {
    std::fs::write(dir.join("anim.gltf"), gltf).unwrap();
    let path = dir.join("anim.toml");
    std::fs::write(&path, format!("scene = \"anim.gltf\"\n{manifest}")).unwrap();
    let out = animate()
        .arg(&path)
        .arg("-o")
        .arg(dir.join("frames"))
        .output()
        .unwrap();
    if !out.status.success() {
        return Err(String::from_utf8_lossy(&out.stderr).to_string());
    }
    let frames = crate::support::entries(&dir.join("frames"));
    Ok(frames.into_iter().filter(|f| f.ends_with(".png")).collect())
}

#[test]
fn animations_give_the_frame_count_and_are_picked_by_name() {
    let text = std::fs::read_to_string(data("generated/interpolation.gltf")).unwrap();
    let dir = tempfile::tempdir().unwrap();
    // Keys to t = 2 s at 4 fps: 9 frames, both ends included.
    let frames = play(dir.path(), &text, "fps = 4\n").unwrap();
    assert_eq!(frames.len(), 9, "{frames:?}");
    let e = play(dir.path(), &text, "fps = 4\n[animation]\nname = \"Walk\"\n").unwrap_err();
    assert!(
        e.contains("anim.toml:3:") && e.contains("Move, Spin"),
        "{e}"
    );
}

/// The pixels of frame 1 of `manifest` (at 4 fps: t = 0.25 s) played on `gltf`.
fn frame_one(gltf: &str, manifest: &str) -> Vec<u8> {
    let dir = tempfile::tempdir().unwrap();
    play(
        dir.path(),
        gltf,
        &format!("fps = 4\nframes = 2\n{manifest}"),
    )
    .unwrap();
    crate::support::pixels(&dir.path().join("frames/frame_0001.png"))
}

#[test]
fn a_node_track_wins_over_the_files_channel() {
    let text = std::fs::read_to_string(data("generated/interpolation.gltf")).unwrap();
    let track = "[[track]]\ntarget = { node = \"Linear\", field = \"translation\" }\n\
                 keys = [{ frame = 0, value = [-2.0, 0.5, 0.0] }]\n";
    let tracked = frame_one(&text, &format!("[animation]\nname = \"Move\"\n{track}"));
    // The same file with node Linear's channel taken out and the track's value put in
    // as its translation: the same picture.
    let mut json: serde_json::Value = serde_json::from_str(&text).unwrap();
    let linear = (json["nodes"].as_array().unwrap().iter())
        .position(|n| n["name"] == "Linear")
        .unwrap();
    json["nodes"][linear]["translation"] = serde_json::json!([-2.0, 0.5, 0.0]);
    for anim in json["animations"].as_array_mut().unwrap() {
        let channels = anim["channels"].as_array_mut().unwrap();
        channels
            .retain(|c| !(c["target"]["node"] == linear && c["target"]["path"] == "translation"));
    }
    let still = frame_one(&json.to_string(), "[animation]\nname = \"Move\"\n");
    assert!(tracked == still, "the tracked frame differs from the still");
    // Without the track the channel moves it: another picture.
    let moved = frame_one(&text, "[animation]\nname = \"Move\"\n");
    assert!(moved != tracked, "the track changed nothing");
}

#[test]
fn a_frames_digest_covers_the_buffer_file_the_gltf_names() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    // The Box sample with its buffer moved to a file beside it.
    let text = std::fs::read_to_string(data("Box.gltf")).unwrap();
    let mut json: serde_json::Value = serde_json::from_str(&text).unwrap();
    let uri = json["buffers"][0]["uri"].as_str().unwrap().to_string();
    let b64 = uri.split_once(',').unwrap().1;
    use base64::Engine;
    let bytes = base64::engine::general_purpose::STANDARD
        .decode(b64)
        .unwrap();
    std::fs::write(d.join("box.bin"), &bytes).unwrap();
    json["buffers"][0]["uri"] = "box.bin".into();
    std::fs::write(d.join("box.gltf"), json.to_string()).unwrap();
    let manifest = d.join("a.toml");
    std::fs::write(&manifest, "scene = \"box.gltf\"\nframes = 1\n").unwrap();
    let run = || {
        let out = animate()
            .arg(&manifest)
            .arg("--resume")
            .arg("-o")
            .arg(d.join("f"))
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        String::from_utf8_lossy(&out.stderr).to_string()
    };
    assert!(run().contains("1 frame rendered, 0 up to date"));
    assert!(run().contains("0 frames rendered, 1 up to date"));
    // A vertex of the buffer moved: the frame is stale.
    let mut changed = bytes.clone();
    changed[300] ^= 0x40;
    std::fs::write(d.join("box.bin"), &changed).unwrap();
    assert!(run().contains("1 frame rendered, 0 up to date"));
}
