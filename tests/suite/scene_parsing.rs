//! Scene.txt through the library (`whitted::Scene::parse`, SPEC §1): the report's example
//! sphere, comments and comment-free files, every record kind, fog types, zero counts,
//! slanted cylinders, the limits, and where errors point.

use glam::DVec3;
use whitted::bump::Bump;
use whitted::fog::Fog;
use whitted::lights::PointLight;
use whitted::object::{Material, Object};
use whitted::optics::Ray;
use whitted::shapes::{Plane, Quadric, Shape, Sphere};
use whitted::texture::Texture;
use whitted::Scene;

fn parse(src: &str) -> Scene {
    Scene::parse(src, "test.txt").unwrap_or_else(|e| panic!("{e}"))
}

fn v(x: f64, y: f64, z: f64) -> DVec3 {
    DVec3::new(x, y, z)
}

/// The report's example sphere, verbatim (III.1).
const REPORT_SPHERE: &str =
    "1.0 0.0 2.0 9.0 2 2 0.5 0.5 0.5 0.0 0.0 1.0 1.0 1.0 0.0 0.3 0.2 0.0 1.5 0 0.0";

#[test]
fn the_reports_example_sphere() {
    let src = format!("640 480\n0 2 -5\n0 2 9\n0 20\n1 0 0 1\n{REPORT_SPHERE}\n5 10 5 1 1 1 1\n");
    let scene = parse(&src);
    assert_eq!(scene.objects.len(), 1);
    let obj = &scene.objects[0];
    match &obj.shape {
        Shape::Sphere(s) => {
            assert_eq!(s.radius, 1.0);
            assert_eq!(s.center, v(0.0, 2.0, 9.0));
        }
        other => panic!("not a sphere: {other:?}"),
    }
    assert_eq!(
        obj.texture,
        Texture::Perlin(v(0.5, 0.5, 0.5), v(0.0, 0.0, 1.0), v(1.0, 1.0, 0.0))
    );
    assert_eq!(
        obj.material,
        Material {
            kd: 0.3,
            kr: 0.2,
            kt: 0.0,
            ior: 1.5,
            bump: Bump::None,
            highlight: Default::default(),
        }
    );
    // And the records around it.
    assert_eq!((scene.width, scene.height), (640, 480));
    assert_eq!(scene.eye, v(0.0, 2.0, -5.0));
    assert_eq!(scene.look_at, v(0.0, 2.0, 9.0));
    assert_eq!(scene.fog, Fog::None);
    assert_eq!(
        scene.lights,
        vec![PointLight {
            position: v(5.0, 10.0, 5.0),
            color: v(1.0, 1.0, 1.0),
            intensity: 1.0
        }]
    );
}

/// A scene with two of every record kind and every texture and bump, in the report's
/// comment-free layout.
const ALL_KINDS: &str = "320 240
1 3 12
0 1 -1
1 25.5
2 2 2 2
0.5 -1 0.5 0   1 0.2 0.4 0.6   0.9 0.1 0 1 0 0
2.5 3 2.5 -4   2 1 1 1 1 0 0 0 0.5 0.5 0.5   0.5 0.5 0 1 1 0.25
0 -1 0  0 1 0   2 3 0.6 0.3 0.1 0.9 0.6 0.3 0 0 0   0.8 0.2 0 1 2 0.05
0 0 -20  0 0 2  2 4 1 1 1 0.1 0.1 0.2 0 0 0   1 0 0 1 0 0
0 1 0  -3 0 -2  0.75   1 0 1 0   0.6 0 0.4 1.33 0 0
1 1 1  4 1 -2   0.25   2 2 0 0 0 1 1 1 0.5 0 0   0.7 0 0 1 1 0.1
10 10 10  1 1 1  1
-10 5 0  1 0.5 0.25  0.5
";

