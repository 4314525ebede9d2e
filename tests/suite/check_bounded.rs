//! `animate check` over many frames with bounded memory (references read frame by
//! frame, not all first), and its HTML report's links for frame names with `?` and `#`.

use crate::support;

use std::process::{Command, Stdio};
use support::*;

/// The peak memory of `animate check` over the first `n` frames of a blessed
/// 400-frame 160×120 sequence.
fn check_peak(manifest: &std::path::Path, n: u32) -> u64 {
    let child = Command::new(assert_cmd::cargo::cargo_bin("animate"))
        .arg("check")
        .arg(manifest)
        .args(["--frames", &format!("0-{}", n - 1), "--threads", "2"])
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let (peak, status) = peak_kib_until_exit(child);
    assert!(status.success(), "check over {n} frames: {status:?}");
    peak
}

#[test]
fn check_memory_does_not_grow_with_the_frames() {
    let text = circle_manifest(
        "\n[render]\nwidth = 160\nheight = 120\n[check]\nframes = [0]\nreferences = \"refs\"\n",
    )
    .replace("frames = 12", "frames = 400");
    let (_dir, manifest) = project(&text);
    animate()
        .arg("bless")
        .arg(&manifest)
        .args(["--frames", "0-399", "-q"])
        .assert()
        .success();
    let (few, many) = (check_peak(&manifest, 20), check_peak(&manifest, 400));
    // All 400 references at once would be 400 × 57.6 kB = 23 MB more.
    assert!(
        many < few + 8 * 1024,
        "20 frames: {few} KiB, 400 frames: {many} KiB"
    );
}

#[test]
fn report_links_survive_question_marks_and_hashes_in_names() {
    let check = "\n[check]\nframes = [3]\nreferences = \"refs\"\n";
    let text = circle_manifest(check).replace("name = \"frame_####\"", "name = \"f?_####_#x\"");
    let (dir, manifest) = project(&text);
    animate().arg("bless").arg(&manifest).assert().success();
    let reference = dir.path().join("refs/f?_0003_#x.png");
    let mut img = image::open(&reference).unwrap().to_rgb8();
    magenta_block(&mut img);
    img.save(&reference).unwrap();
    let page = dir.path().join("page");
    let out = animate()
        .arg("check")
        .arg(&manifest)
        .arg("--html")
        .arg(&page)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    let html = std::fs::read_to_string(page.join("index.html")).unwrap();
    let links: Vec<String> = html
        .split("src=\"")
        .skip(1)
        .map(|rest| rest[..rest.find('"').unwrap()].to_string())
        .collect();
    assert!(
        links.iter().any(|l| l.starts_with("f%3F_0003_%23x.")),
        "{links:?}"
    );
    for link in links {
        assert!(!link.contains(['?', '#']), "{link}");
        let file = percent_encoding::percent_decode_str(&link)
            .decode_utf8()
            .unwrap();
        assert!(page.join(file.as_ref()).is_file(), "{link} names no file");
    }
}
