//! `raytrace [SCENE] [-o OUT] [--size WxH] [--samples N | --aa adaptive[:T[:D]]] [--threads N]
//! [--display tev] [--passes LIST] [--pass NAME] [--exr-depth half|float]`: one image from a
//! Scene.txt, the report's main(). It parses the command line and calls the library;
//! exit statuses follow `whitted::exit` (2 bad input, 1 a failed write, 130/143 stopped by
//! SIGINT/SIGTERM).

use anyhow::Context;
use clap::Parser;
use std::path::PathBuf;
use std::process::ExitCode;
use whitted::display::{Display, Tev};
use whitted::exit::Outcome;
use whitted::output::{
    check_target, write_atomic, write_atomic_layers, ExrDepth, ImageFormat, OutputError,
};
use whitted::passes::{visible::picture, Pass, PassSet};
use whitted::render::{render_layers, render_observed, render_with, Adaptive, Antialias};
use whitted::{trace::Tracer, Scene, SceneError};

/// Rows per band streamed to tev: a band is a few milliseconds of work at the report's
/// sizes, so the picture fills in smoothly.
const STREAM_BAND: u32 = 16;

const AFTER_HELP: &str = "\
Formats, by OUT's extension: .png, .jpg/.jpeg (quality 90), .ppm (binary P6), .raw (the
report's headerless RGB bytes, rows top to bottom), .exr (OpenEXR: the beauty unclamped,
half unless --exr-depth float, and the --passes asked for; docs/exr.md). OUT defaults to
the scene's path with .png, beside the scene file (raytrace sub/t.txt writes sub/t.png).
--pass NAME writes one pass as the picture: depth as near/z (the nearest point white, twice
as far half grey, no hit black); normals as (N+1)/2 in RGB; positions as 0.5+0.5·x/(1+|x|)
per axis; colours clamped and rounded; Cryptomatte ids as flat colours.
Exit status: 0 success; 2 nothing was rendered (bad arguments or scene, an output path
that cannot be used); 1 the image could not be written; 130/143 stopped by SIGINT/SIGTERM
(no image is written). Scene.txt: docs/scene-format.md.";

/// Render one Scene.txt to an image.
#[derive(Parser, Debug)]
#[command(name = "raytrace", version, about, after_help = AFTER_HELP)]
struct Args {
    /// The scene file.
    #[arg(default_value = "Scene.txt")]
    scene: PathBuf,
    /// The image to write (its extension picks the format); defaults to SCENE with .png.
    #[arg(short, long, value_name = "OUT")]
    out: Option<PathBuf>,
    /// Render at this size instead of the scene's resolution: WIDTHxHEIGHT, e.g. 160x120
    /// (the view keeps the report's 0.5 × 0.35 plane).
    #[arg(long, value_name = "WxH", value_parser = parse_size)]
    size: Option<(u32, u32)>,
    /// Anti-aliasing: an N×N stratified grid of samples per pixel (1 = the report's).
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..=16))]
    samples: u32,
    /// Adaptive anti-aliasing instead of the grid (SPEC §15): pixel corners shared, squares
    /// split where corners differ by more than THRESHOLD (0..=3, default 0.5), down to
    /// DEPTH (0..=6, default 3).
    #[arg(long, value_name = "adaptive[:T[:D]]", conflicts_with = "samples",
          value_parser = |s: &str| s.parse::<Adaptive>().map_err(|e| e.to_string()))]
    aa: Option<Adaptive>,
    /// Worker threads (default: all cores).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=1024))]
    threads: Option<u32>,
    /// Passes to store beside the beauty in an .exr: comma-separated names (depth,
    /// position, normal, albedo, ambient, diffuse, specular, reflection, transmission,
    /// fog, crypto_object, crypto_material) or `all`.
    #[arg(long, value_name = "LIST", value_parser = parse_passes)]
    passes: Option<PassSet>,
    /// Write this pass as the picture instead of the beauty (an 8-bit OUT: .png, …).
    #[arg(long, value_name = "NAME", value_parser = parse_pass)]
    pass: Option<Pass>,
    /// The sample type of an .exr beauty.
    #[arg(long, value_name = "DEPTH", value_parser = parse_depth)]
    exr_depth: Option<ExrDepth>,
    /// Print nothing on success.
    #[arg(short, long)]
    quiet: bool,
    /// Also stream the rows to a running tev viewer as they finish: `tev` (at
    /// 127.0.0.1:14158) or `tev=HOST:PORT`. A missing viewer is a warning.
    #[arg(long, value_name = "tev[=HOST:PORT]")]
    display: Option<Display>,
}

fn parse_size(s: &str) -> Result<(u32, u32), String> {
    let bad = || format!("expected WIDTHxHEIGHT within 16384 a side and 2^26 pixels, found {s:?}");
    let (w, h) = s.split_once(['x', 'X']).ok_or_else(bad)?;
    let (w, h): (u32, u32) = (w.parse().map_err(|_| bad())?, h.parse().map_err(|_| bad())?);
    whitted::limits::size_ok(w.into(), h.into())
        .then_some((w, h))
        .ok_or_else(bad)
}

fn pass_names() -> String {
    Pass::ALL.map(|p| p.name()).join(", ")
}

fn parse_pass(s: &str) -> Result<Pass, String> {
    Pass::from_name(s)
        .ok_or_else(|| format!("unknown pass {s:?}, expected one of {}", pass_names()))
}

