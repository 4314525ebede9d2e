//! `raytrace [SCENE] [-o OUT] [--size WxH] [--fov DEG] [--roll DEG]
//! [--samples N | --aa adaptive[:T[:D]]] [--threads N] [--display tev] [--passes LIST] [--pass NAME] [--exr-depth half|float]
//! [--spd] [--stats]`: one image from a Scene.txt (the report's main()) or an NFF file
//! (`*.nff`; `--spd` draws it by the SPD's testing procedure, `--stats` prints the ray
//! counts as a JSON line last on standard error). It parses the command line (`cli`) and calls the library;
//! exit statuses follow `whitted::exit` (2 bad input, 1 a failed write, 130/143 stopped by
//! SIGINT/SIGTERM).

#[path = "raytrace/cli.rs"]
mod cli;

use anyhow::Context;
use clap::Parser;
use cli::Args;
use indicatif::{ProgressBar, ProgressStyle};
use std::io::IsTerminal;
use std::process::ExitCode;
use whitted::exit::Outcome;
use whitted::output::{check_target, write_atomic, write_atomic_layers, ImageFormat, OutputError};
use whitted::passes::{visible::picture, PassSet};
use whitted::render::Antialias;
use whitted::still::Still;
use whitted::{Scene, SceneError};
use whitted_anim::progress::RowPoller;

/// A bar of the image's rows on a terminal (hidden otherwise, or with `--quiet`), moved by
/// the library's rows poller until it is finished.
fn progress(rows: u32, quiet: bool) -> (ProgressBar, Option<RowPoller>) {
    if quiet || !std::io::stderr().is_terminal() {
        return (ProgressBar::hidden(), None);
    }
    let bar = ProgressBar::new(u64::from(rows));
    let style = ProgressStyle::with_template(
        "{elapsed_precise} [{wide_bar}] {pos}/{len} rows  {per_sec}  ETA {eta}",
    )
    .unwrap_or_else(|_| ProgressStyle::default_bar());
    bar.set_style(style.progress_chars("=> "));
    let watch = bar.clone();
    let poll = RowPoller::start(move |rows| watch.set_position(rows));
    (bar, Some(poll))
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
    let started = std::time::Instant::now();
    whitted_anim::process::exit_on_signals();
    let out = args
        .out
        .clone()
        .unwrap_or_else(|| args.scene.with_extension("png"));
    let format = out_format(&args, &out)?;
    if args.scene.extension().is_some_and(|e| e == "toml") {
        return Err(NotAScene(args.scene.display().to_string()).into());
    }
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
    let native = (scene.width, scene.height);
    let spd_size = (whitted::spd::SPD_SIZE, whitted::spd::SPD_SIZE);
    let size = if args.spd { Some(spd_size) } else { args.size };
    (scene.width, scene.height) = size.unwrap_or(native);
    let pool =
        whitted_anim::process::pool(args.threads).context("cannot start the worker threads")?;
    let lens = scene.lens.overridden(args.fov, args.roll);
    let (w, h, n) = (scene.width, scene.height, args.samples);
    let aa = args.aa.map_or(Antialias::Grid(n), Antialias::Adaptive);
    let still = Still::new(&scene, native, (w, h), &lens, aa)
        .and_then(|s| if args.spd { s.spd() } else { Some(s) })
        .expect("the parser refuses an eye placed on its look-at point");
    if !args.quiet {
        if let Some(e) = pool.install(|| still.enormous()) {
            eprintln!("raytrace: warning: {e} (Ctrl-C stops)");
        }
    }
    let (bar, poll) = progress(h, args.quiet);
    let start = std::time::Instant::now();
    let (frame, rays) = if format.is_layered() || args.pass.is_some() {
        let passes = args.pass.map_or(format.passes(), |p| PassSet::of(&[p]));
        let (layers, rays) = pool.install(|| still.render_layers(passes));
        // A --pass is written as a picture below; an .exr is written here, whole.
        let frame = match args.pass {
            Some(p) => Some(picture(&layers, p).context("the pass was not drawn")?),
            None => {
                write_atomic_layers(&out, layers, format, &[])?;
                None
            }
        };
        (frame, rays)
    } else {
        let (frame, rays) = match &args.display {
            None => pool.install(|| still.render()),
            Some(display) => {
                let name = format!("raytrace: {}", out.display());
                pool.install(|| still.render_shown(display, &name, "raytrace"))
            }
        };
        (Some(frame), rays)
    };
    drop(poll);
    bar.finish_and_clear();
    let traced = start.elapsed().as_secs_f64();
    if let Some(frame) = &frame {
        write_atomic(&out, frame, format)?;
    }
    if !args.quiet {
        let mrays = rays.total() as f64 / traced.max(1e-9) / 1e6;
        let n = match aa {
            Antialias::Grid(n) => format!("{} sample(s)/px", n * n),
            Antialias::Adaptive(a) => format!(
                "adaptive {} depth {} {}, {:.3} camera rays/px",
                a.threshold,
                a.depth,
                a.measure.name(),
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
    // Last, so that `tail -1` of standard error is the stats line.
    if args.stats {
        let wall = started.elapsed().as_secs_f64();
        let cpu = whitted_anim::stats::cpu_seconds();
        eprintln!("{}", whitted_anim::stats::line(&rays, wall, cpu));
    }
    Ok(())
}

/// A TOML file given to `raytrace`: an animation manifest, which `animate` renders.
#[derive(Debug, thiserror::Error)]
#[error(
    "{0} looks like an animation manifest (TOML), not a Scene.txt: render it with `animate {0}` \
     (or one frame: `animate {0} --frames 0`)"
)]
struct NotAScene(String);

fn main() -> ExitCode {
    if let Err(e) = whitted_anim::process::check_cpu() {
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
                _ if e.downcast_ref::<NotAScene>().is_some() => Outcome::BadInput,
                (_, Some(o)) => o.outcome(),
                _ => Outcome::Failed,
            };
            ExitCode::from(outcome.code())
        }
    }
}
