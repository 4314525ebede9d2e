//! The extension's shapes and CSG against POV-Ray 3.7 on scenes of our own: a box, a
//! capped and an open cylinder, a cone, a disc with a hole, a torus, a triangle; the same
//! kinds moved by `scale`, `rotate`, `translate`; CSG blocks (a difference whose cut
//! surfaces show the cutter's texture, an intersection, a union, a nested block). Each
//! object is described once (`povray_objects`) and written both as our extension records
//! and in POV-Ray's language. Bound: under 1 % of the pixels more than 6 levels apart on
//! a channel. Skips without POV-Ray (fails under CI).

use crate::povray_objects::{framed, obj, v, Kind, Obj};
use crate::support::povray::{against_povray, assert_close, povray};
use whitted::Scene;

const W: u32 = 160;
const H: u32 = 120;

/// Camera, a grey floor, one white light; the records follow.
const BASE: &str = "160 120  0 5 12  0 0.8 0  0 0  0 1 0 1
0 0 0  0 1 0   1 0.8 0.8 0.8   1 0 0 1 0 0
5 8 6  1 1 1  1
";

/// The same in POV-Ray's language, the report's model as benches/pov/orbit.pov has it.
const POV_BASE: &str = "#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb 1 max_trace_level 6 adc_bailout 1/256 }
camera { perspective location <0, 5, -12> direction <0, 0, 1> right <0.5, 0, 0>
  up <0, 0.35, 0> sky <0, 1, 0> look_at <0, 0.8, 0> }
#macro Fin(Kd) finish { ambient 0.2 diffuse Kd phong (1 - Kd) phong_size 20 } #end
plane { y, 0 pigment { color rgb <0.8, 0.8, 0.8> } Fin(1) }
light_source { <5, 8, -6> color rgb 1 }
";

/// Draws `objects` on the base scene with us and with POV-Ray; the share of pixels
/// apart, or none when POV-Ray is missing.
fn compare(objects: &[Obj], keep: &str) -> Option<f64> {
    povray()?;
    let dir = tempfile::tempdir().unwrap();
    let records: Vec<String> = objects.iter().map(Obj::ours).collect();
    let src = format!("{BASE}{}\n", records.join("\n"));
    let scene = Scene::parse(&src, "shapes.txt").unwrap_or_else(|e| panic!("{e}\n{src}"));
    let pov = dir.path().join("scene.pov");
    let pov_objects: Vec<String> = objects.iter().map(Obj::pov).collect();
    std::fs::write(&pov, format!("{POV_BASE}{}\n", pov_objects.join("\n"))).unwrap();
    if let Some(to) = std::env::var_os("SHAPES_POVRAY_KEEP") {
        let to = std::path::Path::new(&to);
        std::fs::copy(&pov, to.join(format!("{keep}.pov"))).unwrap();
        std::fs::write(to.join(format!("{keep}.txt")), &src).unwrap();
    }
    Some(against_povray(
        &scene,
        &pov,
        (W, H),
        ("SHAPES_POVRAY_KEEP", keep),
    ))
}

const RED: [f64; 3] = [0.9, 0.2, 0.2];
const GREEN: [f64; 3] = [0.2, 0.8, 0.3];
const BLUE: [f64; 3] = [0.2, 0.3, 0.9];
const YELLOW: [f64; 3] = [0.9, 0.8, 0.2];
const MAGENTA: [f64; 3] = [0.8, 0.2, 0.8];
const CYAN: [f64; 3] = [0.2, 0.8, 0.8];

#[test]
fn every_shape_matches_povray() {
    let objects = [
        obj(Kind::Box(v(-3.0, 0.0, -1.0), v(-1.8, 1.2, 0.2)), RED),
        obj(
            Kind::Cylinder(v(-0.9, 0.0, 0.8), v(-0.9, 1.4, 0.8), 0.45, false),
            GREEN,
        ),
        obj(
            Kind::Cone(v(0.3, 0.0, -0.6), 0.6, v(0.3, 1.6, -0.6), 0.1),
            BLUE,
        ),
        obj(
            Kind::Disc(v(1.7, 0.9, 0.6), v(0.0, 0.4, 1.0), 0.7, 0.3),
            YELLOW,
        ),
        obj(
            Kind::Torus(v(0.6, 0.25, 2.0), v(0.0, 1.0, 0.0), 0.7, 0.25),
            MAGENTA,
        ),
        obj(
            Kind::Triangle([v(2.2, 0.0, -1.0), v(3.2, 0.0, -0.5), v(2.7, 1.7, -0.8)]),
            CYAN,
        ),
        obj(
            Kind::Cylinder(v(-2.5, 0.5, -2.5), v(-0.5, 0.5, -2.5), 0.45, true),
            YELLOW,
        ),
    ];
    assert_close(compare(&objects, "shapes"));
}

