//! The path plot: the camera path in a top view and a side view (see `view`), drawn to
//! scale with plotters on a bitmap. It takes plain data, so that whatever decides where
//! things are on each frame can feed it: camera samples (frame, eye, look-at), named
//! polylines of tracked positions, and the scene's spheres, cylinders, planes and lights.
//!
//! Drawn, back to front: planes seen edge-on (dashed lines), cylinders (grey bands, or
//! discs when seen along their axis), spheres (discs in their texture's first colour),
//! tracked paths, the camera path (blue) with arrows along the direction of travel,
//! a few frame numbers with sight lines to their look-at points, the look-at points (red
//! crosses) and the lights (gold, numbered). Frame numbers and arrows that would fall on
//! one already drawn are left out (a circle seen from the side passes each place twice).
//! One legend row under both views names what was drawn.

use super::clip::{Rect, P2};
use super::font::{self, FontError, FAMILY};
use super::legend::{Legend, Swatch};
use super::view::{self, View};
use glam::DVec3;
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;
use whitted::base::Frame;
use whitted::shapes::Shape;
use whitted::Scene;

mod objects;
use objects::{lights, scene_shapes};

/// The plot's size in pixels.
pub const SIZE: (u32, u32) = (1400, 720);
/// How many frame numbers are written along the camera path; arrows are as many.
const LABELS: usize = 8;
const MARGIN: u32 = 12;
/// The height of the legend row.
const LEGEND: u32 = 30;
const X_LABELS: u32 = 36;
const Y_LABELS: u32 = 52;
const CAMERA: RGBColor = RGBColor(30, 90, 200);
const LOOK: RGBColor = RGBColor(210, 30, 30);
const LIGHT: RGBColor = RGBColor(240, 180, 0);
const SOLID: RGBColor = RGBColor(120, 120, 120);
const TRACKS: [RGBColor; 4] = [
    RGBColor(0, 150, 70),
    RGBColor(150, 60, 180),
    RGBColor(220, 110, 0),
    RGBColor(0, 150, 160),
];

/// The camera on one frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CameraSample {
    /// The frame's number.
    pub frame: u32,
    /// The camera's position on that frame.
    pub eye: DVec3,
    /// The point it looks at on that frame.
    pub look_at: DVec3,
}

/// The path of one tracked position (SPEC §7), frame by frame.
#[derive(Clone, Debug, PartialEq)]
pub struct Track {
    /// The legend's label, e.g. `sphere 1 center`.
    pub name: String,
    /// (frame, position) for each sampled frame, in frame order.
    pub points: Vec<(u32, DVec3)>,
}

/// Everything the plot shows.
pub struct PlotData<'a> {
    /// The line above the views (manifest name, frames, fps).
    pub title: String,
    /// The camera on each sampled frame, in frame order.
    pub camera: &'a [CameraSample],
    /// The tracked positions' paths.
    pub tracks: &'a [Track],
    /// The base scene, whose objects and lights are drawn.
    pub scene: &'a Scene,
}

