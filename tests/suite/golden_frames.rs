//! The golden frames: `animate check` on the orbit video's `[check]` frames against the
//! references kept in tests/golden/, at 160×120 (tests/golden/orbit-small.toml) and at full
//! size (animations/orbit.toml). A change to the tracer that moves a pixel past the
//! tolerance fails here; after an intended change, `animate bless` the manifest, look at
//! the new references, and commit them.

use assert_cmd::Command;
use quick_junit::Report;

/// Checks `manifest` through every output: the table, JUnit XML and the HTML page.
fn check(manifest: &str) {
    let root = env!("CARGO_MANIFEST_DIR");
    let work = tempfile::tempdir().unwrap();
    let (junit, html) = (work.path().join("golden.xml"), work.path().join("page"));
    let out = Command::cargo_bin("animate")
        .unwrap()
        .current_dir(root)
        .args(["check", manifest, "--report"])
        .arg(work.path().join("report"))
        .arg("--junit")
        .arg(&junit)
        .arg("--html")
        .arg(&html)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stdout}{stderr}");
    assert_eq!(stdout.matches("PASS").count(), 6, "{stdout}"); // five frames and the verdict
    let xml = std::fs::read_to_string(&junit).unwrap();
    let suite = &Report::deserialize_from_str(&xml).unwrap().test_suites[0];
    assert_eq!((suite.tests, suite.failures), (5, 0), "{xml}");
    let page = std::fs::read_to_string(html.join("index.html")).unwrap();
    assert_eq!(page.matches("<tr class=\"pass\">").count(), 5, "{page}");
}

#[test]
fn orbit_at_160x120_matches_its_references() {
    check("tests/golden/orbit-small.toml");
}

#[test]
fn orbit_at_full_size_matches_its_references() {
    check("animations/orbit.toml");
}
