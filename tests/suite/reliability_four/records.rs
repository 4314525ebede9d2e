//! Point 9's records and folders: `animate stats` followed a cost record linked to
//! `/dev/zero` (2.1 GB, then an abort); `dir = "."` gave a draft folder named
//! `-draft-16x12`, and `dir = ".."` one outside the manifest's folder.

use super::run;
use crate::support::*;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// Runs `cmd` to its end, at most `limit`, killing it if its peak memory passes
/// `max_kib` (so that the fault fails the test instead of taking the machine's memory):
/// (exit code, peak KiB, seconds).
fn bounded(cmd: &mut Command, limit: Duration, max_kib: u64) -> (Option<i32>, u64, f64) {
    let mut child = cmd
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let (start, mut peak) = (Instant::now(), 0);
    let status = format!("/proc/{}/status", child.id());
    loop {
        if let Some(done) = child.try_wait().unwrap() {
            return (done.code(), peak, start.elapsed().as_secs_f64());
        }
        let text = std::fs::read_to_string(&status).unwrap_or_default();
        let hwm = text.lines().find_map(|l| l.strip_prefix("VmHWM:"));
        let kib = hwm.and_then(|v| v.trim().trim_end_matches("kB").trim().parse().ok());
        peak = peak.max(kib.unwrap_or(0));
        if peak > max_kib || start.elapsed() > limit {
            let _ = child.kill();
            let _ = child.wait();
            panic!("stopped at {peak} KiB after {:?}", start.elapsed());
        }
        std::thread::sleep(Duration::from_millis(5));
    }
}

#[test]
fn stats_reads_cost_records_as_regular_files_only() {
    let (dir, m) = project(&circle_manifest(""));
    let (code, _, err) = run(&[&m, &"-q"]);
    assert_eq!(code, Some(0), "{err}");
    let records = dir.path().join("frames/.whitted-record");
    let three = records.join("frame_0003.png.cost.json");
    std::fs::remove_file(&three).unwrap();
    std::os::unix::fs::symlink("/dev/zero", &three).unwrap();
    let five = records.join("frame_0005.png.cost.json");
    std::fs::remove_file(&five).unwrap();
    mkfifo(&five);
    // A link to a record of another frame is not a record either.
    let seven = records.join("frame_0007.png.cost.json");
    std::fs::remove_file(&seven).unwrap();
    std::os::unix::fs::symlink(records.join("frame_0001.png.cost.json"), &seven).unwrap();
    let mut cmd = Command::new(assert_cmd::cargo::cargo_bin("animate"));
    cmd.arg("stats").arg(&m);
    let (code, peak, secs) = bounded(&mut cmd, Duration::from_secs(30), 300 << 10);
    println!(
        "stats with a record linked to /dev/zero: {} MiB, {secs:.2} s",
        peak >> 10
    );
    assert_eq!(code, Some(0));
    assert!(peak < 100 << 10, "{peak} KiB");
    let out = animate()
        .args(["stats", "--json"])
        .arg(&m)
        .output()
        .unwrap();
    let doc: serde_json::Value = serde_json::from_slice(&stdout_ok(out)).unwrap();
    assert_eq!(doc["totals"]["frames"], 9);
    assert_eq!(doc["without_cost"], "3,5,7");
}

#[test]
fn a_draft_of_frames_in_the_manifests_folder_stays_inside_it() {
    // dir = "." and dir = ".." from a manifest in `shot/`: both drafts in `shot/`.
    let (dir, _) = project("");
    let shot = dir.path().join("shot");
    std::fs::create_dir(&shot).unwrap();
    std::fs::copy(dir.path().join("scene.txt"), shot.join("scene.txt")).unwrap();
    for (name, folder) in [("here.toml", "."), ("up.toml", "..")] {
        let m = shot.join(name);
        let text = circle_manifest("").replace("dir = \"frames\"", &format!("dir = \"{folder}\""));
        std::fs::write(&m, text.replace("frame_####", "f_####")).unwrap();
        let (code, _, err) = run(&[&m, &"-q", &"--size", &"16x12", &"--frames", &"0-1"]);
        assert_eq!(code, Some(0), "{name}: {err}");
        let stem = name.trim_end_matches(".toml");
        let draft = shot.join(format!("{stem}-draft-16x12"));
        assert!(
            draft.join("f_0000.png").is_file(),
            "{name}: {:?}",
            entries(&shot)
        );
    }
    assert!(!dir.path().join("-draft-16x12").exists());
    assert!(!dir.path().parent().unwrap().join("-draft-16x12").exists());
    assert!(!dir.path().join("shot-draft-16x12").exists());
    // A folder named with `.` steps is read without them.
    let m = shot.join("dots.toml");
    let text = circle_manifest("").replace("dir = \"frames\"", "dir = \"renders/./b/..\"");
    std::fs::write(&m, text).unwrap();
    let (code, _, err) = run(&[&m, &"-q", &"--size", &"16x12", &"--frames", &"0"]);
    assert_eq!(code, Some(0), "{err}");
    assert!(shot.join("renders-draft-16x12/frame_0000.png").is_file());
}
