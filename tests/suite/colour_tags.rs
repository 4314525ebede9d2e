//! One look in every format, through the binaries: a PNG frame carries an `sRGB` chunk
//! (with its `gAMA` and `cHRM`) and keeps its bytes; a one-sample EXR frame (half floats)
//! converted to sRGB here, with the standard's curve, is the PNG frame's bytes within one;
//! EXR alpha is the coverage of the camera samples (fog and the sky count for nothing) and
//! the colour is not premultiplied; `colour` is refused for other formats; a video is
//! tagged BT.709 (read back with ffprobe) and converted with BT.709's matrix (measured on
//! a lossless encode), and an MP4 has its index first. The video test needs ffmpeg: without
//! it, it says "skipped" and passes, except under CI.

use crate::skip;
use crate::support;

use std::path::Path;
use std::process::Command;
use support::*;

/// A sphere in the middle of a 32×24 frame, the rest sky, with linear fog (the sky is the
/// fog's white), one light.
const SKY_SCENE: &str = "32 24\n0 0 6\n0 0 0\n1 100\n1 0 0 1\n\
    1.5 0 0 0  1 0.8 0.3 0.2  0.9 0 0 1 0 0\n\
    4 5 6  1 1 1  1\n";

/// A manifest over `scene.txt`, still camera, `frames` frames in `format`, `extra`
/// appended to `[output]`, `render` as its `[render]` table.
fn still_manifest(format: &str, frames: u32, extra: &str, render: &str) -> String {
    format!(
        "scene = \"scene.txt\"\nframes = {frames}\nfps = 10\n\n[output]\ndir = \"{format}\"\n\
         format = \"{format}\"\n{extra}\n[render]\n{render}\n"
    )
}

fn write_project(dir: &Path, scene: &str, manifest: &str) -> std::path::PathBuf {
    std::fs::write(dir.join("scene.txt"), scene).unwrap();
    let path = dir.join(format!("m{}.toml", manifest.len()));
    std::fs::write(&path, manifest).unwrap();
    path
}

/// The PNG chunks of `bytes` in order: (type, data).
fn chunks(bytes: &[u8]) -> Vec<(String, Vec<u8>)> {
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n");
    let mut at = 8;
    let mut out = Vec::new();
    while at + 8 <= bytes.len() {
        let len = u32::from_be_bytes(bytes[at..at + 4].try_into().unwrap()) as usize;
        let kind = String::from_utf8_lossy(&bytes[at + 4..at + 8]).into_owned();
        out.push((kind, bytes[at + 8..at + 8 + len].to_vec()));
        at += 12 + len;
    }
    out
}

#[test]
fn png_frames_say_srgb_and_exr_frames_show_their_bytes_in_srgb() {
    let dir = tempfile::tempdir().unwrap();
    let scene = scene_with_eye([1.0, 3.0, 8.0]);
    for format in ["png", "exr"] {
        let m = write_project(dir.path(), &scene, &still_manifest(format, 1, "", ""));
        animate().arg(&m).arg("-q").assert().success();
    }
    // The PNG: IHDR, then sRGB (perceptual, 0), gAMA 45455 and cHRM (Rec.709, D65)
    // before the pixels.
    let png_path = dir.path().join("png/frame_0000.png");
    let png = std::fs::read(&png_path).unwrap();
    let found = chunks(&png);
    let at = |k: &str| found.iter().position(|c| c.0 == k).unwrap_or(usize::MAX);
    assert!(at("sRGB") < at("IDAT") && at("IHDR") == 0, "{:?}", found);
    assert_eq!(found[at("sRGB")].1, [0]);
    assert_eq!(found[at("gAMA")].1, 45455u32.to_be_bytes());
    let chrm: Vec<u32> = found[at("cHRM")]
        .1
        .chunks(4)
        .map(|b| u32::from_be_bytes(b.try_into().unwrap()))
        .collect();
    assert_eq!(
        chrm,
        [31270, 32900, 64000, 33000, 30000, 60000, 15000, 6000]
    );
    // The EXR (half, one sample): its beauty converted to sRGB is the PNG within one
    // level; unconverted it is not.
    let png = pixels(&png_path);
    let exr = exr_channels(&dir.path().join("exr/frame_0000.exr"));
    assert!(exr["R"].len() * 3 == png.len() && exr.contains_key("A"));
    let (mut worst, mut raw_worst) = (0, 0);
    for (k, want) in png.iter().enumerate() {
        let v = exr[["R", "G", "B"][k % 3]][k / 3];
        worst = worst.max(srgb_byte(v).abs_diff(*want));
        let as_is = (v.clamp(0.0, 1.0) * 255.0).round() as u8;
        raw_worst = raw_worst.max(as_is.abs_diff(*want));
    }
    assert!(worst <= 1, "the EXR in sRGB is {worst} levels off the PNG");
    assert!(raw_worst > 20, "the EXR is not linear light ({raw_worst})");
}

