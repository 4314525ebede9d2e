//! `animate job M --openjd`: the Open Job Description template is accepted by `openjd
//! check` (PyPI openjd-cli) and `openjd run` of its render step renders the 12 frames into
//! the same bytes as one plain `animate` run; its video step encodes them with `animate encode`.
//! Without openjd (or ffmpeg for the video) the test says "skipped:" and passes, except
//! under CI, where it fails.

use crate::skip;
use crate::support;

use std::path::Path;
use std::process::Command;
use support::*;

fn job(manifest: &Path, args: &[&str]) -> serde_json::Value {
    let out = animate()
        .arg("job")
        .arg(manifest)
        .args(["--openjd", "--quiet"])
        .args(args)
        .output()
        .unwrap();
    serde_json::from_slice(&stdout_ok(out)).unwrap()
}

#[test]
fn the_template_has_a_chunked_render_step_and_a_video_step_after_it() {
    let (_dir, manifest) = project(&circle_manifest(""));
    let t = job(&manifest, &["--chunk", "5"]);
    assert_eq!(t["specificationVersion"], "jobtemplate-2023-09");
    assert_eq!(t["extensions"], serde_json::json!(["TASK_CHUNKING"]));
    let param = &t["steps"][0]["parameterSpace"]["taskParameterDefinitions"][0];
    assert_eq!(param["type"], "CHUNK[INT]");
    assert_eq!(param["range"], "0-11");
    assert_eq!(param["chunks"]["defaultTaskCount"], 5);
    let args = &t["steps"][0]["script"]["actions"]["onRun"]["args"];
    assert!(
        args.to_string()
            .contains(r#""--frames","{{Task.Param.Frame}}","--resume","--quiet""#),
        "{args}"
    );
    assert_eq!(t["steps"][1]["dependencies"][0]["dependsOn"], "Render");
    let video = &t["steps"][1]["script"]["actions"]["onRun"];
    assert_eq!(video["command"], "{{Param.Animate}}");
    let args = video["args"].to_string();
    let encode = r#"["encode","{{Param.Manifest}}","--dir","{{Param.OutDir}}","-o","{{Param.Video}}","--force","--quiet"]"#;
    assert_eq!(args, encode);
    // A subset of frames is the parameter's range; --chunk-seconds asks the estimate.
    let t = job(&manifest, &["--frames", "0-11x2", "--chunk-seconds", "30"]);
    let param = &t["steps"][0]["parameterSpace"]["taskParameterDefinitions"][0];
    assert_eq!(param["range"], "0,2,4,6,8,10");
    assert_eq!(param["chunks"]["targetRuntimeSeconds"], 30);
    // `animate encode` needs every frame: a job of some frames has no video step.
    assert_eq!(t["steps"].as_array().unwrap().len(), 1, "{t}");
    // These frames take milliseconds: 30 s a task is far more than six frames.
    assert!(param["chunks"]["defaultTaskCount"].as_u64().unwrap() > 6);
}

#[test]
fn openjd_checks_and_runs_the_template_into_the_bytes_of_a_plain_run() {
    if !skip::have("openjd", &["--version"]) {
        return;
    }
    let (dir, manifest) = project(&circle_manifest(""));
    let work = dir.path();
    render_into(&manifest, &work.join("plain"), &[]);
    let template = work.join("job.json");
    let out_dir = work.join("farm");
    let status = animate()
        .arg("job")
        .arg(&manifest)
        .args(["--openjd", "--chunk", "5", "--quiet", "-o"])
        .arg(&template)
        .arg("--out-dir")
        .arg(&out_dir)
        .output()
        .unwrap();
    assert!(
        status.status.success(),
        "{}",
        String::from_utf8_lossy(&status.stderr)
    );
    let check = Command::new("openjd")
        .arg("check")
        .arg(&template)
        .output()
        .unwrap();
    let said = String::from_utf8_lossy(&check.stdout).to_string()
        + &String::from_utf8_lossy(&check.stderr);
    assert!(check.status.success(), "openjd check: {said}");
    let bin = assert_cmd::cargo::cargo_bin("animate");
    let run = |step: &str, extra: &[&str]| {
        let out = Command::new("openjd")
            .arg("run")
            .arg(&template)
            .args(["--step", step])
            .args(extra)
            .arg("-p")
            .arg(format!("Animate={}", bin.display()))
            .output()
            .unwrap();
        let log = String::from_utf8_lossy(&out.stdout).to_string()
            + &String::from_utf8_lossy(&out.stderr);
        assert!(out.status.success(), "openjd run --step {step}: {log}");
        log
    };
    let log = run("Render", &[]);
    // 12 frames in chunks of at most 5: three tasks (openjd makes them 0-3, 4-7, 8-11).
    let chunks = log.matches("Frame(CHUNK[INT]) = ").count();
    assert_eq!(chunks, 3, "{log}");
    assert_eq!(files(&out_dir), files(&work.join("plain")));
    if !skip::have("ffmpeg", &["-version"]) {
        return;
    }
    run("Video", &["--no-run-dependencies"]);
    let video = std::fs::metadata(work.join("farm.mp4")).unwrap();
    assert!(video.len() > 1000, "{video:?}");
}
