//! EXR frames through the binaries (SPEC §12): the beauty's identity with the PNG at one
//! sample, depth / position / normal at hand-computed pixels of a one-sphere scene, the
//! same bytes on any thread count, `--pass` pictures, `--resume` and `status` on an EXR
//! folder, and (issue 23) PNG stamps of manifests and scenes whose names are not Latin-1.

use crate::support;

use support::*;

/// 5×5 pixels, eye at z = 5 looking at the origin, no fog, one unit sphere (colour
/// (0.8, 0.4, 0.2), Kd 1), one light.
const ONE_SPHERE: &str = "5 5  0 0 5  0 0 0  0 0  1 0 0 1\n\
    1 0 0 0  1 0.8 0.4 0.2  1 0 0 1 0 0\n\
    0 5 5  1 1 1  1\n";

/// The ray of pixel (i, j) of a 5×5 frame of the camera above, by SPEC §2: U = −z, D = +x,
/// H' = +y.
fn ray_dir(i: f64, j: f64) -> [f64; 3] {
    let x = -0.25 + 0.5 * (i + 0.5) / 5.0;
    let y = 0.175 - 0.35 * (j + 0.5) / 5.0;
    let n = (x * x + y * y + 1.0f64).sqrt();
    [x / n, y / n, -1.0 / n]
}

#[test]
fn depth_position_and_normal_at_hand_computed_pixels_of_one_sphere() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("s.txt"), ONE_SPHERE).unwrap();
    let out = dir.path().join("s.exr");
    raytrace()
        .arg(dir.path().join("s.txt"))
        .arg("-o")
        .arg(&out)
        .args(["--passes", "depth,position,normal,albedo", "-q"])
        .assert()
        .success();
    let ch = exr_channels(&out);
    let at = |name: &str, i: usize, j: usize| f64::from(ch[name][j * 5 + i]);
    // Centre pixel (2, 2): the ray is −z exactly; it meets the sphere at t = 4, p = (0, 0, 1),
    // N = +z, depth (along the view axis) 4, albedo the sphere's colour (0.4 green) decoded
    // to linear light like the beauty: ((0.4 + 0.055)/1.055)^2.4 = 0.1328683.
    assert!((at("Z", 2, 2) - 4.0).abs() < 1e-6);
    for (name, want) in [("P.X", 0.0), ("P.Y", 0.0), ("P.Z", 1.0), ("N.Z", 1.0)] {
        assert!((at(name, 2, 2) - want).abs() < 1e-6, "{name}");
    }
    assert!((at("albedo.G", 2, 2) - 0.132_868_3).abs() < 1e-6);
    // Pixel (1, 2): d = (−0.1, 0, −1)/|·|; |e + t·d|² = 1 with e = (0, 0, 5) gives
    // t = 5·|d_z| − sqrt(25·d_z² − 24); p = e + t·d is its own normal; depth = t·|d_z|.
    let d = ray_dir(1.0, 2.0);
    let t = 5.0 * -d[2] - (25.0 * d[2] * d[2] - 24.0).sqrt();
    let p = [t * d[0], t * d[1], 5.0 + t * d[2]];
    assert!(
        (at("Z", 1, 2) - t * -d[2]).abs() < 1e-5,
        "{} vs {}",
        at("Z", 1, 2),
        t * -d[2]
    );
    for (k, axis) in ["X", "Y", "Z"].iter().enumerate() {
        assert!(
            (at(&format!("P.{axis}"), 1, 2) - p[k]).abs() < 1e-5,
            "P.{axis}"
        );
        assert!(
            (at(&format!("N.{axis}"), 1, 2) - p[k]).abs() < 1e-5,
            "N.{axis}"
        );
    }
    // Corner (0, 0) misses: 25·d_z² − 24 < 0. Depth +inf, position and normal 0.
    let d = ray_dir(0.0, 0.0);
    assert!(
        25.0 * d[2] * d[2] - 24.0 < 0.0,
        "the corner ray misses by hand too"
    );
    assert_eq!(at("Z", 0, 0), f64::INFINITY);
    assert_eq!((at("P.X", 0, 0), at("N.Z", 0, 0)), (0.0, 0.0));
}