#[test]
fn exr_alpha_is_the_coverage_of_the_camera_samples_not_premultiplied() {
    let dir = tempfile::tempdir().unwrap();
    let m = still_manifest("exr", 1, "exr_depth = \"float\"", "samples = 2");
    let m = write_project(dir.path(), SKY_SCENE, &m);
    animate().arg(&m).arg("-q").assert().success();
    let exr = exr_channels(&dir.path().join("exr/frame_0000.exr"));
    let (a, r) = (&exr["A"], &exr["R"]);
    let px = |x: usize, y: usize| y * 32 + x;
    // The sky: fog's white at full strength, yet no coverage; the colour stays white
    // (not premultiplied by A = 0).
    assert_eq!((a[px(0, 0)], r[px(0, 0)]), (0.0, 1.0));
    // The sphere's middle: every sample hits.
    assert_eq!(a[px(16, 12)], 1.0);
    // 2×2 samples: quarters only, and the sphere's edge has some of each.
    assert!(a.iter().all(|v| [0.0, 0.25, 0.5, 0.75, 1.0].contains(v)));
    for q in [0.25, 0.5, 0.75] {
        assert!(a.contains(&q), "no pixel of coverage {q}");
    }
    // By hand: the sphere (radius 1.5, 6 away) covers a disc of angular radius
    // asin(1.5/6) = 14.48°; the view plane's half height is 0.175 at distance 1, so the
    // disc is tan(14.48°)/0.175·12 = 17.7 rows in radius, more than the frame's 12: the
    // middle column is covered top to bottom, the corners are not.
    assert!((0..24).all(|y| a[px(16, y)] == 1.0));
}

#[test]
fn colour_is_an_exr_option_and_linear_keeps_the_values() {
    let dir = tempfile::tempdir().unwrap();
    let scene = scene_with_eye([1.0, 3.0, 8.0]);
    let m = write_project(
        dir.path(),
        &scene,
        &still_manifest("png", 1, "colour = \"linear\"", ""),
    );
    let out = animate().arg(&m).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("`colour` needs `format = \"exr\"`"), "{err}");
    let m = write_project(
        dir.path(),
        &scene,
        &still_manifest("exr", 1, "colour = \"rec2020\"", ""),
    );
    let out = animate().arg(&m).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("expected one of srgb, linear"), "{err}");
    // raytrace refuses --colour for an 8-bit picture.
    let scene_path = dir.path().join("scene.txt");
    let out = raytrace()
        .arg(&scene_path)
        .args(["-o", "x.png", "--colour", "linear"])
        .current_dir(dir.path())
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--colour needs an .exr image"));
}

/// `ffprobe`'s `key=value` lines of the first video stream of `video`.
fn probe(video: &Path) -> String {
    let out = Command::new("ffprobe")
        .args(["-v", "error", "-select_streams", "v:0", "-show_streams"])
        .arg(video)
        .output()
        .unwrap();
    String::from_utf8_lossy(&out.stdout).into_owned()
}

#[test]
fn videos_are_bt709_in_their_tags_and_their_matrix() {
    if !skip::ffmpeg() {
        return;
    }
    // The red sphere fills most of the frame: BT.601's luma of its colour is 8 levels
    // above BT.709's.
    let dir = tempfile::tempdir().unwrap();
    let m = write_project(dir.path(), SKY_SCENE, &still_manifest("png", 2, "", ""));
    animate().arg(&m).arg("-q").assert().success();
    // The default encode (yuv420p MP4): four tags, and the index (moov) before the data.
    let video = dir.path().join("v.mp4");
    animate()
        .args(["encode"])
        .arg(&m)
        .arg("-o")
        .arg(&video)
        .arg("-q")
        .assert()
        .success();
    let tags = probe(&video);
    for tag in [
        "color_range=tv",
        "color_space=bt709",
        "color_transfer=bt709",
        "color_primaries=bt709",
    ] {
        assert!(tags.contains(tag), "{tag} missing from:\n{tags}");
    }
    let bytes = std::fs::read(&video).unwrap();
    let find = |k: &[u8]| bytes.windows(4).position(|w| w == k).unwrap();
    assert!(find(b"moov") < find(b"mdat"), "no faststart");
    // The matrix, on a lossless 4:4:4 encode through --video: the Y plane is BT.709's
    // luma of the frames' RGB (16 + 219·(0.2126 R + 0.7152 G + 0.0722 B)/255), not
    // BT.601's (0.299, 0.587, 0.114).
    let lossless = dir.path().join("v.mkv");
    animate()
        .arg(&m)
        .args(["--frames", "0", "--force", "-q", "--video"])
        .arg(&lossless)
        .args(["--codec", "libx264", "--crf", "0", "--pix-fmt", "yuv444p"])
        .assert()
        .success();
    assert!(probe(&lossless).contains("color_space=bt709"));
    let out = Command::new("ffmpeg")
        .args(["-v", "error", "-i"])
        .arg(&lossless)
        .args([
            "-frames:v",
            "1",
            "-f",
            "rawvideo",
            "-pix_fmt",
            "yuv444p",
            "-",
        ])
        .output()
        .unwrap();
    let yuv = stdout_ok(out);
    let rgb = pixels(&dir.path().join("png/frame_0000.png"));
    let n = rgb.len() / 3;
    let luma = |w: [f64; 3]| -> f64 {
        let mut err = 0.0;
        for k in 0..n {
            let p = &rgb[3 * k..3 * k + 3];
            let y = 16.0
                + 219.0
                    * (w[0] * f64::from(p[0]) + w[1] * f64::from(p[1]) + w[2] * f64::from(p[2]))
                    / 255.0;
            err += (y - f64::from(yuv[k])).abs();
        }
        err / n as f64
    };
    let (bt709, bt601) = (luma([0.2126, 0.7152, 0.0722]), luma([0.299, 0.587, 0.114]));
    eprintln!("mean |Y − luma|: BT.709 {bt709:.3}, BT.601 {bt601:.3}");
    assert!(bt709 < 0.6, "mean |Y − BT.709 luma| = {bt709}");
    assert!(
        bt601 > 4.0 * bt709 + 2.0,
        "BT.601 {bt601} vs BT.709 {bt709}"
    );
}
