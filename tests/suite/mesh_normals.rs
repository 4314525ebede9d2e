//! `smooth Angle` and `flat` on mesh records (SPEC §18) through the built `raytrace`, and
//! against POV-Ray 3.7: a 24-sided prism written without normals renders, by default
//! (`smooth 30`), as POV-Ray's `mesh2` given the normals the rule makes by hand: radial
//! on the sides (each side quad adds 90° at each of its corners, so the weights are
//! equal), straight up and down on the caps (split from the sides at 90°). `flat` draws
//! the facets; bad modifiers are located errors.

use crate::mesh_povray::compare;
use crate::support::render_scene;
use std::f64::consts::TAU;
use std::path::Path;

const BASE: &str = "96 72  0 3 7  0 0.9 0  0 0  0 1 0 1
0 0 0  0 1 0   1 0.8 0.8 0.8   1 0 0 1 0 0
4 8 6  1 1 1  1
";

const SIDES: usize = 24;

/// The prism's rim: (cos, sin) of each side's start.
fn rim() -> Vec<(f64, f64)> {
    (0..SIDES)
        .map(|k| {
            let a = k as f64 / SIDES as f64 * TAU;
            (a.cos(), a.sin())
        })
        .collect()
}

/// A prism of radius 1 from y = 0 to 1.5: side quads, and caps fanned from their first
/// vertex, without normals (vertices 1..=24 at the bottom, 25..=48 at the top).
fn prism_obj() -> String {
    let mut s = String::new();
    for y in [0.0, 1.5] {
        for (c, z) in rim() {
            s += &format!("v {c} {y} {z}\n");
        }
    }
    for k in 0..SIDES {
        let (a, b) = (k + 1, (k + 1) % SIDES + 1);
        s += &format!("f {a} {} {} {b}\n", a + SIDES, b + SIDES);
    }
    let bottom: Vec<String> = (1..=SIDES).map(|i| i.to_string()).collect();
    let top: Vec<String> = (1..=SIDES).rev().map(|i| (i + SIDES).to_string()).collect();
    s + &format!("f {}\nf {}\n", bottom.join(" "), top.join(" "))
}

/// The same prism as `mesh2` with the normals smooth 30 gives (z negated).
fn prism_mesh2(rest: &str) -> String {
    let r = rim();
    let mut verts = Vec::new();
    let mut normals = Vec::new();
    // Sides: 2 × 24 vertices with radial normals; caps: 2 × 24 with ±y.
    for y in [0.0, 1.5] {
        for &(c, z) in &r {
            verts.push(format!("<{c}, {y}, {}>", -z));
            normals.push(format!("<{c}, 0, {}>", -z));
        }
    }
    for (y, n) in [(0.0, -1.0), (1.5, 1.0)] {
        for &(c, z) in &r {
            verts.push(format!("<{c}, {y}, {}>", -z));
            normals.push(format!("<0, {n}, 0>"));
        }
    }
    let mut faces = Vec::new();
    for k in 0..SIDES {
        let (a, b) = (k, (k + 1) % SIDES);
        faces.push(format!("<{a}, {}, {}>", a + SIDES, b + SIDES));
        faces.push(format!("<{a}, {}, {b}>", b + SIDES));
    }
    for k in 1..SIDES - 1 {
        faces.push(format!(
            "<{}, {}, {}>",
            2 * SIDES,
            2 * SIDES + k,
            2 * SIDES + k + 1
        ));
        faces.push(format!(
            "<{}, {}, {}>",
            3 * SIDES,
            3 * SIDES + k,
            3 * SIDES + k + 1
        ));
    }
    format!(
        "mesh2 {{ vertex_vectors {{ {}, {} }}\nnormal_vectors {{ {}, {} }}\nface_indices {{ {}, {} }}\n{rest} }}\n",
        verts.len(),
        verts.join(", "),
        normals.len(),
        normals.join(", "),
        faces.len(),
        faces.join(", ")
    )
}

#[test]
fn a_prism_without_normals_is_smooth_30_as_povray_draws_it() {
    crate::support::povray::assert_close(compare(
        &[("prism.obj", prism_obj().into_bytes())],
        "mesh \"prism.obj\" 1 0.9 0.3 0.2  0.7 0 0 1 0 0 scale 0.9 0.9 0.9 translate 0 0.2 0\n",
        &prism_mesh2(
            "pigment { color rgb <0.9, 0.3, 0.2> } Fin(0.7) scale 0.9 translate <0, 0.2, 0>",
        ),
    ));
}

/// Renders `records` beside `prism.obj`; the PNG bytes, or the stderr of a failure.
fn render(dir: &Path, records: &str) -> Result<Vec<u8>, String> {
    std::fs::write(dir.join("prism.obj"), prism_obj()).unwrap();
    render_scene(dir, &format!("{BASE}{records}"))
}

const RED: &str = "1 0.9 0.3 0.2  0.7 0 0 1 0 0";

#[test]
fn smooth_and_flat_through_the_binary() {
    let dir = tempfile::tempdir().unwrap();
    let record = |mods: &str| format!("mesh \"prism.obj\" {RED} translate 0 0.2 0 {mods}\n");
    let default = render(dir.path(), &record("")).unwrap();
    assert_eq!(default, render(dir.path(), &record("smooth 30")).unwrap());
    let flat = render(dir.path(), &record("flat")).unwrap();
    assert_ne!(default, flat, "flat draws the facets");
    // At 10° the sides (15° apart) are split too: no longer the default's picture.
    assert_ne!(default, render(dir.path(), &record("smooth 10")).unwrap());
    let e = render(dir.path(), &record("smooth 0")).unwrap_err();
    assert!(
        e.contains("DIR/scene.txt:4:") && e.contains("above 0 and at most 180"),
        "{e}"
    );
    let e = render(dir.path(), &record("smooth 181")).unwrap_err();
    assert!(e.contains("found 181"), "{e}");
    let e = render(dir.path(), &record("smooth 30 flat")).unwrap_err();
    assert!(e.contains("'flat' and 'smooth' exclude each other"), "{e}");
    let e = render(dir.path(), &format!("sphere 0 1 0 1 {RED} flat\n")).unwrap_err();
    assert!(
        e.contains("'flat' does not apply to a sphere record"),
        "{e}"
    );
}