#[test]
fn the_beauty_in_srgb_is_the_png_at_one_sample_in_half_and_float() {
    // The beauty holds the display values decoded to linear light: its sRGB encoding,
    // clamped and rounded, is the PNG's byte, exactly (the stored value is chosen so);
    // `--colour linear` stores the values as they are, whose clamp-and-round is the byte.
    let dir = tempfile::tempdir().unwrap();
    let scene = scene_txt(dir.path(), [1.0, 3.0, 8.0]);
    raytrace()
        .arg(&scene)
        .arg("-o")
        .arg(dir.path().join("a.png"))
        .arg("-q")
        .assert()
        .success();
    let png = pixels(&dir.path().join("a.png"));
    let linear_byte = |v: f32| (f64::from(v).clamp(0.0, 1.0) * 255.0).round() as u8;
    for (depth, colour) in [
        ("half", "srgb"),
        ("float", "srgb"),
        ("half", "linear"),
        ("float", "linear"),
    ] {
        let out = dir.path().join(format!("a-{depth}-{colour}.exr"));
        raytrace()
            .arg(&scene)
            .arg("-o")
            .arg(&out)
            .args(["--exr-depth", depth, "--colour", colour, "-q"])
            .assert()
            .success();
        let ch = exr_channels(&out);
        let byte = |v: f32| match colour {
            "srgb" => srgb_byte(v),
            _ => linear_byte(v),
        };
        let bytes: Vec<u8> = (0..png.len() / 3)
            .flat_map(|k| ["R", "G", "B"].map(|c| byte(ch[c][k])))
            .collect();
        assert_eq!(bytes, png, "{depth} {colour}");
        // The tracer's values, not the bytes over 255.
        assert!(
            ch["R"].iter().any(|v| (v * 255.0).fract().abs() > 1e-3),
            "{depth}"
        );
        // Linear light is darker than the display value it shows (0 < v < 1).
        let (lin, shown) = (
            ch["R"][png.len() / 6],
            f32::from(png[png.len() / 2]) / 255.0,
        );
        if colour == "srgb" && shown > 0.1 && shown < 0.9 {
            assert!(lin < shown - 0.05, "{lin} shows as {shown}");
        }
    }
}

#[test]
fn the_same_bytes_on_any_thread_count_and_run() {
    let dir = tempfile::tempdir().unwrap();
    let scene = scene_txt(dir.path(), [1.0, 3.0, 8.0]);
    let mut all = Vec::new();
    for (k, threads) in ["1", "2", "2", "3"].iter().enumerate() {
        let out = dir.path().join(format!("t{k}.exr"));
        raytrace()
            .arg(&scene)
            .arg("-o")
            .arg(&out)
            .args([
                "--passes",
                "all",
                "--samples",
                "2",
                "--threads",
                threads,
                "-q",
            ])
            .assert()
            .success();
        all.push(std::fs::read(&out).unwrap());
    }
    assert!(all.windows(2).all(|w| w[0] == w[1]));
}

#[test]
fn a_pass_as_a_picture_and_options_refused_where_they_cannot_go() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("s.txt"), ONE_SPHERE).unwrap();
    let scene = dir.path().join("s.txt");
    let out = dir.path().join("z.png");
    raytrace()
        .arg(&scene)
        .arg("-o")
        .arg(&out)
        .args(["--pass", "depth", "-q"])
        .assert()
        .success();
    let z = pixels(&out);
    // The nearest depth (the centre) is white, a miss (the corner) black.
    assert_eq!(&z[(2 * 5 + 2) * 3..][..3], &[255, 255, 255]);
    assert_eq!(&z[..3], &[0, 0, 0]);
    let out = dir.path().join("n.png");
    raytrace()
        .arg(&scene)
        .arg("-o")
        .arg(&out)
        .args(["--pass", "normal", "-q"])
        .assert()
        .success();
    // N = +z at the centre: (0.5, 0.5, 1) → (128, 128, 255).
    assert_eq!(&pixels(&out)[(2 * 5 + 2) * 3..][..3], &[128, 128, 255]);
    for args in [
        vec!["-o", "x.png", "--passes", "depth"],
        vec!["-o", "x.exr", "--pass", "depth"],
        vec!["-o", "x.png", "--pass", "nope"],
    ] {
        raytrace()
            .current_dir(dir.path())
            .arg(&scene)
            .args(&args)
            .assert()
            .code(2);
    }
}

