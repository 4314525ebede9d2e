//! `--shard K/N --balance` on animations/turn-to-glass.toml, whose frames differ more than
//! 8× in cost: 4 balanced shards have predicted costs within 10 % of each other where the
//! 4 equal-count shards differ more than 3×; the balanced shards render every frame once,
//! into the bytes of a plain run; `estimate` and `status --json` report the predictions.

use crate::support;

use std::path::Path;
use support::*;
use whitted_anim::frames::balance::{predicted_costs, split};
use whitted_anim::{Animation, Project};

const MANIFEST: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/animations/turn-to-glass.toml");

#[test]
fn balanced_shards_of_a_turn_to_glass_have_equal_predicted_costs() {
    let project = Project::load(Path::new(MANIFEST)).unwrap();
    let anim = Animation::new(&project).unwrap();
    let frames: Vec<u32> = (0..project.manifest.frames).collect();
    let costs = predicted_costs(&anim, &frames).unwrap();
    // The same prediction every time (ray counts, not times).
    assert_eq!(costs, predicted_costs(&anim, &frames).unwrap());
    let (lo, hi) = (costs.iter().min().unwrap(), costs.iter().max().unwrap());
    assert!(*hi >= 8 * lo, "frames differ only {hi}/{lo}");
    let sums = |b: &[usize]| -> Vec<u64> {
        b.windows(2)
            .map(|w| costs[w[0]..w[1]].iter().sum())
            .collect()
    };
    let balanced = sums(&split(&costs, 4));
    // Four shards of equal frame counts (the last takes the rest).
    let equal: Vec<usize> = (0..=4).map(|k| k * frames.len() / 4).collect();
    let equal = sums(&equal);
    let ratio = |s: &[u64]| *s.iter().max().unwrap() as f64 / *s.iter().min().unwrap() as f64;
    assert!(ratio(&balanced) <= 1.10, "balanced {balanced:?}");
    assert!(ratio(&equal) >= 3.0, "equal counts {equal:?}");
}

#[test]
fn balanced_shards_render_every_frame_once_into_the_plain_bytes() {
    // The small manifest of the other farm tests, with a `[render]` size: 12 frames.
    let (dir, manifest) = project(&circle_manifest("\n[render]\nwidth = 48\nheight = 36\n"));
    render_into(&manifest, &dir.path().join("plain"), &[]);
    // Each shard into a folder of its own: no frame is in two of them, and together they
    // are the plain run's files.
    let mut union = std::collections::BTreeMap::new();
    for k in 0..4 {
        let shard = format!("{k}/4");
        let out = dir.path().join(format!("shard{k}"));
        animate()
            .arg(&manifest)
            .args(["--shard", &shard, "--balance", "--quiet", "-o"])
            .arg(&out)
            .assert()
            .success();
        let mine = files(&out);
        assert!(!mine.is_empty(), "shard {shard} rendered nothing");
        for (name, bytes) in mine {
            assert!(
                union.insert(name.clone(), bytes).is_none(),
                "{name} rendered twice (again by shard {shard})"
            );
        }
    }
    let union: Vec<(String, Vec<u8>)> = union.into_iter().collect();
    assert_eq!(union, files(&dir.path().join("plain")));
    // --balance needs a shard.
    animate().arg(&manifest).arg("--balance").assert().code(2);
}

#[test]
fn estimate_and_status_report_the_prediction() {
    let (_dir, manifest) = project(&circle_manifest(""));
    let out = animate()
        .args(["estimate"])
        .arg(&manifest)
        .args(["--shards", "3"])
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{text}");
    assert!(text.starts_with("frames 0-11: "), "{text}");
    assert!(text.contains("3 balanced shards (--balance):"), "{text}");
    assert!(
        text.contains("3 shards of equal frame counts:\n0-3 "),
        "{text}"
    );
    let out = animate()
        .arg("status")
        .arg(&manifest)
        .arg("--json")
        .output()
        .unwrap();
    let doc: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let rays = doc["predicted_rays"].as_object().unwrap();
    assert_eq!(rays.len(), 12);
    assert!(rays["0"].as_u64().unwrap() > 0);
}

/// The most threads process `pid` had at once, sampled every few milliseconds until it
/// ends (Linux: /proc/PID/status).
fn most_threads(child: &mut std::process::Child) -> u32 {
    let mut most = 0;
    while child.try_wait().unwrap().is_none() {
        let status = std::fs::read_to_string(format!("/proc/{}/status", child.id()));
        let now = status.ok().and_then(|s| {
            s.lines()
                .find_map(|l| l.strip_prefix("Threads:"))
                .and_then(|v| v.trim().parse().ok())
        });
        most = most.max(now.unwrap_or(0));
        std::thread::sleep(std::time::Duration::from_millis(2));
    }
    most
}

#[test]
fn the_balance_pre_pass_runs_on_the_threads_pool() {
    // Rayon's global pool would start RAYON_NUM_THREADS threads (and keep them to the
    // end); --threads 1 must be the only pool the run uses, pre-pass included.
    let (dir, manifest) = project(&circle_manifest("\n[render]\nwidth = 256\nheight = 192\n"));
    let mut child = std::process::Command::new(assert_cmd::cargo::cargo_bin("animate"))
        .arg(&manifest)
        .args([
            "--shard",
            "0/2",
            "--balance",
            "--threads",
            "1",
            "--quiet",
            "-o",
        ])
        .arg(dir.path().join("out"))
        .env("RAYON_NUM_THREADS", "48")
        .spawn()
        .unwrap();
    let most = most_threads(&mut child);
    assert!(child.wait().unwrap().success());
    assert!(most > 0, "never sampled the process");
    assert!(most < 16, "{most} threads at once with --threads 1");
}