#[test]
fn every_record_kind_in_order() {
    let s = parse(ALL_KINDS);
    assert_eq!((s.width, s.height), (320, 240));
    assert_eq!(s.eye, v(1.0, 3.0, 12.0));
    assert_eq!(s.look_at, v(0.0, 1.0, -1.0));
    assert_eq!(s.fog, Fog::Linear(25.5));
    let mat = |kd, kr, kt, ior, bump| Material {
        kd,
        kr,
        kt,
        ior,
        bump,
        highlight: Default::default(),
    };
    let expected = vec![
        Object {
            shape: Shape::Sphere(Sphere::new(v(-1.0, 0.5, 0.0), 0.5)),
            texture: Texture::Uniform(v(0.2, 0.4, 0.6)),
            material: mat(0.9, 0.1, 0.0, 1.0, Bump::None),
        },
        Object {
            shape: Shape::Sphere(Sphere::new(v(3.0, 2.5, -4.0), 2.5)),
            texture: Texture::Checker(v(1.0, 1.0, 1.0), v(0.0, 0.0, 0.0)),
            material: mat(0.5, 0.5, 0.0, 1.0, Bump::Uniform(0.25)),
        },
        Object {
            shape: Shape::Plane(Plane::new(v(0.0, -1.0, 0.0), v(0.0, 1.0, 0.0))),
            texture: Texture::Wood(v(0.6, 0.3, 0.1), v(0.9, 0.6, 0.3)),
            material: mat(0.8, 0.2, 0.0, 1.0, Bump::Water(0.05)),
        },
        Object {
            shape: Shape::Plane(Plane::new(v(0.0, 0.0, -20.0), v(0.0, 0.0, 2.0))),
            texture: Texture::Marble(v(1.0, 1.0, 1.0), v(0.1, 0.1, 0.2)),
            material: mat(1.0, 0.0, 0.0, 1.0, Bump::None),
        },
        Object {
            shape: Shape::Quadric(Quadric::cylinder(
                v(0.0, 1.0, 0.0),
                v(-3.0, 0.0, -2.0),
                0.75,
            )),
            texture: Texture::Uniform(v(0.0, 1.0, 0.0)),
            material: mat(0.6, 0.0, 0.4, 1.33, Bump::None),
        },
        Object {
            shape: Shape::Quadric(Quadric::cylinder(v(1.0, 1.0, 1.0), v(4.0, 1.0, -2.0), 0.25)),
            texture: Texture::Perlin(v(0.0, 0.0, 0.0), v(1.0, 1.0, 1.0), v(0.5, 0.0, 0.0)),
            material: mat(0.7, 0.0, 0.0, 1.0, Bump::Uniform(0.1)),
        },
    ];
    assert_eq!(s.objects, expected);
    assert_eq!(
        s.lights,
        vec![
            PointLight {
                position: v(10.0, 10.0, 10.0),
                color: v(1.0, 1.0, 1.0),
                intensity: 1.0
            },
            PointLight {
                position: v(-10.0, 5.0, 0.0),
                color: v(1.0, 0.5, 0.25),
                intensity: 0.5
            },
        ]
    );
    // The plane normal given as (0, 0, 2) is stored unit.
    match &s.objects[3].shape {
        Shape::Plane(p) => assert_eq!(p.normal(), v(0.0, 0.0, 1.0)),
        other => panic!("not a plane: {other:?}"),
    }
}

#[test]
fn layout_does_not_matter_and_comments_are_blanks() {
    let reference = parse(ALL_KINDS);
    // Every token on one line, separated by single spaces.
    let one_line = ALL_KINDS.split_whitespace().collect::<Vec<_>>().join(" ");
    assert_eq!(parse(&one_line), reference);
    // Tabs, CRLF line ends, one token per line.
    let tabs = ALL_KINDS.split_whitespace().collect::<Vec<_>>().join("\t");
    assert_eq!(parse(&tabs), reference);
    let crlf = ALL_KINDS
        .split_whitespace()
        .collect::<Vec<_>>()
        .join("\r\n");
    assert_eq!(parse(&crlf), reference);
    // Comments on their own lines, after values, glued to a value, with '#' inside them,
    // and one at the very end without a newline.
    let commented: String = ALL_KINDS
        .lines()
        .enumerate()
        .map(|(i, l)| format!("# record line {i} # with a hash\n{l}#glued comment 1 2 3\n"))
        .collect::<String>()
        + "   # the end, no newline";
    assert_eq!(parse(&commented), reference);
    // A comment swallows the rest of its line: a value hidden in one is not read.
    let hidden = ALL_KINDS.replacen("320 240", "320 # 999\n240", 1);
    assert_eq!(parse(&hidden), reference);
}

