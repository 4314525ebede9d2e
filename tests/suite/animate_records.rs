//! Frame records that cannot lie, through the built `animate`: kill -9 and concurrent-run
//! trials (seeded) over RAW folders, and corruption inside frames (RAW bytes replaced,
//! PNG data flipped) seen by `status`, `--resume` and `--verify`.

use crate::support;

use std::path::Path;
use std::time::{Duration, Instant};
use support::*;

/// A small deterministic generator (a 64-bit LCG, Knuth's MMIX constants).
struct Lcg(u64);
impl Lcg {
    fn below(&mut self, n: u64) -> u64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 33) % n
    }
}

/// `animate status --json` of `manifest`: the up-to-date frames.
fn up_to_date(manifest: &Path) -> Vec<u32> {
    let out = animate()
        .args(["status", "--json"])
        .arg(manifest)
        .output()
        .unwrap();
    let doc: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let ranges = doc["up_to_date"].as_str().unwrap().to_string();
    if ranges == "-" {
        return vec![];
    }
    whitted_anim::select::parse_frames(&ranges, 1_000_000).unwrap()
}

/// Asserts that every frame `status` calls up to date has the clean render's bytes.
fn no_record_lies(manifest: &Path, frames: &Path, clean: &Path, trial: &str) {
    for f in up_to_date(manifest) {
        let name = format!("frame_{f:04}.raw");
        assert_eq!(
            std::fs::read(frames.join(&name)).unwrap(),
            std::fs::read(clean.join(&name)).unwrap(),
            "{trial}: {name} is called up to date but holds other pixels"
        );
    }
}

#[test]
fn kill_9_and_concurrent_runs_never_leave_a_lying_raw_record() {
    let (dir, _) = project(&circle_manifest(""));
    let a = raw_manifest(dir.path(), "a.toml", 120, 8.0);
    let b = raw_manifest(dir.path(), "b.toml", 120, 9.5);
    let (frames, clean) = (dir.path().join("frames"), dir.path().join("clean"));
    render_into(&a, &clean, &[]);
    let mut rng = Lcg(23);
    let deadline = Instant::now() + Duration::from_secs(60);
    let mut trials = 0;
    for trial in 0..24 {
        if Instant::now() > deadline {
            break;
        }
        render_into(&a, &frames, &["--resume", "--force"]);
        let name = format!("trial {trial} (seed 23)");
        if trial % 2 == 0 {
            // B over A's folder, killed after 5–90 ms.
            let mut child = spawn_animate(&b, &["--force", "--threads", "2"]);
            std::thread::sleep(Duration::from_millis(5 + rng.below(86)));
            child.kill().unwrap();
            child.wait().unwrap();
        } else {
            // A and B at once into one folder: the lock lets one of them in.
            let mut one = spawn_animate(&b, &["--force"]);
            let mut two = spawn_animate(&a, &["--force"]);
            std::thread::sleep(Duration::from_millis(rng.below(60)));
            if rng.below(2) == 0 {
                one.kill().unwrap();
            }
            let (s1, s2) = (one.wait().unwrap(), two.wait().unwrap());
            assert!(
                s1.code() != Some(1) && s2.code() != Some(1),
                "{name}: {s1:?} {s2:?}"
            );
        }
        no_record_lies(&a, &frames, &clean, &name);
        animate()
            .arg(&a)
            .args(["--resume", "--force", "-q"])
            .assert()
            .success();
        assert_eq!(files(&frames), files(&clean), "{name}: --resume");
        trials += 1;
    }
    assert!(trials >= 6, "only {trials} trials in the time allowed");
}

#[test]
fn a_raw_frame_overwritten_with_other_bytes_is_stale() {
    let (dir, _) = project(&circle_manifest(""));
    let a = raw_manifest(dir.path(), "a.toml", 12, 8.0);
    animate().arg(&a).arg("-q").assert().success();
    let frames = dir.path().join("frames");
    let (f3, f4) = (frames.join("frame_0003.raw"), frames.join("frame_0004.raw"));
    std::fs::copy(&f4, &f3).unwrap();
    let garbage: Vec<u8> = (0..64 * 48 * 3).map(|i| (i * 7 % 251) as u8).collect();
    std::fs::write(frames.join("frame_0005.raw"), garbage).unwrap();
    let out = animate().arg("status").arg(&a).output().unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(1), "{text}");
    assert!(text.contains("      stale:       2  3,5\n"), "{text}");
}

#[test]
fn damage_inside_a_png_is_seen_and_verify_decodes() {
    let (dir, manifest) = project(&circle_manifest(""));
    animate().arg(&manifest).arg("-q").assert().success();
    let frames = dir.path().join("frames");
    // 40 flipped bytes inside frame 2's IDAT: its CRC fails.
    let f2 = frames.join("frame_0002.png");
    let mut bytes = std::fs::read(&f2).unwrap();
    let idat = bytes.windows(4).position(|w| w == b"IDAT").unwrap() + 4;
    for b in &mut bytes[idat + 10..idat + 50] {
        *b ^= 0x5A;
    }
    std::fs::write(&f2, bytes).unwrap();
    // Frame 6's compressed data broken and its CRC made right again: only decoding sees it.
    let f6 = frames.join("frame_0006.png");
    let mut bytes = std::fs::read(&f6).unwrap();
    let at = bytes.windows(4).position(|w| w == b"IDAT").unwrap();
    let len = u32::from_be_bytes(bytes[at - 4..at].try_into().unwrap()) as usize;
    for b in &mut bytes[at + 4 + 2..at + 4 + len - 4] {
        *b = 0xFF;
    }
    let crc = crc32fast::hash(&bytes[at..at + 4 + len]);
    bytes[at + 4 + len..at + 8 + len].copy_from_slice(&crc.to_be_bytes());
    std::fs::write(&f6, bytes).unwrap();
    let out = animate().arg("status").arg(&manifest).output().unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("      stale:       1  2\n"), "{text}");
    let out = animate()
        .args(["status", "--verify"])
        .arg(&manifest)
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("      stale:       2  2,6\n"), "{text}");
    animate()
        .arg(&manifest)
        .args(["--resume", "-q"])
        .assert()
        .success();
    // Plain --resume trusts the cheap checks, which frame 6 passes; --verify does not.
    animate()
        .args(["status", "--verify"])
        .arg(&manifest)
        .assert()
        .code(1);
    animate()
        .arg(&manifest)
        .args(["--resume", "--verify", "-q"])
        .assert()
        .success();
    animate()
        .args(["status", "--verify"])
        .arg(&manifest)
        .assert()
        .success();
}
