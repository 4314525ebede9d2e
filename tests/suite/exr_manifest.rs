//! An EXR manifest (`format = "exr"`) through `animate check`, `animate preview`,
//! `--video` and `animate encode` (SPEC §12, §2): check compares the float beauties with
//! float limits (a difference below one 8-bit level still counts), preview and the videos
//! take the frames' sRGB encoding through the clamp-and-round, so they are the PNG
//! manifest's pictures.
//! The video tests need ffmpeg: without it they say "skipped" and pass, except under CI.

use crate::skip;
use crate::support;

use exr::prelude::write_rgb_file;
use std::path::Path;
use support::*;

/// The circle manifest with `frames` frames in `format`, `extra` appended.
fn manifest(format: &str, frames: u32, extra: &str) -> String {
    circle_manifest(extra)
        .replace("frames = 12", &format!("frames = {frames}"))
        .replace("format = \"png\"", &format!("format = \"{format}\""))
}

/// The R, G, B channels of an EXR file's beauty, as floats.
fn beauty(path: &Path) -> [Vec<f32>; 3] {
    let mut ch = exr_channels(path);
    ["R", "G", "B"].map(|c| ch.remove(c).unwrap())
}

const CHECK: &str = "\n[check]\nframes = [0, 2]\nreferences = \"refs\"\nfail = 0\n\
                     fail_percent = 0\nhard_fail = 64\n";

#[test]
fn check_compares_exr_references_as_floats_below_one_level() {
    let (dir, m) = project(&manifest("exr", 3, CHECK));
    animate().arg("bless").arg(&m).arg("-q").assert().success();
    let refs: Vec<String> = files(&dir.path().join("refs"))
        .into_iter()
        .map(|f| f.0)
        .collect();
    assert_eq!(refs, ["frame_0000.exr", "frame_0002.exr"]);
    let (code, out, err) = check(&m, &["--json"]);
    assert_eq!(code, Some(0), "{out}{err}");
    let doc: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(doc["frames"][0]["max_diff"], 0, "{doc}");
    // Pixel (30, 30)'s red moved by 0.45 to 0.95 of a level, keeping its 8-bit byte b:
    // to (b ∓ 0.45)/255, away from where it was. Compared as bytes the frame would pass.
    let path = dir.path().join("refs/frame_0000.exr");
    let [mut r, g, b] = beauty(&path);
    let at = 30 * 64 + 30;
    let level = f64::from(r[at]) * 255.0;
    assert!((1.0..254.0).contains(&level), "a mid-grey red: {level}");
    let byte = level.round();
    let moved = if level >= byte {
        byte - 0.45
    } else {
        byte + 0.45
    };
    r[at] = (moved / 255.0) as f32;
    write_rgb_file(&path, 64, 48, |x, y| {
        let i = y * 64 + x;
        (r[i], g[i], b[i])
    })
    .unwrap();
    let (code, out, err) = check(&m, &["--json"]);
    assert_eq!(code, Some(1), "{out}{err}");
    let doc: serde_json::Value = serde_json::from_str(&out).unwrap();
    let f0 = &doc["frames"][0];
    assert_eq!(f0["pass"], false, "{doc}");
    assert_eq!(f0["failing_pixels"], 1, "{doc}");
    assert_eq!(f0["max_at"], serde_json::json!([30, 30, 0]), "{doc}");
    assert_eq!(f0["max_diff"], 1, "{doc}"); // below one level, rounded up
    assert_eq!(doc["frames"][1]["pass"], true, "{doc}");
    // A limit of one level lets it pass.
    let (code, out, _) = check(&m, &["--fail", "1"]);
    assert_eq!(code, Some(0), "{out}");
}

#[test]
fn the_preview_of_an_exr_manifest_is_the_png_manifests() {
    let (dir, png) = project(&manifest("png", 6, ""));
    let exr = dir.path().join("exr.toml");
    std::fs::write(&exr, manifest("exr", 6, "")).unwrap();
    for (m, out) in [(&png, "pv-png"), (&exr, "pv-exr")] {
        animate()
            .arg("preview")
            .arg(m)
            .arg("-o")
            .arg(dir.path().join(out))
            .args(["--every", "2", "-q"])
            .assert()
            .success();
    }
    for name in ["animation.gif", "contact-sheet.png"] {
        let read = |d: &str| std::fs::read(dir.path().join(d).join(name)).unwrap();
        assert!(read("pv-png") == read("pv-exr"), "{name} differs");
    }
}

#[test]
fn video_and_encode_of_an_exr_manifest_are_its_clamped_beauty() {
    if !skip::ffmpeg() {
        return;
    }
    let (dir, m) = project(&manifest("exr", 3, ""));
    animate().arg(&m).arg("-q").assert().success();
    // round(255·clamp(sRGB(v))) of each frame's beauty, computed here from the EXR files
    // (the beauty is linear light; the video shows what an sRGB view shows).
    let to_byte = srgb_byte;
    let (mut want, mut above_one) = (Vec::new(), 0);
    for f in 0..3 {
        let [r, g, b] = beauty(&dir.path().join(format!("frames/frame_{f:04}.exr")));
        for i in 0..r.len() {
            want.extend([to_byte(r[i]), to_byte(g[i]), to_byte(b[i])]);
            above_one += [r[i], g[i], b[i]].iter().filter(|&&v| v > 1.0).count();
        }
    }
    assert!(
        above_one > 0,
        "some value of the beauty is above one: the clamp counts"
    );
    let lossless = ["--codec", "ffv1", "--pix-fmt", "gbrp", "-q"];
    let video = dir.path().join("rendered.mkv");
    animate()
        .arg(&m)
        .arg("--video")
        .arg(&video)
        .args(lossless)
        .assert()
        .success();
    assert!(decoded(&video) == want, "--video: not the clamped beauty");
    let encoded = dir.path().join("encoded.mkv");
    animate()
        .arg("encode")
        .arg(&m)
        .arg("-o")
        .arg(&encoded)
        .args(lossless)
        .assert()
        .success();
    assert!(decoded(&encoded) == want, "encode: not the clamped beauty");
}
