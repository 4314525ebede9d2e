//! Malformed scenes through the built `raytrace` (SPEC §1 and §6): every one must exit
//! with status 2, name `file:line:column` of the offending token and its place in the
//! structure ("sphere 2 of 3, field Radius"), say what was expected, and write no image.
//!
//! Each scene marks the offending token with `@` (removed before the file is written);
//! the expected line and column are where the marker was. For a scene that ends too
//! early the marker sits at the very end of the text: the error points at the end of
//! the file.

use crate::common;

use common::{entries, raytrace_in, write_file};
use std::path::Path;
use whitted::Scene;

/// One malformed scene.
pub(super) struct Case {
    pub(super) name: &'static str,
    /// The file's bytes, with one `@` before the offending token.
    pub(super) src: Vec<u8>,
    /// The structural context the message must contain.
    pub(super) context: &'static str,
    /// A piece of the message saying what was wrong or expected.
    pub(super) message: &'static str,
}

pub(super) fn case(
    name: &'static str,
    lines: &[&str],
    context: &'static str,
    message: &'static str,
) -> Case {
    Case {
        name,
        src: lines.join("\n").into_bytes(),
        context,
        message,
    }
}

/// The source without its marker, and the 1-based line and column (in characters) of
/// the marker.
fn split_marker(src: &[u8]) -> (Vec<u8>, usize, usize) {
    let at = src
        .iter()
        .position(|&b| b == b'@')
        .expect("every case marks its offending token with @");
    assert_eq!(
        src.iter().filter(|&&b| b == b'@').count(),
        1,
        "one marker per case"
    );
    let before = std::str::from_utf8(&src[..at]).expect("the text before the marker is UTF-8");
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().unwrap().chars().count() + 1;
    let mut clean = src[..at].to_vec();
    clean.extend_from_slice(&src[at + 1..]);
    (clean, line, column)
}

#[test]
fn marker_positions_by_hand() {
    assert_eq!(split_marker(b"@1 2"), (b"1 2".to_vec(), 1, 1));
    assert_eq!(
        split_marker(b"1 2\n\t 3 @x"),
        (b"1 2\n\t 3 x".to_vec(), 2, 5)
    );
    let (_, line, column) = split_marker("é @x".as_bytes());
    assert_eq!((line, column), (1, 3), "columns count characters");
    assert_eq!(split_marker(b"1\n2\n@"), (b"1\n2\n".to_vec(), 3, 1));
}

mod records;
mod values;

// The valid records the cases are made of.
pub(super) const SPHERE: &str = "1 0 1 0   1 1 0 0   0.7 0.3 0 1 0 0";
pub(super) const PLANE: &str = "0 0 0  0 1 0   1 0.5 0.5 0.5   1 0 0 1 0 0";
pub(super) const CYLINDER: &str = "0 1 0  3 0 -2  0.5   1 0 1 0   0.8 0 0 1 0 0";
pub(super) const LIGHT: &str = "5 10 5  1 1 1  1";

/// Every case of the table: values out of their range first, then broken records and files.
fn cases() -> Vec<Case> {
    let mut all = values::cases();
    all.extend(records::cases());
    all
}

#[test]
fn the_table_is_big_enough() {
    assert!(cases().len() >= 20);
}

/// Runs one case through the binary; returns what went wrong, if anything.
fn check_with_binary(case: &Case) -> Vec<String> {
    let (src, line, column) = split_marker(&case.src);
    let dir = tempfile::tempdir().unwrap();
    write_file(dir.path(), "bad.txt", &src);
    let out = raytrace_in(dir.path()).arg("bad.txt").output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    let mut problems = Vec::new();
    if out.status.code() != Some(2) {
        problems.push(format!("exit status {:?}, not 2", out.status.code()));
    }
    let loc = format!("bad.txt:{line}:{column}: ");
    if !stderr.contains(&loc) {
        problems.push(format!("no location {loc:?}"));
    }
    if !stderr.contains(&format!("({})", case.context)) {
        problems.push(format!("no context {:?}", case.context));
    }
    if !stderr.contains(case.message) {
        problems.push(format!("no message {:?}", case.message));
    }
    if stderr.contains("panicked") || stderr.trim().lines().count() != 1 {
        problems.push("not one clear line".to_string());
    }
    if entries(dir.path()) != ["bad.txt"] {
        problems.push(format!("files left behind: {:?}", entries(dir.path())));
    }
    if !problems.is_empty() {
        problems.push(format!("stderr was: {stderr}"));
    }
    problems
}

