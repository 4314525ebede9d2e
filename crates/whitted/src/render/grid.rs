//! The grid's loops: every pixel's camera ray traced, in parallel over rows with rayon,
//! into a fresh 8-bit picture (`picture`) or added into a float sum (`add`).
//!
//! Each pixel depends only on the scene and its own coordinates, so the bytes are the
//! same whatever the thread count. With `samples` = n > 1 the pixel is the mean of an
//! n×n stratified grid of sub-pixel centres, each sample clamped before averaging (see
//! docs/decisions.md); n = 1 samples the pixel centre, as the report does.

use super::{control, Shot};
use crate::accel::TileView;
use crate::base::{to_rgb, Color, Frame};
use crate::camera::Camera;
use crate::trace::{RayCount, Tracer};
use rayon::prelude::*;

/// The tracer's scene through `camera` at `width`×`height` with `samples`² samples per
/// pixel, as 8-bit RGB. Runs on the current rayon pool. The `Tracer` is built once per
/// scene and shared by every frame drawn of it.
pub(crate) fn picture(
    tracer: &Tracer,
    camera: &Camera,
    width: u32,
    height: u32,
    samples: u32,
) -> (Frame, RayCount) {
    let row_len = width as usize * 3;
    let mut pixels = vec![0u8; row_len * height as usize];
    let n = samples.max(1);
    let view = TileView::new(camera, width, height, &tracer.scene().objects);
    let view = view.as_ref();
    let shot = Shot::new(tracer, camera);
    let count = pixels
        .par_chunks_mut(row_len)
        .enumerate()
        .map(|(j, row)| draw_row(tracer, view, &shot, j, n, row))
        .reduce(RayCount::default, |a, b| a + b);
    let frame = Frame {
        width,
        height,
        pixels,
    };
    (frame, count)
}

/// Draws row `j` into `row` (its width·3 bytes) with n×n samples a pixel, unless the
/// render was cancelled (then the row is left as it is and the caller discards the frame);
/// counts the row as done. `picture` and the streamed picture (`stream`) draw every row
/// this way.
/// Always inlined into the rows' closure, with `Tracer::primary_in`: when the crate's
/// modules moved, LLVM kept the primary call out of line and the orbit took 1.8 % more
/// instructions (callgrind, one thread); inlined, 0.8 % more than before the move.
#[inline(always)]
pub(super) fn draw_row(
    tracer: &Tracer,
    view: Option<&TileView>,
    shot: &Shot,
    j: usize,
    n: u32,
    row: &mut [u8],
) -> RayCount {
    let mut count = RayCount::default();
    if control::stop_row() {
        return count;
    }
    match shot.pinhole() {
        // One pinhole ray a pixel (the report's case): the row's own loop, so that the
        // per-pixel call and its sample grid stay out of the orbit's inner loop.
        // (A scene in linear light takes the general loop, which encodes its colours.)
        Some(camera) if n == 1 && !tracer.scene().linear => {
            for (i, px) in row.chunks_exact_mut(3).enumerate() {
                let hint = view.map(|v| v.hint(i as u32, j as u32));
                let ray = camera.ray(i as f64 + 0.5, j as f64 + 0.5);
                let c = tracer.primary_raw(hint, &ray, &mut count);
                px.copy_from_slice(&to_rgb(c));
            }
        }
        _ => {
            for (i, px) in row.chunks_exact_mut(3).enumerate() {
                let c = pixel(tracer, view, shot, i as f64, j as f64, n, &mut count);
                px.copy_from_slice(&to_rgb(c));
            }
        }
    }
    control::row_done();
    count
}

/// Adds, for every pixel, its colour clamped to 0..1 (the mean of its n×n clamped samples
/// when `samples` > 1) into `sum` (width·height colours, rows top to bottom). Motion blur
/// sums its sub-frames this way and then divides (`Frame::from_sum`), so each sample is
/// clamped, all are averaged, then rounded, as anti-aliasing does.
pub(crate) fn add(
    tracer: &Tracer,
    camera: &Camera,
    width: u32,
    height: u32,
    samples: u32,
    sum: &mut [Color],
) -> RayCount {
    let n = samples.max(1);
    let view = TileView::new(camera, width, height, &tracer.scene().objects);
    let view = view.as_ref();
    let shot = Shot::new(tracer, camera);
    par_rows(sum, width, height, |j, row, count| {
        for (i, acc) in row.iter_mut().enumerate() {
            let c = pixel(tracer, view, &shot, i as f64, j as f64, n, count);
            *acc += c.clamp(Color::ZERO, Color::ONE);
        }
    })
}