#[test]
fn framed_shapes_match_povray() {
    let unit_box = Kind::Box(v(-0.5, -0.5, -0.5), v(0.5, 0.5, 0.5));
    let objects = [
        framed(
            unit_box,
            RED,
            [1.0, 0.6, 1.6],
            [0.0, 35.0, 0.0],
            [-2.2, 0.3, 0.0],
        ),
        framed(
            Kind::Cylinder(v(0.0, 0.0, 0.0), v(0.0, 1.0, 0.0), 0.4, false),
            GREEN,
            [1.0, 1.5, 1.0],
            [60.0, 0.0, 20.0],
            [-0.6, 0.6, 0.5],
        ),
        framed(
            Kind::Torus(v(0.0, 0.0, 0.0), v(0.0, 0.0, 1.0), 0.6, 0.2),
            MAGENTA,
            [1.0, 1.0, 1.0],
            [20.0, 30.0, 0.0],
            [0.9, 0.9, 1.0],
        ),
        framed(
            Kind::Sphere(v(0.0, 0.0, 0.0), 0.5),
            BLUE,
            [1.6, 0.8, 1.0],
            [0.0, 0.0, 30.0],
            [2.3, 0.9, -0.5],
        ),
        framed(
            Kind::Cone(v(0.0, 0.0, 0.0), 0.5, v(0.0, 1.2, 0.0), 0.0),
            YELLOW,
            [1.0, 1.0, 1.0],
            [0.0, 0.0, -100.0],
            [0.4, 0.5, -1.5],
        ),
        framed(
            Kind::Disc(v(0.0, 0.0, 0.0), v(0.0, 0.0, 1.0), 0.6, 0.2),
            CYAN,
            [1.5, 1.0, 1.0],
            [0.0, -30.0, 0.0],
            [-1.6, 1.6, -1.8],
        ),
    ];
    assert_close(compare(&objects, "framed"));
}

#[test]
fn csg_matches_povray() {
    // A cube with a hole along z and a ball bitten out of a corner (the cuts show the
    // cutters' colours); a rounded cube (intersection of a box and a ball); a ring and a
    // ball (union); a nested block: a half ball minus a cylinder, turned.
    let cube = Kind::Csg(
        "difference",
        vec![
            obj(Kind::Box(v(-0.7, -0.7, -0.7), v(0.7, 0.7, 0.7)), RED),
            obj(
                Kind::Cylinder(v(0.0, 0.0, -1.0), v(0.0, 0.0, 1.0), 0.35, false),
                YELLOW,
            ),
            obj(Kind::Sphere(v(0.7, 0.7, 0.7), 0.55), GREEN),
        ],
    );
    let rounded = Kind::Csg(
        "intersection",
        vec![
            obj(Kind::Box(v(-0.6, -0.6, -0.6), v(0.6, 0.6, 0.6)), BLUE),
            obj(Kind::Sphere(v(0.0, 0.0, 0.0), 0.8), CYAN),
        ],
    );
    let ring = Kind::Csg(
        "union",
        vec![
            obj(
                Kind::Torus(v(0.0, 0.0, 0.0), v(0.0, 1.0, 0.0), 0.6, 0.18),
                MAGENTA,
            ),
            obj(Kind::Sphere(v(0.0, 0.2, 0.0), 0.35), YELLOW),
        ],
    );
    let half = Kind::Csg(
        "intersection",
        vec![
            obj(Kind::Sphere(v(0.0, 0.0, 0.0), 0.7), GREEN),
            obj(Kind::Plane(v(0.0, 0.0, 0.0), v(0.0, 1.0, 0.0)), BLUE),
        ],
    );
    let nested = Kind::Csg(
        "difference",
        vec![
            Obj {
                kind: half,
                rgb: GREEN,
                frame: None,
            },
            obj(
                Kind::Cylinder(v(0.0, -1.0, 0.0), v(0.0, 1.0, 0.0), 0.25, false),
                RED,
            ),
        ],
    );
    let objects = [
        framed(
            cube,
            RED,
            [1.0, 1.0, 1.0],
            [0.0, 30.0, 0.0],
            [-2.1, 0.7, 0.3],
        ),
        framed(
            rounded,
            BLUE,
            [1.0, 1.0, 1.0],
            [0.0, 20.0, 0.0],
            [-0.2, 0.6, -0.4],
        ),
        framed(
            ring,
            MAGENTA,
            [1.0, 1.0, 1.0],
            [-30.0, 0.0, 0.0],
            [1.4, 0.6, 1.2],
        ),
        framed(
            nested,
            GREEN,
            [1.0, 1.0, 1.0],
            [180.0, 0.0, 20.0],
            [2.5, 0.8, -1.2],
        ),
    ];
    assert_close(compare(&objects, "csg"));
}
