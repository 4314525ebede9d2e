//! A scene's budgets and the smaller faults of issue 57 (points 3 and 9), through
//! `raytrace`: small files that passed every limit of their own still took gigabytes (an
//! NFF of 4 M spheres, 25 distinct PNGs of 16384 × 1024 on 25 records), so a scene has
//! budgets of objects, image pixels and mesh triangles in all (`limits::MAX_SCENE_*`);
//! and a stray `end` suggested itself, "a image", negative NFF colours, a PNG 2^31 − 1
//! pixels wide refused by the decoder's memory limit instead of the size rule. Each
//! refusal exits 2 at file:line:column and writes no image. Inputs are generated into a
//! temporary folder.

use crate::common::{entries, raytrace_in, write_file};
use std::fmt::Write as _;
use std::path::Path;
use whitted::limits::{MAX_SCENE_OBJECTS, MAX_SCENE_TEXTURE_PIXELS, MAX_SCENE_TRIANGLES};

/// Runs `raytrace scene -o out.png` in `dir`: exit 2 and no image, and its stderr.
fn refused(dir: &Path, scene: &str) -> String {
    let out = raytrace_in(dir)
        .args([scene, "-o", "out.png"])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(!entries(dir).contains(&"out.png".to_string()), "{err}");
    assert!(!err.contains("panicked"), "{err}");
    err
}

/// A Scene.txt head (no report objects, one light) for extension records.
const HEAD: &str = "16 12\n0 1 6\n0 0 0\n0 1\n0 0 0 1\n5 5 5  1 1 1  1\n";

#[test]
fn an_nff_file_past_the_object_budget_is_refused_at_the_first_object_too_many() {
    let dir = tempfile::tempdir().unwrap();
    let n = MAX_SCENE_OBJECTS as usize + 1;
    let mut s = String::with_capacity(n * 16 + 200);
    s += "v\nfrom 0 0 -50\nat 0 0 0\nup 0 1 0\nangle 40\nhither 1\nresolution 4 4\n";
    s += "f 1 1 1 1 0 0 0 0\n";
    for k in 0..n {
        let _ = writeln!(s, "s {} 0 0 0.1", k % 1000);
    }
    write_file(dir.path(), "many.nff", s);
    let err = refused(dir.path(), "many.nff");
    // Line 9 holds the first sphere: the one too many is on line 9 + MAX.
    let line = 9 + MAX_SCENE_OBJECTS;
    assert!(err.contains(&format!("many.nff:{line}:1: ")), "{err}");
    assert!(
        err.contains(&format!("{MAX_SCENE_OBJECTS} objects in all")),
        "{err}"
    );
}

#[test]
fn scene_txt_counts_past_the_object_budget_are_refused_at_the_counts() {
    let dir = tempfile::tempdir().unwrap();
    let src = format!("16 12\n0 1 6\n0 0 0\n0 1\n{MAX_SCENE_OBJECTS} 1 0 1\n");
    write_file(dir.path(), "counts.txt", src);
    let err = refused(dir.path(), "counts.txt");
    assert!(err.contains("counts.txt:5:1: "), "{err}");
    assert!(
        err.contains(&format!("{MAX_SCENE_OBJECTS} in all")),
        "{err}"
    );
}

#[test]
fn distinct_images_past_the_pixel_budget_are_refused_before_decoding() {
    // Two files of 16384 × 1024 (each 2^24 pixels, within its own limit): the second
    // takes the scene past its budget.
    let dir = tempfile::tempdir().unwrap();
    let img = image::RgbImage::new(16384, (MAX_SCENE_TEXTURE_PIXELS / 16384) as u32);
    img.save(dir.path().join("a.png")).unwrap();
    std::fs::copy(dir.path().join("a.png"), dir.path().join("b.png")).unwrap();
    let tex = |f: &str| format!("3 \"{f}\" planar nearest 1");
    let src = format!(
        "{HEAD}sphere -1 0 0 1  {}  1 0 0 1 0 0\nsphere 1 0 0 1  {}  1 0 0 1 0 0\n",
        tex("a.png"),
        tex("b.png")
    );
    write_file(dir.path(), "two.txt", src);
    let err = refused(dir.path(), "two.txt");
    // The second record's file name: line 8, after "sphere 1 0 0 1  3 ".
    assert!(err.contains("two.txt:8:19: "), "{err}");
    assert!(
        err.contains(&format!("{MAX_SCENE_TEXTURE_PIXELS} pixels in all")),
        "{err}"
    );
}

