//! A newcomer's small frictions, through `animate`: `-o still.png` is refused instead of
//! making a folder of that name; `check --junit` into a missing folder (or `--html` under
//! a file) is refused before anything renders; `--html` into a folder of an earlier
//! report leaves only this run's images there.

use crate::support;

use std::path::Path;
use support::*;

const CHECK: &str = "\n[check]\nframes = [0, 5, 9]\nreferences = \"refs\"\n";

#[test]
fn an_output_folder_named_like_an_image_is_refused() {
    let (dir, manifest) = project(&circle_manifest(""));
    let still = dir.path().join("still.png");
    let out = animate()
        .arg(&manifest)
        .arg("-o")
        .arg(&still)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("still.png is the name of an image") && err.contains("--frames N -o DIR"),
        "{err}"
    );
    assert!(!still.exists(), "a folder named still.png was made");
    // A folder that already has such a name is a folder: taken as before.
    std::fs::create_dir(&still).unwrap();
    let out = animate()
        .arg(&manifest)
        .args(["--frames", "0", "-q", "-o"])
        .arg(&still)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(still.join("frame_0000.png").is_file());
}

/// The files of `dir` (none when it does not exist).
fn names(dir: &Path) -> Vec<String> {
    match dir.exists() {
        true => entries(dir),
        false => Vec::new(),
    }
}

#[test]
fn report_paths_are_checked_before_the_render() {
    let (dir, manifest) = blessed(CHECK);
    let d = dir.path();
    edit_reference(d, 5, magenta_block);
    let report = d.join("report");
    let report_arg = report.to_str().unwrap();
    // Frame 5 fails, so a render would write its images into the report folder.
    let junit = d.join("no/such/folder/check.xml");
    let args = ["--report", report_arg, "--junit", junit.to_str().unwrap()];
    let (code, _, err) = check(&manifest, &args);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("no/such/folder/check.xml") && err.contains("does not exist"),
        "{err}"
    );
    assert_eq!(
        names(&report),
        Vec::<String>::new(),
        "the frames were rendered first"
    );
    // A page whose folder would be made under a file: refused the same way.
    std::fs::write(d.join("a-file"), "x").unwrap();
    let html = d.join("a-file/page");
    let (code, _, err) = check(
        &manifest,
        &["--report", report_arg, "--html", html.to_str().unwrap()],
    );
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("is a file"), "{err}");
    assert_eq!(names(&report), Vec::<String>::new());
    // A page folder that does not exist yet is made, after the render, as before.
    let page = d.join("new/deeper/page");
    let (code, _, err) = check(&manifest, &["--html", page.to_str().unwrap()]);
    assert_eq!(code, Some(1), "{err}");
    assert!(page.join("index.html").is_file());
}

#[test]
fn a_page_keeps_only_the_images_of_its_own_run() {
    let (dir, manifest) = blessed(CHECK);
    let d = dir.path();
    let page = d.join("page");
    let page_arg = page.to_str().unwrap();
    edit_reference(d, 5, magenta_block);
    let (code, _, err) = check(&manifest, &["--html", page_arg]);
    assert_eq!(code, Some(1), "{err}");
    assert!(names(&page).contains(&"frame_0005.diff.png".to_string()));
    // Blessed again, frame 9's reference edited: frame 5 passes now, 9 fails.
    animate().arg("bless").arg(&manifest).assert().success();
    edit_reference(d, 9, magenta_block);
    let (code, _, err) = check(&manifest, &["--html", page_arg]);
    assert_eq!(code, Some(1), "{err}");
    let files = names(&page);
    assert!(
        files.contains(&"frame_0009.diff.png".to_string()),
        "{files:?}"
    );
    assert!(
        !files.iter().any(|f| f.starts_with("frame_0005")),
        "{files:?}"
    );
    // Every file but the page itself is named by the page.
    let html = std::fs::read_to_string(page.join("index.html")).unwrap();
    for f in files.iter().filter(|f| *f != "index.html") {
        assert!(html.contains(&format!("\"{f}\"")), "{f} is not on the page");
    }
    // A passing run leaves the page alone in its folder.
    animate().arg("bless").arg(&manifest).assert().success();
    let (code, _, err) = check(&manifest, &["--html", page_arg]);
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(names(&page), ["index.html"]);
}