/// The first `height` rows of `width` items of `buf` drawn in parallel, `draw(j, row,
/// rays)` each, unless the render was cancelled (then the row is left as it is and the
/// caller discards the frame); each row drawn counts as done. The rays of all rows.
/// (`picture` and the streamed picture have `draw_row`, the same loop over rows of bytes.)
pub(crate) fn par_rows<T: Send>(
    buf: &mut [T],
    width: u32,
    height: u32,
    draw: impl Fn(usize, &mut [T], &mut RayCount) + Sync,
) -> RayCount {
    buf.par_chunks_mut(width.max(1) as usize)
        .take(height as usize)
        .enumerate()
        .map(|(j, row)| {
            let mut count = RayCount::default();
            if control::stop_row() {
                return count; // cancelled: the caller discards the frame
            }
            draw(j, row, &mut count);
            control::row_done();
            count
        })
        .reduce(RayCount::default, |a, b| a + b)
}

/// The colour of pixel (i, j) from an n×n grid of samples (each through the lens, when
/// the shot has one); `view`, the frame's tile lists of candidates for camera rays, when
/// there are some.
#[inline]
fn pixel(
    tracer: &Tracer,
    view: Option<&TileView>,
    shot: &Shot,
    i: f64,
    j: f64,
    n: u32,
    count: &mut RayCount,
) -> Color {
    let view = view.map(|v| v.hint(i as u32, j as u32));
    if n == 1 {
        return shot.color(tracer, view, i + 0.5, j + 0.5, count);
    }
    let step = 1.0 / n as f64;
    let mut sum = Color::ZERO;
    for b in 0..n {
        for a in 0..n {
            let (x, y) = sub_pixel(i, j, a, b, step);
            let c = shot.color(tracer, view, x, y, count);
            sum += c.clamp(Color::ZERO, Color::ONE);
        }
    }
    sum / (n * n) as f64
}

/// Where sample (a, b) of pixel (i, j)'s n×n grid (`step` = 1/n) sits: the centre of its
/// cell, (i + (a + ½)/n, j + (b + ½)/n); with n = 1 exactly the pixel's centre
/// (i + 0.5, j + 0.5), since (0 + 0.5)·1.0 is 0.5.
#[inline]
pub(crate) fn sub_pixel(i: f64, j: f64, a: u32, b: u32, step: f64) -> (f64, f64) {
    (i + (a as f64 + 0.5) * step, j + (b as f64 + 0.5) * step)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sub_pixel_by_hand() {
        // 2×2 grid of pixel (3, 5): the cells' centres at quarters.
        assert_eq!(sub_pixel(3.0, 5.0, 0, 0, 0.5), (3.25, 5.25));
        assert_eq!(sub_pixel(3.0, 5.0, 1, 0, 0.5), (3.75, 5.25));
        assert_eq!(sub_pixel(3.0, 5.0, 1, 1, 0.5), (3.75, 5.75));
        // One sample: the centre, bit for bit.
        assert_eq!(sub_pixel(639.0, 479.0, 0, 0, 1.0), (639.5, 479.5));
    }

    #[test]
    fn one_summed_sub_frame_is_the_frame() {
        let scene = crate::Scene::parse(
            "6 4  0 0 5  0 0 0  2 9  1 1 0 1\n\
             1 0 0 0  1 1 0 0  0.5 0.3 0 1 0 0\n\
             0 -1 0  0 1 0  2 1 1 1 1 0 0 0 0 0 0  1 0 0 1 0 0\n\
             0 5 5  1 1 1  1",
            "t.txt",
        )
        .unwrap();
        let tracer = Tracer::new(&scene);
        let camera = scene.camera();
        for n in [1, 2] {
            let (frame, rays) = picture(&tracer, &camera, 6, 4, n);
            let mut sum = vec![Color::ZERO; 24];
            let summed = add(&tracer, &camera, 6, 4, n, &mut sum);
            assert_eq!(Frame::from_sum(&sum, 1, 6, 4), frame);
            assert_eq!(summed, rays);
        }
    }
}
