//! `animate preview` (SPEC §11): fast pictures of an animation for people, written into
//! one folder (default: the frame folder's name + `-preview`):
//!
//! - `animation.gif`: every frame at 1/K size (default K = 4), at the manifest's fps,
//!   looping forever (`gif`);
//! - `contact-sheet.png`: every N-th frame in a grid, labelled with its frame number
//!   (`sheet`; N defaults to about 24 tiles);
//! - `camera-path.png`: top and side views of the camera path, look-at points, objects,
//!   lights and tracked paths, to scale (`plot`, `view`, `clip`).
//!
//! Frames are drawn by the animation pipeline at the small size (`source`, the only file
//! that calls it), in parallel windows; each is quantised for the GIF on its worker, then
//! appended in frame order, so the files are the same bytes on any thread count. Every
//! file is written under a hidden temporary name and renamed when complete.

mod clip;
pub(crate) mod font;
mod gif;
mod legend;
mod plot;
mod sheet;
mod source;
pub use source::scaled;
mod view;

pub use gif::GifError;
use plot::PlotData;
pub use plot::PlotError;

use self::gif::{GifFrame, GifWriter};
use crate::AnimError;
use rayon::prelude::*;
use sheet::{Layout, Sheet};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};
use whitted::base::Frame;
use whitted::output::{write_atomic, ImageFormat, OutputError};
use whitted::scene::MAX_PIXELS;

/// K when `--scale` is not given.
pub const DEFAULT_SCALE: u32 = 4;
/// The file name of the looping GIF inside the preview folder.
pub const GIF_NAME: &str = "animation.gif";
/// The file name of the contact sheet inside the preview folder.
pub const SHEET_NAME: &str = "contact-sheet.png";
/// The file name of the camera-path plot inside the preview folder.
pub const PLOT_NAME: &str = "camera-path.png";
/// The memory the frames in flight may take (pixels and their GIF copy).
const WINDOW_MEMORY: usize = 256 << 20;

/// What `animate preview` was asked for.
#[derive(Clone, Debug, PartialEq)]
pub struct PreviewOptions {
    /// The animation manifest.
    pub manifest: PathBuf,
    /// The folder for the pictures; default `default_dir` of the frame folder.
    pub out: Option<PathBuf>,
    /// Frames are drawn at 1/scale of their size, at least one pixel a side.
    pub scale: u32,
    /// One contact-sheet tile every `every` frames; default `sheet::default_every`.
    pub every: Option<u32>,
}

/// What a preview wrote.
#[derive(Clone, Debug, PartialEq)]
pub struct PreviewSummary {
    /// The preview folder.
    pub dir: PathBuf,
    /// The looping GIF of every frame.
    pub gif: PathBuf,
    /// The contact sheet.
    pub sheet: PathBuf,
    /// The camera-path plot.
    pub plot: PathBuf,
    /// The frames drawn (all of the manifest's).
    pub frames: u32,
    /// The preview frames' width in pixels (1/K of the manifest's, at least 1).
    pub width: u32,
    /// The preview frames' height in pixels.
    pub height: u32,
    /// The contact sheet's tile count.
    pub tiles: u32,
}