#[test]
fn a_leading_byte_order_mark_is_ignored() {
    // Windows editors save UTF-8 with a byte-order mark; it is not part of ResX.
    let reference = parse(ALL_KINDS);
    assert_eq!(parse(&format!("\u{feff}{ALL_KINDS}")), reference);
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("bom.txt");
    std::fs::write(&path, format!("\u{feff}{ALL_KINDS}")).unwrap();
    assert_eq!(Scene::load(&path).unwrap(), reference);
    // Errors on the first line still count columns from the first visible character.
    let err = Scene::parse("\u{feff}640 x", "bom.txt").unwrap_err();
    assert_eq!(err.loc().map(|l| (l.line, l.column)), Some((1, 5)), "{err}");
    // And so does a byte that is not UTF-8.
    std::fs::write(&path, b"\xEF\xBB\xBF40 \xFF30\n").unwrap();
    let err = Scene::load(&path).unwrap_err();
    assert_eq!(err.loc().map(|l| (l.line, l.column)), Some((1, 4)), "{err}");
}

#[test]
fn fog_types() {
    let with_fog = |fog: &str| parse(&format!("4 3\n0 0 5\n0 0 0\n{fog}\n0 0 0 0\n")).fog;
    assert_eq!(with_fog("0 20"), Fog::None);
    // Without fog the distance is not used, so 0 or a negative number is allowed.
    assert_eq!(with_fog("0 0"), Fog::None);
    assert_eq!(with_fog("0 -3"), Fog::None);
    assert_eq!(with_fog("1 20"), Fog::Linear(20.0));
    assert_eq!(with_fog("2 7.5"), Fog::Exponential(7.5));
    assert_eq!(with_fog("3 1e-3"), Fog::ExponentialSquared(0.001));
}

#[test]
fn counts_of_zero() {
    let s = parse("1 1\n0 0 5\n0 0 0\n0 0\n0 0 0 0\n");
    assert!(s.objects.is_empty());
    assert!(s.lights.is_empty());
    assert_eq!((s.width, s.height), (1, 1));
    // Objects and no light; lights and no object; only cylinders.
    let s = parse("2 2\n0 0 5\n0 0 0\n0 0\n1 0 0 0\n1 0 0 0 1 1 1 1 1 0 0 1 0 0\n");
    assert_eq!((s.objects.len(), s.lights.len()), (1, 0));
    let s = parse("2 2\n0 0 5\n0 0 0\n0 0\n0 0 0 2\n1 1 1 1 1 1 1\n2 2 2 1 1 1 1\n");
    assert_eq!((s.objects.len(), s.lights.len()), (0, 2));
    let s = parse("2 2\n0 0 5\n0 0 0\n0 0\n0 0 1 0\n1 0 0 0 0 0 1 1 1 1 1 1 0 0 1 0 0\n");
    assert!(matches!(s.objects[0].shape, Shape::Quadric(_)));
}

#[test]
fn a_cylinder_of_slanted_axis() {
    // Axis (1, 2, -2) (length 3) through (1, 2, 3), radius 0.5.
    let s =
        parse("8 6\n0 0 10\n0 0 0\n0 0\n0 0 1 0\n1 2 -2   1 2 3   0.5   1 1 1 1   1 0 0 1 0 0\n");
    let q = match &s.objects[0].shape {
        Shape::Quadric(q) => *q,
        other => panic!("not a quadric: {other:?}"),
    };
    assert_eq!(
        q,
        Quadric::cylinder(v(1.0, 2.0, -2.0), v(1.0, 2.0, 3.0), 0.5)
    );
    // Points at distance 0.5 from the axis, anywhere along it, are on the surface:
    // (2, -2, -1)/3 and (2, 1, 2)/3 are unit and perpendicular to the axis.
    let a = v(1.0, 2.0, -2.0) / 3.0;
    let u1 = v(2.0, -2.0, -1.0) / 3.0;
    let u2 = v(2.0, 1.0, 2.0) / 3.0;
    assert!(a.dot(u1).abs() < 1e-15 && a.dot(u2).abs() < 1e-15);
    for (h, angle) in [(0.0, 0.0), (4.0, 1.0), (-7.5, 2.5), (100.0, 4.0)] {
        let p = v(1.0, 2.0, 3.0) + a * h + (u1 * f64::cos(angle) + u2 * f64::sin(angle)) * 0.5;
        assert!(q.value(p).abs() < 1e-12, "F = {} at {p}", q.value(p));
        // The normal there points straight away from the axis.
        let radial = (u1 * f64::cos(angle) + u2 * f64::sin(angle)).normalize();
        assert!((q.normal(p) - radial).length() < 1e-12);
    }
    // A ray through the axis, perpendicular to it, crosses at ±0.5 around the axis point.
    let origin = v(1.0, 2.0, 3.0) + u1 * 5.0;
    let hit = s.objects[0]
        .shape
        .hit(&Ray::new(origin, -u1), f64::INFINITY);
    assert!((hit.unwrap() - 4.5).abs() < 1e-12, "{hit:?}");
}

