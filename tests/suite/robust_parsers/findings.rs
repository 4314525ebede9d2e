//! Findings: inputs that once went wrong, kept as regressions.

use super::*;
#[allow(unused_imports)]
use super::{manifest_properties::*, manifests::*, properties::*, seeds::*, tracks::*};
use whitted_anim::{Manifest, ManifestError};

/// A scene with one plane of normal `n` and one cylinder of axis `a`.
pub(super) fn plane_and_cylinder(n: &str, a: &str) -> String {
    format!(
        "4 3\n0 1 5\n0 0 0\n0 0\n0 1 1 1\n\
         0 0 0  {n}  1 1 1 1  1 0 0 1 0 0\n\
         {a}  0 0 -3  0.5  1 1 0 0  1 0 0 1 0 0\n\
         0 5 5  1 1 1  1\n"
    )
}

#[test]
fn a_tiny_or_huge_normal_or_axis_is_not_called_zero() {
    // |v|² under- or overflowed and `try_normalize` refused these as "zero length"
    // (src/scene/parser.rs, `direction`).
    for v in [
        "0 1e-200 0",
        "0 1e200 0",
        "0 4.9e-324 0",
        "1e308 1e308 0",
        "0 -1e-170 0",
    ] {
        let scene =
            Scene::parse(&plane_and_cylinder(v, v), "n.txt").unwrap_or_else(|e| panic!("{v}: {e}"));
        trace_small(&scene).unwrap();
        // The same picture as a unit normal and axis.
        let unit = Scene::parse(&plane_and_cylinder("0 1 0", "0 1 0"), "n.txt").unwrap();
        let sign = if v.starts_with("0 -") { -1.0 } else { 1.0 };
        let parts = |s: &Scene| match (&s.objects[0].shape, &s.objects[1].shape) {
            (Shape::Plane(p), Shape::Quadric(q)) => (p.normal(), q.coef),
            _ => unreachable!(),
        };
        if v.starts_with("0 ") {
            let (n, coef) = parts(&scene);
            let (unit_n, unit_coef) = parts(&unit);
            assert_eq!((n, coef), (sign * unit_n, unit_coef), "{v}");
        }
    }
    // A zero vector is still refused, with its location.
    let src = plane_and_cylinder("0 0 0", "0 1 0");
    let err = Scene::parse(&src, "n.txt").unwrap_err().to_string();
    assert!(
        err.starts_with("n.txt:6:8: the normal (0 0 0) has zero length"),
        "{err}"
    );
    let src = plane_and_cylinder("0 1 0", "0 -0 0");
    let err = Scene::parse(&src, "n.txt").unwrap_err().to_string();
    assert!(
        err.starts_with("n.txt:7:1: the axis (0 -0 0) has zero length"),
        "{err}"
    );
}

#[test]
fn an_overflowing_camera_distance_is_not_called_the_same_point() {
    // look_at − eye overflowed to infinity and the error said the camera was placed on
    // the point it looks at (src/scene/parser.rs, the camera check).
    let src = "4 3\n1e308 0 0\n-1e308 0 0\n0 0\n0 0 0 0\n";
    let err = Scene::parse(src, "far.txt").unwrap_err();
    check_located(src, "far.txt", &err).unwrap();
    let shown = err.to_string();
    assert!(shown.starts_with("far.txt:3:1: "), "{shown}");
    assert!(shown.contains("overflows"), "{shown}");
    assert!(!shown.contains("placed on"), "{shown}");
    // A huge or tiny but finite distance has a direction: |look_at − eye|² under- or
    // overflowed and `Camera::new` refused it (src/camera.rs, `Camera::new`).
    for (eye, look) in [
        ("1e300 0 0", "0 0 0"),
        ("0 0 0", "0 -1e200 1e200"),
        ("0 0 0", "1e-320 0 0"),
        ("1 1 1", "1 1.0000000000000002 1"),
    ] {
        let src = format!("4 3\n{eye}\n{look}\n0 0\n0 0 0 0\n");
        let scene = Scene::parse(&src, "c.txt").unwrap_or_else(|e| panic!("{e}"));
        let camera = scene.camera();
        assert!(camera.ray(2.0, 1.5).dir.is_finite());
    }
    // The true coincidence keeps its message.
    let src = "4 3\n1 2 3\n1 2 3\n0 0\n0 0 0 0\n";
    let shown = Scene::parse(src, "same.txt").unwrap_err().to_string();
    assert!(shown.contains("placed on the point it looks at"), "{shown}");
}

