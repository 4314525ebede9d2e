//! Reliability, round three (issue 40): the faults an attack on the tool found, each run
//! through the built binaries, worst first. Each test fails on the code before its fix:
//! a step that spun forever, sizes checked after the memory was taken, files that were
//! not the tool's removed or overwritten, broken pipes, cross-site requests to `view`,
//! EXR offset tables, OpenJD names, and the smaller ones.

use crate::support;

use std::path::Path;
use std::time::Duration;
use support::*;

/// Long enough for a loaded two-core machine to render twelve 64×48 frames; the fault
/// it guards against never ends at all.
const PROMPT: Duration = Duration::from_secs(60);

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

/// `animate ARGS` run to its end within `PROMPT`: (status, stdout, stderr).
fn run(args: &[&dyn AsRef<std::ffi::OsStr>]) -> (Option<i32>, String, String) {
    let mut cmd = std::process::Command::new(assert_cmd::cargo::cargo_bin("animate"));
    for a in args {
        cmd.arg(a);
    }
    let out = output_within(&mut cmd, PROMPT);
    (out.status.code(), text(&out.stdout), text(&out.stderr))
}

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

// 3. Files that are not the tool's are neither removed nor overwritten.

/// A photo: a sound PNG with no record.
fn photo(path: &Path) {
    image::RgbImage::from_pixel(8, 8, image::Rgb([200, 100, 50]))
        .save(path)
        .unwrap();
}

/// A circle manifest of `frames` frames named `IMG_####` into `shared/`.
fn img_manifest(dir: &Path, name: &str, frames: u32) -> std::path::PathBuf {
    let text = circle_manifest("")
        .replace("frames = 12", &format!("frames = {frames}"))
        .replace("dir = \"frames\"", "dir = \"shared\"")
        .replace("frame_####", "IMG_####");
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path
}

#[test]
fn a_run_does_not_replace_a_file_with_no_record() {
    let (dir, _) = project("");
    let m = img_manifest(dir.path(), "a.toml", 2);
    let shared = dir.path().join("shared");
    std::fs::create_dir(&shared).unwrap();
    photo(&shared.join("IMG_0000.png"));
    let before = std::fs::read(shared.join("IMG_0000.png")).unwrap();
    let (code, _, err) = run(&[&m, &"-q"]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("IMG_0000.png: not written by animate (no record), and would be replaced")
            && err.contains("hint: `--force`"),
        "{err}"
    );
    assert_eq!(std::fs::read(shared.join("IMG_0000.png")).unwrap(), before);
    assert!(!shared.join("IMG_0001.png").exists(), "nothing rendered");
    let (code, _, err) = run(&[&m, &"-q", &"--force"]);
    assert_eq!(code, Some(0), "{err}");
    assert_ne!(std::fs::read(shared.join("IMG_0000.png")).unwrap(), before);
    // The run's own frames are its to replace.
    let (code, _, err) = run(&[&m, &"-q"]);
    assert_eq!(code, Some(0), "{err}");
}

#[test]
fn clean_removes_only_its_own_frames_unless_forced() {
    let (dir, _) = project("");
    let a = img_manifest(dir.path(), "a.toml", 6);
    let b = img_manifest(dir.path(), "b.toml", 12);
    let shared = dir.path().join("shared");
    let (code, _, err) = run(&[&a, &"-q"]);
    assert_eq!(code, Some(0), "{err}");
    // Another manifest's frames past a's end, and a photo under the pattern.
    let (code, _, err) = run(&[&b, &"-q", &"--frames", &"8-9"]);
    assert_eq!(code, Some(0), "{err}");
    photo(&shared.join("IMG_0042.png"));
    // a is shortened: its frames 4 and 5 are past the end, and its own.
    std::fs::write(
        &a,
        std::fs::read_to_string(&a)
            .unwrap()
            .replace("frames = 6", "frames = 4"),
    )
    .unwrap();
    let (code, out, err) = run(&[&"clean", &a]);
    assert_eq!(code, Some(2), "{out}{err}");
    assert!(err.contains("and would be removed"), "{err}");
    assert_eq!(files(&shared).len(), 9, "nothing removed");
    let (code, out, err) = run(&[&"clean", &a, &"--force"]);
    assert_eq!(code, Some(0), "{err}");
    assert!(out.contains("removed 5 frame(s) past the end"), "{out}");
    let names: Vec<String> = files(&shared).into_iter().map(|f| f.0).collect();
    assert_eq!(
        names,
        [
            "IMG_0000.png",
            "IMG_0001.png",
            "IMG_0002.png",
            "IMG_0003.png"
        ]
    );
    // With only its own frames past the end, clean needs no --force.
    std::fs::write(
        &a,
        std::fs::read_to_string(&a)
            .unwrap()
            .replace("frames = 4", "frames = 2"),
    )
    .unwrap();
    let (code, out, err) = run(&[&"clean", &a]);
    assert_eq!(code, Some(0), "{err}");
    assert!(
        out.contains("removed 2 frame(s) past the end (2-3)"),
        "{out}"
    );
}

