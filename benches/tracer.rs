//! Micro and frame benchmarks of the tracer (criterion):
//!
//!     CARGO_TARGET_DIR=/work/target-perf cargo bench --bench tracer
//!     CARGO_TARGET_DIR=/work/target-perf cargo bench --bench tracer -- shapes   # a group
//!
//! - `camera`: primary ray generation for one 640-pixel row;
//! - `shapes`: one intersection of each shape (sphere hit and miss, plane, axis-aligned
//!   and slanted cylinder);
//! - `queries`: nearest hit and shadow query (transmission) of the orbit scene and of the
//!   10,000-sphere scene;
//! - `texture`: noise and the three noise textures;
//! - `frame`: whole frames at 160x120 (orbit; 10 and 10,000 spheres, parse + BVH + render),
//!   and building the tracer (the BVH) of the 10,000-sphere scene;
//! - `gltf`: posing a skinned glTF mesh of 100,000 vertices for one frame (the skinning
//!   alone, and the whole scene of the frame);
//! - `degenerate`: what degenerate input costs: a 64x48 frame of a mesh of 400,000
//!   copies of one triangle against 400,000 distinct ones (at most 10x), and reading a
//!   convex NFF polygon of 40,000 and 200,000 vertices (linear: about 5x apart).
//!
//! The sphere scenes are generated here by the same generator as benches/gen_spheres.py
//! (same LCG, same layout), so nothing large is stored in the repository.

use criterion::{black_box, criterion_group, criterion_main, BenchmarkId, Criterion};
use glam::DVec3;
use std::time::Duration;
use whitted::base::Color;
use whitted::camera::Camera;
use whitted::noise::noise;
use whitted::optics::Ray;
use whitted::render::{render, Options, Picture};
use whitted::shapes::{Plane, Quadric, Shape, Sphere};
use whitted::texture::Texture;
use whitted::trace::{RayCount, Tracer};
use whitted::Scene;

const ORBIT: &str = include_str!("pov/orbit.txt");

