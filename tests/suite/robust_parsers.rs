//! No input makes a parser panic or hang (the reliability issue, SPEC §1 and §6).
//!
//! Property tests throw at `Scene::parse` random token streams (numbers, integers, words,
//! `nan`/`inf`, huge and tiny values, `#` comments, odd whitespace and unicode), truncated
//! and mutated copies of every scene in `scenes/` (read at test time) and of scenes
//! embedded here, random bytes through `Scene::load`, and scenes generated from the
//! grammar with random (often degenerate) values. Each case must end, within a deadline,
//! either in a valid scene (which is then traced on a tiny 4×3 image) or in a located
//! syntax error: the message starts with `name:line:column:` and the position is inside
//! the input, on the first character of a token or just past the end of the text.
//!
//! The number of cases per property is modest so that the suite takes a few seconds in
//! `--release`; `PROPTEST_CASES=N` raises it for a longer hunt.
//!
//! Crashes the coverage-guided fuzzer (`fuzz/`) found are replayed in `fuzz_findings`.

use crate::shipped;

use proptest::prelude::*;
use proptest::sample::Index;
use std::path::Path;
use std::sync::mpsc;
use std::time::Duration;
use whitted::object::Object;
use whitted::scene::FileLoc;
use whitted::shapes::Shape;
use whitted::texture::Texture;
use whitted::trace::{RayCount, Tracer};
use whitted::{Camera, Scene, SceneError};

/// The longest one case may take before it counts as a hang (debug builds included).
const DEADLINE: Duration = Duration::from_secs(20);

/// The number of cases of a property: `PROPTEST_CASES` when set, else `default`.
fn cases(default: u32) -> u32 {
    std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

fn config(default_cases: u32) -> ProptestConfig {
    ProptestConfig {
        cases: cases(default_cases),
        // A failing case is shrunk; keep shrinking bounded so a failure reports quickly.
        max_shrink_iters: 2000,
        ..ProptestConfig::default()
    }
}

/// Runs `f` on another thread and waits at most `DEADLINE`: a panic or a hang becomes
/// an `Err` naming what happened, so proptest can shrink the input.
fn bounded<T: Send + 'static>(f: impl FnOnce() -> T + Send + 'static) -> Result<T, String> {
    let (tx, rx) = mpsc::channel();
    let handle = std::thread::Builder::new()
        .name("robust-case".into())
        .spawn(move || {
            let _ = tx.send(f());
        })
        .expect("cannot spawn a test thread");
    match rx.recv_timeout(DEADLINE) {
        Ok(v) => {
            let _ = handle.join();
            Ok(v)
        }
        Err(mpsc::RecvTimeoutError::Timeout) => Err(format!("no answer within {DEADLINE:?}")),
        Err(mpsc::RecvTimeoutError::Disconnected) => {
            let why = match handle.join() {
                Err(payload) => payload
                    .downcast_ref::<String>()
                    .cloned()
                    .or_else(|| payload.downcast_ref::<&str>().map(|s| s.to_string()))
                    .unwrap_or_else(|| "a panic".to_string()),
                Ok(()) => "the case ended without an answer".to_string(),
            };
            Err(format!("panicked: {why}"))
        }
    }
}

// ---------------------------------------------------------------------------------------
// What a good outcome is
// ---------------------------------------------------------------------------------------

/// The (line, column) just past the last character, as the lexer counts: lines end at
/// '\n' only, columns count characters, and a leading byte-order mark is not a column.
fn end_position(src: &str) -> (usize, usize) {
    let src = src.strip_prefix('\u{feff}').unwrap_or(src);
    let line = src.matches('\n').count() + 1;
    let column = src.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, column)
}

/// The character at a 1-based (line, column), if there is one.
fn char_at(src: &str, line: usize, column: usize) -> Option<char> {
    let src = src.strip_prefix('\u{feff}').unwrap_or(src);
    src.split('\n').nth(line - 1)?.chars().nth(column - 1)
}

/// A syntax error is located inside `src`, on a token's first character, just past a
/// token's last (the end of a line where a value is missing) or at the end, and its message starts with `name:line:column:` and says where in the structure.
fn check_located(src: &str, name: &str, err: &SceneError) -> Result<(), String> {
    let shown = err.to_string();
    let SceneError::Syntax {
        loc,
        message,
        context,
    } = err
    else {
        return Err(format!("parsing text gave a non-syntax error: {shown}"));
    };
    let FileLoc { file, line, column } = loc;
    let (line, column) = (*line, *column);
    if file != name {
        return Err(format!("the error names {file:?}, not {name:?}: {shown}"));
    }
    let prefix = format!("{name}:{line}:{column}: ");
    if !shown.starts_with(&prefix) {
        return Err(format!(
            "the message does not start with {prefix:?}: {shown}"
        ));
    }
    if message.trim().is_empty() || context.trim().is_empty() {
        return Err(format!("an empty message or context: {shown}"));
    }
    if line == 0 || column == 0 {
        return Err(format!("positions are 1-based: {shown}"));
    }
    if (line, column) == end_position(src) {
        return Ok(());
    }
    let token = |c: Option<char>| c.is_some_and(|c| !c.is_whitespace() && c != '#');
    let after = column > 1 && token(char_at(src, line, column - 1));
    match char_at(src, line, column) {
        Some(c) if !c.is_whitespace() && c != '#' => Ok(()),
        _ if after && src.split('\n').nth(line - 1).is_some() => Ok(()),
        Some(c) => Err(format!(
            "the error points at {c:?}, not at the start of a token: {shown}"
        )),
        None => Err(format!(
            "{line}:{column} is outside the input (end at {:?}): {shown}",
            end_position(src)
        )),
    }
}

