//! A skipped test shows in the normal output of `cargo test`: this test runs its own test
//! binary, without `--nocapture`, on tests that skip, and reads their `SKIPPED` lines;
//! under `CI` each of them fails instead.

use crate::skip;

use std::process::Command;

#[test]
fn a_tool_that_is_missing() {
    // Skips only when the test below asks it to (a stand-in for a missing tool).
    if std::env::var_os("WHITTED_SKIP_DEMO").is_some() {
        skip::skip("the demo tool is missing");
    }
}

#[test]
fn a_program_that_is_missing() {
    // `have` and `which` on a program no machine has, only when the test below asks.
    if std::env::var_os("WHITTED_SKIP_DEMO").is_some() {
        assert!(!skip::have("whitted-no-such-tool", &["--version"]));
        assert!(skip::which("whitted-no-such-tool", &["/nonexistent/tool"]).is_none());
    }
}

#[test]
fn what_is_there_is_found_without_a_skip_line() {
    assert!(skip::have("sh", &["-c", "true"]));
    assert!(skip::which("sh", &[]).is_some());
    assert!(skip::which("whitted-no-such-tool", &["/bin/sh"]).is_some());
}

/// Runs this test binary on the one test `name` with the demo skip on, under CI or not.
fn run(name: &str, ci: bool) -> (bool, String) {
    let me = std::env::current_exe().unwrap();
    let mut cmd = Command::new(me);
    let name = format!("skip_visible::{name}");
    cmd.args(["--exact", &name, "--test-threads", "1"])
        .env("WHITTED_SKIP_DEMO", "1")
        .env_remove("CI");
    if ci {
        cmd.env("CI", "1");
    }
    let out = cmd.output().unwrap();
    let text =
        String::from_utf8_lossy(&out.stdout).into_owned() + &String::from_utf8_lossy(&out.stderr);
    (out.status.success(), text)
}

#[test]
fn a_skip_is_visible_without_nocapture_and_fails_under_ci() {
    let (ok, text) = run("a_tool_that_is_missing", false);
    assert!(ok, "{text}");
    assert!(
        text.contains("SKIPPED skip_visible::a_tool_that_is_missing: the demo tool is missing"),
        "{text}"
    );
    let (ok, _) = run("a_tool_that_is_missing", true);
    assert!(!ok, "under CI a missing tool fails the test");
}

#[test]
fn have_and_which_skip_visibly_and_fail_under_ci() {
    let (ok, text) = run("a_program_that_is_missing", false);
    assert!(ok, "{text}");
    let name = "SKIPPED skip_visible::a_program_that_is_missing:";
    assert!(
        text.contains(&format!(
            "{name} whitted-no-such-tool --version is not available"
        )),
        "{text}"
    );
    assert!(
        text.contains(&format!("{name} whitted-no-such-tool not found")),
        "{text}"
    );
    let (ok, text) = run("a_program_that_is_missing", true);
    assert!(!ok, "under CI a missing program fails the test: {text}");
    assert!(text.contains("CI must run"), "{text}");
}
