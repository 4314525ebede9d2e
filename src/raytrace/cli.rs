//! `raytrace`'s command line (clap): the image to write, its size, framing, samples and
//! threads. Kept apart from `main` so that the tests can parse the command lines the
//! documentation quotes.

use clap::Parser;
use std::path::PathBuf;
use whitted::base::Transfer;
use whitted::camera::Lens;
use whitted::display::Display;
use whitted::output::ExrDepth;
use whitted::passes::{Pass, PassSet};
use whitted::render::Adaptive;
use whitted::still::Request;
use whitted_cmd::size::parse_size;

const AFTER_HELP: &str = "\
Formats, by OUT's extension: .png, .jpg/.jpeg (quality 90), .ppm (binary P6), .raw (the
report's headerless RGB bytes, rows top to bottom), .exr (OpenEXR: the beauty unclamped,
in linear light (the display values decoded with the sRGB curve, unless --colour linear),
with alpha (coverage, not premultiplied), half unless --exr-depth float, and the --passes
asked for; docs/exr.md). PNGs are tagged sRGB. OUT defaults to
the scene's path with .png, beside the scene file (raytrace sub/t.txt writes sub/t.png).
--spd renders 512×512 by the SPD's testing procedure; --stats prints
{\"eye\":…,\"eye_hits\":…,\"reflect\":…,\"refract\":…,\"shadow\":…,\"wall_s\":…,\"cpu_s\":…}
on standard error after the image (cpu_s: the process's user and system time).
--pass NAME writes one pass as the picture: depth as near/z (the nearest point white, twice
as far half grey, no hit black); normals as (N+1)/2 in RGB; positions as 0.5+0.5·x/(1+|x|)
per axis; colours clamped and rounded; Cryptomatte ids as flat colours.
Exit status: 0 success; 2 nothing was rendered (bad arguments or scene, an output path
that cannot be used); 1 the image could not be written; 130/143 stopped by SIGINT/SIGTERM
(no image is written). Scene.txt and NFF (*.nff): docs/scene-format.md.";

/// Render one Scene.txt to an image.
#[derive(Parser, Debug)]
#[command(name = "raytrace", version, about, after_help = AFTER_HELP)]
pub struct Args {
    /// The scene file.
    #[arg(default_value = "Scene.txt")]
    pub scene: PathBuf,
    /// The image to write (its extension picks the format); defaults to SCENE with .png.
    #[arg(short, long, value_name = "OUT")]
    pub out: Option<PathBuf>,
    /// Render at this size instead of the scene's resolution: WIDTHxHEIGHT, e.g. 160x120.
    /// A size of the scene's shape keeps the report's 0.5 × 0.35 view; another shape keeps
    /// the view's height and widens or narrows it with square pixels (no stretching).
    #[arg(long, value_name = "WxH", value_parser = parse_size)]
    pub size: Option<(u32, u32)>,
    /// Vertical field of view in degrees (0 < DEG < 180), square pixels; default: the
    /// report's view.
    #[arg(long, value_name = "DEG", value_parser = parse_fov)]
    pub fov: Option<f64>,
    /// Roll about the viewing direction in degrees; positive banks the camera right.
    #[arg(long, value_name = "DEG", default_value_t = 0.0, allow_negative_numbers = true, value_parser = parse_roll)]
    pub roll: f64,
    /// Anti-aliasing: an N×N stratified grid of samples per pixel (1 = the report's).
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..=16))]
    pub samples: u32,
    /// Adaptive anti-aliasing instead of the grid: pixel corners shared, squares split
    /// where corners differ by more than THRESHOLD (0..=3, default 0.4), down to DEPTH
    /// (0..=6, default 2); MEASURE edge (the default: the difference times the square's
    /// side), sum (POV-Ray's) or max.
    #[arg(long, value_name = "adaptive[:T[:D[:MEASURE]]]", conflicts_with = "samples",
          value_parser = |s: &str| s.parse::<Adaptive>().map_err(|e| e.to_string()))]
    pub aa: Option<Adaptive>,
    /// Worker threads (default: all cores).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=1024))]
    pub threads: Option<u32>,
    /// Passes to store beside the beauty in an .exr: comma-separated names (depth,
    /// position, normal, albedo, ambient, diffuse, specular, reflection, transmission,
    /// fog, crypto_object, crypto_material) or `all`.
    #[arg(long, value_name = "LIST", value_parser = parse_passes)]
    pub passes: Option<PassSet>,
    /// Write this pass as the picture instead of the beauty (an 8-bit OUT: .png, …).
    #[arg(long, value_name = "NAME", value_parser = parse_pass)]
    pub pass: Option<Pass>,
    /// The sample type of an .exr beauty.
    #[arg(long, value_name = "DEPTH", value_parser = parse_depth)]
    pub exr_depth: Option<ExrDepth>,
    /// How an .exr stores colours: `srgb` (default: the display values decoded to linear
    /// light, so a viewer's sRGB view shows the PNG's look) or `linear` (as they are).
    #[arg(long, value_name = "srgb|linear", value_parser = parse_colour)]
    pub colour: Option<Transfer>,
    /// Print nothing on success.
    #[arg(short, long)]
    pub quiet: bool,
    /// Also stream the rows to a running tev viewer as they finish: `tev` (at
    /// 127.0.0.1:14158) or `tev=HOST:PORT`. A missing viewer is a warning.
    #[arg(long, value_name = "tev[=HOST:PORT]")]
    pub display: Option<Display>,
    /// The Standard Procedural Databases' testing procedure: 512×512 pixels, each the
    /// average of the 513×513 rays through the pixel corners, depth 5 counting the eye
    /// ray, no weight cut-off (SPEC §17).
    #[arg(long, conflicts_with_all = ["size", "samples", "aa", "passes", "pass", "display"])]
    pub spd: bool,

    /// A glTF scene's camera to look through, by its name (or its node's).
    #[arg(long, value_name = "NAME")]
    pub camera: Option<String>,
    /// After the image, print one JSON line on standard error: the ray counts (eye,
    /// eye_hits, reflect, refract, shadow) and the seconds taken (wall_s, cpu_s).
    #[arg(long)]
    pub stats: bool,
    /// Draw nothing: print each object and light (number, name, kind, triangles, world
    /// bounds) and the camera, and warn of a camera inside an object's bounds or an
    /// object under a pixel.
    #[arg(long, conflicts_with_all = ["out", "passes", "pass", "display", "stats", "exr_depth", "colour"])]
    pub info: bool,
}