/// Why a preview stopped.
#[derive(Debug, thiserror::Error)]
pub enum PreviewError {
    /// Loading the project or drawing a frame failed (its own exit-status row).
    #[error(transparent)]
    Anim(#[from] AnimError),
    /// A scale of 0: frames are drawn at 1/K of their size, so K must be 1 or more.
    #[error("a scale of 0: frames are drawn at 1/K of their size, K must be 1 or more")]
    ZeroScale,
    /// A contact-sheet step of 0: one tile every N frames needs N of 1 or more.
    #[error("a contact-sheet step of 0: one tile every N frames, N must be 1 or more")]
    ZeroEvery,
    /// The contact sheet, one tile every `every` frames, would be past `MAX_PIXELS`.
    #[error(
        "a contact sheet of {tiles} tiles of {width}×{height} would be {sheet_width}×{sheet_height} \
         pixels, past the limit of {MAX_PIXELS}"
    )]
    SheetTooLarge {
        /// One tile every `every` frames.
        every: u32,
        /// The number of tiles.
        tiles: u32,
        /// A tile's size in pixels (the frame at 1/K).
        width: u32,
        /// A tile's height in pixels.
        height: u32,
        /// The sheet's size in pixels.
        sheet_width: u64,
        /// The sheet's height in pixels.
        sheet_height: u64,
    },
    /// The preview folder cannot be created (e.g. it is a file); bad input, as for the
    /// frame folder.
    #[error("cannot use the preview folder {dir}: {source}")]
    Folder {
        /// The folder.
        dir: PathBuf,
        /// The system's reason.
        #[source]
        source: std::io::Error,
    },
    /// The GIF could not be encoded or written.
    #[error(transparent)]
    Gif(#[from] GifError),
    /// The contact sheet or the plot could not be written.
    #[error(transparent)]
    Write(#[from] OutputError),
    /// The plot could not be drawn.
    #[error(transparent)]
    Plot(#[from] PlotError),
}

impl PreviewError {
    /// The row of the exit-status table: bad input (options, or a preview folder that
    /// cannot be used, found before any frame is drawn), or what could not be written or
    /// drawn.
    pub fn outcome(&self) -> whitted::exit::Outcome {
        match self {
            PreviewError::Anim(e) => e.outcome(),
            PreviewError::ZeroScale
            | PreviewError::ZeroEvery
            | PreviewError::SheetTooLarge { .. }
            | PreviewError::Folder { .. } => whitted::exit::Outcome::BadInput,
            _ => whitted::exit::Outcome::Failed,
        }
    }

    /// The exit status: 2 for bad input, 1 for what could not be written or drawn.
    pub fn exit_code(&self) -> u8 {
        self.outcome().code()
    }
}

impl From<font::FontError> for PreviewError {
    fn from(e: font::FontError) -> PreviewError {
        PreviewError::Plot(e.into())
    }
}

/// The default preview folder beside `frame_dir`: its name + `-preview`.
pub fn default_dir(frame_dir: &Path) -> PathBuf {
    let mut name = frame_dir
        .file_name()
        .map(|n| n.to_os_string())
        .unwrap_or_else(|| "frames".into());
    name.push("-preview");
    frame_dir.with_file_name(name)
}

/// Refuses options no preview can be made with.
fn check(opts: &PreviewOptions) -> Result<(), PreviewError> {
    if opts.scale == 0 {
        return Err(PreviewError::ZeroScale);
    }
    if opts.every == Some(0) {
        return Err(PreviewError::ZeroEvery);
    }
    Ok(())
}

/// The sheet's grid, refused when it would be past the pixel limit.
fn layout(frames: u32, every: Option<u32>, w: u32, h: u32) -> Result<Layout, PreviewError> {
    let every = every.unwrap_or_else(|| sheet::default_every(frames));
    let l = Layout::new(frames, every, w, h);
    let (sw, sh) = l.size();
    if sw * sh > MAX_PIXELS {
        return Err(PreviewError::SheetTooLarge {
            every,
            tiles: l.tiles,
            width: w,
            height: h,
            sheet_width: sw,
            sheet_height: sh,
        });
    }
    Ok(l)
}

/// Makes the preview of `opts.manifest`. `progress(done, total)` is called from the
/// worker threads as frames finish.
pub fn run(
    opts: &PreviewOptions,
    progress: &(dyn Fn(usize, usize) + Sync),
) -> Result<PreviewSummary, PreviewError> {
    check(opts)?;
    let src = source::Source::load(&opts.manifest, opts.scale)?;
    let anim = src.animation()?;
    let (w, h, frames) = (anim.width, anim.height, src.frames());
    let layout = layout(frames, opts.every, w, h)?;
    let dir = opts
        .out
        .clone()
        .unwrap_or_else(|| default_dir(src.frame_dir()));
    std::fs::create_dir_all(&dir).map_err(|source| PreviewError::Folder {
        dir: dir.clone(),
        source,
    })?;

    let mut gif = GifWriter::create(&dir.join(GIF_NAME), w, h, src.fps())?;
    let mut sheet = Sheet::new(layout);
    let frame_bytes = (w as usize * h as usize * 4).max(1);
    let window = (4 * rayon::current_num_threads().max(1))
        .min(WINDOW_MEMORY / frame_bytes)
        .max(1);
    let all: Vec<u32> = (0..frames).collect();
    let done = AtomicUsize::new(0);
    let total = all.len();
    for chunk in all.chunks(window) {
        let drawn: Vec<Result<(Frame, GifFrame), AnimError>> = chunk
            .par_iter()
            .map(|&f| {
                let image = source::draw(&anim, f)?;
                let quantised = GifFrame::new(&image);
                progress(done.fetch_add(1, Ordering::Relaxed) + 1, total);
                Ok((image, quantised))
            })
            .collect();
        for (&f, item) in chunk.iter().zip(drawn) {
            let (image, quantised) = item?;
            sheet.place(f, &image);
            gif.add(quantised)?;
        }
    }
    let gif_path = gif.finish()?;
    let sheet_path = dir.join(SHEET_NAME);
    write_atomic(&sheet_path, &sheet.finish()?, ImageFormat::Png, &[])?;

    let name = src.manifest_path().file_name().unwrap_or_default();
    let camera = src.camera_samples();
    let tracks = src.tracks();
    let data = PlotData {
        title: format!(
            "{}: {frames} frames at {} fps",
            name.to_string_lossy(),
            view::number(src.fps())
        ),
        camera: &camera,
        tracks: &tracks,
        scene: src.scene(),
    };
    let plot_path = dir.join(PLOT_NAME);
    write_atomic(&plot_path, &plot::plot(&data)?, ImageFormat::Png, &[])?;
    Ok(PreviewSummary {
        dir,
        gif: gif_path,
        sheet: sheet_path,
        plot: plot_path,
        frames,
        width: w,
        height: h,
        tiles: layout.tiles,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn default_dir_is_a_sibling_named_after_the_frame_folder() {
        assert_eq!(
            default_dir(Path::new("/x/out/orbit")),
            PathBuf::from("/x/out/orbit-preview")
        );
        assert_eq!(
            default_dir(Path::new("frames")),
            PathBuf::from("frames-preview")
        );
    }

    #[test]
    fn zero_scale_and_every_are_refused() {
        let opts = |scale, every| PreviewOptions {
            manifest: "m.toml".into(),
            out: None,
            scale,
            every,
        };
        let e = check(&opts(0, None)).unwrap_err();
        assert!(matches!(e, PreviewError::ZeroScale), "{e}");
        assert!(e.to_string().starts_with("a scale of 0"), "{e}");
        assert_eq!(e.exit_code(), 2);
        let e = check(&opts(4, Some(0))).unwrap_err();
        assert!(matches!(e, PreviewError::ZeroEvery), "{e}");
        assert!(
            e.to_string().starts_with("a contact-sheet step of 0"),
            "{e}"
        );
        assert!(check(&opts(1, Some(1))).is_ok());
    }

    #[test]
    fn a_sheet_past_the_pixel_limit_is_refused_before_rendering() {
        // 1,000,000 tiles of 160×120 at --every 1: far past 2^26 pixels.
        let e = layout(1_000_000, Some(1), 160, 120).unwrap_err();
        assert!(
            matches!(e, PreviewError::SheetTooLarge { every: 1, .. }),
            "{e}"
        );
        assert!(e
            .to_string()
            .starts_with("a contact sheet of 1000000 tiles of 160×120"));
        assert_eq!(e.exit_code(), 2);
        // The default step keeps about 24 tiles: fine.
        assert_eq!(layout(1_000_000, None, 160, 120).unwrap().tiles, 24);
    }
}
