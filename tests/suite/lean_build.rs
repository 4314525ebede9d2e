//! The house's boundaries, as cargo sees them: `raytrace` is built without the
//! animation pipeline, the tracer's own tree stays small, and the tracer builds and
//! renders with no default feature.
//!
//! The tree counts are `cargo tree` over the lock file (`--offline`: nothing is fetched;
//! unique names and versions, build and normal edges). The lean build is `#[ignore]`d:
//! it compiles the tracer's dependencies once more in a target folder of its own (about
//! a minute and a half on two cores); `.ci/run` runs it with `--ignored`.

use std::collections::BTreeSet;
use std::path::Path;
use std::process::Command;

fn cargo() -> Command {
    let mut c = Command::new(std::env::var("CARGO").unwrap_or_else(|_| "cargo".into()));
    c.current_dir(env!("CARGO_MANIFEST_DIR"));
    c
}

/// The crates (name and version) in `cargo tree ARGS -e normal`, the package included.
fn tree(args: &[&str]) -> BTreeSet<String> {
    let out = cargo()
        .args(["tree", "--offline", "-e", "normal", "--prefix", "none"])
        .args(args)
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    text.lines()
        .filter_map(|l| {
            let mut words = l.split_whitespace();
            Some(format!("{} {}", words.next()?, words.next()?))
        })
        .collect()
}

fn names(crates: &BTreeSet<String>) -> BTreeSet<&str> {
    crates.iter().filter_map(|c| c.split(' ').next()).collect()
}

#[test]
fn raytrace_alone_is_built_without_the_pipeline() {
    let lean = tree(&["-p", "whitted-cli", "--no-default-features"]);
    let lean = names(&lean);
    assert!(
        lean.contains("whitted") && lean.contains("whitted-cmd"),
        "{lean:?}"
    );
    for pipeline in ["whitted-anim", "plotters", "notify", "toml"] {
        assert!(!lean.contains(pipeline), "{pipeline} in {lean:?}");
    }
    // With the default features the package has both binaries, and the pipeline.
    assert!(names(&tree(&["-p", "whitted-cli"])).contains("whitted-anim"));
}

#[test]
fn the_tracers_tree_is_small_and_free_of_the_pipeline() {
    let full = tree(&["-p", "whitted"]);
    let lean = tree(&["-p", "whitted", "--no-default-features"]);
    assert!(full.len() <= 95, "{} crates: {full:?}", full.len());
    assert!(lean.len() <= 60, "{} crates: {lean:?}", lean.len());
    for part in ["exr", "zune-jpeg"] {
        assert!(names(&full).contains(part), "{part} missing by default");
        assert!(!names(&lean).contains(part), "{part} in the lean tree");
    }
    for pipeline in ["whitted-anim", "whitted-cmd", "toml", "plotters"] {
        assert!(
            !names(&full).contains(pipeline),
            "{pipeline} in the tracer's tree"
        );
    }
}

#[test]
#[ignore = "a build of the tracer with no default feature: .ci/run runs it with --ignored"]
fn the_lean_tracer_builds_and_renders() {
    let target = Path::new(env!("CARGO_TARGET_TMPDIR")).join("lean");
    let run = cargo()
        .args(["run", "--offline", "--release", "-p", "whitted"])
        .args([
            "--no-default-features",
            "--features",
            "examples",
            "--example",
            "lean_render",
            "--target-dir",
        ])
        .arg(&target)
        .output()
        .unwrap();
    let out = String::from_utf8_lossy(&run.stdout);
    let err = String::from_utf8_lossy(&run.stderr);
    assert!(run.status.success(), "{out}{err}");
    assert!(
        out.contains("lean: 64x48, ") && out.contains("3072 primary rays"),
        "{out}"
    );
    assert!(
        out.contains("exr left out (exr), jpeg left out (jpeg)"),
        "{out}"
    );
}
