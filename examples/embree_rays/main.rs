//! Writes the rays `raytrace SCENE` casts for its picture, and the scene's triangles, for
//! the Embree harness (`benches/embree.sh`, `benches/embree/cast.py`): a developer's
//! tool, not part of `raytrace`.
//!
//!     cargo run --release --features examples --example embree_rays -- SCENE.nff OUT_DIR
//!
//! OUT_DIR gets `triangles.f64`, `rays.f64` and `counts.json` (`dump` says their layout);
//! the rays are the trace loop's, found again by `walk` through the tracer's public
//! queries. A scene that is not all triangles, or that the walk does not follow, is
//! refused (exit 2), as is a bad scene (its file:line:column).

mod dump;
mod walk;

use std::path::PathBuf;
use std::process::ExitCode;

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [scene, dir] = &args[..] else {
        eprintln!("usage: embree_rays SCENE OUT_DIR");
        return ExitCode::from(2);
    };
    let scene = match whitted::Scene::load(&PathBuf::from(scene)) {
        Ok(s) => s,
        Err(e) => {
            eprintln!("embree_rays: {e}");
            return ExitCode::from(2);
        }
    };
    let dir = PathBuf::from(dir);
    if let Err(e) = std::fs::create_dir_all(&dir) {
        eprintln!("embree_rays: {}: {e}", dir.display());
        return ExitCode::from(2);
    }
    match dump::dump(&scene, &dir) {
        Ok(t) => {
            let (c, r, f, s) = (t.camera, t.reflect, t.refract, t.shadow);
            println!("camera {c} reflect {r} refract {f} shadow {s}");
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("embree_rays: {e:#}");
            ExitCode::from(2)
        }
    }
}