/// Every number of a scene is within `limit` in magnitude and every radius is at least
/// `tiny`: scenes where no intermediate value can overflow, whose pixels must be finite.
fn is_tame(scene: &Scene, limit: f64, tiny: f64) -> bool {
    let v = |p: glam::DVec3| p.is_finite() && p.abs().max_element() <= limit;
    let s = |x: f64| x.is_finite() && x.abs() <= limit;
    let obj_ok = |o: &Object| {
        let shape = match o.shape {
            Shape::Sphere(sp) => v(sp.center) && sp.radius >= tiny && s(sp.radius),
            Shape::Plane(pl) => v(pl.point),
            Shape::Quadric(q) => {
                v(q.origin) && q.coef.iter().all(|&c| s(c)) && -q.coef[9] >= tiny * tiny
            }
            // An NFF's shapes and the extension's: not what this check bounds.
            Shape::Triangle(_)
            | Shape::Smooth(_)
            | Shape::Cone(_)
            | Shape::Placed(_)
            | Shape::Mesh(_)
            | Shape::Csg(_) => false,
        };
        let tex = match &o.texture {
            &Texture::Uniform(c) => v(c),
            &(Texture::Checker(a, b) | Texture::Wood(a, b) | Texture::Marble(a, b)) => v(a) && v(b),
            &Texture::Perlin(a, b, c) => v(a) && v(b) && v(c),
            Texture::Image(i) => s(i.size),
            // Only a track scales a texture; a parsed scene has none.
            &Texture::Scaled(_, k) => s(k),
        };
        let m = o.material;
        let bump = match m.bump {
            whitted::bump::Bump::None => true,
            whitted::bump::Bump::Uniform(e) | whitted::bump::Bump::Water(e) => s(e),
        };
        shape && tex && bump && s(m.kd) && s(m.kr) && s(m.kt) && s(m.ior) && m.ior >= tiny
    };
    let fog_ok = match scene.fog {
        whitted::fog::Fog::None => true,
        whitted::fog::Fog::Linear(d)
        | whitted::fog::Fog::Exponential(d)
        | whitted::fog::Fog::ExponentialSquared(d) => s(d) && d >= tiny,
    };
    v(scene.eye)
        && v(scene.look_at)
        && fog_ok
        && scene.objects.iter().all(obj_ok)
        && scene
            .lights
            .iter()
            .all(|l| v(l.position) && v(l.color) && s(l.intensity))
}

/// Traces a 4×3 image of a parsed scene (whatever its own resolution): no panic, and for
/// a tame scene (numbers up to 1e4, radii from 1e-4, coefficients up to 1e4) every
/// colour finite.
fn trace_small(scene: &Scene) -> Result<(), String> {
    let camera =
        Camera::new(scene.eye, scene.look_at, 4, 3).ok_or("a parsed scene has no camera at 4×3")?;
    // The scene's own camera must exist too (`Scene::camera` expects it).
    let _ = scene.camera();
    let tame = is_tame(scene, 1e4, 1e-4);
    let tracer = Tracer::new(scene);
    let mut count = RayCount::default();
    for j in 0..3 {
        for i in 0..4 {
            let c = tracer.primary(&camera.ray(i as f64 + 0.5, j as f64 + 0.5), &mut count);
            if tame && !c.is_finite() {
                return Err(format!("pixel ({i}, {j}) of a tame scene is {c}"));
            }
        }
    }
    Ok(())
}

/// Parses `src` as `name` under the deadline; a valid scene is traced small.
/// Returns whether it parsed.
fn parse_ok_or_located(src: String, name: &'static str) -> Result<bool, String> {
    let shown = src.clone();
    bounded(move || match Scene::parse(&src, name) {
        Ok(scene) => trace_small(&scene).map(|()| true),
        Err(e) => check_located(&src, name, &e).map(|()| false),
    })
    .and_then(|r| r)
    .map_err(|e| format!("{e}\n--- input ---\n{shown}\n---"))
}

/// Loads raw bytes through a file (`Scene::load`, which decodes UTF-8 first): a valid
/// scene or a located error, never an I/O error for a readable file.
fn load_ok_or_located(bytes: Vec<u8>) -> Result<bool, String> {
    let shown = String::from_utf8_lossy(&bytes).into_owned();
    bounded(move || {
        let dir = tempfile::tempdir().map_err(|e| e.to_string())?;
        let path = dir.path().join("scene.txt");
        std::fs::write(&path, &bytes).map_err(|e| e.to_string())?;
        let name = path.display().to_string();
        match Scene::load(&path) {
            Ok(scene) => trace_small(&scene).map(|()| true),
            Err(e) => match std::str::from_utf8(&bytes) {
                Ok(text) => check_located(text, &name, &e).map(|()| false),
                Err(bad) => {
                    // Not UTF-8: the error must point at the first bad byte.
                    let good = std::str::from_utf8(&bytes[..bad.valid_up_to()]).unwrap();
                    // Whether a leading byte-order mark counts as a column there is
                    // left open: either position is accepted.
                    let want = end_position(good);
                    let with_bom = (
                        want.0,
                        want.1 + usize::from(want.0 == 1 && good.starts_with('\u{feff}')),
                    );
                    match e.loc() {
                        Some(loc) if [want, with_bom].contains(&(loc.line, loc.column)) => {
                            let want = (loc.line, loc.column);
                            let prefix = format!("{name}:{}:{}: ", want.0, want.1);
                            if e.to_string().starts_with(&prefix) {
                                Ok(false)
                            } else {
                                Err(format!("the message does not start with {prefix:?}: {e}"))
                            }
                        }
                        _ => Err(format!("a bad byte at {want:?} reported as: {e}")),
                    }
                }
            },
        }
    })
    .and_then(|r| r)
    .map_err(|e| format!("{e}\n--- input (lossy) ---\n{shown}\n---"))
}

// ---------------------------------------------------------------------------------------
// Seeds: every scene of scenes/ and a few embedded ones
// ---------------------------------------------------------------------------------------

/// The report's example sphere (SPEC §1), in a scene of its own.
const REPORT_SPHERE: &str = "320 240\n0 0 10\n0 0 0\n0 0\n1 0 0 1\n\
1.0 0.0 2.0 9.0 2 2 0.5 0.5 0.5 0.0 0.0 1.0 1.0 1.0 0.0 0.3 0.2 0.0 1.5 0 0.0\n\
5 5 5 1 1 1 1\n";

/// Every record kind, every texture type, both bumps, fog, a slanted glass cylinder.
const EVERYTHING: &str = "\
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
const EMPTY: &str = "1 1\n0 0 0\n0 0 -1\n1 1e-3\n0 0 0 0";

/// The seed scenes: the embedded ones and the shipped scenes (tests/shipped).
fn seeds() -> Vec<(String, String)> {
    let mut out = vec![
        ("report-sphere".to_string(), REPORT_SPHERE.to_string()),
        ("everything".to_string(), EVERYTHING.to_string()),
        ("empty".to_string(), EMPTY.to_string()),
    ];
    for p in shipped::scenes() {
        if let Ok(text) = std::fs::read_to_string(&p) {
            // A mesh record names its file from the scene's folder: made absolute, so
            // that the seed and its prefixes parse under any name.
            let dir = p.parent().unwrap().display().to_string();
            let text = text.replace("mesh \"meshes/", &format!("mesh \"{dir}/meshes/"));
            out.push((p.file_name().unwrap().to_string_lossy().into_owned(), text));
        }
    }
    out
}

