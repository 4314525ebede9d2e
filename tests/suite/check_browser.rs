//! The `--html` report page in a real browser: headless Chromium (Debian's `chromium`,
//! which `.ci/run` installs) opens `index.html` from disk and takes a screenshot, and the
//! screenshot must show the pictures. Without Chromium on PATH the test says it skipped,
//! unless CI is set, where a missing browser is a failure.

use crate::skip;
use crate::support;

use std::path::Path;
use std::process::Command;
use support::*;

/// A screenshot of `page` at `width`×`height`, taken by headless Chromium.
fn screenshot(browser: &Path, page: &Path, out: &Path, width: u32, height: u32) {
    let profile = tempfile::tempdir().unwrap();
    let status = Command::new(browser)
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--disable-quic",
            "--no-first-run",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            "--hide-scrollbars",
        ])
        .arg(format!("--user-data-dir={}", profile.path().display()))
        .arg(format!("--screenshot={}", out.display()))
        .arg(format!("--window-size={width},{height}"))
        .arg(format!("file://{}", page.display()))
        .output()
        .unwrap();
    assert!(
        status.status.success() && out.exists(),
        "{}",
        String::from_utf8_lossy(&status.stderr)
    );
}

#[test]
fn report_page_draws_its_pictures_in_chromium() {
    let Some(browser) = skip::chromium() else {
        return;
    };
    let (dir, manifest) = project(&circle_manifest(
        "\n[check]\nframes = [0, 5]\nreferences = \"refs\"\n",
    ));
    animate().arg("bless").arg(&manifest).assert().success();
    // A magenta block in frame 5's reference: the render has none, so it fails, and the
    // page's reference pictures are the only magenta on screen.
    let reference = dir.path().join("refs/frame_0005.png");
    let mut img = image::open(&reference).unwrap().to_rgb8();
    for y in 10..20 {
        for x in 10..20 {
            img.put_pixel(x, y, image::Rgb([255, 0, 255]));
        }
    }
    img.save(&reference).unwrap();
    let page_dir = dir.path().join("page");
    let out = animate()
        .arg("check")
        .arg(&manifest)
        .args(["--flip", "0.5", "--html"])
        .arg(&page_dir)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));

    let shot_path = dir.path().join("shot.png");
    screenshot(
        &browser,
        &page_dir.join("index.html"),
        &shot_path,
        1600,
        1200,
    );
    let shot = image::open(&shot_path).unwrap().to_rgb8();
    let count = |test: &dyn Fn([u8; 3]) -> bool| shot.pixels().filter(|p| test(p.0)).count();
    // Not blank: the page has text and pictures, not one flat colour.
    let white = count(&|p| p.iter().all(|&c| c > 245));
    let total = (shot.width() * shot.height()) as usize;
    assert!(white < total * 95 / 100, "{white} of {total} pixels white");
    // The 10×10 block, drawn 5× (64 px frames are shown 320 px wide) in the reference and
    // in the flip picture: 2 × 2500 pixels. A missing image draws no magenta.
    let magenta = count(&|p| p[0] > 220 && p[1] < 40 && p[2] > 220);
    assert!(magenta >= 4000, "{magenta} magenta pixels");
    // The render and the reference side by side: many pixels of the rendered scene.
    let colourful = count(&|p| {
        let (lo, hi) = (p.iter().min().unwrap(), p.iter().max().unwrap());
        hi - lo > 40
    });
    assert!(
        colourful > 4 * 320 * 240 / 10,
        "{colourful} coloured pixels"
    );
}
