//! The Embree harness (`benches/embree.sh`): the ray dump of `examples/embree_rays` (its
//! files are included here) casts exactly the rays the real render counts, kind by kind,
//! on the three polygon databases and on report scenes with mirrors, glass, bump and the
//! render's screen tiles and light buffer; it refuses a scene that is not all triangles;
//! and Embree 4 (PyPI embreex, `benches/embree/cast.py`) finds the same hits on tetra.
//! The embreex test says SKIPPED where python3 cannot import embreex (fails under CI);
//! the database tests skip where ../shared is absent.

#[path = "../../examples/embree_rays/dump.rs"]
mod dump;
#[path = "../../examples/embree_rays/walk.rs"]
mod walk;

use crate::nff::spd_dir;
use crate::shipped::root;
use crate::skip::have;
use std::path::Path;
use whitted::render::Antialias;
use whitted::still::Still;
use whitted::trace::{RayCount, Tracer};
use whitted::Scene;

/// The rays the real render of `path` counts (`raytrace PATH`'s: the scene's own size and
/// lens, one ray a pixel), and the dump walk's, by kind as written.
fn both_counts(path: &Path) -> (RayCount, RayCount) {
    let scene = Scene::load(path).unwrap();
    let native = (scene.width, scene.height);
    let lens = scene.lens.overridden(None, 0.0);
    let still = Still::new(&scene, native, native, &lens, Antialias::Grid(1)).unwrap();
    let (_, real) = still.render(whitted::render::Picture::new());
    let tracer = Tracer::new(&scene);
    let camera = walk::camera(&scene).unwrap();
    let mut tally = [0u64; 5];
    let walked = walk::walk(&tracer, &camera, native.0, native.1, &mut |c| {
        tally[c.kind as usize] += 1;
        if c.kind == walk::Kind::Camera && c.hit.is_some() {
            tally[4] += 1;
        }
    })
    .unwrap();
    let [camera, reflect, refract, shadow, eye_hits] = tally;
    let dumped = RayCount {
        primary: camera,
        secondary: reflect + refract,
        shadow,
        eye_hits,
        reflect,
        refract,
    };
    assert_eq!(
        walked,
        dumped,
        "{}: the walk counts what it hands on",
        path.display()
    );
    (real, dumped)
}

#[test]
fn the_dump_casts_the_rays_the_render_counts_on_the_polygon_databases() {
    let Some(dir) = spd_dir() else { return };
    for name in ["tetra", "teapot", "gears"] {
        let (real, dumped) = both_counts(&dir.join(format!("{name}.nff")));
        assert_eq!(dumped, real, "{name}");
        assert!(real.shadow > 0, "{name}: {real:?}");
    }
}

#[test]
fn the_dump_casts_the_rays_the_render_counts_on_report_scenes() {
    // Mirrors and glass (orbit), refraction and total internal reflection (05, 06), bump
    // (09, 10): the weight cut-off, the depth limit and the facing normal all decide.
    let mut kinds = RayCount::default();
    for name in [
        "orbit.txt",
        "05-refraction.txt",
        "06-refraction-indices.txt",
        "09-bump-mapping.txt",
        "10-water-bump.txt",
    ] {
        let (real, dumped) = both_counts(&root().join("scenes").join(name));
        assert_eq!(dumped, real, "{name}");
        kinds = kinds + real;
    }
    assert!(
        kinds.reflect > 0 && kinds.refract > 0 && kinds.shadow > 0,
        "{kinds:?}"
    );
}

#[test]
fn the_dump_refuses_a_scene_that_is_not_triangles() {
    let scene = Scene::load(&root().join("scenes/orbit.txt")).unwrap();
    let out = tempfile::tempdir().unwrap();
    let err = dump::dump(&scene, out.path()).unwrap_err().to_string();
    assert!(err.contains("object 1 is not a triangle"), "{err}");
    assert!(!out.path().join("rays.f64").exists());
}

/// `benches/embree/cast.py` on the dump in `dir`: its JSON report.
fn cast(dir: &Path) -> serde_json::Value {
    let run = std::process::Command::new("python3")
        .arg(root().join("benches/embree/cast.py"))
        .arg(dir)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert!(run.status.success(), "{stderr}");
    serde_json::from_slice(&run.stdout).unwrap()
}

#[test]
fn embree_finds_our_hits_on_tetra() {
    let Some(dir) = spd_dir() else { return };
    if !have("python3", &["-c", "import embreex"]) {
        return;
    }
    let scene = Scene::load(&dir.join("tetra.nff")).unwrap();
    let out = tempfile::tempdir().unwrap();
    let tally = dump::dump(&scene, out.path()).unwrap();
    let rays = std::fs::read(out.path().join("rays.f64")).unwrap();
    let total = tally.camera + tally.reflect + tally.refract + tally.shadow;
    assert_eq!(rays.len() as u64, total * 8 * dump::RAY_FLOATS as u64);
    let r = cast(out.path());
    assert_eq!(r["embree"].as_str().unwrap().split('.').next(), Some("4"));
    assert_eq!(r["rays"]["camera"], 512 * 512);
    assert_eq!(r["rays"]["shadow"], tally.shadow);
    assert_eq!(r["triangles"], 4096);
    // Every camera ray but at most one in 10^4 meets the same triangle at the same t
    // (within 1e-4 relative), and all rays agree but one in 10^3.
    assert!(r["agree"]["camera"].as_f64().unwrap() >= 0.9999, "{r}");
    assert!(r["same_triangle"].as_f64().unwrap() >= 0.9999, "{r}");
    assert!(r["agree_all"].as_f64().unwrap() >= 0.999, "{r}");

    // The check is not vacuous: with our t of every camera hit moved by 1 %, only the
    // camera rays that miss still agree.
    let mut moved = rays.clone();
    for row in moved.chunks_exact_mut(8 * dump::RAY_FLOATS) {
        let f =
            |k: usize, row: &[u8]| f64::from_le_bytes(row[8 * k..8 * k + 8].try_into().unwrap());
        let (kind, t) = (f(0, row), f(9, row));
        if kind == 0.0 && t.is_finite() {
            row[72..80].copy_from_slice(&(t * 1.01).to_le_bytes());
        }
    }
    let bad = tempfile::tempdir().unwrap();
    std::fs::write(bad.path().join("rays.f64"), moved).unwrap();
    for name in ["triangles.f64", "counts.json"] {
        std::fs::copy(out.path().join(name), bad.path().join(name)).unwrap();
    }
    let b = cast(bad.path());
    let misses = 1.0 - tally.eye_hits as f64 / tally.camera as f64;
    let camera = b["agree"]["camera"].as_f64().unwrap();
    assert!((camera - misses).abs() < 1e-4, "{camera} vs {misses}: {b}");
}
