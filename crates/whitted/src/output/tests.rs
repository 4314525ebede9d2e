//! The formats' round trips, targets and atomic writes.
use super::*;

fn frame() -> Frame {
    Frame {
        width: 2,
        height: 1,
        pixels: vec![255, 0, 0, 0, 128, 255],
    }
}

#[test]
fn format_from_extension() {
    assert_eq!(
        ImageFormat::from_path(Path::new("a/b.PNG")).unwrap(),
        ImageFormat::Png
    );
    assert_eq!(
        ImageFormat::from_path(Path::new("x.jpeg")).unwrap(),
        ImageFormat::Jpeg { quality: 90 }
    );
    assert_eq!(
        ImageFormat::from_path(Path::new("x.raw")).unwrap(),
        ImageFormat::Raw
    );
    assert_eq!(
        ImageFormat::from_path(Path::new("x.ppm")).unwrap(),
        ImageFormat::Ppm
    );
    assert!(ImageFormat::from_path(Path::new("x.tiff")).is_err());
    assert!(ImageFormat::from_path(Path::new("noext")).is_err());
}

#[test]
fn raw_and_ppm_bytes() {
    let mut raw = Vec::new();
    encode(&frame(), ImageFormat::Raw, &[], &mut raw).unwrap();
    assert_eq!(raw, frame().pixels);
    let mut ppm = Vec::new();
    encode(&frame(), ImageFormat::Ppm, &[], &mut ppm).unwrap();
    assert_eq!(&ppm[..11], b"P6\n2 1\n255\n");
    assert_eq!(&ppm[11..], &frame().pixels[..]);
}

#[test]
fn png_round_trips() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("f.png");
    write_atomic(&path, &frame(), ImageFormat::Png, &[]).unwrap();
    let back = image::open(&path).unwrap().to_rgb8();
    assert_eq!(back.into_raw(), frame().pixels);
    // Only the final file is left in the folder, readable by others as a new file is.
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 1);
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        let mode = std::fs::metadata(&path).unwrap().permissions().mode();
        assert_eq!(mode & 0o044, 0o044, "{mode:o}");
    }
}

#[test]
fn targets_are_checked_before_rendering() {
    let dir = tempfile::tempdir().unwrap();
    assert!(check_target(&dir.path().join("a.png")).is_ok());
    let missing = check_target(&dir.path().join("no/a.png")).unwrap_err();
    assert!(missing.to_string().contains("does not exist"), "{missing}");
    assert_eq!(missing.outcome(), crate::exit::Outcome::BadInput);
    let folder = check_target(dir.path()).unwrap_err();
    assert!(folder.to_string().contains("it is a folder"), "{folder}");
}

#[test]
fn write_errors_name_the_file_not_the_temporary_one() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("no/such/f.png");
    let shown = write_atomic(&path, &frame(), ImageFormat::Png, &[])
        .unwrap_err()
        .to_string();
    // The hidden temporary file would be `.f.png.XXXXXX.tmp`.
    assert!(
        shown.contains("/f.png") && !shown.contains(".f.png."),
        "{shown}"
    );
}

#[test]
fn failed_write_leaves_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let missing = dir.path().join("no/such/dir/f.png");
    assert!(write_atomic(&missing, &frame(), ImageFormat::Png, &[]).is_err());
    assert!(!missing.exists());
}

#[test]
fn temporaries_are_named_after_their_target() {
    assert_eq!(
        temporary_target(".frame_0001.png.a1B2c3.tmp"),
        Some("frame_0001.png")
    );
    assert_eq!(temporary_target("frame_0001.png.a1B2c3.tmp"), None);
    assert_eq!(temporary_target(".frame_0001.png.a1B2.tmp"), None);
    assert_eq!(temporary_target(".notes.tmp"), None);
}