fn exr_manifest(second: &str) -> String {
    format!(
        "scene = \"scene.txt\"\nframes = 6\n[output]\ndir = \"frames\"\nformat = \"exr\"\n\
         passes = [\"depth\", \"crypto_object\"]\n[render]\nwidth = 16\nheight = 12\n\
         [[track]]\ntarget = \"sphere 1 center\"\nkeys = [\n\
         {{ frame = 0, value = [-1.3, 1.0, 0.0] }},\n\
         {{ frame = 2, value = {second} }},\n\
         {{ frame = 5, value = [-1.3, 1.0, 0.0] }},\n]\n"
    )
}

#[test]
fn resume_and_status_treat_exr_frames_like_the_others() {
    let (dir, manifest) = project(&exr_manifest("[-1.0, 1.5, 0.0]"));
    animate().arg(&manifest).assert().success();
    let frames = dir.path().join("frames");
    assert!(frames.join("frame_0003.exr").exists());
    animate().arg("status").arg(&manifest).assert().code(0);
    // Moving the key at frame 2 moves frames 1 to 4 only (linear: 0 and 5 hold).
    std::fs::write(&manifest, exr_manifest("[-1.0, 1.8, 0.0]")).unwrap();
    let out = animate()
        .arg("status")
        .arg(&manifest)
        .arg("--json")
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    let doc: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(doc["stale"], "1-4", "{doc}");
    assert_eq!(doc["up_to_date"], "0,5", "{doc}");
    let before = std::fs::read(frames.join("frame_0000.exr")).unwrap();
    let run = animate().arg(&manifest).arg("--resume").output().unwrap();
    let err = String::from_utf8_lossy(&run.stderr);
    assert!(err.contains("4 frames rendered, 2 up to date"), "{err}");
    assert_eq!(
        std::fs::read(frames.join("frame_0000.exr")).unwrap(),
        before
    );
    animate().arg("status").arg(&manifest).assert().code(0);
    // --verify decodes EXR frames too (their beauty, at the frame's size).
    animate()
        .arg("status")
        .arg(&manifest)
        .arg("--verify")
        .assert()
        .code(0);
    // A frame cut short is stale, not up to date.
    let f = frames.join("frame_0005.exr");
    let bytes = std::fs::read(&f).unwrap();
    std::fs::write(&f, &bytes[..bytes.len() - 10]).unwrap();
    animate().arg("status").arg(&manifest).assert().code(1);
}

#[test]
fn exr_keys_are_checked_and_refused_for_other_formats() {
    for (extra, want) in [
        (
            "format = \"exr\"\npasses = [\"depht\"]",
            "unknown pass `depht`",
        ),
        (
            "format = \"exr\"\nexr_depth = \"double\"",
            "unknown exr_depth `double`",
        ),
        (
            "format = \"exr\"\npasses = [\"fog\", \"fog\"]",
            "pass `fog` is listed twice",
        ),
        (
            "format = \"png\"\npasses = [\"fog\"]",
            "`passes` needs `format = \"exr\"`",
        ),
    ] {
        let text =
            format!("scene = \"scene.txt\"\nframes = 2\n[output]\ndir = \"frames\"\n{extra}\n");
        let (_dir, manifest) = project(&text);
        let out = animate().arg(&manifest).output().unwrap();
        assert_eq!(out.status.code(), Some(2));
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(want) && err.contains("anim.toml:"), "{err}");
    }
}

#[test]
fn png_stamps_of_names_beyond_latin1_use_utf8_text_chunks() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("сцена😀.txt"),
        scene_with_eye([0.0, 3.0, 8.0]),
    )
    .unwrap();
    let manifest = dir.path().join("日本.toml");
    std::fs::write(
        &manifest,
        "scene = \"сцена😀.txt\"\nframes = 2\n[output]\ndir = \"frames\"\n[render]\nwidth = 8\nheight = 6\n",
    )
    .unwrap();
    animate().arg(&manifest).assert().success();
    animate().arg("status").arg(&manifest).assert().code(0);
    let file = std::fs::File::open(dir.path().join("frames/frame_0000.png")).unwrap();
    let reader = png::Decoder::new(std::io::BufReader::new(file))
        .read_info()
        .unwrap();
    let texts: Vec<String> = reader
        .info()
        .utf8_text
        .iter()
        .map(|c| c.get_text().unwrap())
        .collect();
    assert!(texts.iter().any(|t| t == "日本.toml"), "{texts:?}");
    assert!(texts.iter().any(|t| t == "сцена😀.txt"), "{texts:?}");
    let run = animate().arg(&manifest).arg("--resume").output().unwrap();
    assert!(String::from_utf8_lossy(&run.stderr).contains("0 frames rendered, 2 up to date"));
}
