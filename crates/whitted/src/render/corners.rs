//! A picture drawn from its pixel corners (the SPD's testing procedure): each pixel the
//! average of the four rays through its corners, each clamped to 0..1 first, as
//! supersamples are.

use super::grid::par_rows;
use crate::base::Color;
use crate::base::Frame;
use crate::camera::Camera;
use crate::trace::{RayCount, Tracer};

/// A `width` × `height` picture whose pixels average the four of the
/// (width + 1) × (height + 1) rays `corners` shoots through its pixel centres (a camera
/// for that size: its pixel centres are the picture's pixel corners).
pub(super) fn picture(
    tracer: &Tracer,
    corners: &Camera,
    width: u32,
    height: u32,
) -> (Frame, RayCount) {
    let (cw, ch) = (width + 1, height + 1);
    let mut grid = vec![Color::ZERO; cw as usize * ch as usize];
    let count = par_rows(&mut grid, cw, ch, |j, row, count| {
        for (i, c) in row.iter_mut().enumerate() {
            let ray = corners.ray(i as f64 + 0.5, j as f64 + 0.5);
            *c = tracer.primary(&ray, count).clamp(Color::ZERO, Color::ONE);
        }
    });
    let at = |i: u32, j: u32| grid[(j * cw + i) as usize];
    let colors = (0..height).flat_map(|j| {
        (0..width).map(move |i| (at(i, j) + at(i + 1, j) + at(i, j + 1) + at(i + 1, j + 1)) / 4.0)
    });
    (Frame::from_colors(colors, width, height), count)
}