/// Why the plot could not be drawn.
#[derive(Debug, thiserror::Error)]
pub enum PlotError {
    /// The embedded font could not be read.
    #[error(transparent)]
    Font(#[from] FontError),
    /// The drawing backend failed (its message).
    #[error("cannot draw the path plot: {0}")]
    Draw(String),
}

type Chart<'a, 'b> =
    ChartContext<'a, BitMapBackend<'b>, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

fn draw_err<E: std::fmt::Debug>(e: E) -> PlotError {
    PlotError::Draw(format!("{e:?}"))
}

/// Draws the plot.
pub fn plot(data: &PlotData) -> Result<Frame, PlotError> {
    font::ensure()?;
    let (w, h) = SIZE;
    let mut pixels = vec![255u8; w as usize * h as usize * 3];
    {
        let root = BitMapBackend::with_buffer(&mut pixels, (w, h)).into_drawing_area();
        let root = root
            .titled(&data.title, (FAMILY, 22).into_font())
            .map_err(draw_err)?;
        let (_, rh) = root.dim_in_pixel();
        let (views, key_row) = root.split_vertically(rh.saturating_sub(LEGEND));
        let mut legend = Legend::default();
        for (area, v) in views
            .split_evenly((1, 2))
            .iter()
            .zip([View::Top, View::Side])
        {
            panel(area, v, data, &mut legend)?;
        }
        legend.draw(&key_row).map_err(PlotError::Draw)?;
        root.present().map_err(draw_err)?;
    }
    Ok(Frame {
        width: w,
        height: h,
        pixels,
    })
}

/// Everything with a place in `v`, for its window.
fn window(v: View, data: &PlotData, width: u32, height: u32) -> Rect {
    let mut points: Vec<P2> = Vec::new();
    for s in data.camera {
        points.extend([v.project(s.eye), v.project(s.look_at)]);
    }
    points.extend(data.scene.lights.iter().map(|l| v.project(l.position)));
    for t in data.tracks {
        points.extend(t.points.iter().map(|&(_, p)| v.project(p)));
    }
    let discs: Vec<(P2, f64)> = data
        .scene
        .objects
        .iter()
        .filter_map(|o| match o.shape {
            Shape::Sphere(s) => Some((v.project(s.center), s.radius)),
            _ => None,
        })
        .collect();
    view::fit(view::extent(&points, &discs), width, height)
}

fn panel(
    area: &DrawingArea<BitMapBackend, plotters::coord::Shift>,
    v: View,
    data: &PlotData,
    legend: &mut Legend,
) -> Result<(), PlotError> {
    let area = area
        .titled(v.title(), (FAMILY, 16).into_font())
        .map_err(draw_err)?;
    let (aw, ah) = area.dim_in_pixel();
    let plot_w = aw.saturating_sub(2 * MARGIN + Y_LABELS);
    let plot_h = ah.saturating_sub(2 * MARGIN + X_LABELS);
    let r = window(v, data, plot_w, plot_h);
    let mut chart = ChartBuilder::on(&area)
        .margin(MARGIN)
        .x_label_area_size(X_LABELS)
        .y_label_area_size(Y_LABELS)
        .build_cartesian_2d(r.u.0..r.u.1, r.v.0..r.v.1)
        .map_err(draw_err)?;
    let y_label = |y: &f64| v.vertical_label(*y);
    let x_label = |x: &f64| view::number(*x);
    chart
        .configure_mesh()
        .x_desc("x")
        .y_desc(v.vertical())
        .x_label_formatter(&x_label)
        .y_label_formatter(&y_label)
        .light_line_style(RGBColor(238, 238, 238))
        .draw()
        .map_err(draw_err)?;
    let spread = r.diagonal();
    scene_shapes(&mut chart, v, data.scene, &r, legend)?;
    tracks(&mut chart, v, data.tracks, &r, legend)?;
    camera(&mut chart, v, data.camera, spread, legend)?;
    lights(&mut chart, v, data.scene, legend)?;
    Ok(())
}

fn tracks(
    chart: &mut Chart,
    v: View,
    tracks: &[Track],
    r: &Rect,
    legend: &mut Legend,
) -> Result<(), PlotError> {
    for (i, t) in tracks.iter().enumerate() {
        let colour = TRACKS[i % TRACKS.len()];
        let points: Vec<P2> = t.points.iter().map(|&(_, p)| v.project(p)).collect();
        chart
            .draw_series(LineSeries::new(points.clone(), colour.stroke_width(2)))
            .map_err(draw_err)?;
        legend.add(&t.name, Swatch::Line(colour));
        if let Some(&first) = points.first().filter(|p| r.contains(**p)) {
            chart
                .draw_series([EmptyElement::at(first)
                    + Text::new(
                        t.name.clone(),
                        (4, 4),
                        (FAMILY, 12).into_font().color(&colour),
                    )])
                .map_err(draw_err)?;
        }
    }
    Ok(())
}

/// Indices of `LABELS` samples spread along the path, the first included.
fn marked(n: usize) -> Vec<usize> {
    let k = LABELS.min(n);
    (0..k).map(|i| i * n / k.max(1)).collect()
}

/// True when pixel `p` is within `dx`, `dy` of one of `taken`; otherwise `p` is taken.
fn crowded(taken: &mut Vec<(i32, i32)>, p: (i32, i32), dx: i32, dy: i32) -> bool {
    let near = taken
        .iter()
        .any(|q| (q.0 - p.0).abs() < dx && (q.1 - p.1).abs() < dy);
    if !near {
        taken.push(p);
    }
    near
}

fn camera(
    chart: &mut Chart,
    v: View,
    samples: &[CameraSample],
    spread: f64,
    legend: &mut Legend,
) -> Result<(), PlotError> {
    let eyes: Vec<P2> = samples.iter().map(|s| v.project(s.eye)).collect();
    let marks = marked(samples.len());
    // Sight lines from the marked frames to what they look at.
    for &i in &marks {
        let (a, b) = (eyes[i], v.project(samples[i].look_at));
        chart
            .draw_series([PathElement::new(
                [a, b],
                RGBColor(160, 170, 220).stroke_width(1),
            )])
            .map_err(draw_err)?;
    }
    chart
        .draw_series(LineSeries::new(eyes.clone(), CAMERA.stroke_width(2)))
        .map_err(draw_err)?;
    legend.add(
        "camera path (arrows: direction of travel)",
        Swatch::Line(CAMERA),
    );
    // Arrows half-way between marks, pointing the way the camera goes.
    let size = spread * 0.018;
    let mut arrows = Vec::new();
    for &i in &marks {
        let j = (i + samples.len() / (2 * LABELS)).min(eyes.len().saturating_sub(2));
        let Some((&p, &q)) = eyes.get(j).zip(eyes.get(j + 1)) else {
            continue;
        };
        let (du, dv) = (q.0 - p.0, q.1 - p.1);
        let len = du.hypot(dv);
        if len < 1e-12 || crowded(&mut arrows, chart.backend_coord(&p), 24, 24) {
            continue;
        }
        let (ux, uy) = (du / len * size, dv / len * size);
        let tip = (p.0 + ux, p.1 + uy);
        let head = vec![
            tip,
            (p.0 - ux - uy * 0.6, p.1 - uy + ux * 0.6),
            (p.0 - ux + uy * 0.6, p.1 - uy - ux * 0.6),
        ];
        chart
            .draw_series([Polygon::new(head, CAMERA.filled())])
            .map_err(draw_err)?;
    }
    let mut labels = Vec::new();
    for &i in &marks {
        if crowded(&mut labels, chart.backend_coord(&eyes[i]), 36, 16) {
            continue;
        }
        let label = samples[i].frame.to_string();
        let style = (FAMILY, 13).into_font().color(&CAMERA);
        chart
            .draw_series([EmptyElement::at(eyes[i])
                + Circle::new((0, 0), 3, CAMERA.filled())
                + Text::new(label, (5, -15), style)])
            .map_err(draw_err)?;
    }
    // Look-at points, each distinct one once.
    let mut looks: Vec<P2> = samples.iter().map(|s| v.project(s.look_at)).collect();
    looks.dedup_by(|a, b| (a.0 - b.0).hypot(a.1 - b.1) < spread * 1e-4);
    chart
        .draw_series(
            looks
                .into_iter()
                .map(|p| Cross::new(p, 5, LOOK.stroke_width(2))),
        )
        .map_err(draw_err)?;
    legend.add("look-at points", Swatch::Cross(LOOK));
    legend.add("frame numbers", Swatch::Dot(CAMERA));
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn crowded_keeps_the_first_and_refuses_near_ones() {
        let mut taken = Vec::new();
        assert!(!crowded(&mut taken, (100, 100), 36, 16));
        assert!(crowded(&mut taken, (130, 110), 36, 16));
        assert!(!crowded(&mut taken, (136, 100), 36, 16));
        assert!(!crowded(&mut taken, (100, 116), 36, 16));
        assert_eq!(taken.len(), 3);
    }

    #[test]
    fn marks_spread_along_the_path_from_the_first() {
        assert_eq!(marked(16), vec![0, 2, 4, 6, 8, 10, 12, 14]);
        assert_eq!(marked(3), vec![0, 1, 2]);
        assert!(marked(0).is_empty());
    }
}
