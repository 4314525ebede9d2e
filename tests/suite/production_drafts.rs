//! Drafts beside finals, through the built `animate`: `--size`, `--scale`, `--samples`,
//! `--aa` override the manifest for one run, write to the draft's own folder, are recorded
//! in the frames, and `status`, `stats`, `check`, `bless` and `encode` take them too.

use crate::support;

use support::*;

fn status_json(manifest: &std::path::Path, args: &[&str]) -> (Option<i32>, serde_json::Value) {
    let out = animate()
        .arg("status")
        .arg(manifest)
        .arg("--json")
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code(),
        serde_json::from_slice(&out.stdout).unwrap(),
    )
}

#[test]
fn a_draft_goes_to_its_own_folder_and_leaves_the_finals_alone() {
    let (dir, manifest) = project(&circle_manifest(""));
    animate().arg(&manifest).arg("-q").assert().success();
    let finals = files(&dir.path().join("frames"));
    animate()
        .arg(&manifest)
        .args(["-q", "--scale", "4", "--samples", "2"])
        .assert()
        .success();
    let drafts = dir.path().join("frames-draft-16x12-s2");
    let first = image::open(drafts.join("frame_0000.png")).unwrap();
    assert_eq!((first.width(), first.height()), (16, 12));
    assert_eq!(files(&dir.path().join("frames")), finals);
    assert_eq!(files(&drafts).len(), 12);
    // The frame records the draft.
    let bytes = std::fs::read(drafts.join("frame_0000.png")).unwrap();
    let text = String::from_utf8_lossy(&bytes);
    assert!(text.contains("whitted:draft") && text.contains("16x12, samples 2"));
    // status takes the same overrides: the draft folder is up to date, and says so.
    let (code, doc) = status_json(&manifest, &["--scale", "4", "--samples", "2"]);
    assert_eq!(code, Some(0), "{doc}");
    assert_eq!(doc["draft"], "16x12, samples 2");
    let (code, doc) = status_json(&manifest, &[]);
    assert_eq!(code, Some(0));
    assert_eq!(doc["draft"], serde_json::Value::Null);
    // stats too.
    let out = animate()
        .args(["stats", "--json", "--size", "16x12", "--samples", "2"])
        .arg(&manifest)
        .output()
        .unwrap();
    let doc: serde_json::Value = serde_json::from_slice(&stdout_ok(out)).unwrap();
    assert_eq!(doc["totals"]["frames"], 12);
    assert_eq!(doc["totals"]["eye"], 12 * 16 * 12 * 4);
}

#[test]
fn resume_and_status_tell_a_draft_from_a_final_in_one_folder() {
    let (dir, manifest) = project(&circle_manifest(""));
    let frames = dir.path().join("frames");
    // A draft written into the final folder on purpose (-o wins over the draft's folder).
    render_into(
        &manifest,
        &frames,
        &["-q", "--size", "64x48", "--frames", "0-3"],
    );
    render_into(&manifest, &frames, &["-q", "--frames", "4-11"]);
    let out = animate().arg("status").arg(&manifest).output().unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(1), "{text}");
    // Same size as the final, yet told apart.
    assert!(
        text.contains("it is a draft (64x48), now the final"),
        "{text}"
    );
    let out = animate().arg(&manifest).arg("--resume").output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("4 frames rendered, 8 up to date"), "{err}");
    animate().arg("status").arg(&manifest).assert().success();
}

#[test]
fn bad_overrides_are_refused_with_status_2() {
    let (_dir, manifest) = project(&circle_manifest(""));
    for args in [
        &["--samples", "2", "--aa", "adaptive"][..],
        &["--size", "16x12", "--scale", "2"],
        &["--size", "0x12"],
        &["--scale", "0"],
        &["--aa", "grid"],
    ] {
        let out = animate().arg(&manifest).args(args).output().unwrap();
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert!(!_dir.path().join("frames").exists(), "{args:?}");
    }
    let exr = circle_manifest("").replace("format = \"png\"", "format = \"exr\"");
    let (_d, manifest) = project(&exr);
    let out = animate()
        .arg(&manifest)
        .args(["--aa", "adaptive"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("--aa draws 8-bit frames only"), "{err}");
}

#[test]
fn check_and_bless_of_a_draft_use_references_of_its_own() {
    let (dir, manifest) = project(&circle_manifest(
        "\n[check]\nframes = [0, 6]\nreferences = \"refs\"\n",
    ));
    animate()
        .args(["bless", "--scale", "2"])
        .arg(&manifest)
        .assert()
        .success();
    let refs = dir.path().join("refs-draft-32x24");
    let r = image::open(refs.join("frame_0000.png")).unwrap();
    assert_eq!((r.width(), r.height()), (32, 24));
    animate()
        .args(["check", "--scale", "2"])
        .arg(&manifest)
        .assert()
        .success();
    // The final check has no references yet: it cannot run.
    let out = animate().arg("check").arg(&manifest).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn view_takes_the_draft_overrides() {
    use crate::view_common::Viewer;
    let (dir, manifest) = project(&circle_manifest(""));
    let draft = ["--scale", "4", "--samples", "2"];
    animate()
        .arg(&manifest)
        .args(["-q", "--frames", "5"])
        .args(draft)
        .assert()
        .success();
    let v = Viewer::start(&manifest, &draft);
    let (_, state) = v.json("/api/state");
    assert_eq!(
        (state["width"].as_u64(), state["height"].as_u64()),
        (Some(16), Some(12))
    );
    // The whole frame served is the draft frame written, and the strip reads the draft's
    // folder: frame 5 up to date there.
    let r = v.get("/api/frame?n=5&scale=1&format=raw&client=t");
    assert_eq!(r.header("x-size"), Some("16x12"));
    assert!(r.body == pixels(&dir.path().join("frames-draft-16x12-s2/frame_0005.png")));
    let (_, strip) = v.json("/api/status");
    assert_eq!(strip["states"][5], "up-to-date", "{strip}");
    assert_eq!(strip["states"][4], "missing", "{strip}");
}
