//! `animate stats --plot FILE.png`: seconds per frame (blue, with points) against the
//! pre-pass's prediction (orange), drawn with plotters in the preview's typeface and
//! written atomically as a PNG.

use super::Row;
use crate::error::AnimError;
use crate::preview::font::{self, FAMILY};
use plotters::prelude::*;
use std::path::Path;
use whitted::base::Frame;
use whitted::output::{write_atomic, ImageFormat};

/// The plot's size in pixels.
pub const SIZE: (u32, u32) = (960, 480);
const MEASURED: RGBColor = RGBColor(30, 90, 200);
const PREDICTED: RGBColor = RGBColor(230, 120, 0);

/// Draws `rows` (frame order) into a picture.
pub fn draw(rows: &[Row]) -> Result<Frame, String> {
    font::ensure().map_err(|e| e.to_string())?;
    let (w, h) = SIZE;
    let mut pixels = vec![255u8; w as usize * h as usize * 3];
    let err = |e: &dyn std::fmt::Debug| format!("{e:?}");
    {
        let root = BitMapBackend::with_buffer(&mut pixels, (w, h)).into_drawing_area();
        let first = rows.first().map_or(0, |r| r.frame) as f64;
        let last = rows.last().map_or(1, |r| r.frame) as f64;
        let top = rows
            .iter()
            .flat_map(|r| [r.wall_s, r.predicted_s])
            .fold(0.0f64, f64::max)
            .max(1e-3)
            * 1.1;
        let mut chart = ChartBuilder::on(&root)
            .caption("seconds per frame", (FAMILY, 22))
            .margin(12)
            .x_label_area_size(36)
            .y_label_area_size(80)
            .build_cartesian_2d(first - 0.5..last.max(first + 1.0) + 0.5, 0.0..top)
            .map_err(|e| err(&e))?;
        chart
            .configure_mesh()
            .x_desc("frame")
            .y_desc("seconds")
            .label_style((FAMILY, 14))
            .x_label_formatter(&|x| format!("{x:.0}"))
            .draw()
            .map_err(|e| err(&e))?;
        let measured: Vec<(f64, f64)> = rows.iter().map(|r| (r.frame as f64, r.wall_s)).collect();
        let predicted: Vec<(f64, f64)> = rows
            .iter()
            .map(|r| (r.frame as f64, r.predicted_s))
            .collect();
        chart
            .draw_series(LineSeries::new(predicted, PREDICTED.stroke_width(2)))
            .map_err(|e| err(&e))?
            .label("predicted (pre-pass)")
            .legend(|(x, y)| PathElement::new([(x, y), (x + 20, y)], PREDICTED.stroke_width(2)));
        chart
            .draw_series(LineSeries::new(measured.clone(), MEASURED.stroke_width(2)))
            .map_err(|e| err(&e))?
            .label("measured")
            .legend(|(x, y)| PathElement::new([(x, y), (x + 20, y)], MEASURED.stroke_width(2)));
        chart
            .draw_series(
                measured
                    .iter()
                    .map(|&p| Circle::new(p, 3, MEASURED.filled())),
            )
            .map_err(|e| err(&e))?;
        chart
            .configure_series_labels()
            .label_font((FAMILY, 14))
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .draw()
            .map_err(|e| err(&e))?;
        root.present().map_err(|e| err(&e))?;
    }
    Ok(Frame {
        width: w,
        height: h,
        pixels,
    })
}

/// Draws `rows` into the PNG `path`.
pub fn write(path: &Path, rows: &[Row]) -> Result<(), AnimError> {
    let fail = |why: String| AnimError::Plot {
        path: path.to_path_buf(),
        why,
    };
    let picture = draw(rows).map_err(fail)?;
    write_atomic(path, &picture, ImageFormat::Png, &[]).map_err(|e| fail(e.to_string()))
}
