//! Image textures (`3 "file" Map Interp Size`) through the reader and the `raytrace`
//! binary: bad records are located errors with exit 2; an image is read once per scene;
//! the `albedo` pass reads the image; an EXR frame of ours maps like its PNG.

use crate::image_povray::texture_picture;
use crate::support::raytrace;
use std::path::Path;
use std::sync::Arc;
use whitted::texture::Texture;
use whitted::Scene;

/// A wall facing the camera (z = 0, normal +z) with the picture on it, planar, one
/// image per 64 units, its frame's origin at (−0.53·64, −0.53·64, 0): the middle of the
/// view is u = v = 0.53, column ⌊0.53·16⌋ = 8, row ⌊0.47·8⌋ = 3. A white light at the
/// camera.
fn wall(texture: &str) -> String {
    format!(
        "32 24  0 0 10  0 0 0  0 0  0 1 0 1
-33.92 -33.92 0  0 0 1   {texture}   1 0 0 1 0 0
0 0 10  1 1 1  1
"
    )
}

/// Writes the picture as `tex.png` and the scene as `scene.txt` in a new folder.
fn folder(scene: &str) -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    texture_picture().save(dir.path().join("tex.png")).unwrap();
    std::fs::write(dir.path().join("scene.txt"), scene).unwrap();
    dir
}

/// Runs `raytrace scene.txt` with `args` in `dir`: (exit code, stderr).
fn run(dir: &Path, args: &[&str]) -> (Option<i32>, String) {
    let out = raytrace()
        .current_dir(dir)
        .arg("scene.txt")
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn bad_image_records_are_located_errors() {
    let cases = [
        // A missing file: its path named, at the quoted name (line 2, column 28: the
        // TEXTURE starts at 26).
        (
            r#"3 "nope.png" planar nearest 64"#,
            "scene.txt:2:28",
            "nope.png",
        ),
        (
            r#"3 "tex.png" planr nearest 64"#,
            "scene.txt:2:38",
            "did you mean 'planar'?",
        ),
        (
            r#"3 "tex.png" planar bilinar 64"#,
            "scene.txt:2:45",
            "did you mean 'bilinear'?",
        ),
        (
            r#"3 "tex.png" planar nearest 0"#,
            "scene.txt:2:53",
            "Size must be greater than 0",
        ),
        // Unquoted: the line's count of values is a cylinder's, so the counts are
        // blamed, quoting the error at the name.
        (r#"3 tex.png planar nearest 64"#, "2:28", "quoted file name"),
    ];
    for (texture, at, says) in cases {
        let dir = folder(&wall(texture));
        let (code, err) = run(dir.path(), &["-q"]);
        assert_eq!(code, Some(2), "{texture}: {err}");
        assert!(err.contains(at) && err.contains(says), "{texture}: {err}");
        assert!(!dir.path().join("scene.png").exists());
    }
    // Not an image at all, in an extension record: the reason and the path.
    let dir = folder(&wall("1 1 1 1"));
    std::fs::write(dir.path().join("junk.png"), b"junk").unwrap();
    let scene = format!(
        "{}box -1 -1 -1 1 1 1  3 \"junk.png\" planar nearest 1  1 0 0 1 0 0\n",
        wall("1 1 1 1")
    );
    std::fs::write(dir.path().join("scene.txt"), scene).unwrap();
    let (code, err) = run(dir.path(), &["-q"]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("scene.txt:4:") && err.contains("junk.png"),
        "{err}"
    );
}

#[test]
fn an_image_is_read_once_and_shared() {
    let tex = r#"3 "tex.png" planar nearest 64"#;
    let mut scene = wall(tex);
    scene += &format!("box -1 -1 -1 1 1 1  {tex}  1 0 0 1 0 0\n");
    scene += "sphere 0 0 0 1  3 \"tex.png\" spherical bilinear 1  1 0 0 1 0 0\n";
    let dir = folder(&scene);
    let scene = Scene::load(&dir.path().join("scene.txt")).unwrap();
    let pixels: Vec<_> = scene
        .objects
        .iter()
        .map(|o| match &o.texture {
            Texture::Image(i) => Arc::clone(&i.pixels),
            t => panic!("not an image: {t:?}"),
        })
        .collect();
    assert_eq!(pixels.len(), 3);
    assert!(pixels.iter().all(|p| Arc::ptr_eq(p, &pixels[0])));
    assert_eq!(pixels[0].size(), (16, 8));
}

#[test]
fn the_albedo_pass_reads_the_image() {
    let dir = folder(&wall(r#"3 "tex.png" planar nearest 64"#));
    let (code, err) = run(dir.path(), &["-q", "--pass", "albedo", "-o", "albedo.png"]);
    assert_eq!(code, Some(0), "{err}");
    let albedo = image::open(dir.path().join("albedo.png"))
        .unwrap()
        .to_rgb8();
    let want = *texture_picture().get_pixel(8, 3);
    assert_eq!(*albedo.get_pixel(16, 12), want);
    // The beauty is lit: the wall faces the light, so it is the texel times a factor.
    let (code, err) = run(dir.path(), &["-q", "-o", "beauty.png"]);
    assert_eq!(code, Some(0), "{err}");
    let beauty = image::open(dir.path().join("beauty.png"))
        .unwrap()
        .to_rgb8();
    assert_ne!(*beauty.get_pixel(16, 12), image::Rgb([0, 0, 0]));
}

#[test]
fn an_exr_frame_of_ours_maps_like_its_png() {
    // A frame rendered to PNG and to a float EXR, then each mapped on the wall.
    let dir = folder(&wall(r#"3 "tex.png" planar bilinear 16"#));
    for (out, extra) in [
        ("frame.png", vec![]),
        ("frame.exr", vec!["--exr-depth", "float"]),
    ] {
        let mut args = vec!["-q", "-o", out];
        args.extend(extra);
        let (code, err) = run(dir.path(), &args);
        assert_eq!(code, Some(0), "{err}");
    }
    let mut shown = Vec::new();
    for file in ["frame.png", "frame.exr"] {
        let scene = wall(&format!("3 \"{file}\" planar bilinear 16"));
        std::fs::write(dir.path().join("scene.txt"), scene).unwrap();
        let out = format!("{file}.mapped.png");
        let (code, err) = run(dir.path(), &["-q", "-o", &out]);
        assert_eq!(code, Some(0), "{err}");
        shown.push(image::open(dir.path().join(out)).unwrap().to_rgb8());
    }
    let (a, b) = (shown[0].as_raw(), shown[1].as_raw());
    let worst = a.iter().zip(b).map(|(x, y)| x.abs_diff(*y)).max().unwrap();
    assert!(
        worst <= 1,
        "the EXR's mapping is {worst} levels from the PNG's"
    );
    assert!(a.iter().any(|&v| v > 0));
}
