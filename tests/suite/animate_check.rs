//! `animate bless` and `animate check` end to end, on idiff's rules.

use crate::support;

use support::*;

const CHECK: &str = "\n[check]\nframes = [0, 5, 9]\nreferences = \"refs\"\nfail = 2\n\
                     fail_percent = 0.5\nhard_fail = 64\n";

#[test]
fn bless_then_check_passes() {
    let (dir, manifest) = blessed(CHECK);
    let refs: Vec<String> = files(&dir.path().join("refs"))
        .into_iter()
        .map(|f| f.0)
        .collect();
    assert_eq!(refs, ["frame_0000.png", "frame_0005.png", "frame_0009.png"]);
    let (code, out, _) = check(&manifest, &[]);
    assert_eq!(code, Some(0), "{out}");
    assert_eq!(out.matches("PASS").count(), 4, "{out}"); // three rows and the verdict
    assert!(!dir.path().join("frames-check").exists());
}

#[test]
fn a_changed_block_fails_and_names_the_frame() {
    let (dir, manifest) = blessed(CHECK);
    edit_reference(dir.path(), 5, magenta_block);
    let (code, out, _) = check(&manifest, &[]);
    assert_eq!(code, Some(1), "{out}");
    let row5 = row(&out, 5);
    assert!(row5.ends_with("FAIL"), "{out}");
    let row0 = row(&out, 0);
    assert!(row0.ends_with("PASS"), "{out}");
    // Images for the failing frame only.
    let report = files(&dir.path().join("frames-check"));
    let names: Vec<&str> = report.iter().map(|f| f.0.as_str()).collect();
    assert_eq!(names, ["frame_0005.diff.png", "frame_0005.rendered.png"]);
}

#[test]
fn missing_reference_exits_2() {
    let (dir, manifest) = blessed(CHECK);
    std::fs::remove_file(dir.path().join("refs/frame_0009.png")).unwrap();
    let (code, _, err) = check(&manifest, &[]);
    assert_eq!(code, Some(2));
    assert!(err.contains("frame 9") && err.contains("missing"), "{err}");
}

#[test]
fn reference_of_another_size_exits_2() {
    let (dir, manifest) = blessed(CHECK);
    let path = dir.path().join("refs/frame_0000.png");
    image::RgbImage::new(32, 24).save(&path).unwrap();
    let (code, _, err) = check(&manifest, &[]);
    assert_eq!(code, Some(2));
    assert!(err.contains("32×24") && err.contains("64×48"), "{err}");
}

#[test]
fn one_channel_off_by_fail_passes_and_by_fail_plus_one_fails() {
    // With fail_percent 0 a single failing pixel fails the frame.
    let (dir, manifest) = blessed(CHECK);
    let original = image::open(dir.path().join("refs/frame_0000.png"))
        .unwrap()
        .to_rgb8();
    let g = original.get_pixel(30, 30)[1];
    let shifted = |d: u8| if g >= 128 { g - d } else { g + d };
    edit_reference(dir.path(), 0, |img| {
        img.get_pixel_mut(30, 30)[1] = shifted(2)
    });
    let (code, out, _) = check(&manifest, &["--fail-percent", "0"]);
    assert_eq!(code, Some(0), "{out}");
    edit_reference(dir.path(), 0, |img| {
        img.get_pixel_mut(30, 30)[1] = shifted(3)
    });
    let (code, out, _) = check(&manifest, &["--fail-percent", "0"]);
    assert_eq!(code, Some(1), "{out}");
    assert!(out.contains("(30, 30) G"), "{out}");
    // A looser --fail on the command line overrides the manifest.
    let (code, out, _) = check(&manifest, &["--fail-percent", "0", "--fail", "3"]);
    assert_eq!(code, Some(0), "{out}");
}

#[test]
fn hard_fail_trips_on_a_single_pixel() {
    let (dir, manifest) = blessed(CHECK);
    edit_reference(dir.path(), 9, |img| {
        let p = img.get_pixel_mut(3, 4);
        p[0] = if p[0] >= 128 { p[0] - 65 } else { p[0] + 65 };
    });
    // One pixel of 3072 is 0.03 %, under fail_percent 0.5: only hard_fail catches it.
    let (code, out, _) = check(&manifest, &[]);
    assert_eq!(code, Some(1), "{out}");
    let (code, out, _) = check(&manifest, &["--hard-fail", "65"]);
    assert_eq!(code, Some(0), "{out}");
}

#[test]
fn json_output_for_ci() {
    let (dir, manifest) = blessed(CHECK);
    edit_reference(dir.path(), 5, |img| {
        img.put_pixel(1, 1, image::Rgb([0, 0, 0]))
    });
    let (code, out, _) = check(&manifest, &["--json", "--hard-fail", "0"]);
    assert_eq!(code, Some(1));
    let doc: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(doc["pass"], false);
    let frames = doc["frames"].as_array().unwrap();
    assert_eq!(frames.len(), 3);
    assert_eq!(frames[1]["frame"], 5);
    assert_eq!(frames[1]["pass"], false);
    assert!(frames[1]["diff_image"]
        .as_str()
        .unwrap()
        .ends_with("frame_0005.diff.png"));
    assert_eq!(frames[0]["pass"], true);
    assert!(frames[0]["diff_image"].is_null());
    assert!(frames[0]["psnr"].is_null()); // identical: infinite PSNR
}

#[test]
fn no_check_section_and_no_frames_exits_2() {
    let (_dir, manifest) = project(&circle_manifest(""));
    let (code, _, err) = check(&manifest, &[]);
    assert_eq!(code, Some(2));
    assert!(err.contains("[check]"), "{err}");
}
