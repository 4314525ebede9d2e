//! `animate preview` (SPEC §11) through the built binary: the looping GIF (frame count,
//! size, loop, delays), the contact sheet (tile count, size, and that a tile is the frame),
//! the path plot (written, not blank, the camera path drawn), determinism across thread
//! counts, the default folder, and located errors for bad options and bad input.

use crate::support;

use std::path::Path;
use support::*;

/// The 12-frame, 12 fps circle manifest over the 64×48 test scene.
fn orbit() -> (tempfile::TempDir, std::path::PathBuf) {
    project(&circle_manifest(""))
}

fn preview(manifest: &Path, out: &Path, args: &[&str]) -> assert_cmd::assert::Assert {
    animate()
        .arg("preview")
        .arg(manifest)
        .arg("-o")
        .arg(out)
        .args(args)
        .assert()
}

struct Gif {
    width: u16,
    height: u16,
    repeat: gif::Repeat,
    delays: Vec<u16>,
    first: Vec<u8>,
}

fn read_gif(path: &Path) -> Gif {
    let mut options = gif::DecodeOptions::new();
    options.set_color_output(gif::ColorOutput::RGBA);
    let mut d = options
        .read_info(std::fs::File::open(path).unwrap())
        .unwrap();
    let (width, height) = (d.width(), d.height());
    let (mut delays, mut first) = (Vec::new(), Vec::new());
    while let Some(f) = d.read_next_frame().unwrap() {
        assert_eq!((f.width, f.height), (width, height), "every frame is whole");
        if delays.is_empty() {
            first = f.buffer.to_vec();
        }
        delays.push(f.delay);
    }
    Gif {
        width,
        height,
        repeat: d.repeat(),
        delays,
        first,
    }
}

fn rgb_at(img: &image::RgbImage, x: u32, y: u32) -> [u8; 3] {
    img.get_pixel(x, y).0
}

#[test]
fn the_gif_has_every_frame_at_a_quarter_size_looping_at_the_fps() {
    let (dir, manifest) = orbit();
    let out = dir.path().join("pv");
    preview(&manifest, &out, &["-q"]).success();
    let g = read_gif(&out.join("animation.gif"));
    // 64×48 at 1/4: 16×12; 12 frames.
    assert_eq!((g.width, g.height), (16, 12));
    assert_eq!(g.delays.len(), 12);
    assert_eq!(g.repeat, gif::Repeat::Infinite);
    // 12 fps: frame ends at round(100·n/12) = 8, 17, 25, 33, 42, 50, … hundredths.
    assert_eq!(g.delays, [8, 9, 8, 8, 9, 8, 8, 9, 8, 8, 9, 8]);
    assert_eq!(g.delays.iter().map(|&d| u32::from(d)).sum::<u32>(), 100);
    assert!(g.first.chunks(4).any(|p| p[..3] != [0, 0, 0]), "not black");
}

#[test]
fn scale_and_fps_change_the_gif() {
    let (dir, manifest) = project(&circle_manifest("").replace("fps = 12", "fps = 25"));
    let out = dir.path().join("pv");
    preview(&manifest, &out, &["-q", "--scale", "3"]).success();
    let g = read_gif(&out.join("animation.gif"));
    // 64/3 = 21.3 → 21, 48/3 = 16; 25 fps: 4 hundredths each.
    assert_eq!((g.width, g.height), (21, 16));
    assert!(g.delays.iter().all(|&d| d == 4), "{:?}", g.delays);
}

