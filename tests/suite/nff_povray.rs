//! NFF scenes of our own (tests/data/nff) against POV-Ray 3.7 renders of their hand
//! translations: the cone and cylinder (open), the polygon (a non-convex 24-vertex star
//! among them), the smooth triangle, filtering transparency with refraction, the Phong
//! highlight, reflection, coloured and SPD-intensity lights and the background must agree
//! within the shapes issue's bounds: under 1 % of the pixels more than 6 levels apart on
//! a channel. Skips without POV-Ray (fails under CI).

use crate::shipped;
use crate::skip;
use crate::support::{pixels, raytrace};
use std::path::{Path, PathBuf};

/// Renders `name`.nff with `raytrace` and `name`.pov with POV-Ray (no anti-aliasing, no
/// gamma, at the NFF's 160 × 120) and returns the share of pixels more than 6 apart.
fn compare(name: &str) -> Option<f64> {
    let povray = skip::which("povray", &["/usr/bin/povray"])?;
    let data = shipped::root().join("tests/data/nff");
    let dir = tempfile::tempdir().unwrap();
    let ours = dir.path().join("ours.png");
    raytrace()
        .arg(data.join(format!("{name}.nff")))
        .arg("-o")
        .arg(&ours)
        .arg("-q")
        .assert()
        .success();
    let pov = data.join(format!("{name}.pov"));
    let theirs = povray_png(&povray, dir.path(), &pov, 160, 120);
    Some(share_apart(&ours, &theirs, 6))
}

/// The share of pixels whose channels differ by more than `levels` somewhere.
/// POV-Ray's picture of `pov` at w × h (one ray a pixel, linear output, no alpha) as
/// DIR/pov.png, as every comparison with POV-Ray renders it; POV-Ray failing fails the
/// test with its messages.
pub(crate) fn povray_png(povray: &Path, dir: &Path, pov: &Path, w: u32, h: u32) -> PathBuf {
    let theirs = dir.join("pov.png");
    let out = std::process::Command::new(povray)
        .current_dir(dir)
        .arg(format!("+I{}", pov.display()))
        .arg(format!("+O{}", theirs.display()))
        .args([&format!("+W{w}"), &format!("+H{h}"), "-A", "-D", "+FN8"])
        .args(["File_Gamma=1.0", "Output_Alpha=off", "-V", "-GA"])
        .output()
        .unwrap();
    assert!(
        out.status.success() && theirs.exists(),
        "povray failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    theirs
}

/// The bound of every comparison with POV-Ray: under 1 % of the pixels more than 6
/// levels apart (`share` from `share_apart`; none where POV-Ray is missing).
pub(crate) fn assert_close(share: Option<f64>) {
    if let Some(share) = share {
        assert!(
            share < 0.01,
            "{:.2} % of the pixels are apart",
            share * 100.0
        );
    }
}

pub(crate) fn share_apart(a: &Path, b: &Path, levels: u8) -> f64 {
    let (a, b) = (pixels(a), pixels(b));
    assert_eq!(a.len(), b.len(), "the two pictures differ in size");
    let apart = a
        .chunks(3)
        .zip(b.chunks(3))
        .filter(|(p, q)| p.iter().zip(*q).any(|(x, y)| x.abs_diff(*y) > levels))
        .count();
    apart as f64 / (a.len() / 3) as f64
}

#[test]
fn still_life_matches_povray() {
    // Polygon floor, mirror sphere, glass sphere (filter 0.8, ior 1.5), open cone,
    // smooth triangle, z up, a white and a coloured light, a background.
    if let Some(share) = compare("still-life") {
        assert!(
            share < 0.01,
            "{:.2} % of the pixels are apart",
            share * 100.0
        );
    }
}

#[test]
fn gear_star_and_cylinder_match_povray() {
    // A non-convex 24-vertex polygon, an open cylinder, a mirror floor, a filtering
    // square (ior 1), y up, the SPD's intensity for one white light.
    if let Some(share) = compare("gear") {
        assert!(
            share < 0.01,
            "{:.2} % of the pixels are apart",
            share * 100.0
        );
    }
}

#[test]
fn the_comparison_sees_a_difference() {
    // The measure itself: a picture against a copy with a block moved by 7 levels.
    let dir = tempfile::tempdir().unwrap();
    let (a, b) = (dir.path().join("a.png"), dir.path().join("b.png"));
    let img = image::RgbImage::from_fn(10, 10, |x, _| image::Rgb([100, 100, (x * 20) as u8]));
    img.save(&a).unwrap();
    let mut moved = img.clone();
    for y in 0..2 {
        moved.put_pixel(3, y, image::Rgb([107, 100, 60]));
    }
    moved.save(&b).unwrap();
    assert_eq!(share_apart(&a, &b, 6), 0.02);
    assert_eq!(share_apart(&a, &b, 7), 0.0);
}