#[test]
fn a_png_2_31_pixels_wide_meets_the_size_rule() {
    let dir = tempfile::tempdir().unwrap();
    let mut png = vec![
        0x89, b'P', b'N', b'G', b'\r', b'\n', 0x1a, b'\n', 0, 0, 0, 13,
    ];
    png.extend_from_slice(b"IHDR");
    png.extend_from_slice(&0x7fff_ffffu32.to_be_bytes());
    png.extend_from_slice(&1u32.to_be_bytes());
    png.extend_from_slice(&[8, 2, 0, 0, 0]);
    let crc = crc32fast::hash(&png[12..]);
    png.extend_from_slice(&crc.to_be_bytes());
    write_file(dir.path(), "wide.png", &png);
    let src = format!("{HEAD}sphere 0 0 0 1  3 \"wide.png\" planar nearest 1  1 0 0 1 0 0\n");
    write_file(dir.path(), "wide.txt", src);
    let err = refused(dir.path(), "wide.txt");
    assert!(err.contains("wide.txt:7:19: "), "{err}");
    assert!(err.contains("2147483647×1, past the limits"), "{err}");
    assert!(!err.contains("Memory limit"), "{err}");
}

#[test]
fn meshes_past_the_triangle_budget_are_refused_at_the_mesh_too_many() {
    // One file of half the budget and one triangle more, named twice.
    let dir = tempfile::tempdir().unwrap();
    let mut obj = String::from("v 0 0 0\nv 1 0 0\nv 0 1 0\n");
    obj += &"f 1 2 3\n".repeat(MAX_SCENE_TRIANGLES as usize / 2 + 1);
    write_file(dir.path(), "half.obj", obj);
    let mesh = "mesh \"half.obj\"  1 1 1 1  1 0 0 1 0 0";
    write_file(dir.path(), "two.txt", format!("{HEAD}{mesh}\n{mesh}\n"));
    let err = refused(dir.path(), "two.txt");
    assert!(err.contains("two.txt:8:1: "), "{err}");
    assert!(
        err.contains(&format!("{MAX_SCENE_TRIANGLES} triangles in all")),
        "{err}"
    );
}

#[test]
fn a_stray_end_says_what_it_is_not_did_you_mean_end() {
    let dir = tempfile::tempdir().unwrap();
    let src = format!("{HEAD}sphere 0 0 0 1  1 1 0 0  1 0 0 1 0 0\nend\n");
    write_file(dir.path(), "end.txt", src);
    let err = refused(dir.path(), "end.txt");
    assert!(err.contains("end.txt:8:1: "), "{err}");
    assert!(err.contains("no CSG block open"), "{err}");
    assert!(!err.contains("did you mean 'end'"), "{err}");
}

#[test]
fn an_image_that_is_a_folder_is_an_image_not_a_image() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::create_dir(dir.path().join("pic.png")).unwrap();
    let src = format!("{HEAD}sphere 0 0 0 1  3 \"pic.png\" planar nearest 1  1 0 0 1 0 0\n");
    write_file(dir.path(), "dir.txt", src);
    let err = refused(dir.path(), "dir.txt");
    assert!(err.contains("an image must be a regular file"), "{err}");
    assert!(!err.contains("a image"), "{err}");
}

#[test]
fn negative_nff_colours_are_refused_as_scene_txt_refuses_them() {
    let dir = tempfile::tempdir().unwrap();
    let view = "v\nfrom 0 0 -5\nat 0 0 0\nup 0 1 0\nangle 40\nhither 1\nresolution 4 4\n";
    for (name, record, column) in [
        ("f.nff", "f 1 -0.5 0.2 1 0 0 0 0\ns 0 0 0 1\n", 5),
        ("b.nff", "b 0 0 -1\n", 7),
        ("l.nff", "l 0 0 -5 -1 1 1\n", 10),
    ] {
        write_file(dir.path(), name, format!("{view}{record}"));
        let err = refused(dir.path(), name);
        assert!(err.contains(&format!("{name}:8:{column}: ")), "{err}");
        assert!(err.contains("negative"), "{err}");
    }
}
