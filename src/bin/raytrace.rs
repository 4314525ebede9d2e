//! `raytrace [SCENE] [-o OUT] [--samples N] [--threads N]`: one image from a Scene.txt,
//! the report's main(). Exit status 0 on success, 2 on bad input (the scene or the
//! arguments), 1 when the image cannot be written.

use clap::Parser;
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;
use whitted::output::{write_atomic, ImageFormat};
use whitted::trace::Tracer;
use whitted::{render, Scene};

/// Render one Scene.txt to an image (PNG, JPEG, PPM or the report's RAW, by extension).
#[derive(Parser, Debug)]
#[command(name = "raytrace", version, about)]
struct Args {
    /// The scene file.
    #[arg(default_value = "Scene.txt")]
    scene: PathBuf,
    /// The image to write; defaults to the scene's name with `.png`.
    #[arg(short, long, value_name = "OUT")]
    out: Option<PathBuf>,
    /// Anti-aliasing: an N×N stratified grid of samples per pixel (1 = the report's).
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..=16))]
    samples: u32,
    /// Worker threads (default: all cores).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=1024))]
    threads: Option<u32>,
    /// Print nothing on success.
    #[arg(short, long)]
    quiet: bool,
}

/// A failure and the exit status it deserves. The library's errors already carry their
/// cause in their message, so they are printed without the source chain.
enum Failure {
    BadInput(anyhow::Error),
    Output(anyhow::Error),
}

fn run(args: Args) -> Result<(), Failure> {
    let out = args
        .out
        .clone()
        .unwrap_or_else(|| args.scene.with_extension("png"));
    let format = ImageFormat::from_path(&out).map_err(|e| Failure::BadInput(e.into()))?;
    let scene = Scene::load(&args.scene).map_err(|e| Failure::BadInput(e.into()))?;
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(args.threads.unwrap_or(0) as usize)
        .build()
        .map_err(|e| Failure::Output(e.into()))?;

    let start = Instant::now();
    let camera = scene.camera();
    let tracer = Tracer::new(&scene);
    let (frame, rays) =
        pool.install(|| render(&tracer, &camera, scene.width, scene.height, args.samples));
    let traced = start.elapsed().as_secs_f64();
    write_atomic(&out, &frame, format).map_err(|e| Failure::Output(e.into()))?;
    if !args.quiet {
        eprintln!(
            "raytrace: wrote {} ({}×{}, {} sample(s)/px) in {:.3} s: {} rays, {:.2} Mrays/s",
            out.display(),
            frame.width,
            frame.height,
            args.samples * args.samples,
            traced,
            rays.total(),
            rays.total() as f64 / traced.max(1e-9) / 1e6
        );
    }
    Ok(())
}

fn main() -> ExitCode {
    let args = Args::parse();
    match run(args) {
        Ok(()) => ExitCode::SUCCESS,
        Err(Failure::BadInput(e)) => {
            eprintln!("raytrace: {e}");
            ExitCode::from(2)
        }
        Err(Failure::Output(e)) => {
            eprintln!("raytrace: {e}");
            ExitCode::from(1)
        }
    }
}
