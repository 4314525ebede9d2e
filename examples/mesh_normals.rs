//! The cost of `smooth` normals (SPEC §18, issue 55's speed goal: a million triangles
//! under 0.3 s, near-linear at any valence), timed on meshes made here:
//!
//!     cargo run --release --features examples --example mesh_normals   # best of 5 runs each: CPU and wall time
//!
//! - a torus of 1000 × 500 quads cut in two: 1,000,000 triangles, 500,000 vertices
//!   (valence 6), with a crease every 50 rings (smooth 30 splits there);
//! - a fan of 300,000 triangles around one vertex (valence 300,000), a cone;
//! - the same torus at 250,000 triangles, to show the time grows linearly.

use glam::DVec3;
use std::time::Instant;
use whitted::mesh::normals::smooth;

/// A torus of `nu` × `nv` quads (two triangles each); every 50th ring is pinched so
/// that faces meet at a crease there.
fn torus(nu: u32, nv: u32) -> (Vec<DVec3>, Vec<[u32; 3]>) {
    let mut v = Vec::with_capacity((nu * nv) as usize);
    for i in 0..nu {
        let a = i as f64 / nu as f64 * std::f64::consts::TAU;
        let r = if i % 50 == 0 { 0.3 } else { 0.4 };
        for j in 0..nv {
            let b = j as f64 / nv as f64 * std::f64::consts::TAU;
            let (x, y) = (1.0 + r * b.cos(), r * b.sin());
            v.push(DVec3::new(x * a.cos(), y, x * a.sin()));
        }
    }
    let id = |i: u32, j: u32| (i % nu) * nv + (j % nv);
    let mut t = Vec::with_capacity((2 * nu * nv) as usize);
    for i in 0..nu {
        for j in 0..nv {
            let (p, q, r, s) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
            t.extend([[p, q, r], [p, r, s]]);
        }
    }
    (v, t)
}

/// `n` triangles around the apex of a cone.
fn fan(n: u32) -> (Vec<DVec3>, Vec<[u32; 3]>) {
    let mut v = vec![DVec3::new(0.0, 1.0, 0.0)];
    v.extend((0..n).map(|k| {
        let a = k as f64 / n as f64 * std::f64::consts::TAU;
        DVec3::new(a.cos(), 0.0, a.sin())
    }));
    let t = (0..n).map(|k| [0, (k + 1) % n + 1, k + 1]).collect();
    (v, t)
}

/// This thread's time on a CPU so far, in seconds (Linux's /proc/thread-self/schedstat),
/// which a loaded machine does not inflate as it does the wall time.
fn cpu() -> f64 {
    let stat = std::fs::read_to_string("/proc/thread-self/schedstat").unwrap_or_default();
    let ns: f64 = stat
        .split_whitespace()
        .next()
        .and_then(|s| s.parse().ok())
        .unwrap_or(0.0);
    ns / 1e9
}

fn time(name: &str, (v, t): (Vec<DVec3>, Vec<[u32; 3]>)) {
    let (mut wall, mut on_cpu) = (f64::INFINITY, f64::INFINITY);
    let mut out = 0;
    for _ in 0..5 {
        let (start, c0) = (Instant::now(), cpu());
        let s = smooth(&v, &t, 30.0);
        on_cpu = on_cpu.min(cpu() - c0);
        wall = wall.min(start.elapsed().as_secs_f64());
        out = s.normals.len();
    }
    println!(
        "{name}: {} triangles, {} vertices in, {out} out: {on_cpu:.3} s on the CPU, {wall:.3} s wall (best of 5)",
        t.len(),
        v.len(),
    );
}

fn main() {
    time("torus 1000x500", torus(1000, 500));
    time("torus 500x250", torus(500, 250));
    time("fan of 300000", fan(300_000));
}
