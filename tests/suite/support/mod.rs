//! Shared by the `animate` integration tests: a small scene, manifests written into a
//! temporary folder, helpers to run the built binaries and read their frames and folders;
//! processes steered by signals and deadlines are in `process`; videos and EXR files read
//! by outside readers in `media`.

#![allow(dead_code)]

pub mod media;
pub mod povray;
pub mod process;
#[allow(unused_imports)]
pub use media::*;
#[allow(unused_imports)]
pub use process::*;

use assert_cmd::Command;
use std::path::{Path, PathBuf};

/// A small scene with every feature: checker floor, mirror, glass, wood, a cylinder, two
/// lights and fog. `{EYE}` is replaced by the camera position.
pub const SCENE: &str = "\
64 48
{EYE}
0 1 0
2 40
3 1 1 2
1.0  -1.3 1 0   1 0.9 0.9 0.9                                0.1 0.9 0 1 0 0
0.9   1.2 0.9 0.5   1 1 1 1                                0.1 0 0.9 1.5 0 0
0.6   0 0.6 -1.5   2 3 0.6 0.4 0.2 0.3 0.15 0.05 0 0 0     0.8 0 0 1 0 0
0 0 0  0 1 0   2 1 1 1 1 0.1 0.1 0.1 0 0 0                 0.9 0 0 1 0 0
0 1 0  -2 0 -2  0.3   1 0.2 0.5 0.8                        0.7 0 0 1 0 0
5 10 5  1 1 1  0.9
-6 8 4  0.6 0.6 0.8  0.6
";

/// The scene with its camera at `eye`.
pub fn scene_with_eye(eye: [f64; 3]) -> String {
    SCENE.replace("{EYE}", &format!("{:?} {:?} {:?}", eye[0], eye[1], eye[2]))
}

/// Writes `dir/scene.txt`, the scene with its camera at `eye`; its path.
pub fn scene_txt(dir: &Path, eye: [f64; 3]) -> PathBuf {
    let path = dir.join("scene.txt");
    std::fs::write(&path, scene_with_eye(eye)).unwrap();
    path
}

/// A 12-frame circle manifest over `scene.txt` in the same folder; `extra` is appended.
pub fn circle_manifest(extra: &str) -> String {
    format!(
        "scene = \"scene.txt\"\nframes = 12\nfps = 12\n\n[camera]\npath = \"circle\"\n\
         center = [0.0, 1.0, 0.0]\nradius = 8.0\nheight = 3.0\nstart_angle = 0.0\nturns = 1.0\n\n\
         [output]\ndir = \"frames\"\nname = \"frame_####\"\nformat = \"png\"\n{extra}"
    )
}

/// A temporary folder holding `scene.txt` and `anim.toml` (the given manifest text).
pub fn project(manifest: &str) -> (tempfile::TempDir, PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("scene.txt"),
        scene_with_eye([0.0, 3.0, 8.0]),
    )
    .unwrap();
    let path = dir.path().join("anim.toml");
    std::fs::write(&path, manifest).unwrap();
    (dir, path)
}

/// The standard output of a finished command, which must have succeeded (its standard
/// error is the message when it did not).
#[track_caller]
pub fn stdout_ok(out: std::process::Output) -> Vec<u8> {
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    out.stdout
}

pub fn animate() -> Command {
    Command::cargo_bin("animate").unwrap()
}

/// Runs `animate MANIFEST ARGS -o OUT` and expects success.
pub fn render_into(manifest: &Path, out: &Path, args: &[&str]) {
    animate()
        .arg(manifest)
        .args(args)
        .arg("-o")
        .arg(out)
        .assert()
        .success();
}

pub fn raytrace() -> Command {
    Command::cargo_bin("raytrace").unwrap()
}

/// Writes `text` as DIR/scene.txt and renders it with `raytrace` into DIR/out.png: the
/// PNG's bytes, or the standard error (DIR written `DIR`) of a refusal (exit 2, no image
/// written); any other outcome fails the test.
pub fn render_scene(dir: &Path, text: &str) -> Result<Vec<u8>, String> {
    let scene = dir.join("scene.txt");
    std::fs::write(&scene, text).unwrap();
    let png = dir.join("out.png");
    let _ = std::fs::remove_file(&png);
    let out = raytrace().arg(&scene).arg("-o").arg(&png).output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr).replace(&*dir.display().to_string(), "DIR");
    match out.status.code() {
        Some(0) => Ok(std::fs::read(&png).unwrap()),
        Some(2) if !png.exists() && !stderr.contains("panicked") => Err(stderr),
        code => panic!("exit {code:?}: {stderr}"),
    }
}

