//! No NaN and no hang on degenerate geometry (the reliability issue).
//!
//! Each scene is written as Scene.txt text and read with `Scene::parse`, then the colour
//! of EVERY pixel is evaluated with `Tracer::primary` through the scene's camera and must
//! be finite; the image is also rendered twice on the global rayon pool and once each on
//! pools of 1 and 2 threads, and the four must be the same bytes, equal to the clamped
//! per-pixel colours. Scenes: the camera inside an opaque or a glass sphere, lights inside
//! and on objects, rays tangent to spheres and cylinders, rays along a cylinder's axis
//! and along a plane, coordinates of 1e6 with radii of 1e-4, Ior 1 and 0.5, coincident
//! planes and spheres, bump with huge ε, fog with huge and tiny distances, no light and
//! fifty lights, facing mirrors.

use glam::DVec3;
use std::sync::mpsc;
use std::time::Duration;
use whitted::base::to_byte;
use whitted::optics::Ray;
use whitted::render::{render, Options, Picture};
use whitted::shapes::{Quadric, Sphere};
use whitted::trace::{RayCount, Tracer};
use whitted::{Camera, Frame, Scene};

mod extremes;
mod inside;
mod rays;

/// The longest one scene may take (a debug build on a loaded machine included).
const DEADLINE: Duration = Duration::from_secs(120);

// ---------------------------------------------------------------------------------------
// Writing scenes
// ---------------------------------------------------------------------------------------

fn v(p: DVec3) -> String {
    format!("{:?} {:?} {:?}", p.x, p.y, p.z)
}

const RED: &str = "1 0.8 0.2 0.2";
const GREEN: &str = "1 0.2 0.8 0.3";
const WHITE: &str = "1 1 1 1";
const CHECKER: &str = "2 1 0.9 0.9 0.9 0.2 0.2 0.2 0 0 0";
const MARBLE: &str = "2 4 0.9 0.9 0.9 0.2 0.3 0.4 0 0 0";
const PERLIN: &str = "2 2 0.8 0.1 0.0 0.9 0.7 0.1 1 1 1";
const WOOD: &str = "2 3 0.55 0.3 0.1 0.3 0.15 0.05 0 0 0";

const MATTE: &str = "1 0 0 1 0 0";
const SHINY: &str = "0.6 0.3 0 1 0 0";
const MIRROR: &str = "0.2 0.9 0 1 0 0";

fn glass(ior: f64) -> String {
    format!("0.1 0.1 0.9 {ior:?} 0 0")
}

/// A Scene.txt under construction.
#[derive(Clone)]
struct SceneText {
    width: u32,
    height: u32,
    eye: DVec3,
    look: DVec3,
    fog: (u32, f64),
    spheres: Vec<String>,
    planes: Vec<String>,
    cylinders: Vec<String>,
    lights: Vec<String>,
}

impl SceneText {
    fn new(width: u32, height: u32, eye: DVec3, look: DVec3) -> SceneText {
        SceneText {
            width,
            height,
            eye,
            look,
            fog: (0, 0.0),
            spheres: Vec::new(),
            planes: Vec::new(),
            cylinders: Vec::new(),
            lights: Vec::new(),
        }
    }

    fn sphere(mut self, r: f64, c: DVec3, tex: &str, mat: &str) -> Self {
        self.spheres.push(format!("{r:?} {} {tex} {mat}", v(c)));
        self
    }

    fn plane(mut self, p: DVec3, n: DVec3, tex: &str, mat: &str) -> Self {
        self.planes.push(format!("{} {} {tex} {mat}", v(p), v(n)));
        self
    }

    fn cylinder(mut self, axis: DVec3, p: DVec3, r: f64, tex: &str, mat: &str) -> Self {
        self.cylinders
            .push(format!("{} {} {r:?} {tex} {mat}", v(axis), v(p)));
        self
    }

    fn light(mut self, p: DVec3, intensity: f64) -> Self {
        self.lights.push(format!("{} 1 1 1 {intensity:?}", v(p)));
        self
    }

    fn fog(mut self, kind: u32, distance: f64) -> Self {
        self.fog = (kind, distance);
        self
    }

    fn text(&self) -> String {
        let mut s = format!(
            "{} {}\n{}\n{}\n{} {:?}\n{} {} {} {}\n",
            self.width,
            self.height,
            v(self.eye),
            v(self.look),
            self.fog.0,
            self.fog.1,
            self.spheres.len(),
            self.planes.len(),
            self.cylinders.len(),
            self.lights.len()
        );
        for rec in self
            .spheres
            .iter()
            .chain(&self.planes)
            .chain(&self.cylinders)
            .chain(&self.lights)
        {
            s += rec;
            s += "\n";
        }
        s
    }

