//! The preview's looping GIF: every frame, in order, at the manifest's fps, repeating
//! forever. Frames are quantised to their own 256-colour palette (the `gif` crate's
//! NeuQuant, deterministic) on the worker that rendered them; `GifWriter` only appends
//! them, into a hidden temporary file that `finish` renames onto the final name.
//!
//! GIF delays are whole hundredths of a second, so 1/fps is rounded on the running total:
//! frame i lasts round(100·(i+1)/fps) − round(100·i/fps) hundredths, and any n frames last
//! 100·n/fps to within one hundredth (25 fps: 4 each; 30 fps: 3, 4, 3, 3, 4, 3, …). A delay
//! is never below 2 hundredths, the shortest that browsers play as written (they slow
//! shorter ones to 10), so above 50 fps the GIF plays slower than the frames would.

use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};
use whitted::base::Frame;
use whitted::output::temp_beside;

/// The shortest delay written, in hundredths of a second.
pub const MIN_DELAY: u16 = 2;
/// NeuQuant's sampling factor (1 best .. 30 fastest); 10 is the usual balance.
const SPEED: i32 = 10;

/// Why the GIF could not be written.
#[derive(Debug, thiserror::Error)]
#[error("{path}: cannot write the GIF: {message}")]
pub struct GifError {
    /// The GIF's final name.
    pub path: PathBuf,
    /// The encoder's or the system's reason.
    pub message: String,
}

/// The delay of frame `i` at `fps`, in hundredths of a second (see the module note).
pub fn delay(i: u32, fps: f64) -> u16 {
    let at = |n: u32| (100.0 * f64::from(n) / fps).round();
    let d = at(i + 1) - at(i);
    (d.clamp(f64::from(MIN_DELAY), f64::from(u16::MAX))) as u16
}

/// One frame quantised for the GIF (done in parallel, before `GifWriter::add`).
pub struct GifFrame(::gif::Frame<'static>);

impl GifFrame {
    /// Quantises `image` to 256 colours; `image` must be at most 65535 pixels a side.
    pub fn new(image: &Frame) -> GifFrame {
        let (w, h) = (image.width as u16, image.height as u16);
        GifFrame(::gif::Frame::from_rgb_speed(w, h, &image.pixels, SPEED))
    }
}

/// A GIF being written to a temporary file beside its final path.
pub struct GifWriter {
    path: PathBuf,
    encoder: ::gif::Encoder<BufWriter<tempfile::NamedTempFile>>,
    fps: f64,
    next: u32,
}

impl GifWriter {
    /// Starts `path` for frames of `width`×`height` (each at most 65535), looping forever.
    pub fn create(path: &Path, width: u32, height: u32, fps: f64) -> Result<GifWriter, GifError> {
        let fail = |message: String| GifError {
            path: path.to_path_buf(),
            message,
        };
        let (w, h) = match (u16::try_from(width), u16::try_from(height)) {
            (Ok(w), Ok(h)) => (w, h),
            _ => return Err(fail(format!("{width}×{height} is past GIF's 65535 a side"))),
        };
        let tmp = temp_beside(path).map_err(|e| fail(e.to_string()))?;
        let mut encoder =
            ::gif::Encoder::new(BufWriter::new(tmp), w, h, &[]).map_err(|e| fail(e.to_string()))?;
        encoder
            .set_repeat(::gif::Repeat::Infinite)
            .map_err(|e| fail(e.to_string()))?;
        Ok(GifWriter {
            path: path.to_path_buf(),
            encoder,
            fps,
            next: 0,
        })
    }

    fn fail(&self, message: impl ToString) -> GifError {
        GifError {
            path: self.path.clone(),
            message: message.to_string(),
        }
    }

    /// Appends the next frame, lasting its share of the fps.
    pub fn add(&mut self, frame: GifFrame) -> Result<(), GifError> {
        let mut frame = frame.0;
        frame.delay = delay(self.next, self.fps);
        self.next += 1;
        self.encoder.write_frame(&frame).map_err(|e| self.fail(e))
    }

    /// Ends the GIF and renames it onto its final path.
    pub fn finish(self) -> Result<PathBuf, GifError> {
        let path = self.path.clone();
        let fail = |message: String| GifError {
            path: path.clone(),
            message,
        };
        let mut out = self.encoder.into_inner().map_err(|e| fail(e.to_string()))?;
        out.flush().map_err(|e| fail(e.to_string()))?;
        let tmp = out.into_inner().map_err(|e| fail(e.error().to_string()))?;
        tmp.persist(&path).map_err(|e| fail(e.error.to_string()))?;
        Ok(path)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn delays_follow_the_fps_on_the_running_total() {
        // 25 fps: 4 hundredths each.
        assert!((0..10).all(|i| delay(i, 25.0) == 4));
        // 30 fps: 0, 3.33, 6.67, 10, 13.33, 16.67, 20 round to 0, 3, 7, 10, 13, 17, 20.
        let d: Vec<u16> = (0..6).map(|i| delay(i, 30.0)).collect();
        assert_eq!(d, vec![3, 4, 3, 3, 4, 3]);
        // 12 fps: 8.33 → 8, 16.67 → 17, 25 → 25.
        assert_eq!([delay(0, 12.0), delay(1, 12.0), delay(2, 12.0)], [8, 9, 8]);
        // 1 fps: a second each.
        assert_eq!(delay(7, 1.0), 100);
    }

    #[test]
    fn delays_are_never_below_the_shortest_browsers_play() {
        assert_eq!(delay(0, 100.0), MIN_DELAY);
        assert_eq!(delay(5, 1000.0), MIN_DELAY);
    }

    #[test]
    fn a_gif_is_complete_under_its_name_and_loops() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("a.gif");
        let mut w = GifWriter::create(&path, 3, 2, 25.0).unwrap();
        let red = Frame {
            width: 3,
            height: 2,
            pixels: [255, 0, 0].repeat(6),
        };
        w.add(GifFrame::new(&red)).unwrap();
        w.add(GifFrame::new(&red)).unwrap();
        assert!(!path.exists(), "nothing under the final name before finish");
        w.finish().unwrap();
        let mut options = ::gif::DecodeOptions::new();
        options.set_color_output(::gif::ColorOutput::RGBA);
        let mut d = options
            .read_info(std::fs::File::open(&path).unwrap())
            .unwrap();
        let mut n = 0;
        while let Some(f) = d.read_next_frame().unwrap() {
            assert_eq!((f.width, f.height, f.delay), (3, 2, 4));
            assert_eq!(&f.buffer[..4], &[255, 0, 0, 255]);
            n += 1;
        }
        assert_eq!(n, 2);
        assert_eq!(d.repeat(), ::gif::Repeat::Infinite);
    }

    #[test]
    fn a_frame_too_wide_for_gif_is_refused() {
        let dir = tempfile::tempdir().unwrap();
        let e = GifWriter::create(&dir.path().join("a.gif"), 70000, 2, 25.0).err();
        assert!(e.unwrap().message.contains("65535"));
    }
}