/// The visible files of a folder, sorted, with their bytes.
pub fn files(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut out: Vec<(String, Vec<u8>)> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap())
        .filter(|e| !e.file_name().to_string_lossy().starts_with('.'))
        .map(|e| {
            let name = e.file_name().to_string_lossy().into_owned();
            (name, std::fs::read(e.path()).unwrap())
        })
        .collect();
    out.sort();
    out
}

/// The names of the entries of `dir`, sorted, hidden ones included.
pub fn entries(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("cannot list {}: {e}", dir.display()))
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

/// What is left in a frame folder besides the run's folder lock (the library's
/// `LOCK_FILE` and its `LOCK_FILE-<key>` files, the frames' claims) and the frames' cost records, sorted, hidden ones included; nothing when
/// the folder does not exist.
pub fn leftovers(dir: &Path) -> Vec<String> {
    use whitted_anim::frames::lock::LOCK_FILE;
    if !dir.exists() {
        return Vec::new();
    }
    let own = format!("{LOCK_FILE}-");
    // The hidden record folder counts only when it holds more than frames' cost records.
    let records = dir.join(".whitted-record");
    let only_costs =
        !records.is_dir() || entries(&records).iter().all(|n| n.ends_with(".cost.json"));
    entries(dir)
        .into_iter()
        .filter(|n| n != LOCK_FILE && !n.starts_with(&own))
        .filter(|n| n != whitted_anim::frames::claim::CLAIMS)
        .filter(|n| !(n == ".whitted-record" && only_costs))
        .collect()
}

/// A folder holding `scene.txt`: `scene_with_eye` with its eye at (0, 3, 8).
pub fn eye_folder() -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("scene.txt"),
        scene_with_eye([0.0, 3.0, 8.0]),
    )
    .unwrap();
    dir
}

/// Frame `frame` of `manifest` (written into `dir` as `name.toml`, rendered into the
/// folder `name`), as pixels.
pub fn frame_of(dir: &Path, name: &str, manifest: &str, frame: u32) -> Vec<u8> {
    let path = dir.join(format!("{name}.toml"));
    std::fs::write(&path, manifest).unwrap();
    let out = dir.join(name);
    animate()
        .arg(&path)
        .args(["--frames", &frame.to_string(), "-q", "-o"])
        .arg(&out)
        .assert()
        .success();
    pixels(&out.join(format!("frame_{frame:04}.png")))
}

/// The RGB pixels of a PNG file.
pub fn pixels(path: &Path) -> Vec<u8> {
    image::open(path).unwrap().to_rgb8().into_raw()
}

/// A `circle_manifest(check)` project whose `[check]` references are blessed.
pub fn blessed(check: &str) -> (tempfile::TempDir, PathBuf) {
    let (dir, manifest) = project(&circle_manifest(check));
    animate().arg("bless").arg(&manifest).assert().success();
    (dir, manifest)
}

/// Rewrites the reference PNG `refs/frame_NNNN.png` of `dir` after `edit` changes it.
pub fn edit_reference(dir: &Path, frame: u32, edit: impl FnOnce(&mut image::RgbImage)) {
    let path = dir.join(format!("refs/frame_{frame:04}.png"));
    let mut img = image::open(&path).unwrap().to_rgb8();
    edit(&mut img);
    img.save(&path).unwrap();
}

/// Paints the 10×10 block at (10, 10) magenta: a change every check notices.
pub fn magenta_block(img: &mut image::RgbImage) {
    for y in 10..20 {
        for x in 10..20 {
            img.put_pixel(x, y, image::Rgb([255, 0, 255]));
        }
    }
}

/// Runs `animate check MANIFEST ARGS`: its exit status, standard output and error.
pub fn check(manifest: &Path, args: &[&str]) -> (Option<i32>, String, String) {
    let out = animate()
        .arg("check")
        .arg(manifest)
        .args(args)
        .output()
        .unwrap();
    let text = |b: &[u8]| String::from_utf8_lossy(b).into_owned();
    (out.status.code(), text(&out.stdout), text(&out.stderr))
}

/// The row of frame `frame` in `animate check`'s table (`out`, its standard output).
pub fn row(out: &str, frame: u32) -> &str {
    let start = format!("{frame} ");
    let found = out.lines().find(|l| l.trim_start().starts_with(&start));
    found.unwrap_or_else(|| panic!("no row for frame {frame} in:\n{out}"))
}

/// A `frames`-frame circle manifest in RAW at `radius`, written as `name` in `dir`.
pub fn raw_manifest(dir: &Path, name: &str, frames: u32, radius: f64) -> PathBuf {
    let text = circle_manifest("")
        .replace("frames = 12", &format!("frames = {frames}"))
        .replace("radius = 8.0", &format!("radius = {radius:?}"))
        .replace("format = \"png\"", "format = \"raw\"");
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path
}
