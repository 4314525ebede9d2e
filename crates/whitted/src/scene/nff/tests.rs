//! The NFF reader on small files by hand, and its located errors.

use super::*;
use crate::shapes::Shape;

const VIEW: &str = "v\nfrom 0 -5 1\nat 0 0 1\nup 0 0 1\nangle 40\nhither 1\nresolution 64 48\n";

fn read(body: &str) -> std::result::Result<Scene, SceneError> {
    parse(&format!("{VIEW}{body}"), "t.nff")
}

fn error(body: &str) -> (usize, usize, String) {
    match read(body) {
        Err(SceneError::Syntax { loc, message, .. }) => (loc.line, loc.column, message),
        other => panic!("expected an error, got {other:?}"),
    }
}

#[test]
fn a_small_scene_by_hand() {
    let s = read(
        "b 0.1 0.2 0.3\nl 1 2 3\nl 4 5 6 0.5 0.5 0.5\n# a comment\n\
         f 1 0 0 0.7 0.3 20 0 1\ns 0 0 1 0.5\np 4\n-1 -1 0\n1 -1 0\n1 1 0\n-1 1 0\n\
         f 0 1 0 1 0 1 0.5 1.5\nc 0 0 0 0.2 0 0 2 0.1\npp 3\n0 0 3 0 0 1\n1 0 3 0 0 1\n0 1 3 0 0 1\n",
    )
    .unwrap();
    assert_eq!((s.width, s.height), (64, 48));
    assert_eq!(
        (s.eye, s.look_at),
        (DVec3::new(0.0, -5.0, 1.0), DVec3::new(0.0, 0.0, 1.0))
    );
    assert_eq!(s.background, Color::new(0.1, 0.2, 0.3));
    assert_eq!(s.lens.up, DVec3::Z);
    assert_eq!((s.lens.fov, s.lens.centres), (Some(40.0), true));
    // Two lights: the white one gets √2/4, the coloured one its colour at 1.
    assert_eq!(s.lights[0].intensity, 2f64.sqrt() / 4.0);
    assert_eq!(
        (s.lights[1].color, s.lights[1].intensity),
        (Color::splat(0.5), 1.0)
    );
    // A sphere, two triangles of the square, a cone, a patch.
    let kinds: Vec<&str> = s.specs.iter().map(|p| p.kind()).collect();
    assert_eq!(kinds, ["sphere", "triangle", "triangle", "cone", "patch"]);
    let m = s.objects[0].material;
    assert_eq!((m.kd, m.kr, m.kt), (0.7, 0.3, 0.0));
    assert_eq!(
        m.highlight,
        Highlight::Phong {
            ks: 0.3,
            shine: 20.0
        }
    );
    assert_eq!(
        (s.objects[3].material.kt, s.objects[3].material.ior),
        (0.5, 1.5)
    );
    assert!(matches!(s.objects[3].shape, Shape::Cone(_)));
    // The epsilon: 1e-7 × the largest coordinate (the eye's 5).
    assert_eq!(s.t_min, 5.0 * EPSILON_SCALE);
    let names: Vec<String> = s.object_names().collect();
    assert_eq!(names[2], "triangle 2");
}

#[test]
fn located_errors() {
    // An unknown record, at its token.
    assert_eq!(error("f 1 1 1 1 0 1 0 1\nq 1 2 3\n").0, 9);
    let (line, col, msg) = error("f 1 1 1 1 0 1 0 1\n  q 1 2 3\n");
    assert_eq!((line, col), (9, 3));
    assert!(msg.contains("unknown record 'q'"), "{msg}");
    // A polygon short of its vertices: the next record's keyword where a number belongs.
    let (line, col, msg) = error("f 1 1 1 1 0 1 0 1\np 4\n0 0 0\n1 0 0\n1 1 0\ns 0 0 0 1\n");
    assert_eq!((line, col), (13, 1));
    assert!(msg.contains("vertex 4 of 4"), "{msg}");
    // Fewer than three vertices.
    assert_eq!(error("f 1 1 1 1 0 1 0 1\np 2\n0 0 0 1 0 0\n").0, 9);
    // An object before any f.
    let (line, col, msg) = error("s 0 0 0 1\n");
    assert_eq!((line, col), (8, 1));
    assert!(msg.contains("before any 'f'"), "{msg}");
    // nan.
    let (line, col, _) = error("f 1 1 1 1 0 1 0 1\ns 0 nan 0 1\n");
    assert_eq!((line, col), (9, 5));
    // No v at all: at the end of the file.
    match parse("f 1 1 1 1 0 1 0 1\ns 0 0 0 1\n", "t.nff") {
        Err(SceneError::Syntax { loc, message, .. }) => {
            assert_eq!((loc.line, loc.column), (3, 1));
            assert!(message.contains("no 'v'"), "{message}");
        }
        other => panic!("{other:?}"),
    }
    // A degenerate view and a zero-area polygon.
    assert!(parse(
        "v\nfrom 0 0 0\nat 0 0 0\nup 0 0 1\nangle 40\nhither 1\nresolution 4 4\n",
        "t.nff"
    )
    .is_err());
    assert!(error("f 1 1 1 1 0 1 0 1\np 3\n0 0 0\n1 0 0\n2 0 0\n")
        .2
        .contains("without area"));
}

#[test]
fn nff_by_extension() {
    assert!(is_nff(Path::new("a/balls.nff")) && is_nff(Path::new("X.NFF")));
    assert!(!is_nff(Path::new("Scene.txt")) && !is_nff(Path::new("nff")));
}

#[test]
fn every_prefix_and_line_deletion_is_read_or_refused_without_a_panic() {
    let src = format!(
        "{VIEW}b 0.1 0.2 0.3\nl 1 2 3\nl 4 5 6 0.5 0.5 0.5\nf 1 0 0 0.7 0.3 20 0.5 1.5\n\
         s 0 0 1 0.5\np 5\n-1 -1 0\n1 -1 0\n0 0 0\n1 1 0\n-1 1 0\nc 0 0 0 0.2 0 0 2 0.1\n\
         pp 3\n0 0 3 0 0 1\n1 0 3 0 0 1\n0 1 3 0 0 1\ns 1e308 -1e308 0 -1e300\n"
    );
    let mut read = 0;
    for end in 0..=src.len() {
        if src.is_char_boundary(end) {
            read += parse(&src[..end], "t.nff").is_ok() as usize;
        }
    }
    let lines: Vec<&str> = src.lines().collect();
    for k in 0..lines.len() {
        let mut v = lines.clone();
        v.remove(k);
        let _ = parse(&v.join("\n"), "t.nff");
        // And a line's tokens swapped for nonsense.
        let mut w = lines.clone();
        w[k] = "1e309 -0 nan x 0 0 0";
        assert!(parse(&w.join("\n"), "t.nff").is_err(), "line {k}");
    }
    assert!(read > 10, "{read}");
}
