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

mod findings;
mod manifest_properties;
mod manifests;
mod properties;
mod seeds;
mod tracks;