#[test]
fn every_malformed_scene_is_refused_by_the_binary() {
    let mut failures = Vec::new();
    for case in cases() {
        let problems = check_with_binary(&case);
        if !problems.is_empty() {
            failures.push(format!("{}:\n  {}", case.name, problems.join("\n  ")));
        }
    }
    assert!(failures.is_empty(), "\n{}", failures.join("\n"));
}

#[test]
fn the_library_reports_the_same_locations() {
    let dir = tempfile::tempdir().unwrap();
    for case in cases() {
        let (src, line, column) = split_marker(&case.src);
        let path = write_file(dir.path(), "bad.txt", &src);
        let err = Scene::load(&path).expect_err(case.name);
        let loc = err
            .loc()
            .unwrap_or_else(|| panic!("{}: no location", case.name));
        assert_eq!(
            (loc.line, loc.column),
            (line, column),
            "{}: {err}",
            case.name
        );
        assert_eq!(loc.file, path.display().to_string(), "{}", case.name);
    }
}

/// A valid scene, to show that the failures above come from the defect alone.
const VALID: &str = "40 30\n0 2 10\n0 1 0\n0 20\n1 1 1 1\n\
    1 0 1 0   1 1 0 0   0.7 0.3 0 1 0 0\n\
    0 0 0  0 1 0   1 0.5 0.5 0.5   1 0 0 1 0 0\n\
    0 1 0  3 0 -2  0.5   1 0 1 0   0.8 0 0 1 0 0\n\
    5 10 5  1 1 1  1\n";

#[test]
fn the_valid_base_renders() {
    let dir = tempfile::tempdir().unwrap();
    write_file(dir.path(), "good.txt", VALID);
    raytrace_in(dir.path())
        .args(["good.txt", "--quiet"])
        .assert()
        .success();
    assert_eq!(entries(dir.path()), ["good.png", "good.txt"]);
}

fn assert_refused(dir: &Path, args: &[&str], needle: &str) {
    let before = entries(dir);
    let out = raytrace_in(dir).args(args).output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
    assert!(stderr.contains(needle), "{args:?}: {stderr}");
    assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
    assert_eq!(entries(dir), before, "{args:?} left files behind");
}

#[test]
fn a_missing_scene_file_is_named() {
    let dir = tempfile::tempdir().unwrap();
    assert_refused(dir.path(), &["no/such/scene.txt"], "no/such/scene.txt");
    assert_refused(
        dir.path(),
        &["absent.txt", "-o", "x.png"],
        "absent.txt: cannot read",
    );
    // No argument: the report's Scene.txt in the current folder.
    assert_refused(dir.path(), &[], "Scene.txt");
    // A folder is not a scene.
    std::fs::create_dir(dir.path().join("folder.txt")).unwrap();
    assert_refused(dir.path(), &["folder.txt"], "folder.txt");
}

#[test]
fn an_unknown_output_extension_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    write_file(dir.path(), "good.txt", VALID);
    assert_refused(dir.path(), &["good.txt", "-o", "out.bmp"], "out.bmp");
    assert_refused(
        dir.path(),
        &["good.txt", "-o", "out"],
        "unknown image extension",
    );
    assert_refused(
        dir.path(),
        &["good.txt", "-o", "out.png.tmp"],
        "out.png.tmp",
    );
    assert_eq!(entries(dir.path()), ["good.txt"]);
}
