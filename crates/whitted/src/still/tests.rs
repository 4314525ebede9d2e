//! The warning before an enormous picture: asked of a small picture, it builds no tracer
//! (whose trees `run` builds anyway), and its ray count is the renderer's arithmetic.

use super::*;
use crate::trace::MADE;

#[test]
fn a_small_pictures_warning_builds_no_tracer() {
    let scene = concat!(env!("CARGO_MANIFEST_DIR"), "/../../scenes/01-ambient.txt");
    let request = Request {
        scene: scene.into(),
        samples: 1,
        ..Request::default()
    };
    let job = Job::prepare(&request).unwrap();
    let before = MADE.with(|m| m.get());
    assert!(job.enormous().is_none());
    assert_eq!(MADE.with(|m| m.get()), before);
}

#[test]
fn a_pictures_camera_rays_are_samples_squared_a_pixel() {
    let src = "1 1  0 1 10  0 0 0  0 0  0 1 0 0\n0 0 0  0 1 0  1 1 1 1  1 0 0 1 0 0\n";
    let scene = Scene::parse(src, "t.txt").unwrap();
    // 16384 × 16384 pixels at 2 × 2 samples: 2^30 camera rays, past 2^28.
    assert_eq!(
        camera_rays(&scene, (16384, 16384), Antialias::Grid(2)),
        1 << 30
    );
    assert_eq!(
        camera_rays(&scene, (640, 480), Antialias::Grid(3)),
        640 * 480 * 9
    );
}
