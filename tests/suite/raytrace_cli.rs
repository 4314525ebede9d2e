//! The built `raytrace` (SPEC §3 and §4): every scene of `scenes/` renders at its
//! resolution; the thread count does not change a byte; the defaults (Scene.txt in the
//! current folder, OUT = the scene's name with .png); the four image formats agree on
//! the pixels; supersampling.

use crate::common;
use crate::shipped;

use common::{entries, raytrace_in, rich_scene, write_file};
use std::path::{Path, PathBuf};
use whitted::Scene;

/// Decodes an image file into (width, height, RGB bytes).
fn decode(path: &Path) -> (u32, u32, Vec<u8>) {
    let img = image::open(path)
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()))
        .to_rgb8();
    (img.width(), img.height(), img.into_raw())
}

/// Runs `raytrace` in `dir` with `args` and asserts success.
fn render(dir: &Path, args: &[&str]) {
    let out = raytrace_in(dir).args(args).output().unwrap();
    assert!(
        out.status.success(),
        "raytrace {args:?} failed with {:?}: {}",
        out.status.code(),
        String::from_utf8_lossy(&out.stderr)
    );
}

#[test]
fn every_shipped_scene_renders_at_its_resolution() {
    // The shipped scenes by name (tests/shipped), not whatever a user put in scenes/.
    let scenes: Vec<PathBuf> = shipped::scenes();
    let out_dir = tempfile::tempdir().unwrap();
    let mut rendered = 0;
    for scene_path in &scenes {
        let scene = Scene::load(scene_path).unwrap_or_else(|e| panic!("{e}"));
        let name = scene_path.file_stem().unwrap().to_str().unwrap();
        let out = out_dir.path().join(format!("{name}.png"));
        render(
            out_dir.path(),
            &[
                scene_path.to_str().unwrap(),
                "-o",
                out.to_str().unwrap(),
                "--quiet",
            ],
        );
        let (w, h) = image::image_dimensions(&out).unwrap();
        assert_eq!(
            (w, h),
            (scene.width, scene.height),
            "{}",
            scene_path.display()
        );
        rendered += 1;
    }
    assert_eq!(rendered, scenes.len());
    // Only the images: no temporary file left beside them.
    assert_eq!(entries(out_dir.path()).len(), scenes.len());
}

#[test]
fn the_thread_count_does_not_change_a_byte() {
    let dir = tempfile::tempdir().unwrap();
    write_file(dir.path(), "rich.txt", rich_scene(97, 61));
    render(dir.path(), &["rich.txt", "-o", "one.png", "--threads", "1"]);
    render(
        dir.path(),
        &["rich.txt", "-o", "three.png", "--threads", "3"],
    );
    render(dir.path(), &["rich.txt", "-o", "all.png"]);
    render(
        dir.path(),
        &[
            "rich.txt",
            "-o",
            "one4.png",
            "--threads",
            "1",
            "--samples",
            "2",
        ],
    );
    render(
        dir.path(),
        &["rich.txt", "-o", "all4.png", "--samples", "2"],
    );
    let read = |n: &str| std::fs::read(dir.path().join(n)).unwrap();
    assert_eq!(read("one.png"), read("all.png"));
    assert_eq!(read("three.png"), read("all.png"));
    assert_eq!(read("one4.png"), read("all4.png"));
    // The scene is not trivial: many distinct colours, not a blank frame.
    let (w, h, px) = decode(&dir.path().join("all.png"));
    assert_eq!((w, h), (97, 61));
    let mut colours: Vec<&[u8]> = px.chunks(3).collect();
    colours.sort();
    colours.dedup();
    assert!(
        colours.len() > 200,
        "only {} distinct colours",
        colours.len()
    );
}

#[test]
fn the_default_scene_is_scene_txt_and_the_default_output_its_png() {
    let dir = tempfile::tempdir().unwrap();
    write_file(dir.path(), "Scene.txt", rich_scene(32, 24));
    render(dir.path(), &["--quiet"]);
    assert_eq!(entries(dir.path()), ["Scene.png", "Scene.txt"]);
    assert_eq!(
        image::image_dimensions(dir.path().join("Scene.png")).unwrap(),
        (32, 24)
    );
    // A scene elsewhere: its image goes beside it, under its name.
    std::fs::create_dir(dir.path().join("sub")).unwrap();
    write_file(&dir.path().join("sub"), "my.scene.txt", rich_scene(20, 10));
    render(dir.path(), &["sub/my.scene.txt"]);
    assert_eq!(
        entries(&dir.path().join("sub")),
        ["my.scene.png", "my.scene.txt"]
    );
    assert_eq!(
        image::image_dimensions(dir.path().join("sub/my.scene.png")).unwrap(),
        (20, 10)
    );
    // The same scene gives the same pixels whichever way it was named.
    let (_, _, a) = decode(&dir.path().join("Scene.png"));
    render(dir.path(), &["Scene.txt", "-o", "named.png"]);
    let (_, _, b) = decode(&dir.path().join("named.png"));
    assert_eq!(a, b);
}

