//! The layered render (`Layered`, `LayeredSum`): the beauty and the passes asked for, from
//! one trace per sample (the tracer's `primary_rec` with a `passes::record::Sample`
//! listening), in parallel over rows like the grid's picture. The beauty here is the mean
//! of the unclamped samples (SPEC §12); with one sample and no motion blur it is exactly
//! the colour the picture rounds. `camera_matrices`: the EXR header's camera.

use super::grid::{par_rows, sub_pixel};
use super::Shot;
use crate::accel::{Hint, TileView};
use crate::camera::{Camera, VIEW_DISTANCE};
use crate::optics::Ray;
use crate::passes::record::{finish, Hit, Sample, Sums};
use crate::passes::{CameraMatrices, Layers, Pass, PassSet};
use crate::trace::{RayCount, Tracer};

/// Adds every pixel's `samples`² samples into `sums` (width·height, rows top to bottom,
/// made by `Sums::new` for `passes`): one sub-frame of a frame of layers. With a lens
/// each sample is its `rays_per_sample` lens rays, each added as a sample of its own. Without passes
/// only the beauty and the hits (alpha) are summed, through a recorder that hears the hit
/// alone (the same colours the recording path computes, added in the same order);
/// `passes` also says whether
/// Cryptomatte coverage is kept; the rest is cheap enough to record always.
pub(super) fn add(
    tracer: &Tracer,
    camera: &Camera,
    width: u32,
    height: u32,
    samples: u32,
    passes: PassSet,
    sums: &mut Sums,
) -> RayCount {
    let n = samples.max(1);
    let crypto = passes.has(Pass::CryptoObject) || passes.has(Pass::CryptoMaterial);
    let forward = camera.basis().2;
    let view = TileView::new(camera, width, height, &tracer.scene().objects);
    let view = view.as_ref();
    let shot = &Shot::new(tracer, camera);
    match sums {
        Sums::Beauty(sums) => par_rows(sums, width, height, |j, row, count| {
            row_samples(shot, view, width, n, j, count, |i, hint, ray, count| {
                let mut hit = Hit::default();
                row[i].colour += tracer.primary_rec(hint, ray, count, &mut hit);
                row[i].hits += u32::from(hit.0);
            });
        }),
        Sums::Passes(sums) => par_rows(sums, width, height, |j, row, count| {
            row_samples(shot, view, width, n, j, count, |i, hint, ray, count| {
                let mut s = Sample::default();
                let c = tracer.primary_rec(hint, ray, count, &mut s);
                row[i].add(c, &s, ray.dir, forward, crypto);
            });
        }),
    }
}

/// Every camera ray of row `j`, pixel by pixel and each pixel's n×n grid in order (each
/// sample's lens rays in turn, with a lens): `add(i, hint, ray, count)` for the rays of
/// pixel i.
fn row_samples(
    shot: &Shot,
    view: Option<&TileView>,
    width: u32,
    n: u32,
    j: usize,
    count: &mut RayCount,
    mut add: impl FnMut(usize, Option<Hint>, &Ray, &mut RayCount),
) {
    let step = 1.0 / n as f64;
    for i in 0..width as usize {
        let hint = view.map(|v| v.hint(i as u32, j as u32));
        for b in 0..n {
            for a in 0..n {
                let (x, y) = sub_pixel(i as f64, j as f64, a, b, step);
                shot.each_ray(x, y, |ray| add(i, hint, ray, count));
            }
        }
    }
}

/// The beauty and `passes` of the tracer's scene through `camera`.
pub(super) fn layers(
    tracer: &Tracer,
    camera: &Camera,
    width: u32,
    height: u32,
    samples: u32,
    passes: PassSet,
) -> (Layers, RayCount) {
    let mut sums = Sums::new(width as usize * height as usize, passes);
    let rays = add(tracer, camera, width, height, samples, passes, &mut sums);
    let n = samples.max(1);
    let layers = finish(
        &sums,
        n * n * super::rays_per_sample(tracer.scene()),
        width,
        height,
        passes,
        tracer.scene(),
        Some(camera_matrices(camera)),
    );
    (layers, rays)
}

