//! The grid's picture with an observer (`Picture::observed`): the image is drawn in bands
//! of whole rows, the rows of a band in parallel as `grid::picture` draws them, and each
//! finished band is handed to the observer (a tev display, say) before the next starts.
//! Every row goes through the same `draw_row` as `grid::picture`'s, so the frame, and
//! every band streamed, is exactly the unobserved picture's bytes.
//!
//! ```text
//! render(&tracer, &camera, &Options::grid(w, h, n), Picture::observed(16, &|y0, rows| tev.rows("img", w, y0, rows)))
//! ```

use super::grid::draw_row;
use crate::accel::TileView;
use crate::base::Frame;
use crate::camera::Camera;
use crate::trace::{RayCount, Tracer};
use rayon::prelude::*;

/// Draws as `grid::picture` does, `band` rows at a time (at least 1), calling
/// `observe(first_row, band_pixels)` with each finished band, top to bottom.
pub(super) fn picture(
    tracer: &Tracer,
    camera: &Camera,
    width: u32,
    height: u32,
    samples: u32,
    band: u32,
    observe: &dyn Fn(u32, &[u8]),
) -> (Frame, RayCount) {
    let row_len = width as usize * 3;
    let mut pixels = vec![0u8; row_len * height as usize];
    let n = samples.max(1);
    let view = TileView::new(camera, width, height, &tracer.scene().objects);
    let view = view.as_ref();
    let band = band.max(1) as usize;
    let shot = super::Shot::new(tracer, camera);
    let mut count = RayCount::default();
    if row_len == 0 {
        return (
            Frame {
                width,
                height,
                pixels,
            },
            count,
        );
    }
    for (b, rows) in pixels.chunks_mut(row_len * band).enumerate() {
        let j0 = b * band;
        count = count
            + rows
                .par_chunks_mut(row_len)
                .enumerate()
                .map(|(dj, row)| draw_row(tracer, view, &shot, j0 + dj, n, row))
                .reduce(RayCount::default, |a, b| a + b);
        observe(j0 as u32, rows);
    }
    (
        Frame {
            width,
            height,
            pixels,
        },
        count,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::Mutex;

    #[test]
    fn the_bands_are_the_frame() {
        let scene = crate::Scene::parse(
            "7 5  0 0 5  0 0 0  2 9  1 1 0 1\n\
             1 0 0 0  1 1 0 0  0.5 0.3 0 1 0 0\n\
             0 -1 0  0 1 0  2 1 1 1 1 0 0 0 0 0 0  1 0 0 1 0 0\n\
             0 5 5  1 1 1  1",
            "t.txt",
        )
        .unwrap();
        let tracer = Tracer::new(&scene);
        let camera = scene.camera();
        for (samples, band) in [(1, 2), (2, 1), (1, 100)] {
            let (want, rays) = super::super::grid::picture(&tracer, &camera, 7, 5, samples);
            let seen = Mutex::new(vec![0u8; 7 * 5 * 3]);
            let starts = Mutex::new(Vec::new());
            let (got, counted) = picture(&tracer, &camera, 7, 5, samples, band, &|y, p| {
                seen.lock().unwrap()[y as usize * 21..][..p.len()].copy_from_slice(p);
                starts.lock().unwrap().push(y);
            });
            assert_eq!(got, want);
            assert_eq!(counted, rays);
            assert_eq!(seen.into_inner().unwrap(), want.pixels);
            let bands: Vec<u32> = (0..5).step_by(band as usize).collect();
            assert_eq!(starts.into_inner().unwrap(), bands);
        }
    }
}