#[test]
fn the_contact_sheet_has_every_nth_frame_as_a_labelled_tile() {
    let (dir, manifest) = orbit();
    let out = dir.path().join("pv");
    preview(&manifest, &out, &["-q", "--every", "3"]).success();
    let sheet = image::open(out.join("contact-sheet.png"))
        .unwrap()
        .to_rgb8();
    // Frames 0, 3, 6, 9: 4 tiles of 16×12, ⌈√6⌉ = 3 columns, 2 rows, 4 px apart with a
    // 16 px label band: 3·16 + 4·4 = 64 wide, 2·(12 + 16) + 3·4 = 68 high.
    assert_eq!(sheet.dimensions(), (64, 68));
    let slot = |k: u32| (4 + (k % 3) * 20, 4 + (k / 3) * 32);
    let background = [32, 32, 32];
    for k in 0..6 {
        let (x0, y0) = slot(k);
        let drawn = (0..12)
            .flat_map(|y| (0..16).map(move |x| (x0 + x, y0 + y)))
            .filter(|&(x, y)| rgb_at(&sheet, x, y) != background)
            .count();
        if k < 4 {
            assert!(drawn > 150, "tile {k} holds a frame ({drawn} pixels drawn)");
        } else {
            assert_eq!(drawn, 0, "slot {k} is empty");
        }
    }
    // Each tile has a label: some light pixels in its band.
    for k in 0..4 {
        let (x0, y0) = slot(k);
        let ink = (0..16)
            .flat_map(|y| (0..16).map(move |x| (x0 + x, y0 + 12 + y)))
            .filter(|&(x, y)| rgb_at(&sheet, x, y)[0] > 120)
            .count();
        assert!(
            ink > 3,
            "tile {k} has its frame number ({ink} light pixels)"
        );
    }
}

#[test]
fn a_tile_is_exactly_the_frame_raytrace_draws_at_that_size() {
    // Frame 0 of the circle is the scene file's own camera (0, 3, 8) looking at (0, 1, 0),
    // so tile 0 must be the scene rendered at 16×12 by `raytrace`, byte for byte.
    let (dir, manifest) = orbit();
    let out = dir.path().join("pv");
    preview(&manifest, &out, &["-q", "--every", "3"]).success();
    let small = dir.path().join("small.txt");
    let text = scene_with_eye([0.0, 3.0, 8.0]).replacen("64 48", "16 12", 1);
    std::fs::write(&small, text).unwrap();
    let png = dir.path().join("small.png");
    raytrace()
        .arg(&small)
        .arg("-o")
        .arg(&png)
        .arg("-q")
        .assert()
        .success();
    let frame = image::open(&png).unwrap().to_rgb8();
    let sheet = image::open(out.join("contact-sheet.png"))
        .unwrap()
        .to_rgb8();
    for y in 0..12 {
        for x in 0..16 {
            assert_eq!(
                rgb_at(&sheet, 4 + x, 4 + y),
                rgb_at(&frame, x, y),
                "({x}, {y})"
            );
        }
    }
}

#[test]
fn the_default_sheet_aims_at_about_24_tiles() {
    let (dir, manifest) = orbit();
    let out = dir.path().join("pv");
    preview(&manifest, &out, &["-q"]).success();
    // 12 frames, every 1: 12 tiles, ⌈√18⌉ = 5 columns, 3 rows: 5·16 + 6·4 = 104 wide,
    // 3·28 + 4·4 = 100 high.
    let sheet = image::open(out.join("contact-sheet.png")).unwrap();
    assert_eq!((sheet.width(), sheet.height()), (104, 100));
}

#[test]
fn the_path_plot_is_written_and_shows_the_camera_path() {
    let (dir, manifest) = orbit();
    let out = dir.path().join("pv");
    preview(&manifest, &out, &["-q"]).success();
    let plot = image::open(out.join("camera-path.png")).unwrap().to_rgb8();
    assert_eq!(plot.dimensions(), (1400, 720));
    let total = plot.pixels().count();
    let white = plot.pixels().filter(|p| p.0 == [255, 255, 255]).count();
    assert!(
        white < total * 95 / 100,
        "not blank: {white} of {total} white"
    );
    // The camera path's blue (30, 90, 200) and the lights' gold (240, 180, 0).
    let count = |c: [u8; 3]| plot.pixels().filter(|p| p.0 == c).count();
    assert!(count([30, 90, 200]) > 2000, "camera path drawn");
    assert!(count([240, 180, 0]) > 100, "lights drawn");
}