    /// The camera this scene will have.
    fn camera(&self) -> Camera {
        Camera::new(self.eye, self.look, self.width, self.height).unwrap()
    }
}

/// A floor, a back wall and three spheres around the origin: something to see.
fn room(s: SceneText, offset: DVec3) -> SceneText {
    s.plane(offset, DVec3::Y, CHECKER, SHINY)
        .plane(offset + DVec3::new(0.0, 0.0, -20.0), DVec3::Z, WHITE, MATTE)
        .sphere(1.0, offset + DVec3::new(-2.2, 1.0, 0.0), RED, SHINY)
        .sphere(1.0, offset + DVec3::new(0.0, 1.0, -1.0), MARBLE, MIRROR)
        .sphere(0.9, offset + DVec3::new(2.0, 0.9, 0.5), WHITE, &glass(1.5))
        .light(offset + DVec3::new(-6.0, 8.0, 8.0), 0.9)
}

// ---------------------------------------------------------------------------------------
// Checking
// ---------------------------------------------------------------------------------------

/// What a checked scene gave: every pixel's unclamped colour, and the image.
struct Image {
    colours: Vec<DVec3>,
    frame: Frame,
}

impl Image {
    fn at(&self, i: u32, j: u32) -> DVec3 {
        self.colours[(j * self.frame.width + i) as usize]
    }
}

/// Parses the scene, evaluates every pixel's colour (all must be finite), renders it
/// twice and on rayon pools of 1 and 2 threads (all the same bytes, equal to the clamped
/// colours), all within `DEADLINE`.
fn check(name: &str, scene: &SceneText) -> Image {
    let src = scene.text();
    let label = name.to_string();
    let (tx, rx) = mpsc::channel();
    let worker = std::thread::spawn(move || {
        let scene = Scene::parse(&src, &label).unwrap_or_else(|e| panic!("{e}\n{src}"));
        let (w, h) = (scene.width, scene.height);
        let camera = scene.camera();
        let tracer = Tracer::new(&scene);
        let mut colours = Vec::with_capacity((w * h) as usize);
        let mut bad = Vec::new();
        for j in 0..h {
            for i in 0..w {
                let ray = camera.ray(i as f64 + 0.5, j as f64 + 0.5);
                let c = tracer.primary(&ray, &mut RayCount::default());
                if !c.is_finite() {
                    bad.push(format!("({i}, {j}) = {c}"));
                }
                colours.push(c);
            }
        }
        assert!(
            bad.is_empty(),
            "{label}: {} pixels are not finite: {}\n{src}",
            bad.len(),
            bad.iter().take(8).cloned().collect::<Vec<_>>().join(", ")
        );
        let grid = Options::grid(w, h, 1);
        let first = render(&tracer, &camera, &grid, Picture::new()).0;
        let second = render(&tracer, &camera, &grid, Picture::new()).0;
        let pool = |n| {
            rayon::ThreadPoolBuilder::new()
                .num_threads(n)
                .build()
                .unwrap()
                .install(|| render(&tracer, &camera, &grid, Picture::new()).0)
        };
        let (one, two) = (pool(1), pool(2));
        assert!(first == second, "{label}: two renders differ");
        assert!(
            first == one,
            "{label}: 1 thread differs from the global pool"
        );
        assert!(
            first == two,
            "{label}: 2 threads differ from the global pool"
        );
        let bytes: Vec<u8> = colours
            .iter()
            .flat_map(|c| [to_byte(c.x), to_byte(c.y), to_byte(c.z)])
            .collect();
        assert!(
            first.pixels == bytes,
            "{label}: the image is not the clamped colours"
        );
        let _ = tx.send(Image {
            colours,
            frame: first,
        });
    });
    match rx.recv_timeout(DEADLINE) {
        Ok(image) => {
            worker.join().unwrap();
            image
        }
        Err(mpsc::RecvTimeoutError::Timeout) => panic!("{name}: no image within {DEADLINE:?}"),
        Err(mpsc::RecvTimeoutError::Disconnected) => match worker.join() {
            Err(p) => std::panic::resume_unwind(p),
            Ok(()) => panic!("{name}: the worker ended without an image"),
        },
    }
}

fn close(a: DVec3, b: DVec3) -> bool {
    (a - b).abs().max_element() < 1e-12
}

fn count_non_black(img: &Image) -> usize {
    img.frame
        .pixels
        .chunks(3)
        .filter(|p| p.iter().any(|&b| b > 0))
        .count()
}

// ---------------------------------------------------------------------------------------
// Grazing rays
// ---------------------------------------------------------------------------------------

/// A unit vector perpendicular to both `a` and `b` (b itself when they are parallel).
fn perpendicular(a: DVec3, b: DVec3) -> DVec3 {
    a.cross(b)
        .try_normalize()
        .unwrap_or_else(|| a.any_orthonormal_vector())
}
