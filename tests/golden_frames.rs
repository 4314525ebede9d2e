//! The golden frames: `animate check` on the orbit video's `[check]` frames against the
//! references kept in tests/golden/, at 160×120 (tests/golden/orbit-small.toml) and at full
//! size (animations/orbit.toml). A change to the tracer that moves a pixel past the
//! tolerance fails here; after an intended change, `animate bless` the manifest, look at
//! the new references, and commit them.

use assert_cmd::Command;

fn check(manifest: &str) {
    let root = env!("CARGO_MANIFEST_DIR");
    let out = Command::cargo_bin("animate")
        .unwrap()
        .current_dir(root)
        .args(["check", manifest, "--report"])
        .arg(std::env::temp_dir().join(format!("golden-report-{}", std::process::id())))
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stdout}{stderr}");
    assert_eq!(stdout.matches("PASS").count(), 6, "{stdout}"); // five frames and the verdict
}

#[test]
fn orbit_at_160x120_matches_its_references() {
    check("tests/golden/orbit-small.toml");
}

#[test]
fn orbit_at_full_size_matches_its_references() {
    check("animations/orbit.toml");
}
