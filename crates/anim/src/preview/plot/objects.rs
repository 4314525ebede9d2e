//! The scene's objects in the path plot, to scale: planes seen edge-on, cylinders as
//! bands (discs along their axis), spheres as discs in their texture's first colour, the
//! other bounded shapes (boxes, cones, tori, triangles, CSG blocks …) as their bounding
//! box seen along the view's axis, and the lights, numbered; each clipped to its panel.

use super::{draw_err, Chart, PlotError, LIGHT, SOLID};
use crate::preview::clip::{self, Rect, P2};
use crate::preview::font::FAMILY;
use crate::preview::legend::{Legend, Swatch};
use crate::preview::view::{self, View};
use glam::DVec3;
use plotters::prelude::*;
use whitted::shapes::Shape;
use whitted::texture::Texture;
use whitted::Scene;

/// The points of a circle, as a polygon of 96 sides (`libm`'s sine and cosine: glibc's
/// pick an FMA variant by CPU, and a plot's pixels must not depend on the machine).
pub(super) fn circle(c: P2, r: f64) -> Vec<P2> {
    (0..96)
        .map(|i| {
            let t = std::f64::consts::TAU * f64::from(i) / 96.0;
            let (sin, cos) = libm::sincos(t);
            (c.0 + r * cos, c.1 + r * sin)
        })
        .collect()
}

pub(super) fn rgb(c: DVec3) -> RGBColor {
    let b = |x: f64| (x.clamp(0.0, 1.0) * 255.0).round() as u8;
    RGBColor(b(c.x), b(c.y), b(c.z))
}

pub(super) fn first_color(t: &Texture) -> DVec3 {
    match *t.pattern() {
        Texture::Uniform(c)
        | Texture::Checker(c, _)
        | Texture::Perlin(c, _, _)
        | Texture::Wood(c, _)
        | Texture::Marble(c, _) => c,
        Texture::Image(_) | Texture::Scaled(..) => DVec3::splat(0.5),
    }
}

/// Draws a filled, outlined polygon clipped to `r`.
pub(super) fn shape(
    chart: &mut Chart,
    poly: &[P2],
    r: &Rect,
    fill: RGBColor,
    edge: RGBColor,
) -> Result<(), PlotError> {
    let mut inside = clip::polygon(poly, r);
    if inside.len() < 3 {
        return Ok(());
    }
    chart
        .draw_series([Polygon::new(inside.clone(), fill.mix(0.55).filled())])
        .map_err(draw_err)?;
    inside.push(inside[0]);
    chart
        .draw_series([PathElement::new(inside, edge.stroke_width(1))])
        .map_err(draw_err)?;
    Ok(())
}

pub(super) fn scene_shapes(
    chart: &mut Chart,
    v: View,
    scene: &Scene,
    r: &Rect,
    legend: &mut Legend,
) -> Result<(), PlotError> {
    let far = r.diagonal() * 4.0;
    for o in &scene.objects {
        match o.shape {
            // The extension's shapes, meshes, CSG blocks and an NFF's finite shapes: their
            // bounding box seen along the view's axis, in their texture's colour.
            Shape::Triangle(_)
            | Shape::Smooth(_)
            | Shape::Cone(_)
            | Shape::Placed(_)
            | Shape::Mesh(_)
            | Shape::Csg(_) => {
                let Some((lo, hi)) = o.shape.bounds() else {
                    continue;
                };
                let (a, b) = (v.project(lo), v.project(hi));
                let (u0, u1) = (a.0.min(b.0), a.0.max(b.0));
                let (v0, v1) = (a.1.min(b.1), a.1.max(b.1));
                let poly = [(u0, v0), (u1, v0), (u1, v1), (u0, v1)];
                let fill = rgb(first_color(&o.texture));
                shape(chart, &poly, r, fill, BLACK)?;
                legend.add(
                    "other shapes (bounding box, texture colour)",
                    Swatch::Fill(RGBColor(200, 170, 150)),
                );
            }
            Shape::Plane(p) => {
                // Edge-on when the normal is across the line of sight: a line.
                let n = p.normal();
                if n.dot(v.depth()).abs() > 1e-9 {
                    continue;
                }
                let along = n.cross(v.depth()).normalize();
                let (a, b) = (
                    v.project(p.point - along * far),
                    v.project(p.point + along * far),
                );
                if let Some((a, b)) = clip::segment(a, b, r) {
                    chart
                        .draw_series(DashedLineSeries::new([a, b], 6, 4, SOLID.stroke_width(2)))
                        .map_err(draw_err)?;
                    legend.add("planes (edge-on)", Swatch::Dashed(SOLID));
                }
            }
            Shape::Quadric(q) => {
                let Some((axis, point, radius)) = view::cylinder(&q) else {
                    continue;
                };
                let c = v.project(point);
                let a = v.project(point + axis);
                let (du, dv) = (a.0 - c.0, a.1 - c.1);
                let len = du.hypot(dv);
                let poly = if len < 1e-9 {
                    circle(c, radius)
                } else {
                    let (ux, uy) = (du / len * far, dv / len * far);
                    let (nx, ny) = (-dv / len * radius, du / len * radius);
                    vec![
                        (c.0 - ux + nx, c.1 - uy + ny),
                        (c.0 + ux + nx, c.1 + uy + ny),
                        (c.0 + ux - nx, c.1 + uy - ny),
                        (c.0 - ux - nx, c.1 - uy - ny),
                    ]
                };
                shape(chart, &poly, r, SOLID, BLACK)?;
                legend.add("cylinders", Swatch::Fill(SOLID));
            }
            Shape::Sphere(s) => {
                let c = v.project(s.center);
                // A sphere that holds the whole window (a sky dome) is left out.
                let corners = [
                    (r.u.0, r.v.0),
                    (r.u.0, r.v.1),
                    (r.u.1, r.v.0),
                    (r.u.1, r.v.1),
                ];
                if corners
                    .iter()
                    .all(|p| (p.0 - c.0).hypot(p.1 - c.1) < s.radius)
                {
                    continue;
                }
                let fill = rgb(first_color(&o.texture));
                shape(chart, &circle(c, s.radius), r, fill, BLACK)?;
                legend.add(
                    "spheres (texture colour)",
                    Swatch::Fill(RGBColor(150, 170, 200)),
                );
            }
        }
    }
    Ok(())
}

pub(super) fn lights(
    chart: &mut Chart,
    v: View,
    scene: &Scene,
    legend: &mut Legend,
) -> Result<(), PlotError> {
    let style = (FAMILY, 13).into_font().color(&BLACK);
    let lights = scene.lights.iter().enumerate().map(|(i, l)| {
        EmptyElement::at(v.project(l.position))
            + Circle::new((0, 0), 6, LIGHT.filled())
            + Circle::new((0, 0), 6, BLACK.stroke_width(1))
            + Text::new(format!("L{}", i + 1), (8, -6), style.clone())
    });
    chart.draw_series(lights).map_err(draw_err)?;
    if !scene.lights.is_empty() {
        legend.add("lights", Swatch::Dot(LIGHT));
    }
    Ok(())
}