#[test]
fn bless_keeps_to_its_references_and_the_folder_lock() {
    let check = "\n[check]\nframes = [0, 1]\nreferences = \"refs\"\n";
    let (dir, a) = project(&circle_manifest(check));
    let b = dir.path().join("b.toml");
    std::fs::write(
        &b,
        circle_manifest(check).replace("radius = 8.0", "radius = 7.0"),
    )
    .unwrap();
    let refs = dir.path().join("refs");
    let (code, _, err) = run(&[&"bless", &a, &"-q"]);
    assert_eq!(code, Some(0), "{err}");
    let before = files(&refs);
    let (code, _, err) = run(&[&"bless", &b, &"-q"]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("rendered by another manifest (anim.toml)"),
        "{err}"
    );
    assert_eq!(files(&refs), before);
    let (code, _, err) = run(&[&"bless", &b, &"-q", &"--force"]);
    assert_eq!(code, Some(0), "{err}");
    assert_ne!(files(&refs), before);
    // A run of another manifest writing into the folder holds it: bless waits its turn.
    let slow = dir.path().join("slow.toml");
    let text = circle_manifest("\n[render]\nwidth = 640\nheight = 480\nsamples = 4\n")
        .replace("frames = 12", "frames = 200")
        .replace("frame_####", "slow_####");
    std::fs::write(&slow, text).unwrap();
    let mut child = spawn_animate(&slow, &["-q", "-o", refs.to_str().unwrap()]);
    // Its lock file is the third manifest's (anim.toml's and b.toml's are there).
    let locks = || {
        let names = std::fs::read_dir(&refs).unwrap().flatten();
        names
            .filter(|e| {
                e.file_name()
                    .to_string_lossy()
                    .starts_with(".whitted-lock-")
            })
            .count()
    };
    let locked = poll_until(PROMPT, || {
        locks() == 3 && child.try_wait().unwrap().is_none()
    });
    assert!(locked.is_some(), "the slow run never took the lock");
    std::thread::sleep(Duration::from_millis(300));
    let (code, _, err) = run(&[&"bless", &a, &"-q", &"--force"]);
    let _ = child.kill();
    let _ = child.wait();
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("a run of another manifest is writing into"),
        "{err}"
    );
}

// 4. Outputs do not overwrite inputs or others' files.