#[test]
fn raw_ppm_png_and_jpeg_hold_the_same_image() {
    let dir = tempfile::tempdir().unwrap();
    let (w, h) = (45usize, 31usize);
    write_file(dir.path(), "s.txt", rich_scene(w as u32, h as u32));
    for out in ["s.png", "s.raw", "s.ppm", "s.jpg", "s.JPEG"] {
        render(dir.path(), &["s.txt", "-o", out, "--quiet"]);
    }
    let (pw, ph, png) = decode(&dir.path().join("s.png"));
    assert_eq!((pw, ph), (w as u32, h as u32));

    // RAW: exactly ResX·ResY·3 bytes, the PNG's pixels, rows top to bottom.
    let raw = std::fs::read(dir.path().join("s.raw")).unwrap();
    assert_eq!(raw.len(), w * h * 3);
    assert_eq!(raw, png);

    // PPM: a P6 header, then the same bytes.
    let ppm = std::fs::read(dir.path().join("s.ppm")).unwrap();
    let header = format!("P6\n{w} {h}\n255\n");
    assert!(ppm.starts_with(header.as_bytes()), "{:?}", &ppm[..20]);
    assert_eq!(&ppm[header.len()..], &raw[..]);

    // JPEG: decodes at the right size, close to the pixels (lossy).
    for name in ["s.jpg", "s.JPEG"] {
        let bytes = std::fs::read(dir.path().join(name)).unwrap();
        assert_eq!(&bytes[..3], &[0xFF, 0xD8, 0xFF], "{name} is not a JPEG");
        let img = image::load_from_memory_with_format(&bytes, image::ImageFormat::Jpeg)
            .unwrap()
            .to_rgb8();
        assert_eq!((img.width(), img.height()), (w as u32, h as u32));
        let mean_err = img
            .as_raw()
            .iter()
            .zip(&raw)
            .map(|(&a, &b)| (a as f64 - b as f64).abs())
            .sum::<f64>()
            / raw.len() as f64;
        assert!(mean_err < 12.0, "{name}: mean error {mean_err}");
    }
}

/// A white sphere with no light on black: ambient only, so every pixel of the sphere is
/// exactly 0.2 → 51 and every other pixel 0. Only pixels on the outline can differ
/// between one sample and a 2×2 grid.
const FLAT_SPHERE: &str = "64 48\n0 0 10\n0 0 0\n0 20\n1 0 0 0\n\
    1.2  0 0 0   1 1 1 1   1 0 0 1 0 0\n";

#[test]
fn supersampling_smooths_edges_only() {
    let dir = tempfile::tempdir().unwrap();
    write_file(dir.path(), "flat.txt", FLAT_SPHERE);
    render(dir.path(), &["flat.txt", "-o", "one.raw", "--samples", "1"]);
    render(dir.path(), &["flat.txt", "-o", "two.raw", "--samples", "2"]);
    render(dir.path(), &["flat.txt", "-o", "default.raw"]);
    let one = std::fs::read(dir.path().join("one.raw")).unwrap();
    let two = std::fs::read(dir.path().join("two.raw")).unwrap();
    assert_eq!(one, std::fs::read(dir.path().join("default.raw")).unwrap());
    let (w, h) = (64usize, 48usize);
    assert_eq!(one.len(), w * h * 3);
    assert_eq!(two.len(), w * h * 3);
    // One sample: only the two flat values, and both present.
    assert!(one.iter().all(|&b| b == 0 || b == 51));
    assert!(one.contains(&0) && one.contains(&51));
    // The value of pixel (i, j) and whether its 3×3 neighbourhood is uniform.
    let at = |img: &[u8], i: usize, j: usize| img[(j * w + i) * 3];
    let uniform = |i: usize, j: usize| {
        let v = at(&one, i, j);
        (i.saturating_sub(1)..=(i + 1).min(w - 1))
            .all(|x| (j.saturating_sub(1)..=(j + 1).min(h - 1)).all(|y| at(&one, x, y) == v))
    };
    let mut edge_blends = 0;
    for j in 0..h {
        for i in 0..w {
            let (a, b) = (at(&one, i, j), at(&two, i, j));
            if uniform(i, j) {
                assert_eq!(a, b, "pixel ({i}, {j}) away from the outline changed");
            } else if b != 0 && b != 51 {
                edge_blends += 1;
            }
            // Grey stays grey: the three channels agree.
            let k = (j * w + i) * 3;
            assert!(two[k] == two[k + 1] && two[k + 1] == two[k + 2]);
        }
    }
    assert!(
        edge_blends > 10,
        "only {edge_blends} blended outline pixels"
    );
    assert_ne!(one, two);
}

