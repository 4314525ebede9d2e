//! The seeds: every scene of scenes/ and a few embedded ones, and what their prefixes,
//! deletions, duplications and nasty replacements give.

use super::*;
#[allow(unused_imports)]
use super::{findings::*, manifest_properties::*, manifests::*, properties::*, tracks::*};

/// The report's example sphere (SPEC §1), in a scene of its own.
pub(super) const REPORT_SPHERE: &str = "320 240\n0 0 10\n0 0 0\n0 0\n1 0 0 1\n\
1.0 0.0 2.0 9.0 2 2 0.5 0.5 0.5 0.0 0.0 1.0 1.0 1.0 0.0 0.3 0.2 0.0 1.5 0 0.0\n\
5 5 5 1 1 1 1\n";

/// Every record kind, every texture type, both bumps, fog, a slanted glass cylinder.
pub(super) const EVERYTHING: &str = "\
# every feature of the format
64 48       # resolution
0 2.5 10    # eye
0 1 0       # look at
3 25.5      # exponential squared fog
4 2 2 3     # counts
1.2  -1.5 1.2 1   2 2 0.9 0.9 1.0  0.6 0.8 1.0  1 1 1   0.1 0.2 0.7 1.5 0 0
1.0   1.6 1.0 0   2 4 0.9 0.9 0.9  0.2 0.2 0.3  0 0 0   0.4 0.5 0 1 1 0.3
0.8   0 0.8 -3    2 3 0.6 0.3 0.1  0.9 0.6 0.3  0 0 0   0.8 0 0 1 0 0
0.5   3 0.5 2     2 1 1 0 0  0 0 1  0 1 0               1 0 0 1 0 0
0 0 0   0 1 0     2 1 1 1 1  0.1 0.1 0.1  0 0 0      0.7 0.3 0 1 2 0.05
0 0 -12  0 0 1    1 0.4 0.5 0.7                      0.9 0 0 1 0 0
1 1 0   4 0 -4  0.5   1 0.9 0.4 0.4                  0.2 0.1 0.6 1.3 0 0
0 1 0   -4 0 -2  0.3  2 2 1 0 0  0 1 0  0 0 1        0.5 0.5 0 1 1 2
5 10 8   1 1 1   1
-6 6 4   1 0.8 0.6   0.6
0 20 0   0.5 0.5 1   +2
";

/// Nothing but the header: no objects, no lights, linear fog.
pub(super) const EMPTY: &str = "1 1\n0 0 0\n0 0 -1\n1 1e-3\n0 0 0 0";

/// The seed scenes: the embedded ones and the shipped scenes (tests/shipped).
pub(super) fn seeds() -> Vec<(String, String)> {
    let mut out = vec![
        ("report-sphere".to_string(), REPORT_SPHERE.to_string()),
        ("everything".to_string(), EVERYTHING.to_string()),
        ("empty".to_string(), EMPTY.to_string()),
    ];
    for p in shipped::scenes() {
        if let Ok(text) = std::fs::read_to_string(&p) {
            // A mesh record names its file from the scene's folder (meshes/ or models/):
            // made absolute, so that the seed and its prefixes parse under any name.
            let dir = p.parent().unwrap().display().to_string();
            let text = text
                .replace("mesh \"meshes/", &format!("mesh \"{dir}/meshes/"))
                .replace("mesh \"models/", &format!("mesh \"{dir}/models/"));
            out.push((p.file_name().unwrap().to_string_lossy().into_owned(), text));
        }
    }
    out
}

/// Byte ranges of the tokens of `src` (split as the lexer splits, comments skipped).
pub(super) fn token_spans(src: &str) -> Vec<(usize, usize)> {
    let mut spans = Vec::new();
    let mut start = None;
    let mut in_comment = false;
    for (i, c) in src.char_indices() {
        let blank = c.is_whitespace() || c == '#' || in_comment;
        if c == '#' {
            in_comment = true;
        } else if c == '\n' {
            in_comment = false;
        }
        match (blank, start) {
            (true, Some(s)) => {
                spans.push((s, i));
                start = None;
            }
            (false, None) => start = Some(i),
            _ => {}
        }
    }
    if let Some(s) = start {
        spans.push((s, src.len()));
    }
    spans
}

