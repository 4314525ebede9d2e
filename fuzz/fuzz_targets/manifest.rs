//! Fuzz target: `Manifest::parse` on arbitrary text (bytes decoded lossily), then, for a
//! manifest that parses, its camera and file names on frames in and out of the sequence.
//!
//! A crash is any panic, an I/O error from parsing text, an `Invalid` error (or a line of
//! an `Unknown` one) whose `path:line:column:` is missing or outside the input, a
//! non-finite camera position or look-at point, or a file name that is empty or has a `/`.

#![no_main]

use libfuzzer_sys::fuzz_target;
use std::path::Path;
use whitted_anim::{Manifest, ManifestError};

const PATH: &str = "fuzz/anim.toml";

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    match Manifest::parse(&text, Path::new(PATH)) {
        Ok(m) => exercise(&m),
        Err(e) => check_located(&text, &e),
    }
});

fn check_located(src: &str, err: &ManifestError) {
    let shown = err.to_string();
    let entries: Vec<_> = match err {
        ManifestError::Invalid { loc, .. } => vec![loc],
        ManifestError::Unknown(found) => found.iter().map(|(loc, _)| loc).collect(),
        ManifestError::Io { .. } => panic!("an I/O error from text: {shown}"),
    };
    assert!(!entries.is_empty(), "{shown}");
    for (loc, shown) in entries.into_iter().zip(shown.lines()) {
        let (path, line, column) = (&loc.file, &loc.line, &loc.column);
        assert_eq!(path, PATH);
        assert!(
            shown.starts_with(&format!("{PATH}:{line}:{column}: ")),
            "{shown}"
        );
        let lines: Vec<&str> = src.split('\n').collect();
        assert!(
            *line >= 1
                && *line <= lines.len()
                && *column >= 1
                && *column <= lines[line - 1].chars().count() + 1,
            "outside the input: {shown}"
        );
    }
}

fn exercise(m: &Manifest) {
    let n = m.frames;
    assert!(m.fps.is_finite() && m.fps > 0.0);
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
        let (eye, look) = m.camera.at(frame, n, glam::DVec3::new(0.5, -1.0, 2.0));
        assert!(
            eye.is_finite() && look.is_finite(),
            "frame {frame}: {eye} {look}"
        );
        let name = m.output.file_name(frame, n);
        assert!(!name.is_empty() && !name.contains('/'), "{name:?}");
    }
}
