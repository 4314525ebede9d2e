//! Manifests: every manifest of animations/ cut, thinned and given nasty values; a
//! parsed one must be usable, a refused one located.

use super::*;
#[allow(unused_imports)]
use super::{findings::*, manifest_properties::*, properties::*, seeds::*, tracks::*};

use whitted_anim::{Manifest, ManifestError};

/// The name manifests are parsed under (never read: `parse` takes the text).
pub(super) const MANIFEST_PATH: &str = "anims/fuzz.toml";

/// A parsed manifest is usable: every frame's camera is finite and every frame has a
/// file name, including frames outside the sequence.
pub(super) fn exercise_manifest(m: &Manifest) -> Result<(), String> {
    let n = m.frames;
    for frame in [
        0,
        1,
        n / 3,
        n / 2,
        n.saturating_sub(1),
        n,
        n.saturating_add(7),
        u32::MAX,
    ] {
        if let Some(camera) = &m.camera {
            let (eye, look) = camera.at(f64::from(frame), n, glam::DVec3::new(0.5, -1.0, 2.0));
            if !eye.is_finite() || !look.is_finite() {
                return Err(format!("frame {frame} of {n}: eye {eye}, look-at {look}"));
            }
        }
        let name = m.output.file_name(frame, n);
        if name.is_empty() || name.contains('/') {
            return Err(format!("frame {frame}: file name {name:?}"));
        }
    }
    if !(m.fps.is_finite() && m.fps > 0.0) {
        return Err(format!("fps {}", m.fps));
    }
    Ok(())
}

/// An `Invalid` error (or each line of an `Unknown` one) names the manifest, and its line
/// and column are inside the text.
pub(super) fn check_manifest_error(src: &str, err: &ManifestError) -> Result<(), String> {
    let shown = err.to_string();
    let entries: Vec<(&whitted::fileloc::FileLoc, &String)> = match err {
        ManifestError::Invalid { loc, message } => vec![(loc, message)],
        ManifestError::Unknown(found) => found.iter().map(|(l, m)| (l, m)).collect(),
        ManifestError::Io { .. } => return Err(format!("parsing text gave an I/O error: {shown}")),
    };
    let several = matches!(err, ManifestError::Unknown(_));
    if entries.is_empty() || (several && entries.len() != shown.lines().count()) {
        return Err(format!("not one line per error: {shown}"));
    }
    for ((loc, message), shown) in entries.into_iter().zip(shown.lines()) {
        check_located_line(src, loc, message, shown)?;
    }
    Ok(())
}

pub(super) fn check_located_line(
    src: &str,
    loc: &whitted::fileloc::FileLoc,
    message: &str,
    shown: &str,
) -> Result<(), String> {
    let (path, line, column) = (&loc.file, loc.line, loc.column);
    if path != MANIFEST_PATH {
        return Err(format!("the error names {path:?}: {shown}"));
    }
    let prefix = format!("{MANIFEST_PATH}:{line}:{column}: ");
    if !shown.starts_with(&prefix) {
        return Err(format!(
            "the message does not start with {prefix:?}: {shown}"
        ));
    }
    if message.trim().is_empty() {
        return Err(format!("an empty message: {shown}"));
    }
    let lines: Vec<&str> = src.split('\n').collect();
    let inside = line >= 1
        && line <= lines.len()
        && column >= 1
        && column <= lines[line - 1].chars().count() + 1;
    if inside {
        Ok(())
    } else {
        Err(format!("{line}:{column} is outside the input: {shown}"))
    }
}

/// Parses manifest text under the deadline: a usable manifest or a located error.
pub(super) fn manifest_ok_or_located(src: String) -> Result<bool, String> {
    let shown = src.clone();
    bounded(
        move || match Manifest::parse(&src, Path::new(MANIFEST_PATH)) {
            Ok(m) => exercise_manifest(&m).map(|()| true),
            Err(e) => check_manifest_error(&src, &e).map(|()| false),
        },
    )
    .and_then(|r| r)
    .map_err(|e| format!("{e}\n--- manifest ---\n{shown}\n---"))
}

pub(super) const CIRCLE: &str = r#"scene = "../scenes/orbit.txt"
frames = 250
fps = 25

[camera]
path = "circle"
center = [0.0, 1.0, 0.0]
radius = 12.0
height = 3.0
start_angle = 0.0
turns = 1.0
look_at = [0.0, 0.5, 0.0]

[output]
dir = "../out/orbit"
name = "frame_####"
format = "jpeg"
jpeg_quality = 90

[render]
width = 320
height = 240
samples = 2

[check]
frames = [0, 62, 125, 187, 249]
references = "../tests/golden/orbit"
fail = 2
fail_percent = 0.1
hard_fail = 64
"#;

pub(super) const SPLINE_KEYS_LOOK: &str = r#"scene = "s.txt"
frames = 10
[camera]
path = "spline"
closed = false
constant_speed = true
keys = [
  { frame = 0, position = [0.0, 3.0, 12.0], look_at = [0.0, 1.0, 0.0] },
  { frame = 4, position = [0.0, 3.0, 12.0], look_at = [0.0, 1.0, 0.0] },
  { frame = 9, position = [1e9, -1e9, 0.0], look_at = [1.0, 1.0, 1.0] },
]
"#;

