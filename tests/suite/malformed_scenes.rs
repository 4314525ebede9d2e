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
struct Case {
    name: &'static str,
    /// The file's bytes, with one `@` before the offending token.
    src: Vec<u8>,
    /// The structural context the message must contain.
    context: &'static str,
    /// A piece of the message saying what was wrong or expected.
    message: &'static str,
}

fn case(name: &'static str, lines: &[&str], context: &'static str, message: &'static str) -> Case {
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

fn cases() -> Vec<Case> {
    // The valid records the cases are made of.
    const SPHERE: &str = "1 0 1 0   1 1 0 0   0.7 0.3 0 1 0 0";
    const PLANE: &str = "0 0 0  0 1 0   1 0.5 0.5 0.5   1 0 0 1 0 0";
    const CYLINDER: &str = "0 1 0  3 0 -2  0.5   1 0 1 0   0.8 0 0 1 0 0";
    const LIGHT: &str = "5 10 5  1 1 1  1";
    let mut non_utf8 = b"40 30\n0 2 10   # cam@".to_vec();
    non_utf8.push(0xE9); // 'é' in Latin-1
    non_utf8.extend_from_slice(b"ra\n0 1 0\n0 20\n0 0 0 0\n");
    let mut raw_byte = b"40 30\n0 2 @".to_vec();
    raw_byte.extend_from_slice(&[0xFF, b'1', b'0']);
    raw_byte.extend_from_slice(b"\n0 1 0\n0 20\n0 0 0 0\n");

    vec![
        case(
            "nan",
            &["40 30", "0 @nan 10", "0 1 0", "0 20", "0 0 0 0"],
            "camera position, field y",
            "finite number",
        ),
        case(
            "inf",
            &[
                "40 30",
                "0 2 10",
                "0 1 0",
                "0 20",
                "1 0 0 1",
                "1 0 1 @inf   1 1 0 0   0.7 0.3 0 1 0 0",
                LIGHT,
            ],
            "sphere 1 of 1, field Cz",
            "finite number",
        ),
        case(
            "a literal that overflows to infinity",
            &[
                "40 30",
                "0 2 10",
                "0 1 0",
                "0 20",
                "0 0 0 1",
                "5 10 5  1 1 1  @1e999",
            ],
            "light 1 of 1, field Intensity",
            "finite number",
        ),
        case(
            "-inf in a plane normal",
            &[
                "40 30",
                "0 2 10",
                "0 1 0",
                "0 20",
                "0 1 0 1",
                "0 0 0  0 @-inf 0   1 0.5 0.5 0.5   1 0 0 1 0 0",
                LIGHT,
            ],
            "plane 1 of 1, field Ny",
            "finite number",
        ),
        case(
            "a word instead of a number",
            &[
                "40 30",
                "0 2 10",
                "0 1 0",
                "0 20",
                "0 0 0 1",
                "5 10 5  1 @green 1  1",
            ],
            "light 1 of 1, field G",
            "expected a number",
        ),
        case(
            "a decimal comma",
            &[
                "40 30",
                "0 2 10",
                "0 1 0",
                "0 20",
                "1 0 0 1",
                "1 0 1 0   1 1 0 0   @0,7 0.3 0 1 0 0",
                LIGHT,
            ],
            "sphere 1 of 1, material, field Kd",
            "expected a number",
        ),
        case(
            "non-integer count",
            &["40 30", "0 2 10", "0 1 0", "0 20", "@2.5 0 0 1", LIGHT],
            "counts, field NSpheres",
            "not an integer",
        ),
        case(
            "negative count",
            &["40 30", "0 2 10", "0 1 0", "0 20", "0 0 0 @-1"],
            "counts, field NLights",
            "a count from 0",
        ),
        case(
            "a word for a count",
            &["40 30", "0 2 10", "0 1 0", "0 20", "0 @two 0 1", LIGHT],
            "counts, field NPlanes",
            "not a number",
        ),
        case(
            "non-integer resolution",
            &["@640.0 480", "0 2 10", "0 1 0", "0 20", "0 0 0 0"],
            "resolution, field ResX",
            "not an integer",
        ),
        case(
            "resolution 0",
            &["640 @0", "0 2 10", "0 1 0", "0 20", "0 0 0 0"],
            "resolution, field ResY",
            "an integer from 1 to 16384",
        ),
        case(
            "resolution past 16384",
            &["@16385 2", "0 2 10", "0 1 0", "0 20", "0 0 0 0"],
            "resolution, field ResX",
            "an integer from 1 to 16384",
        ),
        case(
            "past 2^26 pixels",
            &["8193   @8192", "0 2 10", "0 1 0", "0 20", "0 0 0 0"],
            "resolution, field ResY",
            "2^26",
        ),
        case(
            "radius 0",
            &[
                "40 30",
                "0 2 10",
                "0 1 0",
                "0 20",
                "3 0 0 1",
                SPHERE,
                "@0 2 1 0   1 1 0 0   0.7 0.3 0 1 0 0",
                SPHERE,
                LIGHT,
            ],
            "sphere 2 of 3, field Radius",
            "Radius must be greater than 0",
        ),
        case(
            "negative radius",
            &[
                "40 30",
                "0 2 10",
                "0 1 0",
                "0 20",
                "0 0 1 1",
                "0 1 0  3 0 -2  @-0.5   1 0 1 0   0.8 0 0 1 0 0",
                LIGHT,
            ],
            "cylinder 1 of 1, field Radius",
            "Radius must be greater than 0",
        ),
        case(
            "zero-length plane normal",
            &[
                "40 30",
                "0 2 10",
                "0 1 0",
                "0 20",
                "0 1 0 1",
                "0 0 0  @0 0.0 -0   1 0.5 0.5 0.5   1 0 0 1 0 0",
                LIGHT,
            ],
            "plane 1 of 1, field Nx",
            "zero length",
        ),
        case(
            "zero-length cylinder axis",
            &[
                "40 30",
                "0 2 10",
                "0 1 0",
                "0 20",
                "0 0 2 1",
                CYLINDER,
                "@0 0 0  3 0 -2  0.5   1 0 1 0   0.8 0 0 1 0 0",
                LIGHT,
            ],
            "cylinder 2 of 2, field Ax",
            "zero length",
        ),
        case(
            "unknown texture marker",
            &[
                "40 30",
                "0 2 10",
                "0 1 0",
                "0 20",
                "1 0 0 1",
                "1 0 1 0   @4 1 0 0   0.7 0.3 0 1 0 0",
                LIGHT,
            ],
            "sphere 1 of 1, texture, field kind",
            "1 (one colour), 2 (procedural) or 3 (image)",
        ),
        case(
            "unknown texture type",
            &[
                "40 30",
                "0 2 10",
                "0 1 0",
                "0 20",
                "0 1 0 1",
                "0 0 0  0 1 0   2 @5 1 1 1  0 0 0  0 0 0   1 0 0 1 0 0",
                LIGHT,
            ],
            "plane 1 of 1, texture, field Type",
            "4 (marble)",
        ),
        case(
            "non-integer texture type",
            &[
                "40 30",
                "0 2 10",
                "0 1 0",
                "0 20",
                "0 1 0 1",
                "0 0 0  0 1 0   2 @2.0 1 1 1  0 0 0  0 0 0   1 0 0 1 0 0",
                LIGHT,
            ],
            "plane 1 of 1, texture, field Type",
            "not an integer",
        ),
        case(
            "unknown bump type",
            &[
                "40 30",
                "0 2 10",
                "0 1 0",
                "0 20",
                "0 0 1 1",
                "0 1 0  3 0 -2  0.5   1 0 1 0   0.8 0 0 1 @3 0",
                LIGHT,
            ],
            "cylinder 1 of 1, material, field BumpType",
            "2 (plane/water)",
        ),
        case(
            "Ior 0",
            &[
                "40 30",
                "0 2 10",
                "0 1 0",
                "0 20",
                "1 0 0 1",
                "1 0 1 0   1 1 0 0   0.1 0.2 0.7 @0 0 0",
                LIGHT,
            ],
            "sphere 1 of 1, material, field Ior",
            "Ior must be greater than 0",
        ),
        case(
            "unknown fog type",
            &["40 30", "0 2 10", "0 1 0", "@4 20", "0 0 0 0"],
            "fog, field FogType",
            "0 (none), 1, 2 or 3",
        ),
        case(
            "fog distance 0 with fog",
            &["40 30", "0 2 10", "0 1 0", "1 @0", "0 0 0 0"],
            "fog, field FogDistance",
            "FogDistance must be greater than 0",
        ),
        case(
            "negative fog distance with fog",
            &["40 30", "0 2 10", "0 1 0", "3    @-5.5", "0 0 0 0"],
            "fog, field FogDistance",
            "FogDistance must be greater than 0",
        ),
        case(
            "camera on the look-at point",
            &["40 30", "0 2 10", "@0.0 2.0 1e1", "0 20", "0 0 0 0"],
            "point looked at, field x",
            "the camera is placed on the point it looks at",
        ),
        case(
            "end of file mid-sphere, in its texture",
            &[
                "40 30",
                "0 2 10",
                "0 1 0",
                "0 20",
                "2 0 0 1",
                SPHERE,
                "1.0 0.0 2.0 9.0 2 2 0.5 0.5 0.5@",
                "",
            ],
            "sphere 2 of 2, texture, field C2.r",
            "found the end of the file",
        ),
        case(
            "end of file mid-sphere, after blanks and a comment",
            &[
                "40 30",
                "0 2 10",
                "0 1 0",
                "0 20",
                "1 0 0 1",
                "1 0 1@   # the centre is cut short\n   ",
            ],
            "sphere 1 of 1, field Cz",
            "found the end of the file",
        ),
        case(
            "too few lights",
            &[
                "40 30", "0 2 10", "0 1 0", "0 20", "1 1 1 2", SPHERE, PLANE, CYLINDER,
                "5 10 5  1 1 1  1@", "",
            ],
            "light 2 of 2, field Lx",
            "found the end of the file",
        ),
        case(
            "extra tokens after the last light",
            &[
                "40 30", "0 2 10", "0 1 0", "0 20", "1 1 1 1", SPHERE, PLANE, CYLINDER, LIGHT,
                "  @oops",
            ],
            "after the last light",
            "unknown keyword 'oops'",
        ),
        // Issue 16 item 4: a record that runs into the next section is put on the count
        // that announced it, saying what the count announced.
        case(
            "a second light the counts forgot",
            &[
                "40 30",
                "0 2 10",
                "0 1 0",
                "0 20",
                "1 1 1 @1",
                SPHERE,
                PLANE,
                CYLINDER,
                LIGHT,
                "# a second light the counts forgot",
                "  -5 10 5  1 1 1  1",
            ],
            "counts, field NLights",
            "the counts announce 1 light, but line 11, after the last record, holds 7 values, as a light does: should NLights be 2",
        ),
        case(
            "five spheres announced, four given",
            &[
                "40 30", "0 2 10", "0 1 0", "0 20", "@5 1 0 1", SPHERE, SPHERE, SPHERE, SPHERE,
                PLANE, LIGHT,
            ],
            "counts, field NSpheres",
            "the counts announce 5 spheres, but line 10, read as sphere 5 of 5, holds 16 values, as a plane does: is a sphere missing, or should NSpheres be 4? (the error there, 10:1: Radius must be greater than 0, found '0')",
        ),
        case(
            "a sphere the counts forgot, read as a cylinder",
            &[
                "40 30", "0 2 10", "0 1 0", "0 20", "@1 0 1 1", SPHERE, SPHERE, CYLINDER, LIGHT,
            ],
            "counts, field NSpheres",
            "the counts announce 1 sphere, but line 7, read as cylinder 1 of 1, holds 14 values, as a sphere does: should NSpheres be 2, or is this sphere out of place?",
        ),
        case(
            "a wrong record that fits no kind stays where it is",
            &[
                "40 30", "0 2 10", "0 1 0", "0 20", "2 0 0 0", SPHERE, "@-1 0 1 0   1 1 0 0   0.7 0.3 0 1 0",
            ],
            "sphere 2 of 2, field Radius",
            "Radius must be greater than 0",
        ),
        Case {
            name: "a Latin-1 byte in a comment",
            src: non_utf8,
            context: "byte that cannot be read",
            message: "not UTF-8",
        },
        Case {
            name: "a stray 0xFF byte",
            src: raw_byte,
            context: "byte that cannot be read",
            message: "not UTF-8",
        },
        // A value missing from a record's line: at the end of that line, however far on
        // the error surfaces (in the header, the next record, two records on).
        case(
            "a camera position short of z",
            &["40 30", "0 2@", "0 1 0", "0 20", "0 0 0 0"],
            "camera position, field z",
            "z is missing at the end of this line: the camera position has 2 values here, so reading on took '0' from line 3 for it (and then failed at 4:3: expected 0 (none), 1, 2 or 3 for FogType, found '20')",
        ),
        case(
            "a sphere short of its BumpValue",
            &[
                "40 30", "0 2 10", "0 1 0", "0 20", "2 0 0 1", "1 0 1 0   1 1 0 0   0.7 0.3 0 1 0@",
                SPHERE, LIGHT,
            ],
            "sphere 1 of 2, material, field BumpValue",
            "BumpValue is missing at the end of this line: the sphere 1 of 2 has 13 values here, so reading on took '1' from line 7",
        ),
        case(
            "a cylinder short of a value, failing two lines on",
            &[
                "40 30", "0 2 10", "0 1 0", "0 20", "0 0 1 2",
                "0 1 0  3 0 -2  0.5   1 0 1 0   0.8 0 0 1 0@", LIGHT, "-6 8 4  0.6 0.6 0.8  0.6",
            ],
            "cylinder 1 of 1, material, field BumpValue",
            "reading on took '5' from line 7 for it (and then failed at 8:1: Intensity must be from 0 to 1000, found '-6')",
        ),
        case(
            "records laid out otherwise keep the error at its token",
            &["40 30 0 2 10 0 1 0", "1 @-5", "0 0 0 0"],
            "fog, field FogDistance",
            "FogDistance must be greater than 0 with fog, found '-5'",
        ),
        case(
            "a record written over two lines is not a missing value",
            &[
                "40 30", "0 2 10", "0 1 0", "0 20", "2 0 0 1", "1 0 1 0   1 1 0 0",
                "0.7 0.3 0 1 0 0", "@-1 0 1 0   1 1 0 0   0.7 0.3 0 1 0 0", LIGHT,
            ],
            "sphere 2 of 2, field Radius",
            "Radius must be greater than 0, found '-1'",
        ),
        case(
            "an empty file",
            &["@"],
            "resolution, field ResX",
            "found the end of the file",
        ),
        case(
            "a file of comments only",
            &["# Scene.txt", "  # nothing yet", "@"],
            "resolution, field ResX",
            "found the end of the file",
        ),
    ]
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