fn parse_passes(s: &str) -> Result<PassSet, String> {
    if s == "all" {
        return Ok(PassSet::of(&Pass::ALL));
    }
    let list: Result<Vec<Pass>, String> = s.split(',').map(|p| parse_pass(p.trim())).collect();
    Ok(PassSet::of(&list?))
}

fn parse_depth(s: &str) -> Result<ExrDepth, String> {
    ExrDepth::from_name(s).ok_or_else(|| format!("expected half or float, found {s:?}"))
}

/// The format of OUT with the EXR options, refusing options its format cannot carry.
fn out_format(args: &Args, out: &std::path::Path) -> Result<ImageFormat, OutputError> {
    let refuse = |reason: &str| OutputError::Target {
        path: out.to_path_buf(),
        reason: reason.into(),
    };
    let format = ImageFormat::from_path(out)?;
    if args.aa.is_some() && (format.is_layered() || args.pass.is_some()) {
        return Err(refuse(
            "--aa adaptive draws 8-bit pictures only; an .exr or a --pass takes --samples",
        ));
    }
    match format {
        ImageFormat::Exr(mut o) => {
            if args.pass.is_some() {
                return Err(refuse("--pass writes an 8-bit picture (.png, .jpg, .ppm, .raw); an .exr takes --passes"));
            }
            o.passes = args.passes.unwrap_or_default();
            o.depth = args.exr_depth.unwrap_or_default();
            Ok(ImageFormat::Exr(o))
        }
        _ if args.passes.is_some() => Err(refuse("--passes needs an .exr image")),
        _ if args.exr_depth.is_some() => Err(refuse("--exr-depth needs an .exr image")),
        other => Ok(other),
    }
}

fn run(args: Args) -> anyhow::Result<()> {
    whitted::process::exit_on_signals();
    let out = args
        .out
        .clone()
        .unwrap_or_else(|| args.scene.with_extension("png"));
    let format = out_format(&args, &out)?;
    let mut scene = Scene::load(&args.scene)?;
    check_target(&out)?;
    let same = |a: &std::path::Path, b: &std::path::Path| matches!((a.canonicalize(), b.canonicalize()), (Ok(x), Ok(y)) if x == y);
    if same(&args.scene, &out) {
        return Err(OutputError::Target {
            path: out,
            reason: "it is the scene file being read (name another image with -o)".into(),
        }
        .into());
    }
    (scene.width, scene.height) = args.size.unwrap_or((scene.width, scene.height));
    let pool = whitted::process::pool(args.threads).context("cannot start the worker threads")?;
    let start = std::time::Instant::now();
    let (camera, tracer) = (scene.camera(), Tracer::new(&scene));
    let (w, h, n) = (scene.width, scene.height, args.samples);
    let aa = args.aa.map_or(Antialias::Grid(n), Antialias::Adaptive);
    let (frame, rays) = if format.is_layered() || args.pass.is_some() {
        let passes = args.pass.map_or(format.passes(), |p| PassSet::of(&[p]));
        let (layers, rays) = pool.install(|| render_layers(&tracer, &camera, w, h, n, passes));
        let frame = match args.pass {
            Some(p) => picture(&layers, p).context("the pass was not drawn")?,
            None => {
                write_atomic_layers(&out, &layers, format, &[])?;
                layers.to_frame()
            }
        };
        (Some(frame).filter(|_| args.pass.is_some()), rays)
    } else {
        let (frame, rays) = match &args.display {
            None => pool.install(|| render_with(&tracer, &camera, w, h, aa)),
            Some(Display::Tev(addr)) => {
                let tev = Tev::connect_stderr(addr, "raytrace");
                let name = format!("raytrace: {}", out.display());
                tev.create(&name, w, h);
                if let Antialias::Adaptive(_) = aa {
                    // Adaptive frames are drawn whole (their corner lattice first), then sent.
                    let drawn = pool.install(|| render_with(&tracer, &camera, w, h, aa));
                    tev.rows(&name, w, 0, &drawn.0.pixels);
                    drawn
                } else {
                    let band = STREAM_BAND;
                    let send = |y0: u32, rows: &[u8]| tev.rows(&name, w, y0, rows);
                    pool.install(|| render_observed(&tracer, &camera, w, h, n, band, &send))
                }
            }
        };
        (Some(frame), rays)
    };
    let traced = start.elapsed().as_secs_f64();
    if let Some(frame) = &frame {
        write_atomic(&out, frame, format)?;
    }
    if !args.quiet {
        let mrays = rays.total() as f64 / traced.max(1e-9) / 1e6;
        let n = match aa {
            Antialias::Grid(n) => format!("{} sample(s)/px", n * n),
            Antialias::Adaptive(a) => format!(
                "adaptive {} depth {}, {:.3} camera rays/px",
                a.threshold,
                a.depth,
                rays.primary as f64 / (f64::from(w) * f64::from(h))
            ),
        };
        eprintln!(
            "raytrace: wrote {} ({}×{}, {n}) in {traced:.3} s: {} rays, {mrays:.2} Mrays/s",
            out.display(),
            w,
            h,
            rays.total()
        );
    }
    Ok(())
}

fn main() -> ExitCode {
    if let Err(e) = whitted::process::check_cpu() {
        eprintln!("raytrace: {e}");
        return ExitCode::from(Outcome::BadInput.code());
    }
    match run(Args::parse()) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("raytrace: {e}");
            let outcome = match (
                e.downcast_ref::<SceneError>(),
                e.downcast_ref::<OutputError>(),
            ) {
                (Some(_), _) => Outcome::BadInput,
                (_, Some(o)) => o.outcome(),
                _ => Outcome::Failed,
            };
            ExitCode::from(outcome.code())
        }
    }
}