pub(super) const SPLINE_TABLES: &str = r#"scene = "s.txt"
frames = 3
[camera]
path = "spline"
closed = true
constant_speed = true
look_at = [0, 0, 0]
[[camera.keys]]
frame = 0
position = [1, 2, 3]
[[camera.keys]]
frame = 1
position = [1, 2, 3]
[output]
format = "raw"
name = "x"
"#;

/// The seed manifests: the embedded ones and the shipped manifests (tests/shipped).
pub(super) fn manifest_seeds() -> Vec<String> {
    let mut out = vec![
        CIRCLE.to_string(),
        SPLINE_KEYS_LOOK.to_string(),
        SPLINE_TABLES.to_string(),
        TRACKS.to_string(),
    ];
    let files = shipped::animations();
    out.extend(files.iter().filter_map(|p| std::fs::read_to_string(p).ok()));
    out
}

#[test]
fn every_manifest_seed_parses() {
    for src in manifest_seeds() {
        let m = Manifest::parse(&src, Path::new(MANIFEST_PATH))
            .unwrap_or_else(|e| panic!("{e}\n{src}"));
        exercise_manifest(&m).unwrap();
    }
}

#[test]
fn every_line_prefix_and_line_deletion_of_every_manifest_is_handled() {
    for src in manifest_seeds() {
        let lines: Vec<&str> = src.split_inclusive('\n').collect();
        for k in 0..=lines.len() {
            for variant in [
                lines[..k].concat(),
                lines[..k].concat() + lines.get(k).map_or("", |l| &l[..l.len() / 2]),
                lines
                    .iter()
                    .enumerate()
                    .filter(|&(i, _)| i != k)
                    .map(|(_, l)| *l)
                    .collect(),
            ] {
                if !variant.is_char_boundary(variant.len()) {
                    continue;
                }
                manifest_ok_or_located(variant).unwrap_or_else(|e| panic!("{e}"));
            }
        }
    }
}

/// Values that break each kind of manifest field.
pub(super) const NASTY_VALUES: &[&str] = &[
    "nan",
    "-nan",
    "inf",
    "-inf",
    "1e308",
    "-1.7976931348623157e308",
    "5e-324",
    "0",
    "-1",
    "0.0",
    "-0.0",
    "9223372036854775807",
    "-9223372036854775808",
    "4294967296",
    "1000001",
    "16385",
    "0x7fffffff",
    "1_000",
    "true",
    "\"\"",
    "\"é\"",
    "\"../\"",
    "\"a/b\"",
    "\"\\u0000\"",
    "\"####\"",
    "\"#\"",
    "'spline'",
    "'circle'",
    "[]",
    "[[]]",
    "[1e9, -1e9, 1e9]",
    "[1e10, 0, 0]",
    "[nan, 0, 0]",
    "[0, 0]",
    "[0, 0, 0, 0]",
    "[\"a\", 1, 2]",
    "{}",
    "{ frame = 0 }",
    "{ frame = -1, position = [0, 0, 0] }",
    "[{ frame = 0, position = [0, 0, 0] }]",
    "[{ frame = 5, position = [0, 0, 0] }, { frame = 5, position = [1, 1, 1] }]",
    "1979-05-27T07:32:00Z",
    "07:32:00",
];

#[test]
fn every_value_of_every_manifest_replaced_by_every_nasty_value_is_handled() {
    for src in manifest_seeds().iter().take(3) {
        let lines: Vec<&str> = src.split_inclusive('\n').collect();
        for (k, line) in lines.iter().enumerate() {
            let Some(eq) = line.find('=') else { continue };
            for nasty in NASTY_VALUES {
                let mut out: String = lines[..k].concat();
                out += &line[..=eq];
                out += " ";
                out += nasty;
                out += "\n";
                out += &lines[k + 1..].concat();
                manifest_ok_or_located(out).unwrap_or_else(|e| panic!("{e}"));
            }
        }
    }
}

/// The keys a manifest knows, and a few it does not.
pub(super) const KEYS: &[&str] = &[
    "scene",
    "frames",
    "fps",
    "path",
    "center",
    "radius",
    "height",
    "start_angle",
    "turns",
    "look_at",
    "closed",
    "constant_speed",
    "keys",
    "frame",
    "position",
    "dir",
    "name",
    "format",
    "jpeg_quality",
    "width",
    "samples",
    "references",
    "fail",
    "fail_percent",
    "hard_fail",
    "camera",
    "output",
    "render",
    "check",
    "camera.path",
    "\"quoted key\"",
    "'lit'",
    "é",
    "\"\"",
];

pub(super) const TABLES: &[&str] = &[
    "[camera]",
    "[output]",
    "[render]",
    "[check]",
    "[[camera.keys]]",
    "[camera.keys]",
    "[[check]]",
    "[ camera ]",
    "[camera.extra]",
    "[other]",
    "[]",
    "[[]]",
    "[camera",
];