#[test]
fn every_seed_parses() {
    let seeds = seeds();
    assert!(seeds.len() >= 3);
    for (name, text) in &seeds {
        let scene = Scene::parse(text, name).unwrap_or_else(|e| panic!("{name}: {e}"));
        trace_small(&scene).unwrap_or_else(|e| panic!("{name}: {e}"));
    }
}

#[test]
fn every_token_prefix_of_every_seed_fails_at_its_end() {
    for (name, text) in seeds() {
        let spans = token_spans(&text);
        // A scene with extension records is whole after its last light and after each
        // complete record: there a prefix may parse.
        let records = !Scene::parse(&text, &name).unwrap().ext.is_empty();
        for k in 0..spans.len() {
            // Cut after token k-1 (or before the first one) and drop the rest.
            let cut = if k == 0 { 0 } else { spans[k - 1].1 };
            let prefix = &text[..cut];
            let err = match Scene::parse(prefix, "cut.txt") {
                Ok(_) if records => continue,
                Ok(_) => panic!("{name}: the first {k} tokens parse as a whole scene"),
                Err(e) => e,
            };
            check_located(prefix, "cut.txt", &err).unwrap_or_else(|e| panic!("{name}: {e}"));
            // A CSG block the cut leaves open is named where it opens.
            if records && err.to_string().contains("has no 'end'") {
                continue;
            }
            let loc = err.loc().unwrap();
            assert_eq!(
                (loc.line, loc.column),
                end_position(prefix),
                "{name}, {k} tokens: {err}"
            );
            assert!(err.to_string().contains("end of the file"), "{err}");
        }
    }
}

#[test]
fn every_character_prefix_of_every_seed_is_handled() {
    for (name, text) in seeds() {
        let ends: Vec<usize> = text
            .char_indices()
            .map(|(i, _)| i)
            .chain([text.len()])
            .collect();
        for &cut in &ends {
            let prefix = &text[..cut];
            match Scene::parse(prefix, "cut.txt") {
                Ok(scene) => trace_small(&scene).unwrap_or_else(|e| panic!("{name}@{cut}: {e}")),
                Err(e) => check_located(prefix, "cut.txt", &e)
                    .unwrap_or_else(|m| panic!("{name}@{cut}: {m}")),
            }
        }
    }
}

#[test]
fn every_single_token_deletion_and_duplication_is_handled() {
    for (name, text) in seeds() {
        for &(s, e) in &token_spans(&text) {
            let deleted = format!("{}{}", &text[..s], &text[e..]);
            let duplicated = format!("{} {}", &text[..e], &text[s..]);
            for src in [deleted, duplicated] {
                match Scene::parse(&src, "m.txt") {
                    Ok(scene) => trace_small(&scene).unwrap_or_else(|m| panic!("{name}: {m}")),
                    Err(err) => {
                        check_located(&src, "m.txt", &err).unwrap_or_else(|m| panic!("{name}: {m}"))
                    }
                }
            }
        }
    }
}

/// Tokens that break each kind of field: what every token of every seed is replaced by.
pub(super) const NASTY: &[&str] = &[
    "nan",
    "NaN",
    "-nan",
    "inf",
    "-inf",
    "infinity",
    "1e309",
    "-1e309",
    "1e308",
    "-1e308",
    "1e-320",
    "4.9e-324",
    "0",
    "-0",
    "-1",
    "0.5",
    "2.0",
    "+3",
    "18446744073709551616",
    "99999999999999999999999",
    "16385",
    "1000001",
    "0x10",
    "1_000",
    "1,5",
    ".",
    "-",
    "+",
    "e5",
    "1e",
    "é",
    "🎥",
    "\u{feff}",
    "\u{0}",
    "∞",
];

#[test]
fn every_token_replaced_by_every_nasty_token_is_handled() {
    // Cheap enough to do exhaustively for the embedded seeds and one file.
    let seeds = seeds();
    for (name, text) in seeds.iter().take(4) {
        for &(s, e) in &token_spans(text) {
            for nasty in NASTY {
                let src = format!("{}{}{}", &text[..s], nasty, &text[e..]);
                match Scene::parse(&src, "n.txt") {
                    Ok(scene) => trace_small(&scene).unwrap_or_else(|m| panic!("{name}: {m}")),
                    Err(err) => {
                        check_located(&src, "n.txt", &err).unwrap_or_else(|m| panic!("{name}: {m}"))
                    }
                }
            }
        }
    }
}
