//! What each frame cost, through the built `animate`: a cost record beside every frame
//! (never in its bytes, never deciding up-to-date), and `animate stats` (totals, slowest
//! frames, frames off the prediction, the plot).

use crate::support;

use std::path::Path;
use support::*;

fn cost_of(frames: &Path, frame: u32) -> serde_json::Value {
    let path = frames.join(format!(".whitted-record/frame_{frame:04}.png.cost.json"));
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

fn stats_json(manifest: &Path, args: &[&str]) -> serde_json::Value {
    let out = animate()
        .arg("stats")
        .arg(manifest)
        .arg("--json")
        .args(args)
        .output()
        .unwrap();
    serde_json::from_slice(&stdout_ok(out)).unwrap()
}

#[test]
fn every_frame_records_its_cost_beside_it_not_in_it() {
    let (dir, manifest) = project(&circle_manifest(""));
    let (a, b) = (dir.path().join("frames"), dir.path().join("again"));
    render_into(&manifest, &a, &["-q"]);
    render_into(&manifest, &b, &["-q", "--threads", "1"]);
    // Same frame bytes whatever the costs measured (they differ run to run).
    assert_eq!(files(&a), files(&b));
    for f in 0..12 {
        let c = cost_of(&a, f);
        assert_eq!(c["frame"], f);
        for key in ["wall_s", "cpu_s"] {
            assert!(c[key].as_f64().is_some_and(|s| s >= 0.0), "{key}: {c}");
        }
        assert!(
            c["peak_memory_bytes"].as_u64().is_some_and(|b| b > 1 << 20),
            "{c}"
        );
        // 64×48 camera rays at one sample; every kind is named as `raytrace --stats` names it.
        assert_eq!(c["eye"], 64 * 48, "{c}");
        for key in ["eye_hits", "reflect", "refract", "shadow"] {
            assert!(c[key].as_u64().is_some(), "{key}: {c}");
        }
        assert!(c["shadow"].as_u64().unwrap() > 0);
    }
    // A cost record changed or removed does not make a frame stale.
    std::fs::write(a.join(".whitted-record/frame_0003.png.cost.json"), "{}").unwrap();
    std::fs::remove_file(a.join(".whitted-record/frame_0004.png.cost.json")).unwrap();
    animate()
        .args(["status", "-o"])
        .arg(&a)
        .arg(&manifest)
        .assert()
        .success();
    let out = animate()
        .arg(&manifest)
        .args(["--resume", "-o"])
        .arg(&a)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("0 frames rendered, 12 up to date"), "{err}");
    // stats names the two frames whose cost is no longer known.
    let doc = stats_json(&manifest, &["-o", a.to_str().unwrap()]);
    assert_eq!(doc["without_cost"], "3-4");
    assert_eq!(doc["totals"]["frames"], 10);
}

#[test]
fn stats_totals_slowest_and_frames_off_the_prediction() {
    let (dir, manifest) = project(&circle_manifest(""));
    let frames = dir.path().join("frames");
    render_into(&manifest, &frames, &["-q"]);
    // Frame 7 is made to have taken a minute: slowest, and far off its prediction.
    let path = frames.join(".whitted-record/frame_0007.png.cost.json");
    let mut c = cost_of(&frames, 7);
    c["wall_s"] = 60.0.into();
    std::fs::write(&path, c.to_string()).unwrap();
    let plot = dir.path().join("plot.png");
    let doc = stats_json(&manifest, &["--plot", plot.to_str().unwrap()]);
    let sum: f64 = (0..12)
        .map(|f| cost_of(&frames, f)["wall_s"].as_f64().unwrap())
        .sum();
    let t = &doc["totals"];
    assert_eq!(t["frames"], 12);
    assert!((t["wall_s"].as_f64().unwrap() - sum).abs() < 1e-9, "{t}");
    assert_eq!(t["eye"], 12 * 64 * 48);
    let shadow: u64 = (0..12)
        .map(|f| cost_of(&frames, f)["shadow"].as_u64().unwrap())
        .sum();
    assert_eq!(t["shadow"], shadow);
    assert_eq!(doc["slowest"][0]["frame"], 7);
    let off: Vec<u64> = doc["off_prediction"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r["frame"].as_u64().unwrap())
        .collect();
    assert!(off.contains(&7), "{doc}");
    let r = &doc["off_prediction"][off.iter().position(|&f| f == 7).unwrap()];
    assert!(r["ratio"].as_f64().unwrap() > 2.0, "{r}");
    // The predictions add up to the measured total.
    let predicted: f64 = doc["per_frame"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r["predicted_s"].as_f64().unwrap())
        .sum();
    assert!(
        (predicted - sum).abs() < 1e-6 * sum.max(1.0),
        "{predicted} vs {sum}"
    );
    let plot = image::open(&plot).unwrap();
    assert_eq!((plot.width(), plot.height()), (960, 480));
    // The table says the same for people.
    let out = animate().arg("stats").arg(&manifest).output().unwrap();
    let text = String::from_utf8(stdout_ok(out)).unwrap();
    assert!(text.contains("slowest frames:\n  frame 7 "), "{text}");
    assert!(
        text.contains("off the prediction by more than 2x:\n"),
        "{text}"
    );
}

#[test]
fn stats_refuses_bad_input_with_status_2() {
    let (_dir, manifest) = project(&circle_manifest(""));
    let out = animate()
        .arg("stats")
        .arg(&manifest)
        .args(["--frames", "40"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
}
