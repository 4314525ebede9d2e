//! Our pictures against POV-Ray 3.7's (every new shape, light and texture is compared on
//! a scene of its own): POV-Ray found or the test skipped (`povray`), its picture of a
//! `.pov` file rendered as every comparison renders it (`povray_png`), ours drawn in
//! memory beside it (`against_povray`), and the bound they must meet (`share_apart`,
//! `assert_close`: under 1 % of the pixels more than 6 levels apart on a channel).

use crate::skip;
use crate::support::pixels;
use std::path::{Path, PathBuf};
use whitted::trace::Tracer;
use whitted::Scene;

/// POV-Ray's path, or `None` after the test said it skipped (it fails under CI).
pub fn povray() -> Option<PathBuf> {
    skip::which("povray", &["/usr/bin/povray"])
}

/// POV-Ray's picture of `pov` at w × h (one ray a pixel, linear output, no alpha) as
/// DIR/pov.png; POV-Ray failing fails the test with its messages.
pub fn povray_png(povray: &Path, dir: &Path, pov: &Path, w: u32, h: u32) -> PathBuf {
    povray_png_encoded(povray, dir, pov, (w, h), "1.0")
}

/// `povray_png` with the output encoded by `gamma` (POV-Ray's `File_Gamma`: `1.0` writes
/// the linear values, `srgb` sRGB-encodes them as a linear-light scene's frame is).
pub fn povray_png_encoded(
    povray: &Path,
    dir: &Path,
    pov: &Path,
    (w, h): (u32, u32),
    gamma: &str,
) -> PathBuf {
    let theirs = dir.join("pov.png");
    let out = std::process::Command::new(povray)
        .current_dir(dir)
        .arg(format!("+I{}", pov.display()))
        .arg(format!("+O{}", theirs.display()))
        .args([&format!("+W{w}"), &format!("+H{h}"), "-A", "-D", "+FN8"])
        .arg(format!("File_Gamma={gamma}"))
        .args(["Output_Alpha=off", "-V", "-GA"])
        .output()
        .unwrap();
    assert!(
        out.status.success() && theirs.exists(),
        "povray failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    theirs
}

/// `scene` drawn by us at w × h (one sample a pixel) as DIR/ours.png, and POV-Ray's
/// picture of `pov` beside it: the share of pixels more than 6 levels apart. When the
/// environment variable `keep` names a folder, both pictures are copied there as
/// `TAG-ours.png` and `TAG-pov.png`, to look at.
pub fn against_povray(scene: &Scene, pov: &Path, (w, h): (u32, u32), keep: (&str, &str)) -> f64 {
    let povray = povray().expect("the caller found POV-Ray first");
    let dir = pov.parent().unwrap();
    let tracer = Tracer::new(scene);
    let grid = whitted::render::Options::grid(w, h, 1);
    let (frame, _) = whitted::render(
        &tracer,
        &scene.camera(),
        &grid,
        whitted::render::Picture::new(),
    );
    let ours = dir.join("ours.png");
    image::RgbImage::from_raw(w, h, frame.pixels)
        .unwrap()
        .save(&ours)
        .unwrap();
    let theirs = povray_png(&povray, dir, pov, w, h);
    let (var, tag) = keep;
    if let Some(to) = std::env::var_os(var) {
        let to = Path::new(&to);
        std::fs::copy(&ours, to.join(format!("{tag}-ours.png"))).unwrap();
        std::fs::copy(&theirs, to.join(format!("{tag}-pov.png"))).unwrap();
    }
    share_apart(&ours, &theirs, 6)
}

/// The bound of every comparison with POV-Ray: under 1 % of the pixels more than 6
/// levels apart (`share` from `share_apart`; none where POV-Ray is missing).
pub fn assert_close(share: Option<f64>) {
    if let Some(share) = share {
        assert!(
            share < 0.01,
            "{:.2} % of the pixels are apart",
            share * 100.0
        );
    }
}

/// The share of pixels whose channels differ by more than `levels` somewhere.
pub fn share_apart(a: &Path, b: &Path, levels: u8) -> f64 {
    let (a, b) = (pixels(a), pixels(b));
    assert_eq!(a.len(), b.len(), "the two pictures differ in size");
    let apart = a
        .chunks(3)
        .zip(b.chunks(3))
        .filter(|(p, q)| p.iter().zip(*q).any(|(x, y)| x.abs_diff(*y) > levels))
        .count();
    apart as f64 / (a.len() / 3) as f64
}