/// Byte ranges of the tokens of `src` (split as the lexer splits, comments skipped).
fn token_spans(src: &str) -> Vec<(usize, usize)> {
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
const NASTY: &[&str] = &[
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

// ---------------------------------------------------------------------------------------
// Strategies
// ---------------------------------------------------------------------------------------

/// One token of any kind, leaning towards the small integers the header needs.
fn token() -> impl Strategy<Value = String> {
    prop_oneof![
        4 => (0u32..5).prop_map(|n| n.to_string()),
        2 => (0u32..70_000).prop_map(|n| n.to_string()),
        2 => any::<i64>().prop_map(|n| n.to_string()),
        3 => (-100.0f64..100.0).prop_map(|x| format!("{x}")),
        2 => any::<f64>().prop_map(|x| format!("{x:e}")),
        1 => any::<f64>().prop_map(|x| format!("{x}")),
        2 => prop::sample::select(NASTY).prop_map(str::to_string),
        1 => "[a-zA-Z_]{1,8}",
        1 => "[0-9.eE+-]{1,6}",
        1 => "\\PC{1,3}",
        1 => "[0-9]{1,3}#[a-z]{0,3}",
    ]
}

/// What goes between tokens: blanks of every kind, comments, nothing at all.
fn separator() -> impl Strategy<Value = String> {
    prop_oneof![
        8 => Just(" ".to_string()),
        2 => Just("\n".to_string()),
        1 => Just("\t".to_string()),
        1 => Just("\r\n".to_string()),
        1 => Just("  \t \n\n".to_string()),
        1 => Just("\u{a0}".to_string()),
        1 => Just("\u{2028}".to_string()),
        1 => Just("\u{3000}".to_string()),
        1 => Just("\x0b\x0c".to_string()),
        1 => "#[^\n]{0,12}\n",
        1 => "#[^\n]{0,12}",
        1 => Just(String::new()),
    ]
}

fn stream(len: std::ops::Range<usize>) -> impl Strategy<Value = String> {
    prop::collection::vec((token(), separator()), len)
        .prop_map(|parts| parts.into_iter().map(|(t, s)| t + &s).collect::<String>())
}

/// A header that parses (tiny image, camera, fog, counts), so that random tokens after it
/// reach the records.
fn header() -> impl Strategy<Value = String> {
    (
        1u32..5,
        1u32..5,
        0u32..4,
        0u32..3,
        0u32..3,
        0u32..3,
        0u32..3,
    )
        .prop_map(|(w, h, fog, ns, np, nc, nl)| {
            format!("{w} {h}\n0 1 5\n0 0 0\n{fog} 7\n{ns} {np} {nc} {nl}\n")
        })
}

/// A number for a field of a generated scene: usually ordinary, sometimes degenerate.
fn value() -> impl Strategy<Value = f64> {
    prop_oneof![
        6 => (-3i32..=3).prop_map(f64::from),
        6 => -10.0f64..10.0,
        2 => 0.0f64..1.0,
        1 => prop::sample::select(&[
            0.0, -0.0, 1e-300, 1e-9, 1e-4, 1e4, 1e6, -1e6, 1e9, 1e150, 1e300, -1e300, 1.7e308,
            5e-324,
        ][..]),
        1 => any::<f64>(),
    ]
}

/// A number for a field that must be > 0 (radius, Ior, fog distance): usually valid.
fn positive() -> impl Strategy<Value = f64> {
    prop_oneof![
        10 => 0.01f64..10.0,
        2 => prop::sample::select(&[
            1e-300, 1e-9, 1e-4, 1e4, 1e6, 1e9, 1e150, 1e300, 1.7e308, 5e-324,
        ][..]),
        1 => value(),
    ]
}

fn vec3() -> impl Strategy<Value = String> {
    (value(), value(), value()).prop_map(|(x, y, z)| format!("{x:?} {y:?} {z:?}"))
}

fn texture() -> impl Strategy<Value = String> {
    prop_oneof![
        vec3().prop_map(|c| format!("1 {c}")),
        (1u32..=4, vec3(), vec3(), vec3()).prop_map(|(t, a, b, c)| format!("2 {t} {a} {b} {c}")),
    ]
}

fn material() -> impl Strategy<Value = String> {
    (value(), value(), value(), positive(), 0u32..=2, value())
        .prop_map(|(kd, kr, kt, ior, bt, bv)| format!("{kd:?} {kr:?} {kt:?} {ior:?} {bt} {bv:?}"))
}

/// A scene following the grammar, with random and often degenerate values: it parses
/// unless a value breaks a rule (radius ≤ 0, zero normal, Ior ≤ 0, eye on look-at...).
fn grammar_scene() -> impl Strategy<Value = String> {
    let sphere = (positive(), vec3(), texture(), material())
        .prop_map(|(r, c, t, m)| format!("{r:?} {c} {t} {m}\n"));
    let plane = (vec3(), vec3(), texture(), material())
        .prop_map(|(p, n, t, m)| format!("{p} {n} {t} {m}\n"));
    let cylinder = (vec3(), vec3(), positive(), texture(), material())
        .prop_map(|(a, p, r, t, m)| format!("{a} {p} {r:?} {t} {m}\n"));
    let light = (vec3(), vec3(), value()).prop_map(|(p, c, i)| format!("{p} {c} {i:?}\n"));
    (
        (1u32..6, 1u32..6, vec3(), vec3(), 0u32..4, positive()),
        prop::collection::vec(sphere, 0..4),
        prop::collection::vec(plane, 0..3),
        prop::collection::vec(cylinder, 0..3),
        prop::collection::vec(light, 0..4),
    )
        .prop_map(|((w, h, eye, look, fog, fd), s, p, c, l)| {
            let mut out = format!(
                "{w} {h}\n{eye}\n{look}\n{fog} {fd:?}\n{} {} {} {}\n",
                s.len(),
                p.len(),
                c.len(),
                l.len()
            );
            for rec in s.iter().chain(&p).chain(&c).chain(&l) {
                out += rec;
            }
            out
        })
}

/// One edit of a text: on tokens or on bytes.
#[derive(Clone, Debug)]
enum Edit {
    DeleteToken(Index),
    DuplicateToken(Index),
    ReplaceToken(Index, String),
    InsertToken(Index, String),
    SwapTokens(Index, Index),
    Truncate(Index),
    FlipByte(Index, u8),
    InsertBytes(Index, Vec<u8>),
}

fn edit() -> impl Strategy<Value = Edit> {
    prop_oneof![
        3 => any::<Index>().prop_map(Edit::DeleteToken),
        2 => any::<Index>().prop_map(Edit::DuplicateToken),
        4 => (any::<Index>(), token()).prop_map(|(i, t)| Edit::ReplaceToken(i, t)),
        2 => (any::<Index>(), token()).prop_map(|(i, t)| Edit::InsertToken(i, t)),
        1 => (any::<Index>(), any::<Index>()).prop_map(|(a, b)| Edit::SwapTokens(a, b)),
        1 => any::<Index>().prop_map(Edit::Truncate),
        2 => (any::<Index>(), 1u8..=255).prop_map(|(i, m)| Edit::FlipByte(i, m)),
        1 => (any::<Index>(), prop::collection::vec(any::<u8>(), 1..4))
            .prop_map(|(i, b)| Edit::InsertBytes(i, b)),
    ]
}

/// Applies `edits` to `text`; the result may no longer be UTF-8.
fn apply(text: &str, edits: &[Edit]) -> Vec<u8> {
    let mut bytes = text.as_bytes().to_vec();
    for e in edits {
        // Token edits work on the text as it is now (lossy if a byte edit broke it).
        let now = String::from_utf8_lossy(&bytes).into_owned();
        let spans = token_spans(&now);
        let pick = |i: &Index| (!spans.is_empty()).then(|| spans[i.index(spans.len())]);
        let splice = |(s, e): (usize, usize), with: &str| {
            format!("{}{}{}", &now[..s], with, &now[e..]).into_bytes()
        };
        bytes = match e {
            Edit::DeleteToken(i) => pick(i).map_or(bytes, |sp| splice(sp, "")),
            Edit::DuplicateToken(i) => pick(i).map_or(bytes, |(s, e)| {
                splice((s, e), &format!("{0} {0}", &now[s..e]))
            }),
            Edit::ReplaceToken(i, t) => pick(i).map_or(bytes, |sp| splice(sp, t)),
            Edit::InsertToken(i, t) => match pick(i) {
                Some((s, _)) => splice((s, s), &format!("{t} ")),
                None => t.clone().into_bytes(),
            },
            Edit::SwapTokens(a, b) => match (pick(a), pick(b)) {
                (Some(x), Some(y)) if x.0 < y.0 => format!(
                    "{}{}{}{}{}",
                    &now[..x.0],
                    &now[y.0..y.1],
                    &now[x.1..y.0],
                    &now[x.0..x.1],
                    &now[y.1..]
                )
                .into_bytes(),
                _ => bytes,
            },
            Edit::Truncate(i) => {
                let cut = i.index(bytes.len() + 1);
                bytes.truncate(cut);
                bytes
            }
            Edit::FlipByte(i, m) => {
                if !bytes.is_empty() {
                    let k = i.index(bytes.len());
                    bytes[k] ^= m;
                }
                bytes
            }
            Edit::InsertBytes(i, b) => {
                let k = i.index(bytes.len() + 1);
                bytes.splice(k..k, b.iter().copied());
                bytes
            }
        };
    }
    bytes
}

// ---------------------------------------------------------------------------------------
// Properties
// ---------------------------------------------------------------------------------------

proptest! {
    #![proptest_config(config(1500))]

    #[test]
    fn random_token_streams(src in stream(0..40)) {
        parse_ok_or_located(src, "random.txt").map_err(TestCaseError::fail)?;
    }

    #[test]
    fn random_records_after_a_valid_header(head in header(), tail in stream(0..80)) {
        parse_ok_or_located(head + &tail, "records.txt").map_err(TestCaseError::fail)?;
    }

    #[test]
    fn mutated_seed_scenes(seed in any::<Index>(), edits in prop::collection::vec(edit(), 1..5)) {
        let seeds = seeds();
        let (_, text) = &seeds[seed.index(seeds.len())];
        let bytes = apply(text, &edits);
        match String::from_utf8(bytes) {
            Ok(src) => parse_ok_or_located(src, "mutant.txt").map(|_| ()),
            Err(e) => load_ok_or_located(e.into_bytes()).map(|_| ()),
        }
        .map_err(TestCaseError::fail)?;
    }
}

proptest! {
    #![proptest_config(config(400))]

    #[test]
    fn grammar_scenes_with_degenerate_values(src in grammar_scene()) {
        parse_ok_or_located(src, "grammar.txt").map_err(TestCaseError::fail)?;
    }

    #[test]
    fn random_bytes_through_a_file(bytes in prop::collection::vec(any::<u8>(), 0..200)) {
        load_ok_or_located(bytes).map_err(TestCaseError::fail)?;
    }
}

// ---------------------------------------------------------------------------------------
// Manifests
// ---------------------------------------------------------------------------------------

use whitted_anim::{Manifest, ManifestError};

/// The name manifests are parsed under (never read: `parse` takes the text).
const MANIFEST_PATH: &str = "anims/fuzz.toml";

/// A parsed manifest is usable: every frame's camera is finite and every frame has a
/// file name, including frames outside the sequence.
fn exercise_manifest(m: &Manifest) -> Result<(), String> {
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
fn check_manifest_error(src: &str, err: &ManifestError) -> Result<(), String> {
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

fn check_located_line(
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
fn manifest_ok_or_located(src: String) -> Result<bool, String> {
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

const CIRCLE: &str = r#"scene = "../scenes/orbit.txt"
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

const SPLINE_KEYS_LOOK: &str = r#"scene = "s.txt"
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

const SPLINE_TABLES: &str = r#"scene = "s.txt"
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
fn manifest_seeds() -> Vec<String> {
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
const NASTY_VALUES: &[&str] = &[
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
const KEYS: &[&str] = &[
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

const TABLES: &[&str] = &[
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

/// A TOML string literal of any text (basic string, escaped).
fn toml_string(s: &str) -> String {
    let mut out = String::from("\"");
    for c in s.chars() {
        match c {
            '"' => out += "\\\"",
            '\\' => out += "\\\\",
            c if c.is_control() => out += &format!("\\u{:04X}", c as u32),
            c => out.push(c),
        }
    }
    out + "\""
}

/// A TOML value of any type, nested a little; sometimes not valid TOML at all.
fn toml_value() -> impl Strategy<Value = String> {
    let leaf = prop_oneof![
        3 => (0i64..300).prop_map(|n| n.to_string()),
        1 => any::<i64>().prop_map(|n| n.to_string()),
        3 => (-1e3f64..1e3).prop_map(|x| format!("{x:?}")),
        1 => any::<f64>().prop_filter("finite", |x| x.is_finite()).prop_map(|x| format!("{x:?}")),
        2 => prop::sample::select(NASTY_VALUES).prop_map(str::to_string),
        2 => prop::sample::select(&[
            "circle", "spline", "png", "jpeg", "ppm", "raw", "bmp", "frame_####", "s.txt", "",
        ][..])
        .prop_map(toml_string),
        1 => "\\PC{0,6}".prop_map(|s| toml_string(&s)),
        1 => any::<bool>().prop_map(|b| b.to_string()),
        1 => "[a-z0-9.\\[\\]{}=,\"' -]{1,6}",
    ];
    leaf.prop_recursive(3, 24, 4, |inner| {
        prop_oneof![
            prop::collection::vec(inner.clone(), 0..4).prop_map(|v| format!("[{}]", v.join(", "))),
            prop::collection::vec((prop::sample::select(KEYS), inner), 0..4).prop_map(|kv| {
                let body: Vec<String> = kv.iter().map(|(k, v)| format!("{k} = {v}")).collect();
                format!("{{ {} }}", body.join(", "))
            }),
        ]
    })
}

/// Random TOML: table headers and key = value lines from the manifest's vocabulary.
fn toml_document() -> impl Strategy<Value = String> {
    let line = prop_oneof![
        5 => (prop::sample::select(KEYS), toml_value()).prop_map(|(k, v)| format!("{k} = {v}")),
        1 => ("[a-z_]{1,8}", toml_value()).prop_map(|(k, v)| format!("{k} = {v}")),
        2 => prop::sample::select(TABLES).prop_map(str::to_string),
        1 => "#[^\n]{0,10}",
        1 => Just(String::new()),
    ];
    let end = prop_oneof![8 => Just("\n"), 1 => Just("\r\n"), 1 => Just(" # c\n"), 1 => Just("")];
    prop::collection::vec((line, end), 0..16)
        .prop_map(|v| v.into_iter().map(|(l, e)| l + e).collect())
}

/// A value for a manifest field: usually of the right type, sometimes anything.
fn field(good: BoxedStrategy<String>) -> impl Strategy<Value = Option<String>> {
    prop_oneof![
        14 => good.prop_map(Some),
        1 => toml_value().prop_map(Some),
        1 => Just(None),
    ]
}

fn float() -> BoxedStrategy<String> {
    prop_oneof![
        4 => (-20.0f64..20.0).prop_map(|x| format!("{x:?}")),
        1 => prop::sample::select(&["0.0", "1e9", "-1e9", "1e10", "1e-300", "nan", "inf"][..])
            .prop_map(str::to_string),
    ]
    .boxed()
}

fn int(range: std::ops::Range<i64>) -> BoxedStrategy<String> {
    range.prop_map(|n| n.to_string()).boxed()
}

fn point() -> BoxedStrategy<String> {
    (float(), float(), float())
        .prop_map(|(x, y, z)| format!("[{x}, {y}, {z}]"))
        .boxed()
}

fn key_entry() -> BoxedStrategy<String> {
    (int(-2..40), point(), prop::option::of(point()))
        .prop_map(|(f, p, l)| match l {
            Some(l) => format!("{{ frame = {f}, position = {p}, look_at = {l} }}"),
            None => format!("{{ frame = {f}, position = {p} }}"),
        })
        .boxed()
}

/// A manifest shaped like SPEC §5 with random, often out-of-range, values.
fn structured_manifest() -> impl Strategy<Value = String> {
    let top = (
        field(Just("\"s.txt\"".to_string()).boxed()),
        field(int(-2..50)),
        field(float()),
    );
    let circle = (
        field(point()),
        field(float()),
        field(float()),
        field(float()),
        field(float()),
        field(point()),
    )
        .prop_map(|(c, r, h, a, t, l)| {
            let mut s = "path = \"circle\"\n".to_string();
            for (k, v) in [
                ("center", c),
                ("radius", r),
                ("height", h),
                ("start_angle", a),
                ("turns", t),
                ("look_at", l),
            ] {
                if let Some(v) = v {
                    s += &format!("{k} = {v}\n");
                }
            }
            s
        });
    let spline = (
        field(any::<bool>().prop_map(|b| b.to_string()).boxed()),
        field(any::<bool>().prop_map(|b| b.to_string()).boxed()),
        prop::option::of(point()),
        prop::collection::vec(key_entry(), 0..6),
    )
        .prop_map(|(closed, speed, look, keys)| {
            let mut s = "path = \"spline\"\n".to_string();
            for (k, v) in [
                ("closed", closed),
                ("constant_speed", speed),
                ("look_at", look),
            ] {
                if let Some(v) = v {
                    s += &format!("{k} = {v}\n");
                }
            }
            s + &format!("keys = [\n  {}\n]\n", keys.join(",\n  "))
        });
    let output = (
        field(Just("\"out\"".to_string()).boxed()),
        field(
            prop::sample::select(
                &[
                    "\"f_####\"",
                    "\"#\"",
                    "\"a#b##\"",
                    "\"x\"",
                    "\"##########\"",
                ][..],
            )
            .prop_map(str::to_string)
            .boxed(),
        ),
        field(
            prop::sample::select(&["\"png\"", "\"jpeg\"", "\"ppm\"", "\"raw\"", "\"gif\""][..])
                .prop_map(str::to_string)
                .boxed(),
        ),
        field(int(-1..120)),
    );
    let render = (
        field(int(0..20000)),
        field(int(0..20000)),
        field(int(-1..20)),
    );
    let check = (
        field(
            prop::collection::vec(-2i64..50, 0..5)
                .prop_map(|v| format!("{v:?}"))
                .boxed(),
        ),
        field(Just("\"golden\"".to_string()).boxed()),
        field(int(-1..300)),
        field(float()),
        field(int(-1..300)),
    );
    (
        top,
        prop_oneof![circle, spline],
        prop::option::of(output),
        prop::option::of(render),
        prop::option::of(check),
    )
        .prop_map(|((scene, frames, fps), camera, output, render, check)| {
            let mut s = String::new();
            for (k, v) in [("scene", scene), ("frames", frames), ("fps", fps)] {
                if let Some(v) = v {
                    s += &format!("{k} = {v}\n");
                }
            }
            s += "[camera]\n";
            s += &camera;
            let mut table = |name: &str, kv: Vec<(&str, Option<String>)>| {
                s += &format!("[{name}]\n");
                for (k, v) in kv {
                    if let Some(v) = v {
                        s += &format!("{k} = {v}\n");
                    }
                }
            };
            if let Some((d, n, f, q)) = output {
                table(
                    "output",
                    vec![("dir", d), ("name", n), ("format", f), ("jpeg_quality", q)],
                );
            }
            if let Some((w, h, n)) = render {
                table("render", vec![("width", w), ("height", h), ("samples", n)]);
            }
            if let Some((fr, r, f, p, h)) = check {
                table(
                    "check",
                    vec![
                        ("frames", fr),
                        ("references", r),
                        ("fail", f),
                        ("fail_percent", p),
                        ("hard_fail", h),
                    ],
                );
            }
            s
        })
}

/// One edit of a manifest, by lines, values or bytes.
#[derive(Clone, Debug)]
enum ManifestEdit {
    DeleteLine(Index),
    DuplicateLine(Index),
    SwapLines(Index, Index),
    ReplaceValue(Index, String),
    InsertLine(Index, String),
    Text(Edit),
}

fn manifest_edit() -> impl Strategy<Value = ManifestEdit> {
    prop_oneof![
        2 => any::<Index>().prop_map(ManifestEdit::DeleteLine),
        2 => any::<Index>().prop_map(ManifestEdit::DuplicateLine),
        1 => (any::<Index>(), any::<Index>()).prop_map(|(a, b)| ManifestEdit::SwapLines(a, b)),
        4 => (any::<Index>(), toml_value()).prop_map(|(i, v)| ManifestEdit::ReplaceValue(i, v)),
        2 => (any::<Index>(), toml_document()).prop_map(|(i, d)| ManifestEdit::InsertLine(i, d)),
        3 => edit().prop_map(ManifestEdit::Text),
    ]
}

fn apply_manifest(text: &str, edits: &[ManifestEdit]) -> Vec<u8> {
    let mut bytes = text.as_bytes().to_vec();
    for e in edits {
        let now = String::from_utf8_lossy(&bytes).into_owned();
        let mut lines: Vec<String> = now.split_inclusive('\n').map(str::to_string).collect();
        if lines.is_empty() {
            lines.push(String::new());
        }
        let n = lines.len();
        match e {
            ManifestEdit::DeleteLine(i) => {
                lines.remove(i.index(n));
            }
            ManifestEdit::DuplicateLine(i) => {
                let k = i.index(n);
                let l = lines[k].clone();
                lines.insert(k, l);
            }
            ManifestEdit::SwapLines(a, b) => lines.swap(a.index(n), b.index(n)),
            ManifestEdit::ReplaceValue(i, v) => {
                let k = i.index(n);
                if let Some(eq) = lines[k].find('=') {
                    lines[k] = format!("{}= {v}\n", &lines[k][..eq]);
                }
            }
            ManifestEdit::InsertLine(i, d) => lines.insert(i.index(n + 1), d.clone() + "\n"),
            ManifestEdit::Text(edit) => {
                bytes = apply(&now, std::slice::from_ref(edit));
                continue;
            }
        }
        bytes = lines.concat().into_bytes();
    }
    bytes
}

proptest! {
    #![proptest_config(config(1000))]

    #[test]
    fn random_toml_documents(src in toml_document()) {
        manifest_ok_or_located(src).map_err(TestCaseError::fail)?;
    }

    #[test]
    fn structured_manifests_with_random_values(src in structured_manifest()) {
        manifest_ok_or_located(src).map_err(TestCaseError::fail)?;
    }

    #[test]
    fn mutated_seed_manifests(
        seed in any::<Index>(),
        edits in prop::collection::vec(manifest_edit(), 1..4),
    ) {
        let seeds = manifest_seeds();
        let text = &seeds[seed.index(seeds.len())];
        let src = String::from_utf8_lossy(&apply_manifest(text, &edits)).into_owned();
        manifest_ok_or_located(src).map_err(TestCaseError::fail)?;
    }
}

// ---------------------------------------------------------------------------------------
// Findings: inputs that once went wrong, kept as regressions
// ---------------------------------------------------------------------------------------

/// A scene with one plane of normal `n` and one cylinder of axis `a`.
fn plane_and_cylinder(n: &str, a: &str) -> String {
    format!(
        "4 3\n0 1 5\n0 0 0\n0 0\n0 1 1 1\n\
         0 0 0  {n}  1 1 1 1  1 0 0 1 0 0\n\
         {a}  0 0 -3  0.5  1 1 0 0  1 0 0 1 0 0\n\
         0 5 5  1 1 1  1\n"
    )
}

#[test]
fn a_tiny_or_huge_normal_or_axis_is_not_called_zero() {
    // |v|² under- or overflowed and `try_normalize` refused these as "zero length"
    // (src/scene/parser.rs, `direction`).
    for v in [
        "0 1e-200 0",
        "0 1e200 0",
        "0 4.9e-324 0",
        "1e308 1e308 0",
        "0 -1e-170 0",
    ] {
        let scene =
            Scene::parse(&plane_and_cylinder(v, v), "n.txt").unwrap_or_else(|e| panic!("{v}: {e}"));
        trace_small(&scene).unwrap();
        // The same picture as a unit normal and axis.
        let unit = Scene::parse(&plane_and_cylinder("0 1 0", "0 1 0"), "n.txt").unwrap();
        let sign = if v.starts_with("0 -") { -1.0 } else { 1.0 };
        let parts = |s: &Scene| match (&s.objects[0].shape, &s.objects[1].shape) {
            (Shape::Plane(p), Shape::Quadric(q)) => (p.normal(), q.coef),
            _ => unreachable!(),
        };
        if v.starts_with("0 ") {
            let (n, coef) = parts(&scene);
            let (unit_n, unit_coef) = parts(&unit);
            assert_eq!((n, coef), (sign * unit_n, unit_coef), "{v}");
        }
    }
    // A zero vector is still refused, with its location.
    let src = plane_and_cylinder("0 0 0", "0 1 0");
    let err = Scene::parse(&src, "n.txt").unwrap_err().to_string();
    assert!(
        err.starts_with("n.txt:6:8: the normal (0 0 0) has zero length"),
        "{err}"
    );
    let src = plane_and_cylinder("0 1 0", "0 -0 0");
    let err = Scene::parse(&src, "n.txt").unwrap_err().to_string();
    assert!(
        err.starts_with("n.txt:7:1: the axis (0 -0 0) has zero length"),
        "{err}"
    );
}

#[test]
fn an_overflowing_camera_distance_is_not_called_the_same_point() {
    // look_at − eye overflowed to infinity and the error said the camera was placed on
    // the point it looks at (src/scene/parser.rs, the camera check).
    let src = "4 3\n1e308 0 0\n-1e308 0 0\n0 0\n0 0 0 0\n";
    let err = Scene::parse(src, "far.txt").unwrap_err();
    check_located(src, "far.txt", &err).unwrap();
    let shown = err.to_string();
    assert!(shown.starts_with("far.txt:3:1: "), "{shown}");
    assert!(shown.contains("overflows"), "{shown}");
    assert!(!shown.contains("placed on"), "{shown}");
    // A huge or tiny but finite distance has a direction: |look_at − eye|² under- or
    // overflowed and `Camera::new` refused it (src/camera.rs, `Camera::new`).
    for (eye, look) in [
        ("1e300 0 0", "0 0 0"),
        ("0 0 0", "0 -1e200 1e200"),
        ("0 0 0", "1e-320 0 0"),
        ("1 1 1", "1 1.0000000000000002 1"),
    ] {
        let src = format!("4 3\n{eye}\n{look}\n0 0\n0 0 0 0\n");
        let scene = Scene::parse(&src, "c.txt").unwrap_or_else(|e| panic!("{e}"));
        let camera = scene.camera();
        assert!(camera.ray(2.0, 1.5).dir.is_finite());
    }
    // The true coincidence keeps its message.
    let src = "4 3\n1 2 3\n1 2 3\n0 0\n0 0 0 0\n";
    let shown = Scene::parse(src, "same.txt").unwrap_err().to_string();
    assert!(shown.contains("placed on the point it looks at"), "{shown}");
}

/// Loads manifest bytes from a file: a usable manifest or a located `Invalid` error,
/// never an I/O error for a file that exists.
fn load_manifest_ok_or_located(bytes: Vec<u8>) -> Result<bool, String> {
    let shown = String::from_utf8_lossy(&bytes).into_owned();
    bounded(move || {
        let dir = tempfile::tempdir().map_err(|e| e.to_string())?;
        let path = dir.path().join("anim.toml");
        std::fs::write(&path, &bytes).map_err(|e| e.to_string())?;
        match Manifest::load(&path) {
            Ok(m) => exercise_manifest(&m).map(|()| true),
            Err(ManifestError::Io { source, .. }) => Err(format!("an I/O error: {source}")),
            Err(e @ (ManifestError::Invalid { .. } | ManifestError::Unknown(_))) => {
                let (line, column) = e.loc().map_or((0, 0), |l| (l.line, l.column));
                let text = match std::str::from_utf8(&bytes) {
                    Ok(t) => t,
                    Err(bad) => std::str::from_utf8(&bytes[..bad.valid_up_to()]).unwrap(),
                };
                let lines: Vec<&str> = text.split('\n').collect();
                let inside = line >= 1
                    && line <= lines.len()
                    && column >= 1
                    && column <= lines[line - 1].chars().count() + 1;
                let prefix = format!("{}:{line}:{column}: ", path.display());
                if inside && e.to_string().starts_with(&prefix) {
                    Ok(false)
                } else {
                    Err(format!("badly located: {e}"))
                }
            }
        }
    })
    .and_then(|r| r)
    .map_err(|e| format!("{e}\n--- manifest (lossy) ---\n{shown}\n---"))
}

#[test]
fn a_manifest_that_is_not_utf8_gets_a_located_error() {
    // `Manifest::load` used `read_to_string` and answered an I/O error without a place
    // (src/anim/manifest.rs, `load`).
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("bad.toml");
    std::fs::write(&path, b"scene = \"a.txt\"\nfr\xffames = 1\n").unwrap();
    let err = Manifest::load(&path).unwrap_err();
    let shown = err.to_string();
    assert!(
        matches!(
            err,
            ManifestError::Invalid { ref loc, .. } if (loc.line, loc.column) == (2, 3)
        ),
        "{shown}"
    );
    assert!(
        shown.starts_with(&format!("{}:2:3: ", path.display())),
        "{shown}"
    );
    assert!(shown.contains("UTF-8"), "{shown}");
    // A missing file is still an I/O error.
    let err = Manifest::load(&dir.path().join("missing.toml")).unwrap_err();
    assert!(matches!(err, ManifestError::Io { .. }));
}

#[test]
fn a_manifest_with_a_byte_order_mark() {
    // Windows editors write one; it either parses or is refused at a place.
    let src = format!("\u{feff}{CIRCLE}");
    manifest_ok_or_located(src.clone()).unwrap();
    load_manifest_ok_or_located(src.into_bytes()).unwrap();
}

proptest! {
    #![proptest_config(config(300))]

    #[test]
    fn mutated_manifest_bytes_through_a_file(
        seed in any::<Index>(),
        edits in prop::collection::vec(manifest_edit(), 1..4),
    ) {
        let seeds = manifest_seeds();
        let bytes = apply_manifest(&seeds[seed.index(seeds.len())], &edits);
        load_manifest_ok_or_located(bytes).map_err(TestCaseError::fail)?;
    }
}

#[test]
fn extreme_values_are_refused_or_render_finite() {
    // Colours, Kd, Kr, Kt (0..1) and intensities (0..1000) are bounded, because near 1e300
    // their products overflowed into NaN pixels; the first two scenes did. Geometry, bump
    // and fog numbers may be any finite value: the third scene renders finite.
    for src in [
        "4 3\n0 1 5\n0 0 0\n1 1\n1 0 0 1\n1 0 0 0 1 1e300 1e300 1e300 1 0 0 1 0 0\n\
         0 5 5 1e300 1e300 1e300 1e300\n",
        "4 3\n0 1 5\n0 0 0\n0 1\n1 0 0 1\n1 0 0 0 1 -1e300 1e300 1e300 0.5 1e300 0 1 0 0\n\
         0 5 5 1 1 1 1.7e308\n",
    ] {
        let err = Scene::parse(src, "x.txt").unwrap_err().to_string();
        assert!(
            err.starts_with("x.txt:6:") && err.contains("must be from 0 to 1"),
            "{err}"
        );
    }
    let src = "4 3\n1e300 0 0\n0 0 0\n3 1e-300\n1 0 0 1\n\
               1e300 0 0 0 1 1 1 1 0.1 0.1 0.9 1e300 2 1e300\n-1e300 0 0 1 1 1 1\n";
    let scene = Scene::parse(src, "x.txt").unwrap();
    let camera = scene.camera();
    let tracer = Tracer::new(&scene);
    for j in 0..3 {
        for i in 0..4 {
            let ray = camera.ray(i as f64 + 0.5, j as f64 + 0.5);
            let c = tracer.primary(&ray, &mut Default::default());
            assert!(c.is_finite(), "pixel ({i}, {j}): {c}");
        }
    }
}

// ---- Tracks (SPEC §7): random [[track]] tables, resolved against a real scene ----

use whitted_anim::Timeline;

/// A scene with one object of each kind, fog and two lights, for track targets.
const TRACK_SCENE: &str = "8 6  0 2 10  0 1 0  2 30  2 1 1 2
1.0  0 1 0   1 0.9 0.1 0.1   0.7 0.3 0 1 1 0.1
0.5  2 0.5 0   2 2 0.1 0.2 0.3 0.4 0.5 0.6 0.7 0.8 0.9   0.8 0 0.5 1.5 0 0
0 0 0  0 1 0   2 1 1 1 1 0 0 0 0 0 0   0.9 0 0 1 0 0
0 1 0  -2 0 -2  0.3   1 0.2 0.5 0.8   0.7 0 0 1 0 0
5 10 5  1 1 1  0.9
-6 8 4  0.6 0.6 0.8  0.6";

/// Every track feature at once, as a seed.
const TRACKS: &str = r#"scene = "s.txt"
frames = 30
[camera]
look_at = "sphere 2"
[render]
motion_blur = { shutter = 0.75, samples = 3 }
[[track]]
target = "sphere 1 center"
interpolation = "smooth"
ease = "in-out"
keys = [{ frame = 0, value = [0, 1, 0] }, { frame = 10, value = [0, 3, 0], ease = "out" }, { frame = 29, value = [1, 1, 0] }]
[[track]]
target = "light 1 position"
path = "circle"
center = [0, 0, 0]
radius = 5.0
height = 8.0
turns = -2.0
[[track]]
target = "plane 1 color1"
interpolation = "step"
keys = [{ frame = 0, value = [1, 1, 1] }, { frame = 15, value = [0.2, 0.3, 0.4] }]
[[track]]
target = "fog distance"
keys = [{ frame = 3, value = 30 }, { frame = 20, value = 5.5 }]
"#;

fn track_target() -> BoxedStrategy<String> {
    let kinds = [
        "sphere 1",
        "sphere 2",
        "sphere 3",
        "plane 1",
        "cylinder 1",
        "light 1",
        "light 2",
        "cube 1",
        "fog",
        "",
    ];
    let fields = [
        "center",
        "radius",
        "point",
        "normal",
        "axis",
        "color",
        "color1",
        "color2",
        "color3",
        "kd",
        "kr",
        "kt",
        "ior",
        "bump",
        "position",
        "intensity",
        "distance",
        "size",
    ];
    (
        prop::sample::select(kinds.to_vec()),
        prop::sample::select(fields.to_vec()),
    )
        .prop_map(|(k, f)| format!("\"{k} {f}\""))
        .boxed()
}

fn track_value() -> BoxedStrategy<String> {
    prop_oneof![
        3 => (-3.0f64..3.0).prop_map(|x| format!("{x:?}")),
        3 => ((-3.0f64..3.0), (-0.5f64..1.5), (-3.0f64..3.0)).prop_map(|(x, y, z)| format!("[{x:?}, {y:?}, {z:?}]")),
        2 => (0.0f64..1.0).prop_map(|x| format!("{x:?}")),
        2 => ((0.0f64..1.0), (0.0f64..1.0), (0.0f64..1.0)).prop_map(|(x, y, z)| format!("[{x:?}, {y:?}, {z:?}]")),
        1 => float(),
        1 => point(),
    ]
    .boxed()
}

fn track_table() -> BoxedStrategy<String> {
    let names = |v: &'static [&'static str]| prop::option::of(prop::sample::select(v));
    let key = (
        int(-2..14),
        track_value(),
        names(&["none", "in", "out", "in-out", "inout"]),
    )
        .prop_map(|(f, v, e)| match e {
            Some(e) => format!("{{ frame = {f}, value = {v}, ease = \"{e}\" }}"),
            None => format!("{{ frame = {f}, value = {v} }}"),
        });
    let keys =
        prop::collection::vec(key, 0..5).prop_map(|k| format!("keys = [{}]\n", k.join(", ")));
    let circle = (point(), float(), float()).prop_map(|(c, r, h)| {
        format!("path = \"circle\"\ncenter = {c}\nradius = {r}\nheight = {h}\n")
    });
    (
        track_target(),
        names(&["linear", "smooth", "step", "cubic"]),
        names(&["none", "in", "out", "in-out"]),
        prop_oneof![4 => keys, 1 => circle],
    )
        .prop_map(|(t, i, e, motion)| {
            let mut s = format!("[[track]]\ntarget = {t}\n");
            if let Some(i) = i {
                s += &format!("interpolation = \"{i}\"\n");
            }
            if let Some(e) = e {
                s += &format!("ease = \"{e}\"\n");
            }
            s + &motion
        })
        .boxed()
}

/// A manifest with random tracks over `TRACK_SCENE`: the timeline either accepts it,
/// and then every value at every sampled time is finite and every frame's scene draws
/// a camera, or refuses it with a location inside the text.
fn timeline_ok_or_located(src: String) -> Result<(), String> {
    let shown = src.clone();
    bounded(move || {
        let m = match Manifest::parse(&src, Path::new(MANIFEST_PATH)) {
            Ok(m) => m,
            Err(e) => return check_manifest_error(&src, &e),
        };
        let scene = Scene::parse(TRACK_SCENE, "s.txt").map_err(|e| e.to_string())?;
        let timeline = match Timeline::new(scene, &m) {
            Ok(t) => t,
            Err(e) => return check_manifest_error(&src, &e),
        };
        for frame in 0..m.frames {
            for t in timeline.times(frame) {
                let s = timeline.at(t);
                let values_ok = s
                    .scene
                    .objects
                    .iter()
                    .all(|o| format!("{o:?}").find("NaN").is_none())
                    && s.scene
                        .lights
                        .iter()
                        .all(|l| l.position.is_finite() && l.intensity.is_finite());
                if !values_ok || !s.eye.is_finite() || !s.look_at.is_finite() {
                    return Err(format!("frame {frame} (t = {t}): a value is not finite"));
                }
            }
        }
        Ok(())
    })
    .and_then(|r| r)
    .map_err(|e| format!("{e}\n--- manifest ---\n{shown}\n---"))
}

#[test]
fn the_tracks_seed_resolves_against_its_scene() {
    timeline_ok_or_located(TRACKS.to_string()).unwrap();
    let m = Manifest::parse(TRACKS, Path::new(MANIFEST_PATH)).unwrap();
    let timeline = Timeline::new(Scene::parse(TRACK_SCENE, "s.txt").unwrap(), &m).unwrap();
    assert_eq!(timeline.tracks.len(), 4);
    assert_eq!(timeline.times(0).len(), 3);
}

proptest! {
    #![proptest_config(config(600))]

    #[test]
    fn random_tracks_resolve_or_are_located(
        frames in 1u32..16,
        blur in prop::option::of((0.05f64..1.0, 1u32..5)),
        tracks in prop::collection::vec(track_table(), 1..4),
    ) {
        let mut src = format!("scene = \"s.txt\"\nframes = {frames}\n");
        if let Some((shutter, samples)) = blur {
            src += &format!("[render]\nmotion_blur = {{ shutter = {shutter:?}, samples = {samples} }}\n");
        }
        src += &tracks.concat();
        timeline_ok_or_located(src).map_err(TestCaseError::fail)?;
    }

    #[test]
    fn mutated_tracks_seed(edits in prop::collection::vec(manifest_edit(), 1..4)) {
        let bytes = apply_manifest(TRACKS, &edits);
        let src = String::from_utf8_lossy(&bytes).into_owned();
        timeline_ok_or_located(src).map_err(TestCaseError::fail)?;
    }
}