/// benches/gen_spheres.py in Rust: `n` small spheres over the checker floor.
fn spheres_scene(n: usize, w: u32, h: u32) -> String {
    let mut state: u64 = 12345;
    let mut rnd = || {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut out = format!(
        "# {n} small spheres over a checker floor (benches/gen_spheres.py {n})\n\
         {w} {h}\n0 3 12\n0 1 0\n2 40\n{n} 1 0 2\n"
    );
    for i in 0..n {
        let r = 0.05 + 0.07 * rnd();
        let x = -20.0 + 40.0 * rnd();
        let z = -40.0 + 46.0 * rnd();
        let (cr, cg, cb) = (0.2 + 0.8 * rnd(), 0.2 + 0.8 * rnd(), 0.2 + 0.8 * rnd());
        let mat = if i % 25 == 7 {
            "0.1 0.1 0.8 1.5 0 0"
        } else if i % 10 == 3 {
            "0.2 0.8 0.0 1.0 0 0"
        } else {
            "0.8 0.0 0.0 1.0 0 0"
        };
        out += &format!("{r:.4} {x:.4} {r:.4} {z:.4}  1 {cr:.3} {cg:.3} {cb:.3}  {mat}\n");
    }
    out += "0 0 0  0 1 0  2 1 1 1 1 0.1 0.1 0.1 0 0 0  0.9 0.0 0.0 1.0 0 0\n";
    out += "5 10 5  1 1 1  0.8\n-6 8 3  1 0.9 0.8  0.5\n";
    out
}

fn parse(src: &str) -> Scene {
    Scene::parse(src, "bench").expect("bench scene parses")
}

fn camera(c: &mut Criterion) {
    let cam = Camera::new(
        DVec3::new(0.0, 3.0, 12.0),
        DVec3::new(0.0, 1.0, 0.0),
        640,
        480,
    )
    .unwrap();
    c.bench_function("camera/row_of_640_rays", |b| {
        b.iter(|| {
            let mut acc = DVec3::ZERO;
            for i in 0..640 {
                acc += cam.ray(black_box(i as f64 + 0.5), black_box(240.5)).dir;
            }
            acc
        })
    });
}

fn shapes(c: &mut Criterion) {
    let mut g = c.benchmark_group("shapes");
    let ray = Ray::new(
        DVec3::new(0.3, 3.0, 12.0),
        DVec3::new(0.0, -0.15, -1.0).normalize(),
    );
    let cases = [
        (
            "sphere_hit",
            Shape::Sphere(Sphere::new(DVec3::new(0.0, 1.0, 0.0), 1.0)),
        ),
        (
            "sphere_miss",
            Shape::Sphere(Sphere::new(DVec3::new(4.0, 1.0, 0.0), 1.0)),
        ),
        ("plane", Shape::Plane(Plane::new(DVec3::ZERO, DVec3::Y))),
        (
            "cylinder_y",
            Shape::Quadric(Quadric::cylinder(DVec3::Y, DVec3::ZERO, 0.35)),
        ),
        (
            "cylinder_slanted",
            Shape::Quadric(Quadric::cylinder(
                DVec3::new(1.0, 1.0, 0.3),
                DVec3::ZERO,
                0.35,
            )),
        ),
    ];
    for (name, shape) in cases {
        g.bench_function(name, |b| {
            b.iter(|| black_box(&shape).hit(black_box(&ray), f64::INFINITY))
        });
    }
    g.finish();
}

/// Rays of the scene's own camera over a 32x24 grid, and the surface points they hit.
fn sample_rays(scene: &Scene, tracer: &Tracer) -> (Vec<Ray>, Vec<DVec3>) {
    let cam = Camera::new(scene.eye, scene.look_at, 32, 24).unwrap();
    let rays: Vec<Ray> = (0..24)
        .flat_map(|j| (0..32).map(move |i| (i, j)))
        .map(|(i, j)| cam.ray(i as f64 + 0.5, j as f64 + 0.5))
        .collect();
    let points = rays
        .iter()
        .filter_map(|r| tracer.nearest(r).map(|(t, _)| r.at(t)))
        .collect();
    (rays, points)
}

fn queries(c: &mut Criterion) {
    let mut g = c.benchmark_group("queries");
    let orbit = parse(ORBIT);
    let many = parse(&spheres_scene(10_000, 160, 120));
    for (name, scene) in [("orbit", &orbit), ("spheres10000", &many)] {
        let tracer = Tracer::new(scene);
        let (rays, points) = sample_rays(scene, &tracer);
        let light = scene.lights[0].position;
        g.bench_with_input(
            BenchmarkId::new("nearest_768_rays", name),
            &rays,
            |b, rays| b.iter(|| rays.iter().filter(|r| tracer.nearest(r).is_some()).count()),
        );
        g.bench_with_input(
            BenchmarkId::new("shadow_queries", name),
            &points,
            |b, points| {
                b.iter(|| {
                    let mut sum = Color::ZERO;
                    for &p in points {
                        let to = light - p;
                        let d = to.length();
                        sum += tracer.transmission(p, to / d, d);
                    }
                    sum
                })
            },
        );
    }
    g.finish();
}

fn texture(c: &mut Criterion) {
    let mut g = c.benchmark_group("texture");
    let p = DVec3::new(3.15, 42.0, 7.0);
    g.bench_function("noise", |b| {
        b.iter(|| noise(black_box(p.x), black_box(p.y), black_box(p.z)))
    });
    let (c1, c2, c3) = (
        Color::new(1.0, 0.0, 0.0),
        Color::new(0.0, 1.0, 0.0),
        Color::ONE,
    );
    for (name, t) in [
        ("checker", Texture::Checker(c1, c2)),
        ("perlin", Texture::Perlin(c1, c2, c3)),
        ("wood", Texture::Wood(c1, c2)),
        ("marble", Texture::Marble(c1, c2)),
    ] {
        g.bench_function(name, |b| b.iter(|| black_box(&t).color_at(black_box(p))));
    }
    g.finish();
}

fn frame(c: &mut Criterion) {
    let mut g = c.benchmark_group("frame");
    g.sample_size(10).measurement_time(Duration::from_secs(10));
    let orbit = parse(ORBIT);
    let tracer = Tracer::new(&orbit);
    let cam = Camera::new(orbit.eye, orbit.look_at, 160, 120).unwrap();
    g.bench_function("orbit_160x120", |b| {
        let grid = Options::grid(160, 120, 1);
        b.iter(|| render(&tracer, &cam, &grid, Picture::new()).1.total())
    });
    // The whole job the 10 vs 10,000 target measures: parse, build the BVH, render.
    for n in [10usize, 10_000] {
        let src = spheres_scene(n, 160, 120);
        g.bench_with_input(BenchmarkId::new("spheres_160x120", n), &src, |b, src| {
            b.iter(|| {
                let scene = parse(src);
                let tracer = Tracer::new(&scene);
                let cam = scene.camera();
                let grid = Options::grid(160, 120, 1);
                let (_, count): (_, RayCount) = render(&tracer, &cam, &grid, Picture::new());
                count.total()
            })
        });
    }
    let many = parse(&spheres_scene(10_000, 160, 120));
    g.bench_function("build_tracer_10000", |b| {
        b.iter(|| Tracer::new(black_box(&many)).scene().objects.len())
    });
    g.bench_function("parse_10000", |b| {
        let src = spheres_scene(10_000, 160, 120);
        b.iter(|| parse(black_box(&src)).objects.len())
    });
    g.finish();
}

/// An OBJ of `n` copies of one triangle (`copies`) or of `n` distinct small ones over
/// the same unit square.
fn triangles_obj(n: usize, copies: bool) -> String {
    use std::fmt::Write as _;
    if copies {
        return String::from("v 0 0 0\nv 1 0 0\nv 0 1 0\n") + &"f 1 2 3\n".repeat(n);
    }
    let side = (n as f64).sqrt().ceil() as usize;
    let h = 1.0 / side as f64;
    let mut s = String::with_capacity(n * 60);
    for k in 0..n {
        let (x, y) = ((k % side) as f64 * h, (k / side) as f64 * h);
        let _ = writeln!(s, "v {x} {y} 0\nv {} {y} 0\nv {x} {} 0", x + h, y + h);
    }
    for k in 0..n {
        let _ = writeln!(s, "f {} {} {}", 3 * k + 1, 3 * k + 2, 3 * k + 3);
    }
    s
}

/// An NFF scene of one convex polygon of `n` vertices on a circle.
fn polygon_nff(n: usize) -> String {
    use std::fmt::Write as _;
    let mut s = String::from(
        "v\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 40\nhither 1\nresolution 16 16\n\
         l 0 0 5\nf 1 0.5 0.2 1 0 0 0 0\n",
    );
    let _ = writeln!(s, "p {n}");
    for i in 0..n {
        let a = std::f64::consts::TAU * i as f64 / n as f64;
        let _ = writeln!(s, "{} {} 0", a.cos(), a.sin());
    }
    s
}

fn degenerate(c: &mut Criterion) {
    let mut g = c.benchmark_group("degenerate");
    g.sample_size(10).measurement_time(Duration::from_secs(20));
    let dir = tempfile::tempdir().unwrap();
    for (name, copies) in [("copies", true), ("distinct", false)] {
        let obj = dir.path().join(format!("{name}.obj"));
        std::fs::write(&obj, triangles_obj(400_000, copies)).unwrap();
        let scene = dir.path().join(format!("{name}.txt"));
        let text = format!(
            "64 48\n0.3 0.3 3\n0.3 0.3 0\n0 1\n0 0 0 1\n0 1 4  1 1 1  1\n\
             mesh \"{name}.obj\"  1 0.8 0.6 0.2  0.8 0 0 1 0 0\n"
        );
        std::fs::write(&scene, text).unwrap();
        g.bench_function(BenchmarkId::new("mesh_400k_frame", name), |b| {
            b.iter(|| {
                let scene = Scene::load(&scene).unwrap();
                let tracer = Tracer::new(&scene);
                let grid = Options::grid(64, 48, 1);
                black_box(render(&tracer, &scene.camera(), &grid, Picture::new()))
            })
        });
    }
    for n in [40_000, 200_000] {
        let text = polygon_nff(n);
        g.bench_function(BenchmarkId::new("convex_polygon_read", n), |b| {
            b.iter(|| black_box(Scene::parse(&text, "polygon.nff").unwrap()))
        });
    }
    g.finish();
}

/// A skinned grid of `n`×`n` vertices (two joints, weights blending across it) and one
/// animation turning the second joint: what a glTF character's frame costs to pose.
fn skinned_rig(n: usize) -> whitted::gltf::Model {
    use whitted::gltf::clip::{Channel, Clip, Interp, Path};
    use whitted::gltf::rig::{Local, Node, Prim, Rig, Skin};
    let mut prim = Prim::default();
    for i in 0..n {
        for j in 0..n {
            let (x, y) = (i as f64 / n as f64, j as f64 / n as f64);
            prim.positions.push(DVec3::new(x, y, 0.0));
            prim.normals.push(DVec3::Z);
            prim.joints.push([0, 1, 0, 0]);
            prim.weights.push([1.0 - x, x, 0.0, 0.0]);
        }
    }
    for i in 0..n as u32 - 1 {
        for j in 0..n as u32 - 1 {
            let k = i * n as u32 + j;
            prim.triangles.push([k, k + n as u32, k + 1]);
            prim.triangles.push([k + 1, k + n as u32, k + n as u32 + 1]);
        }
    }
    let still = |name: &str, children: Vec<usize>| Node {
        name: Some(name.into()),
        children,
        local: Local::Matrix(glam::DMat4::IDENTITY),
        mesh: None,
        camera: None,
        light: None,
        skin: None,
        weights: None,
    };
    let mut mesh = still("Grid", vec![]);
    (mesh.mesh, mesh.skin) = (Some(0), Some(0));
    let rig = Rig {
        file: "bench".into(),
        nodes: vec![mesh, still("Root", vec![2]), still("Bend", vec![])],
        roots: vec![0, 1],
        meshes: vec![vec![prim]],
        mesh_weights: vec![vec![]],
        looks: vec![whitted::mesh::Look {
            texture: Texture::Uniform(Color::ONE),
            material: whitted::gltf::material::terms(Color::ONE, 0.0, 1.0, 0.0, 1.0, 0).0,
        }],
        pbr: vec![whitted::gltf::material::terms(Color::ONE, 0.0, 1.0, 0.0, 1.0, 0).1],
        double_sided: vec![false],
        skins: vec![Skin {
            joints: vec![1, 2],
            inverse_bind: vec![glam::DMat4::IDENTITY; 2],
        }],
        clips: vec![Clip {
            name: Some("Bend".into()),
            channels: vec![Channel {
                node: 2,
                path: Path::Rotation,
                interp: Interp::Linear,
                times: vec![0.0, 1.0],
                values: vec![0.0, 0.0, 0.0, 1.0, 0.0, 0.3826834, 0.0, 0.9238795],
                width: 4,
            }],
        }],
        ..Rig::default()
    };
    whitted::gltf::Model {
        rig: std::sync::Arc::new(rig),
        options: Default::default(),
        posed: None,
    }
}

/// Posing a glTF character: the skinning of 100,000 vertices alone (`Pose::at` and
/// `pose::place`), and the whole scene of a frame from the file (skinning, the mesh's
/// triangles kept, normals, the view and lights).
fn gltf(c: &mut Criterion) {
    let model = skinned_rig(317); // 100,489 vertices
    let mut g = c.benchmark_group("gltf");
    g.sample_size(20).measurement_time(Duration::from_secs(6));
    let rig = &model.rig;
    g.bench_function("skin 100k vertices", |b| {
        b.iter(|| {
            let pose = whitted::gltf::Pose::at(rig, black_box(0.5), &[0], &[]);
            whitted::gltf::pose::place(rig, &pose, 0, &rig.meshes[0][0])
        })
    });
    g.bench_function("scene of a skinned frame, 100k vertices", |b| {
        b.iter(|| model.scene_at(black_box(0.5), &[0], &[]).unwrap())
    });
    g.finish();
}

criterion_group!(benches, camera, shapes, queries, texture, frame, degenerate, gltf);
criterion_main!(benches);