/// Loads manifest bytes from a file: a usable manifest or a located `Invalid` error,
/// never an I/O error for a file that exists.
pub(super) fn load_manifest_ok_or_located(bytes: Vec<u8>) -> Result<bool, String> {
    let shown = String::from_utf8_lossy(&bytes).into_owned();
    bounded(move || {
        let dir = tempfile::tempdir().map_err(|e| e.to_string())?;
        let path = dir.path().join("anim.toml");
        std::fs::write(&path, &bytes).map_err(|e| e.to_string())?;
        match Manifest::load(&path) {
            Ok(m) => exercise_manifest(&m).map(|()| true),
            Err(ManifestError::Io { source, .. }) => Err(format!("an I/O error: {source}")),
            Err(e @ (ManifestError::Invalid { .. } | ManifestError::Unknown(_))) => {
                let (line, column) = e.loc().map_or((0, 0), |l| (l.line, l.column));
                let text = match std::str::from_utf8(&bytes) {
                    Ok(t) => t,
                    Err(bad) => std::str::from_utf8(&bytes[..bad.valid_up_to()]).unwrap(),
                };
                let lines: Vec<&str> = text.split('\n').collect();
                let inside = line >= 1
                    && line <= lines.len()
                    && column >= 1
                    && column <= lines[line - 1].chars().count() + 1;
                let prefix = format!("{}:{line}:{column}: ", path.display());
                if inside && e.to_string().starts_with(&prefix) {
                    Ok(false)
                } else {
                    Err(format!("badly located: {e}"))
                }
            }
        }
    })
    .and_then(|r| r)
    .map_err(|e| format!("{e}\n--- manifest (lossy) ---\n{shown}\n---"))
}

#[test]
fn a_manifest_that_is_not_utf8_gets_a_located_error() {
    // `Manifest::load` used `read_to_string` and answered an I/O error without a place
    // (src/anim/manifest.rs, `load`).
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("bad.toml");
    std::fs::write(&path, b"scene = \"a.txt\"\nfr\xffames = 1\n").unwrap();
    let err = Manifest::load(&path).unwrap_err();
    let shown = err.to_string();
    assert!(
        matches!(
            err,
            ManifestError::Invalid { ref loc, .. } if (loc.line, loc.column) == (2, 3)
        ),
        "{shown}"
    );
    assert!(
        shown.starts_with(&format!("{}:2:3: ", path.display())),
        "{shown}"
    );
    assert!(shown.contains("UTF-8"), "{shown}");
    // A missing file is still an I/O error.
    let err = Manifest::load(&dir.path().join("missing.toml")).unwrap_err();
    assert!(matches!(err, ManifestError::Io { .. }));
}

#[test]
fn a_manifest_with_a_byte_order_mark() {
    // Windows editors write one; it either parses or is refused at a place.
    let src = format!("\u{feff}{CIRCLE}");
    manifest_ok_or_located(src.clone()).unwrap();
    load_manifest_ok_or_located(src.into_bytes()).unwrap();
}

proptest! {
    #![proptest_config(config(300))]

    #[test]
    fn mutated_manifest_bytes_through_a_file(
        seed in any::<Index>(),
        edits in prop::collection::vec(manifest_edit(), 1..4),
    ) {
        let seeds = manifest_seeds();
        let bytes = apply_manifest(&seeds[seed.index(seeds.len())], &edits);
        load_manifest_ok_or_located(bytes).map_err(TestCaseError::fail)?;
    }
}

#[test]
fn extreme_values_are_refused_or_render_finite() {
    // Colours, Kd, Kr, Kt (0..1) and intensities (0..1000) are bounded, because near 1e300
    // their products overflowed into NaN pixels; the first two scenes did. Geometry, bump
    // and fog numbers may be any finite value: the third scene renders finite.
    for src in [
        "4 3\n0 1 5\n0 0 0\n1 1\n1 0 0 1\n1 0 0 0 1 1e300 1e300 1e300 1 0 0 1 0 0\n\
         0 5 5 1e300 1e300 1e300 1e300\n",
        "4 3\n0 1 5\n0 0 0\n0 1\n1 0 0 1\n1 0 0 0 1 -1e300 1e300 1e300 0.5 1e300 0 1 0 0\n\
         0 5 5 1 1 1 1.7e308\n",
    ] {
        let err = Scene::parse(src, "x.txt").unwrap_err().to_string();
        assert!(
            err.starts_with("x.txt:6:") && err.contains("must be from 0 to 1"),
            "{err}"
        );
    }
    let src = "4 3\n1e300 0 0\n0 0 0\n3 1e-300\n1 0 0 1\n\
               1e300 0 0 0 1 1 1 1 0.1 0.1 0.9 1e300 2 1e300\n-1e300 0 0 1 1 1 1\n";
    let scene = Scene::parse(src, "x.txt").unwrap();
    let camera = scene.camera();
    let tracer = Tracer::new(&scene);
    for j in 0..3 {
        for i in 0..4 {
            let ray = camera.ray(i as f64 + 0.5, j as f64 + 0.5);
            let c = tracer.primary(&ray, &mut Default::default());
            assert!(c.is_finite(), "pixel ({i}, {j}): {c}");
        }
    }
}
