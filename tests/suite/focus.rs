//! Depth of field (`focus Aperture Distance Samples`): a render through the thin lens is
//! the mean of pinhole renders from the same lens points, each a camera sheared so that
//! every pixel's ray meets the plane in focus where the eye's pinhole ray does (the lens
//! points computed here from SPEC §16's formula: cell centres, Shirley's concentric map,
//! eye + (Aperture/2)·(x·D + y·H')), each ray clamped before the mean; with `samples` the
//! lens samples multiply the pixel's; the same bytes on 1 and 2 threads; and a scene
//! without `focus` is untouched by the lens code.

use crate::support::raytrace;
use glam::DVec3;
use whitted::base::to_byte;
use whitted::base::Color;
use whitted::base::Frame;
use whitted::camera::thin_lens::concentric;
use whitted::camera::Camera;
use whitted::optics::Ray;
use whitted::render::{render, Options, Picture};
use whitted::trace::{RayCount, Tracer};
use whitted::Scene;

const W: u32 = 48;
const H: u32 = 36;

/// Three balls at 4, 8 and 14 from the eye, a checker floor, one light; in focus at 8.
const SCENE: &str = "48 36  0 1.5 8  0 1 0  0 0  3 1 0 1
0.8  -1.5 0.8 4   1 0.9 0.3 0.2   0.7 0 0 1 0 0
0.8   0 0.8 0     1 0.2 0.8 0.3   0.6 0.3 0 1 0 0
0.8   2 0.8 -6    1 0.3 0.4 0.9   0.7 0 0 1 0 0
0 0 0  0 1 0   2 1 1 1 1 0.1 0.1 0.1 0 0 0   0.9 0 0 1 0 0
4 8 6  1 1 1  1
focus 0.6 8 3
";

/// The lens points of §16 for `camera` (i major, j minor).
fn lens_points(scene: &Scene) -> Vec<DVec3> {
    let f = scene.ext.focus.unwrap();
    let cam = scene.camera();
    let (right, up, _) = cam.basis();
    let n = f.samples;
    let mut out = Vec::new();
    for i in 0..n {
        for j in 0..n {
            let a = 2.0 * (f64::from(i) + 0.5) / f64::from(n) - 1.0;
            let b = 2.0 * (f64::from(j) + 0.5) / f64::from(n) - 1.0;
            let (x, y) = concentric(a, b);
            out.push(cam.eye() + f.aperture / 2.0 * (x * right + y * up));
        }
    }
    out
}

/// The colour of the pinhole render from lens point `q` at image point (x, y): the
/// camera sheared onto the focal plane.
fn sheared(tracer: &Tracer, scene: &Scene, q: DVec3, x: f64, y: f64) -> Color {
    let cam = scene.camera();
    let (_, _, forward) = cam.basis();
    let d = cam.ray(x, y).dir;
    let f = cam.eye() + d * (scene.ext.focus.unwrap().distance / d.dot(forward));
    let ray = Ray::new(q, (f - q).normalize());
    let c = tracer.primary(&ray, &mut RayCount::default());
    c.clamp(Color::ZERO, Color::ONE)
}

/// The mean over the lens points of the sheared pinhole renders, each pixel sampled on
/// an n×n grid, every ray clamped: the frame's bytes.
fn mean_of_pinholes(scene: &Scene, n: u32) -> Vec<u8> {
    let tracer = Tracer::new(scene);
    let points = lens_points(scene);
    let mut bytes = Vec::new();
    for j in 0..H {
        for i in 0..W {
            let mut pixel = Color::ZERO;
            for b in 0..n {
                for a in 0..n {
                    let x = f64::from(i) + (f64::from(a) + 0.5) / f64::from(n);
                    let y = f64::from(j) + (f64::from(b) + 0.5) / f64::from(n);
                    let mut sum = Color::ZERO;
                    for &q in &points {
                        sum += sheared(&tracer, scene, q, x, y);
                    }
                    pixel += (sum / points.len() as f64).clamp(Color::ZERO, Color::ONE);
                }
            }
            let c = pixel / f64::from(n * n);
            bytes.extend([to_byte(c.x), to_byte(c.y), to_byte(c.z)]);
        }
    }
    bytes
}