#[test]
fn the_preview_is_the_same_bytes_on_one_thread_or_two_and_nothing_else_is_left() {
    let (dir, manifest) = orbit();
    let (one, two) = (dir.path().join("one"), dir.path().join("two"));
    preview(&manifest, &one, &["-q", "--threads", "1"]).success();
    preview(&manifest, &two, &["-q", "--threads", "2"]).success();
    let (a, b) = (files(&one), files(&two));
    let names: Vec<&str> = a.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(
        names,
        ["animation.gif", "camera-path.png", "contact-sheet.png"]
    );
    assert!(a == b, "same bytes whatever the thread count");
    let hidden = std::fs::read_dir(&one).unwrap().count();
    assert_eq!(hidden, 3, "no temporary file left");
}

#[test]
fn the_default_folder_is_the_frame_folder_name_plus_preview_and_a_summary_is_printed() {
    let (dir, manifest) = orbit();
    let assert = animate().arg("preview").arg(&manifest).assert().success();
    let err = String::from_utf8_lossy(&assert.get_output().stderr).into_owned();
    assert!(err.contains("preview of 12 frames at 16×12"), "{err}");
    let pv = dir.path().join("frames-preview");
    assert!(pv.join("animation.gif").is_file());
    assert!(pv.join("contact-sheet.png").is_file());
    assert!(pv.join("camera-path.png").is_file());
    assert!(!dir.path().join("frames").exists(), "no frame is rendered");
}

fn fails_with(args: &[&str], manifest: &Path, code: i32, needle: &str) {
    let out = animate()
        .arg("preview")
        .arg(manifest)
        .args(args)
        .assert()
        .failure()
        .code(code);
    let err = String::from_utf8_lossy(&out.get_output().stderr).into_owned();
    assert!(err.contains(needle), "{needle:?} not in: {err}");
    assert!(!err.contains("panicked"), "{err}");
}

#[test]
fn bad_options_are_refused_by_name() {
    let (dir, manifest) = orbit();
    let out = dir.path().join("pv");
    let o = out.to_str().unwrap();
    fails_with(&["-o", o, "--scale", "0"], &manifest, 2, "--scale <K>");
    fails_with(&["-o", o, "--scale", "x"], &manifest, 2, "--scale <K>");
    fails_with(&["-o", o, "--every", "0"], &manifest, 2, "--every <N>");
    fails_with(&["-o", o, "--every=-3"], &manifest, 2, "--every <N>");
    fails_with(&["-o", o, "--frames", "1"], &manifest, 2, "--frames");
    assert!(!out.exists(), "nothing written");
}

#[test]
fn a_sheet_too_large_is_refused_before_anything_is_written() {
    let text = circle_manifest("").replace("frames = 12", "frames = 100000");
    let (dir, manifest) = project(&text);
    let out = dir.path().join("pv");
    let o = out.to_str().unwrap();
    fails_with(
        &["-o", o, "--scale", "1", "--every", "1"],
        &manifest,
        2,
        "--every 1: a contact sheet of 100000 tiles of 64×48",
    );
    assert!(!out.exists());
}

#[test]
fn bad_input_gets_a_located_error() {
    let (dir, manifest) = project(&circle_manifest("").replace("radius = 8.0", "radius = -8.0"));
    let out = dir.path().join("pv");
    let o = out.to_str().unwrap();
    let located = format!("{}:8:", manifest.display());
    fails_with(&["-o", o], &manifest, 2, &located);
    let missing = dir.path().join("nope.toml");
    fails_with(&["-o", o], &missing, 2, "nope.toml");
    // A preview folder that is a file.
    let (dir, manifest) = orbit();
    let file = dir.path().join("taken");
    std::fs::write(&file, "x").unwrap();
    fails_with(
        &["-o", file.to_str().unwrap()],
        &manifest,
        2,
        "cannot use the preview folder",
    );
}
