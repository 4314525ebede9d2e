use super::*;
use crate::project::{Animation, Project};
use whitted::base::Frame;
use whitted::output::ImageFormat;

const SCENE: &str = "8 6  0 1 6  0 1 0  0 0  1 0 0 1
1.0  0 1 0   1 0.9 0.2 0.1   0.7 0.3 0 1 0 0
5 10 5  1 1 1  0.9";

fn load(dir: &Path, scene: &str, extra: &str) -> Project {
    std::fs::write(dir.join("s.txt"), scene).unwrap();
    let path = dir.join("m.toml");
    std::fs::write(&path, format!("scene = \"s.txt\"\nframes = 4\n{extra}")).unwrap();
    Project::load(&path).unwrap()
}

fn digests(dir: &Path, scene: &str, extra: &str) -> Vec<String> {
    let p = load(dir, scene, extra);
    let anim = Animation::new(&p).unwrap();
    (0..4).map(|f| anim.plan(f).digest().to_string()).collect()
}

#[test]
fn values_count_not_bytes() {
    let dir = tempfile::tempdir().unwrap();
    let base = digests(dir.path(), SCENE, "");
    assert_eq!(base[0].len(), 64);
    // A comment and other spacing change nothing.
    let commented = SCENE.replace("0.9 0.2 0.1", "0.90  0.2\n  0.1 # red\n");
    assert_eq!(digests(dir.path(), &commented, ""), base);
    // A colour changes every frame; a still camera makes all frames alike.
    let recoloured = digests(dir.path(), &SCENE.replace("0.9 0.2 0.1", "0.9 0.2 0.2"), "");
    assert!(recoloured.iter().zip(&base).all(|(a, b)| a != b));
    assert!(base.iter().all(|d| d == &base[0]));
    // Settings count: samples and format.
    assert_ne!(
        digests(dir.path(), SCENE, "[render]\nsamples = 2\n")[0],
        base[0]
    );
    assert_ne!(
        digests(dir.path(), SCENE, "[output]\nformat = \"ppm\"\n")[0],
        base[0]
    );
    // A track changes the frames whose values it changes, and only those.
    let track = "[[track]]\ntarget = \"light 1 intensity\"\nkeys = [{ frame = 0, value = 0.9 }, { frame = 1, value = 0.9 }, { frame = 3, value = 0.5 }]\n";
    let tracked = digests(dir.path(), SCENE, track);
    assert_eq!(tracked[..2], base[..2]);
    assert!(tracked[2] != base[2] && tracked[3] != base[3]);
}

/// The digest `status` reads from a frame file of 2×2 pixels: that of a sound file only.
fn recorded_digest(path: &Path, format: ImageFormat) -> Option<String> {
    match inspect(path, format, 2, 2, false) {
        Inspection::Sound(record) => record.digest,
        Inspection::Missing | Inspection::Damaged(_) => None,
    }
}

#[test]
fn every_format_carries_its_digest() {
    let dir = tempfile::tempdir().unwrap();
    let frame = Frame {
        width: 2,
        height: 2,
        pixels: vec![7; 12],
    };
    let meta = vec![
        (DIGEST_KEY.to_string(), "ab12".to_string()),
        ("whitted:frame".to_string(), "3 of 4".to_string()),
    ];
    for format in [
        ImageFormat::Png,
        ImageFormat::Jpeg { quality: 90 },
        ImageFormat::Ppm,
    ] {
        let path = dir.path().join(format!("f.{}", format.extension()));
        whitted::output::write_atomic(&path, &frame, format, &meta).unwrap();
        assert_eq!(
            recorded_digest(&path, format).as_deref(),
            Some("ab12"),
            "{format:?}"
        );
        // Still an ordinary image (the image crate here reads PNG and JPEG).
        if format != ImageFormat::Ppm {
            let back = image::open(&path).unwrap().to_rgb8();
            assert_eq!((back.width(), back.height()), (2, 2), "{format:?}");
        }
    }
    // A foreign or truncated file is no digest, not a crash.
    let png = dir.path().join("f.png");
    let bytes = std::fs::read(&png).unwrap();
    std::fs::write(&png, &bytes[..20]).unwrap();
    assert_eq!(recorded_digest(&png, ImageFormat::Png), None);
    std::fs::write(&png, b"not a png").unwrap();
    assert_eq!(recorded_digest(&png, ImageFormat::Png), None);
    assert_eq!(
        recorded_digest(&dir.path().join("none.raw"), ImageFormat::Raw),
        None
    );
}

#[test]
fn a_frame_is_sound_only_where_its_format_ends() {
    let dir = tempfile::tempdir().unwrap();
    let frame = Frame {
        width: 3,
        height: 2,
        pixels: vec![9; 18],
    };
    let meta = vec![(DIGEST_KEY.to_string(), "ab".to_string())];
    let sound =
        |path: &Path, format, h| matches!(inspect(path, format, 3, h, false), Inspection::Sound(_));
    for format in [
        ImageFormat::Png,
        ImageFormat::Jpeg { quality: 90 },
        ImageFormat::Ppm,
        ImageFormat::Exr(Default::default()),
    ] {
        let path = dir.path().join(format!("f.{}", format.extension()));
        whitted::output::write_atomic(&path, &frame, format, &meta).unwrap();
        assert!(sound(&path, format, 2), "{format:?}");
        if matches!(format, ImageFormat::Ppm | ImageFormat::Exr(_)) {
            assert!(!sound(&path, format, 3), "{format:?}: another size");
        }
        let bytes = std::fs::read(&path).unwrap();
        std::fs::write(&path, &bytes[..bytes.len() - 1]).unwrap();
        assert!(!sound(&path, format, 2), "{format:?}: cut short");
    }
    let none = dir.path().join("none.png");
    assert_eq!(
        inspect(&none, ImageFormat::Png, 3, 2, false),
        Inspection::Missing
    );
}