/// The W×H picture of `tracer`'s scene through `camera`, n×n samples a pixel.
fn picture(tracer: &Tracer, camera: &Camera, n: u32) -> (Frame, RayCount) {
    render(tracer, camera, &Options::grid(W, H, n), Picture::new())
}

#[test]
fn focus_is_the_mean_of_sheared_pinhole_renders() {
    let scene = Scene::parse(SCENE, "focus.txt").unwrap();
    let tracer = Tracer::new(&scene);
    for n in [1, 2] {
        let (frame, rays) = picture(&tracer, &scene.camera(), n);
        let want = mean_of_pinholes(&scene, n);
        let apart = frame
            .pixels
            .iter()
            .zip(&want)
            .filter(|(a, b)| a != b)
            .count();
        assert_eq!(apart, 0, "samples {n}: {apart} channels differ");
        // Nine lens rays per camera sample.
        assert_eq!(rays.primary, u64::from(W * H * n * n * 9));
    }
    // The lens blurs: the frame is not the pinhole's (the near ball is out of focus).
    let mut pinhole = scene.clone();
    pinhole.ext.focus = None;
    let (sharp, _) = picture(&Tracer::new(&pinhole), &pinhole.camera(), 1);
    let (soft, _) = picture(&tracer, &scene.camera(), 1);
    let differ = sharp
        .pixels
        .iter()
        .zip(&soft.pixels)
        .filter(|(a, b)| a != b);
    assert!(differ.count() > 100);
}

#[test]
fn focus_gives_the_same_bytes_on_one_and_two_threads() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("scene.txt"), SCENE).unwrap();
    let mut frames = Vec::new();
    for (threads, extra) in [
        ("1", None),
        ("2", None),
        ("1", Some("adaptive")),
        ("2", Some("adaptive")),
    ] {
        let out = format!("t{threads}{}.png", extra.unwrap_or(""));
        let mut cmd = raytrace();
        cmd.current_dir(dir.path())
            .args(["scene.txt", "-q", "--threads", threads, "-o", &out]);
        if let Some(aa) = extra {
            cmd.args(["--aa", aa]);
        }
        let got = cmd.output().unwrap();
        assert!(
            got.status.success(),
            "{}",
            String::from_utf8_lossy(&got.stderr)
        );
        frames.push(std::fs::read(dir.path().join(out)).unwrap());
    }
    assert_eq!(frames[0], frames[1]);
    assert_eq!(frames[2], frames[3]);
}

#[test]
fn exr_passes_with_focus_count_every_lens_ray() {
    // The layered render adds each lens ray as a sample: its beauty, clamped and rounded,
    // is the PNG's wherever no ray of the pixel is brighter than 1 (here: everywhere).
    let dir = tempfile::tempdir().unwrap();
    let scene = SCENE.replace("4 8 6  1 1 1  1", "4 8 6  1 1 1  0.6");
    std::fs::write(dir.path().join("scene.txt"), scene).unwrap();
    for args in [
        vec!["-o", "f.png"],
        vec![
            "-o",
            "f.exr",
            "--exr-depth",
            "float",
            "--colour",
            "linear",
            "--passes",
            "all",
        ],
    ] {
        let got = raytrace()
            .current_dir(dir.path())
            .args(["scene.txt", "-q"])
            .args(args)
            .output()
            .unwrap();
        assert!(
            got.status.success(),
            "{}",
            String::from_utf8_lossy(&got.stderr)
        );
    }
    let png = image::open(dir.path().join("f.png")).unwrap().to_rgb8();
    let exr_path = dir.path().join("f.exr");
    let format = whitted::output::ImageFormat::from_path(&exr_path).unwrap();
    let exr = whitted::output::read_rgb(&exr_path, format, W, H).unwrap();
    let worst = png
        .as_raw()
        .iter()
        .zip(&exr)
        .map(|(a, b)| a.abs_diff(*b))
        .max()
        .unwrap();
    assert!(worst <= 1, "the EXR beauty is {worst} levels from the PNG");
}
