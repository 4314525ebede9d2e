//! `animate check --junit`, `--html` and `--flip` end to end: the JUnit file parsed back,
//! the page's images on disk, FLIP figures and the FLIP limit deciding the verdict, and
//! the heat map's fixed scale read back from a written diff image.

use crate::support;

use quick_junit::{NonSuccessKind, Report, TestCaseStatus};
use std::path::Path;
use support::*;

const CHECK: &str = "\n[check]\nframes = [0, 5, 9]\nreferences = \"refs\"\n";

#[test]
fn junit_parsed_back_marks_the_failing_frame_with_its_figures() {
    let (dir, manifest) = blessed(CHECK);
    edit_reference(dir.path(), 5, magenta_block);
    let xml_path = dir.path().join("check.xml");
    let xml_arg = xml_path.to_str().unwrap();
    let (code, out, err) = check(&manifest, &["--junit", xml_arg, "--flip", "1"]);
    assert_eq!(code, Some(1), "{out}{err}");
    let xml = std::fs::read_to_string(&xml_path).unwrap();
    let report = Report::deserialize_from_str(&xml).unwrap();
    let suite = &report.test_suites[0];
    assert_eq!(
        (report.test_suites.len(), suite.tests, suite.failures),
        (1, 3, 1)
    );
    let names: Vec<&str> = suite.test_cases.iter().map(|c| c.name.as_str()).collect();
    let m = manifest.display();
    assert_eq!(
        names,
        [0, 5, 9].map(|n| format!("frame {n} ({m})")),
        "{xml}"
    );
    for (i, case) in suite.test_cases.iter().enumerate() {
        assert!(case.time.is_some());
        let failed = matches!(case.status, TestCaseStatus::NonSuccess { .. });
        assert_eq!(failed, i == 1, "{xml}");
    }
    let TestCaseStatus::NonSuccess {
        kind, message, ty, ..
    } = &suite.test_cases[1].status
    else {
        unreachable!()
    };
    assert_eq!(*kind, NonSuccessKind::Failure);
    assert_eq!(ty.as_ref().unwrap().as_str(), "fail_percent, hard_fail");
    let message = message.as_ref().unwrap().as_str();
    for figure in [
        "max difference",
        "at (",
        "% of pixels failing",
        "PSNR",
        "mean FLIP 0.0",
    ] {
        assert!(message.contains(figure), "{figure:?} not in {message}");
    }
    // The table still prints, with its FLIP column.
    assert!(out.lines().next().unwrap().contains("FLIP"), "{out}");
}

#[test]
fn junit_of_a_passing_check_and_an_unwritable_junit_path() {
    let (dir, manifest) = blessed(CHECK);
    let xml_path = dir.path().join("ok.xml");
    let (code, _, _) = check(&manifest, &["--junit", xml_path.to_str().unwrap()]);
    assert_eq!(code, Some(0));
    let report = Report::deserialize_from_str(&std::fs::read_to_string(&xml_path).unwrap());
    assert_eq!(report.unwrap().test_suites[0].failures, 0);
    let bad = dir.path().join("no/such/folder/check.xml");
    let (code, _, err) = check(&manifest, &["--junit", bad.to_str().unwrap()]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("no/such/folder/check.xml"), "{err}");
    assert!(!err.contains("panicked"), "{err}");
}

/// Every `src="…"` and `data-…="….png"` the page names.
fn named_images(html: &str) -> Vec<String> {
    let mut names: Vec<String> = html
        .split('"')
        .filter(|s| s.ends_with(".png"))
        .map(str::to_string)
        .collect();
    names.sort();
    names.dedup();
    names
}

#[test]
fn html_page_names_images_that_exist_beside_it() {
    let (dir, manifest) = blessed(CHECK);
    edit_reference(dir.path(), 5, magenta_block);
    let html_dir = dir.path().join("report-page");
    let args = ["--html", html_dir.to_str().unwrap(), "--flip", "0.5"];
    let (code, out, err) = check(&manifest, &args);
    assert_eq!(code, Some(1), "{out}{err}");
    let html = std::fs::read_to_string(html_dir.join("index.html")).unwrap();
    let names = named_images(&html);
    let expected = [
        "flip-legend.png",
        "frame_0005.diff.png",
        "frame_0005.flip.png",
        "frame_0005.reference.png",
        "frame_0005.rendered.png",
        "heat-legend.png",
    ];
    assert_eq!(names, expected, "{html}");
    for name in &names {
        let img = image::open(html_dir.join(name)).unwrap();
        assert!(img.width() > 0, "{name}");
    }
    // The page's reference is the (edited) reference, its render the rendered frame.
    let reference = pixels(&html_dir.join("frame_0005.reference.png"));
    let rendered = pixels(&html_dir.join("frame_0005.rendered.png"));
    assert_eq!(&reference[3 * (10 * 64 + 10)..][..3], &[255, 0, 255]);
    assert_ne!(reference, rendered);
    // One row per frame; the page needs nothing outside its folder.
    assert_eq!(html.matches("<tr class=").count(), 3);
    assert!(!html.contains("http") && !html.contains("/refs/"), "{html}");
}