/// The header matrices of `camera` (see `CameraMatrices`).
pub fn camera_matrices(camera: &Camera) -> CameraMatrices {
    let (r, u, f) = camera.basis();
    let e = camera.eye();
    let w2c = [
        [r.x, u.x, f.x, 0.0],
        [r.y, u.y, f.y, 0.0],
        [r.z, u.z, f.z, 0.0],
        [-e.dot(r), -e.dot(u), -e.dot(f), 1.0],
    ];
    // x_ndc = x·(2d/W)/z, y_ndc = y·(2d/H)/z, z_ndc = (z − near)/z, w = z, with W × H
    // the camera's own view plane (the report's, or the framing's).
    let near = crate::optics::T_MIN;
    let (plane_w, plane_h) = camera.plane();
    let proj = [
        [2.0 * VIEW_DISTANCE / plane_w, 0.0, 0.0, 0.0],
        [0.0, 2.0 * VIEW_DISTANCE / plane_h, 0.0, 0.0],
        [0.0, 0.0, 1.0, 1.0],
        [0.0, 0.0, -near, 0.0],
    ];
    let mut ndc = [[0.0f64; 4]; 4];
    for (i, row) in ndc.iter_mut().enumerate() {
        for (j, v) in row.iter_mut().enumerate() {
            *v = (0..4).map(|k| w2c[i][k] * proj[k][j]).sum();
        }
    }
    let flat = |m: [[f64; 4]; 4]| {
        let mut out = [0.0f32; 16];
        for (k, v) in m.iter().flatten().enumerate() {
            out[k] = *v as f32;
        }
        out
    };
    CameraMatrices {
        world_to_camera: flat(w2c),
        world_to_ndc: flat(ndc),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::base::Color;
    use crate::render::grid::picture;

    const SCENE: &str = "8 6  0 1 6  0 0 0  1 20  2 1 0 1\n\
        1 0 0 0  1 1 0 0  0.5 0.3 0.2 1.5 0 0\n\
        1.5 2 0 -1  1 0.2 0.8 0.2  1 0 0 1 0 0\n\
        0 -1 0  0 1 0  2 1 1 1 1 0 0 0 0 0 0  0.6 0.4 0 1 0 0\n\
        3 5 5  1 1 1  1";

    #[test]
    fn one_sample_beauty_is_the_pictures_colour_and_the_split_sums_to_it() {
        // Black behind (no background layer), then a `background` record: the rays that
        // miss see it, fogged, in a layer of its own, and the layers still sum.
        // Linear fog to 20 whitens the misses wholly; without fog they show the colour.
        let back = "background 0.2 0.4 0.9\n";
        for (fog, back, layer) in [
            ("1 20", "", false),
            ("1 20", back, true),
            ("0 20", back, true),
        ] {
            // The eye lowered to y = 0: the top rows look over the floor's horizon.
            let text = SCENE.replacen("0 1 6  0 0 0  1 20", &format!("0 0 6  0 0 0  {fog}"), 1);
            let text = format!("{text}\n{back}");
            let scene = crate::Scene::parse(&text, "t.txt").unwrap();
            let tracer = Tracer::new(&scene);
            let camera = scene.camera();
            let all = PassSet::of(&Pass::ALL);
            let (layers, rays) = layers(&tracer, &camera, 8, 6, 1, all);
            let (frame, plain_rays) = picture(&tracer, &camera, 8, 6, 1);
            assert_eq!(layers.to_frame(), frame);
            assert_eq!(rays, plain_rays, "one trace per sample");
            let names = crate::passes::record::BACKGROUND;
            assert_eq!(layers.channel(names[0]).is_some(), layer);
            let mut seen = 0;
            for (k, b) in layers.beauty.iter().enumerate() {
                let at = |c: &str| layers.channel(c).map_or(0.0, |c| f64::from(c.values[k]));
                let back = Color::new(at(names[0]), at(names[1]), at(names[2]));
                seen += usize::from(back.z > 0.0);
                let sum: Color = Pass::LIGHT
                    .iter()
                    .map(|p| {
                        let [r, g, bl] = p.channels().map(|c| at(&c));
                        Color::new(r, g, bl)
                    })
                    .sum::<Color>()
                    + back;
                let err = (sum - *b).abs().max_element() / b.abs().max_element().max(1e-3);
                assert!(err < 1e-5, "pixel {k}: {sum} vs {b}");
            }
            assert_eq!(seen > 0, fog == "0 20" && layer, "{seen} pixels see it");
        }
    }

    #[test]
    fn without_passes_the_beauty_alone_is_summed_to_the_same_bits() {
        // A plain EXR sums colours only (`Sums::Beauty`); its beauty is bit for bit the
        // beauty of the recording path, so the file's bytes are those it had.
        let scene = crate::Scene::parse(SCENE, "t.txt").unwrap();
        let tracer = Tracer::new(&scene);
        let camera = scene.camera();
        assert!(matches!(
            Sums::new(48, PassSet::NONE),
            Sums::Beauty(ref v) if v.len() == 48
        ));
        for n in [1, 2, 3] {
            let (plain, rays) = layers(&tracer, &camera, 8, 6, n, PassSet::NONE);
            let all = PassSet::of(&Pass::ALL);
            let (layered, layered_rays) = layers(&tracer, &camera, 8, 6, n, all);
            let bits = |l: &Layers| -> Vec<[u64; 3]> {
                l.beauty
                    .iter()
                    .map(|c| c.to_array().map(f64::to_bits))
                    .collect()
            };
            assert_eq!(bits(&plain), bits(&layered), "{n}² samples");
            assert!(plain.channels.is_empty() && plain.crypto.is_empty());
            assert_eq!(plain.camera, layered.camera);
            assert_eq!(plain.alpha, layered.alpha, "{n}² samples");
            assert_eq!(rays, layered_rays);
        }
    }

    #[test]
    fn world_to_camera_puts_the_look_at_point_straight_ahead() {
        let cam = Camera::new(glam::DVec3::new(0.0, 0.0, 5.0), glam::DVec3::ZERO, 4, 3).unwrap();
        let m = camera_matrices(&cam);
        // Row-vector convention: the origin maps to the last row plus nothing: (0, 0, 5).
        let w = m.world_to_camera;
        assert_eq!([w[12], w[13], w[14], w[15]], [0.0, 0.0, 5.0, 1.0]);
        // NDC of the origin: x = y = 0, z = (5 − 0.01)/5, w = 5.
        let n = m.world_to_ndc;
        assert_eq!((n[12], n[13], n[15]), (0.0, 0.0, 5.0));
        assert!((n[14] / n[15] - (5.0 - 0.01) / 5.0).abs() < 1e-6);
    }

    /// The NDC (x, y) of `p` through the header's row-vector matrix.
    fn ndc(m: &[f32; 16], p: glam::DVec3) -> (f64, f64) {
        let col = |j: usize| {
            let m = |i: usize| f64::from(m[4 * i + j]);
            p.x * m(0) + p.y * m(1) + p.z * m(2) + m(3)
        };
        (col(0) / col(3), col(1) / col(3))
    }

    #[test]
    fn world_to_ndc_follows_the_framing() {
        use crate::camera::Lens;
        use glam::DVec3;
        // A 16:9 frame of a 4:3 scene, a fov'd one, a rolled one: the point 7 units down
        // the camera ray through a pixel's centre lands at that pixel's NDC (x right, y
        // up, −1..1 across the picture).
        let (eye, at) = (DVec3::new(1.0, 3.0, 12.0), DVec3::new(0.0, 1.0, 0.0));
        let lenses = [
            Lens::default(),
            Lens {
                fov: Some(60.0),
                roll: 0.0,
                ..Lens::default()
            },
            Lens {
                fov: Some(30.0),
                roll: 20.0,
                ..Lens::default()
            },
        ];
        for lens in lenses {
            for (w, h) in [(640u32, 480u32), (1920, 1080)] {
                let cam = Camera::framed(eye, at, (640, 480), (w, h), &lens).unwrap();
                let m = camera_matrices(&cam).world_to_ndc;
                for (x, y) in [(0.5, 0.5), (100.5, 400.5), (639.5, 20.5), (320.0, 240.0)] {
                    let ray = cam.ray(x, y);
                    let (nx, ny) = ndc(&m, ray.origin + 7.0 * ray.dir);
                    let want = (2.0 * x / w as f64 - 1.0, 1.0 - 2.0 * y / h as f64);
                    assert!(
                        (nx - want.0).abs() < 1e-5 && (ny - want.1).abs() < 1e-5,
                        "{lens:?} {w}x{h} pixel ({x}, {y}): ndc ({nx}, {ny}), want {want:?}"
                    );
                }
            }
        }
    }
}
