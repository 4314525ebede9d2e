//! The tracer taken in part: a Scene.txt parsed and rendered into memory, then encoded as
//! a PNG, with whatever features this build has. `cargo run --release -p whitted
//! --no-default-features --features examples --example lean_render` is the lean build's check
//! (tests/suite/lean_build.rs): it prints one line `lean: WxH, N PNG bytes, M primary
//! rays; exr FEATURE, jpeg FEATURE` and exits 0, or says what went wrong and exits 1.

use std::process::ExitCode;
use whitted::output::{encode, ImageFormat, OutputError};
use whitted::render::{render, Options, Picture};
use whitted::{trace::Tracer, Scene};

/// A red sphere on the report's checker floor, one light: every part of a frame.
const SCENE: &str = "64 48  0 1 6  0 0 0  0 0  1 1 0 1
1 0 0 0  1 1 0 0  1 0 0 1 0 0
0 -1 0  0 1 0  2 1 1 1 1 0 0 0 0 0 0  1 0 0 1 0 0
0 5 5  1 1 1  1
";

fn main() -> ExitCode {
    match run() {
        Ok(line) => {
            println!("{line}");
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("lean_render: {e}");
            ExitCode::FAILURE
        }
    }
}

fn run() -> Result<String, Box<dyn std::error::Error>> {
    let scene = Scene::parse(SCENE, "lean.txt")?;
    let tracer = Tracer::new(&scene);
    let grid = Options::grid(64, 48, 1);
    let (frame, rays) = render(&tracer, &scene.camera(), &grid, Picture::new());
    let mut png = Vec::new();
    encode(&frame, ImageFormat::Png, &[], &mut png)?;
    if !png.starts_with(b"\x89PNG") {
        return Err("the PNG has no PNG signature".into());
    }
    // The centre of the image sees the lit red sphere.
    let centre = &frame.pixels[(24 * 64 + 32) * 3..][..3];
    if !(centre[0] > 100 && centre[1] == 0 && centre[2] == 0) {
        return Err(format!("the centre is {centre:?}, not the red sphere").into());
    }
    let state = |path: &str| match ImageFormat::from_path(std::path::Path::new(path)) {
        Ok(_) => "built".to_string(),
        Err(OutputError::NotBuilt { feature, .. }) => format!("left out ({feature})"),
        Err(e) => e.to_string(),
    };
    Ok(format!(
        "lean: {}x{}, {} PNG bytes, {} primary rays; exr {}, jpeg {}",
        frame.width,
        frame.height,
        png.len(),
        rays.primary,
        state("x.exr"),
        state("x.jpg")
    ))
}