#[test]
fn number_spellings() {
    // Exponents, leading and trailing dots, signs, negative zero, and '+' on integers.
    let s = parse("+4 3\n.5 -0.0 1e1\n5. +2 -1E-1\n0 20\n0 0 0 +1\n1 1 1 1 1 1 1\n");
    assert_eq!((s.width, s.height), (4, 3));
    assert_eq!(s.eye, v(0.5, 0.0, 10.0));
    assert_eq!(s.look_at, v(5.0, 2.0, -0.1));
    assert_eq!(s.lights.len(), 1);
}

#[test]
fn resolution_limits() {
    let res = |r: &str| Scene::parse(&format!("{r}\n0 0 5\n0 0 0\n0 0\n0 0 0 0\n"), "t.txt");
    // Exactly 16384 on a side and exactly 2^26 pixels are allowed.
    let s = res("16384 4096").unwrap();
    assert_eq!((s.width, s.height), (16384, 4096));
    assert_eq!(res("1 16384").unwrap().height, 16384);
    // One more is refused, at the token that breaks the rule.
    for (r, col) in [
        ("16384 4097", 7),
        ("16385 1", 1),
        ("1 16385", 3),
        ("0 1", 1),
    ] {
        let err = res(r).unwrap_err();
        let loc = err.loc().unwrap();
        assert_eq!((loc.line, loc.column), (1, col), "{r}: {err}");
    }
}

#[test]
fn errors_carry_file_line_column_and_context() {
    let src = "40 30\n0 2 10\n0 1 0\n0 20\n2 0 0 0\n1 0 1 0 1 1 0 0 0.7 0.3 0 1 0 0\n\n   -2 0 1 0 1 1 0 0 0.7 0.3 0 1 0 0\n";
    let err = Scene::parse(src, "dir/scene.txt").unwrap_err();
    let loc = err.loc().unwrap();
    assert_eq!(
        (loc.file.as_str(), loc.line, loc.column),
        ("dir/scene.txt", 8, 4)
    );
    let text = err.to_string();
    assert!(text.starts_with("dir/scene.txt:8:4: "), "{text}");
    assert!(text.contains("sphere 2 of 2, field Radius"), "{text}");
    assert!(text.contains("'-2'"), "{text}");
}

#[test]
fn a_negative_count_is_an_integer_out_of_range() {
    // "-1" is an integer: the message says what range was expected, not "not an integer".
    let err = Scene::parse("40 30\n0 2 10\n0 1 0\n0 20\n0 -1 0 0\n", "t.txt").unwrap_err();
    let text = err.to_string();
    assert!(text.contains("a count from 0 to"), "{text}");
    assert!(text.contains("'-1'"), "{text}");
    assert!(!text.contains("not an integer"), "{text}");
    // While "2.5" and "x" are still told apart.
    let err = Scene::parse("40 30\n0 2 10\n0 1 0\n0 20\n0 2.5 0 0\n", "t.txt").unwrap_err();
    assert!(err.to_string().contains("(not an integer)"), "{err}");
    let err = Scene::parse("40 30\n0 2 10\n0 1 0\n0 20\n0 x 0 0\n", "t.txt").unwrap_err();
    assert!(err.to_string().contains("(not a number)"), "{err}");
    let err = Scene::parse("40 30\n0 2 10\n0 1 0\n0 20\n0 +-1 0 0\n", "t.txt").unwrap_err();
    assert!(err.to_string().contains("(not a number)"), "{err}");
}

#[test]
fn the_scene_camera_looks_at_its_point() {
    let s = parse("64 48\n0 2 10\n0 2 0\n0 20\n0 0 0 0\n");
    let cam = s.camera();
    assert_eq!(cam.eye(), v(0.0, 2.0, 10.0));
    // The centre of the image (a pixel corner for an even size) looks along −z.
    let r = cam.ray(32.0, 24.0);
    assert!((r.dir - v(0.0, 0.0, -1.0)).length() < 1e-12, "{}", r.dir);
    // Looking straight down works too (the up vector falls back to +z).
    let s = parse("64 48\n0 10 0\n0 0 0\n0 20\n0 0 0 0\n");
    assert!((s.camera().ray(32.0, 24.0).dir - v(0.0, -1.0, 0.0)).length() < 1e-12);
}
