//! Figures for benches/pov/adaptive.sh (adaptive anti-aliasing, SPEC §15):
//!
//! ```text
//! cargo run --release --features examples --example aa_figures -- compare REF.png IMG.png   # PSNR dB, FLIP mean
//! cargo run --release --features examples --example aa_figures -- heat SCENE.txt OUT.png T D # leaves per pixel
//! ```
//!
//! `heat` draws the scene adaptively and writes the count of leaves of every pixel on a
//! log scale (FLIP's magma colours: black 1 leaf, the corners only; pale yellow 4^D, split
//! everywhere to the depth), and prints the camera rays per pixel.

use anyhow::{bail, Context};
use std::path::Path;
use whitted::base::Frame;
use whitted::render::adaptive::{trace, Adaptive, BAND};
use whitted::{trace::Tracer, Scene};

fn load(path: &str) -> anyhow::Result<Frame> {
    let img = image::open(path)
        .with_context(|| path.to_string())?
        .to_rgb8();
    Ok(Frame {
        width: img.width(),
        height: img.height(),
        pixels: img.into_raw(),
    })
}

fn compare(reference: &str, image: &str) -> anyhow::Result<()> {
    let (a, b) = (load(reference)?, load(image)?);
    if (a.width, a.height) != (b.width, b.height) {
        bail!("{reference} and {image} differ in size");
    }
    let mse = a
        .pixels
        .iter()
        .zip(&b.pixels)
        .map(|(&x, &y)| (f64::from(x) - f64::from(y)).powi(2))
        .sum::<f64>()
        / a.pixels.len() as f64;
    let psnr = 10.0 * (255.0f64 * 255.0 / mse.max(1e-12)).log10();
    let flip = whitted_anim::check::flip::flip(&a, &b).mean;
    println!("{psnr:.3} {flip:.5}");
    Ok(())
}

fn heat(scene: &str, out: &str, aa: Adaptive) -> anyhow::Result<()> {
    let scene = Scene::load(Path::new(scene))?;
    let tracer = Tracer::new(&scene);
    let (w, h) = (scene.width, scene.height);
    let done = trace(&tracer, &scene.camera(), w, h, aa, BAND);
    let top = (4f32).powi(aa.depth as i32).log2().max(1.0);
    let values: Vec<f32> = done
        .leaves
        .iter()
        .map(|&n| (n as f32).log2() / top)
        .collect();
    let map =
        nv_flip::FlipImageFloat::with_data(w, h, &values).apply_color_lut(&nv_flip::magma_lut());
    image::save_buffer(out, &map.to_vec(), w, h, image::ExtendedColorType::Rgb8)?;
    let split = done.leaves.iter().filter(|&&n| n > 1).count();
    println!(
        "{:.4} camera rays/px, {:.4} rays/px in all, {:.2}% of pixels split",
        done.rays.primary as f64 / f64::from(w * h),
        done.rays.total() as f64 / f64::from(w * h),
        100.0 * split as f64 / f64::from(w * h)
    );
    Ok(())
}

fn main() -> anyhow::Result<()> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.iter().map(String::as_str).collect::<Vec<_>>()[..] {
        ["compare", reference, image] => compare(reference, image),
        ["heat", scene, out, t, d] => heat(scene, out, format!("adaptive:{t}:{d}").parse()?),
        _ => bail!("usage: aa_figures compare REF IMG | heat SCENE OUT T D"),
    }
}