impl Args {
    /// What the command line asks the library to draw.
    pub fn request(&self) -> Request {
        let lens = Lens {
            fov: self.fov,
            roll: self.roll,
            ..Lens::default()
        };
        Request {
            scene: self.scene.clone(),
            out: self.out.clone(),
            size: self.size,
            lens,
            samples: self.samples,
            aa: self.aa,
            passes: self.passes,
            pass: self.pass,
            exr_depth: self.exr_depth,
            colour: self.colour,
            display: self.display.clone(),
            spd: self.spd,
            camera: self.camera.clone(),
        }
    }
}

fn parse_fov(s: &str) -> Result<f64, String> {
    match s.parse::<f64>() {
        Ok(v) if Lens::fov_ok(v) => Ok(v),
        _ => Err(format!(
            "expected a vertical field of view in degrees between 0 and 180 (both excluded), found {s:?}"
        )),
    }
}

fn parse_roll(s: &str) -> Result<f64, String> {
    match s.parse::<f64>() {
        Ok(v) if Lens::roll_ok(v) => Ok(v),
        _ => Err(format!("expected a roll in degrees, found {s:?}")),
    }
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

fn parse_colour(s: &str) -> Result<Transfer, String> {
    Transfer::from_name(s).ok_or_else(|| format!("expected srgb or linear, found {s:?}"))
}

fn parse_depth(s: &str) -> Result<ExrDepth, String> {
    ExrDepth::from_name(s).ok_or_else(|| format!("expected half or float, found {s:?}"))
}