/// The mean FLIP figure of each frame, from `--json`.
fn flip_figures(manifest: &Path, args: &[&str]) -> (Option<i32>, serde_json::Value) {
    let (code, out, err) = check(manifest, &[&["--json"], args].concat());
    (
        code,
        serde_json::from_str(&out).unwrap_or_else(|_| panic!("{out}{err}")),
    )
}

#[test]
fn flip_scores_zero_for_identical_more_for_a_visible_change_and_the_limit_decides() {
    let (dir, manifest) = blessed(CHECK);
    edit_reference(dir.path(), 5, magenta_block);
    edit_reference(dir.path(), 9, |img| {
        let p = img.get_pixel_mut(30, 30);
        p[1] = if p[1] >= 128 { p[1] - 3 } else { p[1] + 3 };
    });
    // idiff's limits out of the way: only FLIP can fail a frame.
    let loose = ["--fail-percent", "100", "--hard-fail", "255"];
    let (code, doc) = flip_figures(&manifest, &[&loose[..], &["--flip", "1"]].concat());
    assert_eq!(code, Some(0), "{doc}");
    let flip = |i: usize| doc["frames"][i]["flip"].as_f64().unwrap();
    let (same, block, faint) = (flip(0), flip(1), flip(2));
    assert_eq!(same, 0.0);
    assert!(faint > 0.0 && block > 10.0 * faint, "{block} {faint}");
    // A limit between the two fails the block frame only, and names FLIP as the reason.
    let limit = ((block * faint).sqrt()).to_string();
    let (code, doc) = flip_figures(&manifest, &[&loose[..], &["--flip", &limit]].concat());
    assert_eq!(code, Some(1), "{doc}");
    let failed: Vec<&serde_json::Value> = doc["frames"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|f| f["pass"] == false)
        .collect();
    assert_eq!(failed.len(), 1, "{doc}");
    assert_eq!(failed[0]["frame"], 5);
    assert_eq!(failed[0]["failed"], serde_json::json!(["flip"]));
    // The same limit from the manifest.
    let with_flip = format!("{CHECK}fail_percent = 100\nhard_fail = 255\nflip = {limit}\n");
    std::fs::write(&manifest, circle_manifest(&with_flip)).unwrap();
    let (code, out, _) = check(&manifest, &[]);
    assert_eq!(code, Some(1), "{out}");
    let row5 = row(&out, 5);
    assert!(row5.contains("flip") && row5.ends_with("FAIL"), "{out}");
}

#[test]
fn flip_limit_out_of_range_is_refused_with_its_place() {
    let (_dir, manifest) = project(&circle_manifest(&format!("{CHECK}flip = 1.5\n")));
    let (code, _, err) = check(&manifest, &[]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("anim.toml:") && err.contains("`flip`"),
        "{err}"
    );
    let (_dir, manifest) = blessed(CHECK);
    let (code, _, err) = check(&manifest, &["--flip=-0.1"]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("--flip"), "{err}");
}

#[test]
fn heat_map_scale_is_fixed_and_logarithmic() {
    let (dir, manifest) = blessed(CHECK);
    let toward_middle = |v: u8, d: u8| if v >= 128 { v - d } else { v + d };
    edit_reference(dir.path(), 0, |img| {
        let p = img.get_pixel_mut(5, 5);
        p[0] = toward_middle(p[0], 1); // one level: dim red, not the frame's top colour
        let q = img.get_pixel_mut(40, 30);
        q[2] = toward_middle(q[2], 15); // 15 levels: orange
    });
    let (code, out, _) = check(&manifest, &["--fail", "0", "--fail-percent", "0"]);
    assert_eq!(code, Some(1), "{out}");
    assert!(
        out.contains("log scale"),
        "the legend follows the table: {out}"
    );
    let diff = image::open(dir.path().join("frames-check/frame_0000.diff.png"))
        .unwrap()
        .to_rgb8();
    assert_eq!(diff.get_pixel(5, 5).0, [96, 0, 0]);
    assert_eq!(diff.get_pixel(40, 30).0, [255, 128, 0]);
    assert_eq!(diff.get_pixel(20, 20).0, [0, 0, 0]);
}