#[test]
fn reports_and_templates_do_not_overwrite_inputs_or_others_files() {
    let check = "\n[check]\nframes = [0]\nreferences = \"refs\"\n";
    let (dir, m) = project(&circle_manifest(check));
    let manifest = std::fs::read(&m).unwrap();
    let (code, _, err) = run(&[&"bless", &m, &"-q"]);
    assert_eq!(code, Some(0), "{err}");
    for args in [
        vec!["job", "--openjd", "-o"],
        vec!["job", "--openjd", "--force", "-o"],
        vec!["check", "--junit"],
        vec!["check", "--force", "--junit"],
    ] {
        let mut all: Vec<&dyn AsRef<std::ffi::OsStr>> = vec![&args[0], &m];
        all.extend(args[1..].iter().map(|a| a as &dyn AsRef<std::ffi::OsStr>));
        all.push(&m);
        let (code, _, err) = run(&all);
        assert_eq!(code, Some(2), "{args:?}: {err}");
        assert!(
            err.contains("it is an input of this run"),
            "{args:?}: {err}"
        );
        assert_eq!(std::fs::read(&m).unwrap(), manifest, "{args:?}");
    }
    // A page that is not the tool's, then a file that is not a template.
    let site = dir.path().join("site");
    std::fs::create_dir(&site).unwrap();
    std::fs::write(site.join("index.html"), "<h1>my site</h1>").unwrap();
    let (code, _, err) = run(&[&"check", &m, &"--html", &site]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("it exists and was not written by animate"),
        "{err}"
    );
    assert_eq!(
        std::fs::read_to_string(site.join("index.html")).unwrap(),
        "<h1>my site</h1>"
    );
    let (code, _, err) = run(&[&"check", &m, &"--html", &site, &"--force"]);
    assert_eq!(code, Some(0), "{err}");
    // Its own page is its to replace.
    let (code, _, err) = run(&[&"check", &m, &"--html", &site]);
    assert_eq!(code, Some(0), "{err}");
    let notes = dir.path().join("notes.json");
    std::fs::write(&notes, "{}").unwrap();
    let (code, _, err) = run(&[&"job", &m, &"--openjd", &"-o", &notes]);
    assert_eq!(code, Some(2), "{err}");
    let (code, _, err) = run(&[&"job", &m, &"--openjd", &"-o", &notes, &"--force"]);
    assert_eq!(code, Some(0), "{err}");
    let (code, _, err) = run(&[&"job", &m, &"--openjd", &"-o", &notes]);
    assert_eq!(code, Some(0), "its own template: {err}");
    // 9. `job -o folder/` was exit 1.
    let (code, _, err) = run(&[&"job", &m, &"--openjd", &"-o", &site]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("it is a folder"), "{err}");
}

// 5. A closed standard output ends a command quietly.

/// `animate ARGS` with standard output a pipe whose reader has already gone away:
/// (status, stderr).
fn into_closed_pipe(args: &[&dyn AsRef<std::ffi::OsStr>]) -> (Option<i32>, String) {
    let (reader, writer) = std::io::pipe().unwrap();
    drop(reader);
    let mut cmd = std::process::Command::new(assert_cmd::cargo::cargo_bin("animate"));
    for a in args {
        cmd.arg(a);
    }
    let mut child = cmd
        .stdout(writer)
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let (code, _) = wait_within(&mut child, PROMPT);
    let mut err = String::new();
    std::io::Read::read_to_string(&mut child.stderr.take().unwrap(), &mut err).unwrap();
    (code, err)
}

#[test]
fn a_closed_stdout_ends_quietly_with_the_verdict() {
    let check = "\n[check]\nframes = [0]\nreferences = \"refs\"\n";
    let (dir, m) = project(&circle_manifest(check));
    let (code, _, err) = run(&[&"bless", &m, &"-q"]);
    assert_eq!(code, Some(0), "{err}");
    std::fs::create_dir(dir.path().join("frames")).unwrap();
    let cases: [(&[&dyn AsRef<std::ffi::OsStr>], i32); 7] = [
        // The frames are missing: status's verdict is 1, text or no text.
        (&[&"status", &m], 1),
        (&[&"status", &m, &"--json"], 1),
        (&[&"check", &m], 0),
        (&[&"check", &m, &"--json"], 0),
        (&[&"clean", &m], 0),
        // Their text is their product: cut short.
        (&[&"estimate", &m, &"--shards", &"3"], 141),
        (&[&"job", &m, &"--openjd"], 141),
    ];
    for (args, expected) in cases {
        let (code, err) = into_closed_pipe(args);
        let shown: Vec<String> = args
            .iter()
            .map(|a| a.as_ref().to_string_lossy().into())
            .collect();
        assert_eq!(code, Some(expected), "{shown:?}: {err}");
        assert_eq!(err, "", "{shown:?}");
    }
    // A check that fails keeps its 1.
    edit_reference(dir.path(), 0, magenta_block);
    let (code, err) = into_closed_pipe(&[&"check", &m]);
    assert_eq!((code, err.as_str()), (Some(1), ""));
}
