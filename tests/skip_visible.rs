//! A skipped test shows in the normal output of `cargo test`: this test runs its own test
//! binary, without `--nocapture`, on a test that skips, and reads the `SKIPPED` line.

mod skip;

use std::process::Command;

#[test]
fn a_tool_that_is_missing() {
    // Skips only when the test below asks it to (a stand-in for a missing tool).
    if std::env::var_os("WHITTED_SKIP_DEMO").is_some() {
        skip::skip("the demo tool is missing");
    }
}

#[test]
fn a_skip_is_visible_without_nocapture_and_fails_under_ci() {
    let me = std::env::current_exe().unwrap();
    let run = |ci: bool| {
        let mut cmd = Command::new(&me);
        cmd.args(["--exact", "a_tool_that_is_missing", "--test-threads", "1"])
            .env("WHITTED_SKIP_DEMO", "1")
            .env_remove("CI");
        if ci {
            cmd.env("CI", "1");
        }
        cmd.output().unwrap()
    };
    let out = run(false);
    let text =
        String::from_utf8_lossy(&out.stdout).into_owned() + &String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{text}");
    assert!(
        text.contains("SKIPPED skip_visible::a_tool_that_is_missing: the demo tool is missing"),
        "{text}"
    );
    let out = run(true);
    assert!(
        !out.status.success(),
        "under CI a missing tool fails the test"
    );
}