/// `estimate`'s sample size: the `N bytes encoded` of its first line.
fn estimated_bytes(manifest: &Path) -> u64 {
    let out = stdout_ok(animate().arg("estimate").arg(manifest).output().unwrap());
    let text = String::from_utf8(out).unwrap();
    let first = text.lines().next().unwrap();
    let before = first.split(" bytes encoded").next().unwrap();
    before
        .rsplit(' ')
        .next()
        .unwrap()
        .parse()
        .unwrap_or_else(|_| panic!("{first}"))
}

#[test]
fn estimate_times_the_frame_as_the_run_writes_it() {
    // Ten passes in float EXR: the file is several times the beauty; the estimate's
    // timed frame must be that file (less its provenance header), not the beauty alone.
    let passes = "format = \"exr\"\npasses = [\"depth\", \"position\", \"normal\", \"albedo\", \
                  \"ambient\", \"diffuse\", \"specular\", \"reflection\", \"transmission\", \"fog\"]\n";
    let (dir, manifest) = project(&circle_manifest("").replace("format = \"png\"\n", passes));
    let d = dir.path();
    let estimated = estimated_bytes(&manifest);
    animate()
        .arg(&manifest)
        .args(["--frames", "0", "-q"])
        .assert()
        .success();
    let written = std::fs::metadata(d.join("frames/frame_0000.exr"))
        .unwrap()
        .len();
    // The provenance header is a few kilobytes at most; the frames of a circle differ a
    // little in how they compress.
    let diff = written.abs_diff(estimated);
    assert!(
        diff < written / 5,
        "estimated {estimated} bytes, the frame has {written}"
    );
    // The beauty alone would be far smaller than the frame with its passes.
    let beauty = project(&circle_manifest("").replace("format = \"png\"\n", "format = \"exr\"\n"));
    assert!(
        estimated_bytes(&beauty.1) * 3 < estimated,
        "the passes were not encoded"
    );
}

#[test]
fn the_enormous_render_warning_counts_only_the_frames_to_render() {
    // 64×48 at 16×16 samples: 786,432 camera rays a frame, so 342 frames are past the
    // warning's 2^28 and one frame is far below it.
    let manifest = "scene = \"scene.txt\"\nframes = 342\n[render]\nsamples = 16\n\
                    [output]\ndir = \"frames\"\n";
    let (dir, path) = project(manifest);
    let frames = dir.path().join("frames");
    animate()
        .arg(&path)
        .args(["--frames", "0", "-q"])
        .assert()
        .success();
    // The camera holds still and nothing is tracked: every frame is frame 0's picture,
    // recorded with the same digest, so copies of it are up to date (all but the last).
    let first = frames.join("frame_0000.png");
    for f in 1..341 {
        std::fs::hard_link(&first, frames.join(format!("frame_{f:04}.png"))).unwrap();
    }
    let out = animate().arg(&path).arg("--resume").output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{err}");
    assert!(err.contains("1 frame rendered, 341 up to date"), "{err}");
    assert!(
        !err.contains("warning"),
        "a warning for frames that are done: {err}"
    );
}

#[test]
fn a_job_takes_the_codec_options_encode_takes() {
    let (_dir, manifest) = project(&circle_manifest(""));
    let job = |args: &[&str]| {
        animate()
            .arg("job")
            .arg(&manifest)
            .args(["--openjd", "--quiet"])
            .args(args)
            .output()
            .unwrap()
    };
    let codec = [
        "--codec",
        "libx265",
        "--crf",
        "28",
        "--pix-fmt",
        "yuv420p10le",
    ];
    let t: serde_json::Value = serde_json::from_slice(&stdout_ok(job(&codec))).unwrap();
    let args = t["steps"][1]["script"]["actions"]["onRun"]["args"].to_string();
    let want = r#"["encode","{{Param.Manifest}}","--dir","{{Param.OutDir}}","-o","{{Param.Video}}","--force","--quiet","--codec","libx265","--crf","28","--pix-fmt","yuv420p10le"]"#;
    assert_eq!(args, want);
    // A job of some frames has no video step to give them to; braces would be read as
    // the template's expressions.
    for (args, why) in [
        (
            &["--frames", "0-5", "--crf", "20"][..],
            "--crf applies to the job's video step",
        ),
        (
            &["--codec", "{{Param.X}}"][..],
            "cannot go into a job template",
        ),
    ] {
        let out = job(args);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{err}");
        assert!(err.contains(why), "{why:?} not in {err}");
        assert!(out.stdout.is_empty());
    }
}
