//! Fuzz target: `Scene::parse` on arbitrary bytes (as UTF-8 when they are, lossily
//! decoded otherwise), then, for a scene that parses, a tiny image traced through the
//! library: at most 4×3 pixels whatever the scene's resolution.
//!
//! A crash is any panic, a syntax error whose `file:line:column:` is missing or outside
//! the input, or a non-finite colour in a tame scene (every number up to 1e4 in
//! magnitude, radii and Ior from 1e-4, the extension's shapes and CSG blocks within
//! boxes of that size): extreme but finite values (1e300) may overflow to infinity by
//! design, a tame scene must not.

#![no_main]

use libfuzzer_sys::fuzz_target;
use whitted::bump::Bump;
use whitted::fog::Fog;
use whitted::object::Object;
use whitted::base::to_byte;
use whitted::shapes::Shape;
use whitted::texture::Texture;
use whitted::trace::{RayCount, Tracer};
use whitted::{Camera, Scene, SceneError};

const NAME: &str = "fuzz.txt";

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    match Scene::parse(&text, NAME) {
        Ok(scene) => trace_tiny(&scene),
        Err(e) => check_located(&text, &e),
    }
});

/// The error starts with `fuzz.txt:line:column: ` and points inside the text, at the
/// first character of a token or just past the end.
fn check_located(src: &str, err: &SceneError) {
    let shown = err.to_string();
    let loc = err.loc().unwrap_or_else(|| panic!("no location: {shown}"));
    assert_eq!(loc.file, NAME);
    let prefix = format!("{NAME}:{}:{}: ", loc.line, loc.column);
    assert!(shown.starts_with(&prefix), "{shown}");
    // A leading byte-order mark is not a column.
    let body = src.strip_prefix('\u{feff}').unwrap_or(src);
    let end = (
        body.matches('\n').count() + 1,
        body.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1,
    );
    if (loc.line, loc.column) == end {
        return;
    }
    let c = body
        .split('\n')
        .nth(loc.line.wrapping_sub(1))
        .and_then(|l| l.chars().nth(loc.column.wrapping_sub(1)))
        .unwrap_or_else(|| panic!("outside the input (end {end:?}): {shown}"));
    assert!(
        !c.is_whitespace() && c != '#',
        "points at {c:?}, not at a token: {shown}"
    );
}

fn trace_tiny(scene: &Scene) {
    let (w, h) = (scene.width.min(4), scene.height.min(3));
    let camera = Camera::new(scene.eye, scene.look_at, w, h).expect("a parsed scene's camera");
    let _ = scene.camera();
    let tame = is_tame(scene);
    let tracer = Tracer::new(scene);
    let mut count = RayCount::default();
    for j in 0..h {
        for i in 0..w {
            let c = tracer.primary(&camera.ray(i as f64 + 0.5, j as f64 + 0.5), &mut count);
            assert!(
                !tame || c.is_finite(),
                "pixel ({i}, {j}) = {c} in a tame scene"
            );
            std::hint::black_box([to_byte(c.x), to_byte(c.y), to_byte(c.z)]);
        }
    }
}

const LIMIT: f64 = 1e4;
const TINY: f64 = 1e-4;

fn is_tame(scene: &Scene) -> bool {
    let v = |p: glam::DVec3| p.is_finite() && p.abs().max_element() <= LIMIT;
    let s = |x: f64| x.is_finite() && x.abs() <= LIMIT;
    let obj_ok = |o: &Object| {
        let shape = match o.shape {
            Shape::Sphere(sp) => v(sp.center) && sp.radius >= TINY && s(sp.radius),
            Shape::Plane(pl) => v(pl.point),
            Shape::Quadric(q) => {
                v(q.origin) && q.coef.iter().all(|&c| s(c)) && -q.coef[9] >= TINY * TINY
            }
            // The extension's shapes and CSG blocks: tame when their box is (an unbounded
            // block, e.g. one with a plane, is judged by its other fields).
            Shape::Triangle(_)
            | Shape::Smooth(_)
            | Shape::Cone(_)
            | Shape::Placed(_)
            | Shape::Csg(_) => o
                .shape
                .bounds()
                .is_none_or(|(lo, hi)| v(lo) && v(hi) && (hi - lo).min_element() >= TINY),
        };
        let tex = match o.texture {
            Texture::Uniform(c) => v(c),
            Texture::Checker(a, b) | Texture::Wood(a, b) | Texture::Marble(a, b) => v(a) && v(b),
            Texture::Perlin(a, b, c) => v(a) && v(b) && v(c),
        };
        let m = &o.material;
        let bump = match m.bump {
            Bump::None => true,
            Bump::Uniform(e) | Bump::Water(e) => s(e),
        };
        shape && tex && bump && s(m.kd) && s(m.kr) && s(m.kt) && s(m.ior) && m.ior >= TINY
    };
    let fog_ok = match scene.fog {
        Fog::None => true,
        Fog::Linear(d) | Fog::Exponential(d) | Fog::ExponentialSquared(d) => s(d) && d >= TINY,
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
