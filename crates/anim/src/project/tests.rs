use super::*;
use whitted::render::{render, Options, Picture};
use whitted::trace::Tracer;

/// A still of `scene` through `cam` at 16×12, one sample a pixel.
fn still(scene: &Scene, cam: &Camera) -> Frame {
    let grid = Options::grid(16, 12, 1);
    render(&Tracer::new(scene), cam, &grid, Picture::new()).0
}

fn project(manifest: &str, scene: &str) -> (tempfile::TempDir, Project) {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("s.txt"), scene).unwrap();
    let path = dir.path().join("m.toml");
    std::fs::write(&path, format!("scene = \"s.txt\"\nframes = 10\n{manifest}")).unwrap();
    let p = Project::load(&path).unwrap();
    (dir, p)
}

const SCENE: &str = "16 12  0 1 6  0 1 0  0 0  1 1 0 1
1.0  0 1 0   1 0.9 0.2 0.1   0.7 0.3 0 1 0 0
0 0 0  0 1 0   2 1 1 1 1 0 0 0 0 0 0   0.9 0 0 1 0 0
5 10 5  1 1 1  0.9";

#[test]
fn a_missing_scene_is_reported_at_the_manifest_line() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("m.toml");
    std::fs::write(&path, "frames = 3\nscene = \"nowhere.txt\"\n").unwrap();
    let Err(e) = Project::load(&path) else {
        panic!("loaded")
    };
    let shown = e.to_string();
    assert!(
        shown.starts_with(&format!("{}:2:9: scene: cannot read ", path.display())),
        "{shown}"
    );
    assert_eq!(e.exit_code(), 2);
}

#[test]
fn motion_blur_is_the_mean_of_the_sub_frames() {
    let track = "[[track]]\ntarget = \"sphere 1 center\"\nkeys = [{ frame = 0, value = [-1.0, 1.0, 0.0] }, { frame = 9, value = [1.0, 1.0, 0.0] }]\n";
    let blur = "[render]\nmotion_blur = { shutter = 1.0, samples = 4 }\n";
    let (_d, p) = project(&format!("{blur}{track}"), SCENE);
    let anim = Animation::new(&p).unwrap();
    let (frame, _) = anim.render(&anim.plan(5)).unwrap();
    // Each sub-frame drawn on its own, as a still of the scene at t_k.
    let stills: Vec<Frame> = p
        .timeline
        .times(5)
        .iter()
        .map(|&t| {
            let s = p.timeline.at(t);
            let cam = Camera::new(s.eye, s.look_at, 16, 12).unwrap();
            still(&s.scene, &cam)
        })
        .collect();
    let mut differs = false;
    for (i, &v) in frame.pixels.iter().enumerate() {
        let mean = stills.iter().map(|f| f64::from(f.pixels[i])).sum::<f64>() / 4.0;
        assert!(
            (f64::from(v) - mean).abs() <= 1.0,
            "byte {i}: {v} vs {mean}"
        );
        differs |= stills.iter().any(|f| f.pixels[i] != stills[0].pixels[i]);
    }
    assert!(differs, "the sub-frames should differ: the sphere moves");
}

#[test]
fn one_structure_serves_frames_whose_geometry_holds() {
    let colour = "[[track]]\ntarget = \"sphere 1 color\"\nkeys = [{ frame = 0, value = [0.0, 0.0, 1.0] }, { frame = 9, value = [1.0, 0.0, 0.0] }]\n";
    let (_d, p) = project(colour, SCENE);
    let anim = Animation::new(&p).unwrap();
    assert!(anim.shared.is_some());
    // Drawn through the shared structure, frame 4 is the still of its scene.
    let s = p.timeline.at(4.0);
    let cam = Camera::new(s.eye, s.look_at, 16, 12).unwrap();
    assert_eq!(anim.render(&anim.plan(4)).unwrap().0, still(&s.scene, &cam));
    let moving = "[[track]]\ntarget = \"sphere 1 radius\"\nkeys = [{ frame = 0, value = 1.0 }, { frame = 9, value = 0.5 }]\n";
    let (_d, p) = project(moving, SCENE);
    assert!(Animation::new(&p).unwrap().shared.is_none());
}

#[test]
fn sizes_past_the_limits_are_refused() {
    let (_d, p) = project("", SCENE);
    assert!(Animation::with_size(&p, 16385, 1).is_err());
    assert!(Animation::with_size(&p, 16384, 4096).is_ok());
}

fn window_for(width: u32, height: u32, threads: usize, per_thread: usize) -> usize {
    let (_d, p) = project("", SCENE);
    let anim = Animation::with_size(&p, width, height).unwrap();
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .unwrap();
    pool.install(|| anim.window(per_thread))
}

#[test]
fn window_is_per_thread_for_small_frames() {
    assert_eq!(window_for(640, 480, 2, 4), 8);
    assert_eq!(window_for(640, 480, 3, 2), 6);
}

#[test]
fn window_is_capped_by_memory_for_huge_frames() {
    // The largest frame, 2^26 pixels: 192 MiB, twice with its encoded copy, so two fit
    // in 1 GiB however many threads there are.
    assert_eq!(window_for(16384, 4096, 64, 4), 2);
    assert_eq!(window_for(8192, 8192, 64, 2), 2);
    assert_eq!(window_for(8192, 8192, 1, 1), 1);
}