#[test]
fn bad_sample_and_thread_counts_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    write_file(dir.path(), "flat.txt", FLAT_SPHERE);
    for args in [
        &["flat.txt", "--samples", "0"][..],
        &["flat.txt", "--samples", "-1"],
        &["flat.txt", "--samples", "two"],
        &["flat.txt", "--threads", "0"],
        &["flat.txt", "--unknown-flag"],
    ] {
        let out = raytrace_in(dir.path()).args(args).output().unwrap();
        assert_eq!(
            out.status.code(),
            Some(2),
            "{args:?}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        assert!(!out.stderr.is_empty(), "{args:?}: no message");
        assert_eq!(entries(dir.path()), ["flat.txt"], "{args:?} wrote a file");
    }
}

#[test]
fn quiet_prints_nothing_and_the_default_reports_the_render() {
    let dir = tempfile::tempdir().unwrap();
    write_file(dir.path(), "flat.txt", FLAT_SPHERE);
    let out = raytrace_in(dir.path())
        .args(["flat.txt", "-q"])
        .output()
        .unwrap();
    assert!(out.status.success());
    assert!(out.stdout.is_empty() && out.stderr.is_empty());
    let out = raytrace_in(dir.path()).arg("flat.txt").output().unwrap();
    assert!(out.status.success());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("flat.png"), "{stderr}");
    assert!(out.stdout.is_empty(), "stdout is kept free");
}

#[test]
fn an_output_in_a_missing_folder_is_bad_input_and_leaves_nothing() {
    let dir = tempfile::tempdir().unwrap();
    write_file(dir.path(), "flat.txt", FLAT_SPHERE);
    let out = raytrace_in(dir.path())
        .args(["flat.txt", "-o", "missing/folder/x.png"])
        .output()
        .unwrap();
    // Checked before rendering: bad input, exit 2 (the exit table of `whitted::exit`).
    assert_eq!(out.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("missing/folder/x.png") && stderr.contains("does not exist"),
        "{stderr}"
    );
    assert_eq!(entries(dir.path()), ["flat.txt"]);
    // An output that is a folder, likewise.
    std::fs::create_dir(dir.path().join("taken.png")).unwrap();
    let out = raytrace_in(dir.path())
        .args(["flat.txt", "-o", "taken.png"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn a_failed_write_after_rendering_is_status_1_and_names_the_file() {
    // /proc/self is a folder that takes no new file: the write fails after the render.
    let dir = tempfile::tempdir().unwrap();
    write_file(dir.path(), "flat.txt", FLAT_SPHERE);
    let out = raytrace_in(dir.path())
        .args(["flat.txt", "-o", "/proc/self/x.png"])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(matches!(out.status.code(), Some(1)), "{stderr}");
    assert!(
        stderr.contains("x.png") && !stderr.contains(".tmp"),
        "{stderr}"
    );
}

#[test]
fn size_renders_a_quick_look_and_help_lists_the_formats() {
    let dir = tempfile::tempdir().unwrap();
    write_file(dir.path(), "flat.txt", FLAT_SPHERE);
    render(
        dir.path(),
        &["flat.txt", "--size", "40x30", "-o", "small.png"],
    );
    let (w, h, _) = decode(&dir.path().join("small.png"));
    assert_eq!((w, h), (40, 30));
    for bad in ["40", "0x30", "40x", "20000x10", "9000x9000"] {
        let out = raytrace_in(dir.path())
            .args(["flat.txt", "--size", bad])
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2), "{bad}");
    }
    let out = raytrace_in(dir.path()).arg("--help").output().unwrap();
    let help = String::from_utf8_lossy(&out.stdout);
    for word in [
        ".png",
        ".jpg",
        ".ppm",
        ".raw",
        "beside the scene",
        "Exit status",
    ] {
        assert!(help.contains(word), "{word}: {help}");
    }
}
