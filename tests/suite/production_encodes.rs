//! Safe encodes, through the built `animate encode`: a folder with drafts among finals,
//! missing or broken frames is refused before ffmpeg starts, with the frames named;
//! `--allow-mixed` takes sound mixed frames, never missing or broken ones.

use crate::{skip, support};

use support::*;

fn encode(manifest: &std::path::Path, args: &[&str]) -> (Option<i32>, String) {
    let out = animate()
        .arg("encode")
        .arg(manifest)
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn drafts_among_finals_and_broken_frames_are_refused_with_the_frames_named() {
    let (dir, manifest) = project(&circle_manifest(""));
    let frames = dir.path().join("frames");
    render_into(&manifest, &frames, &["-q"]);
    render_into(
        &manifest,
        &frames,
        // Over the finals: forced (reliability round four, point 6).
        &["-q", "--size", "64x48", "--frames", "2-3", "--force"],
    );
    let (code, err) = encode(&manifest, &[]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("drafts mixed with finals 2-3"), "{err}");
    assert!(err.contains("--allow-mixed"), "{err}");
    assert!(!dir.path().join("frames.mp4").exists());
    // A missing and a cut-short frame are refused even with --allow-mixed.
    std::fs::remove_file(frames.join("frame_0005.png")).unwrap();
    let cut = std::fs::read(frames.join("frame_0007.png")).unwrap();
    std::fs::write(frames.join("frame_0007.png"), &cut[..cut.len() / 2]).unwrap();
    let (code, err) = encode(&manifest, &["--allow-mixed"]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("missing 5") && err.contains("broken 7"),
        "{err}"
    );
    assert!(!err.contains("drafts mixed"), "{err}");
}

#[test]
fn allow_mixed_encodes_sound_mixed_frames() {
    if !skip::ffmpeg() {
        return;
    }
    let (dir, manifest) = project(&circle_manifest(""));
    let frames = dir.path().join("frames");
    render_into(&manifest, &frames, &["-q"]);
    render_into(
        &manifest,
        &frames,
        // Over the finals: forced (reliability round four, point 6).
        &["-q", "--size", "64x48", "--frames", "2-3", "--force"],
    );
    let (code, err) = encode(&manifest, &["--allow-mixed", "-q"]);
    assert_eq!(code, Some(0), "{err}");
    assert!(dir.path().join("frames.mp4").is_file());
    // A draft folder encodes with the same overrides: its frames are not mixed.
    animate()
        .arg(&manifest)
        .args(["-q", "--scale", "2"])
        .assert()
        .success();
    let (code, err) = encode(&manifest, &["-q", "--scale", "2"]);
    assert_eq!(code, Some(0), "{err}");
    assert!(dir.path().join("frames-draft-32x24.mp4").is_file());
}
