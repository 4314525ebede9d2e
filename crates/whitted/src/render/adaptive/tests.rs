use super::*;
use crate::Scene;

const WHITE: Color = Color::ONE;
const BLACK: Color = Color::ZERO;

/// POV-Ray's measure, the same at every level, with no split amid neighbours.
fn aa(threshold: f64, depth: u32) -> Adaptive {
    Adaptive {
        threshold,
        depth,
        measure: Measure::Sum,
    }
}

fn edge(threshold: f64, depth: u32) -> Adaptive {
    Adaptive {
        measure: Measure::Edge,
        ..aa(threshold, depth)
    }
}

#[test]
fn agreeing_corners_are_the_pixel_and_trace_nothing_more() {
    let c = Color::new(0.25, 0.5, 0.75);
    let mut never = |_: u32, _: u32| -> Color { panic!("a square whose corners agree split") };
    let (colour, split) = square(&aa(0.1, 3), (0, 0), 8, 0, [c; 4], &mut never);
    assert_eq!(colour, c);
    assert_eq!(
        split,
        Split {
            leaves: 1,
            deepest: 0
        }
    );
    // Four different corners within the threshold: their plain mean.
    let d = [
        Color::new(0.0, 0.0, 0.0),
        Color::new(0.04, 0.0, 0.0),
        Color::new(0.0, 0.04, 0.0),
        Color::new(0.0, 0.0, 0.04),
    ];
    let (colour, _) = square(&aa(0.1, 3), (0, 0), 8, 0, d, &mut never);
    assert_eq!(colour, Color::new(0.01, 0.01, 0.01));
}

#[test]
fn the_mean_is_over_the_leaves_areas() {
    // Depth 2 on a 4×4 lattice: only the top-left point is white. The pixel splits into
    // four quarters; the top-left quarter splits again; its top-left sixteenth (a leaf of
    // area 1/16 at the deepest level) has corners W, B, B, B: mean 1/4. Every other leaf
    // is black, so the pixel is 1/16 · 1/4 = 1/64 (a plain mean over the 7 leaves would
    // give 1/28).
    let mut calls = Vec::new();
    let mut sample = |x: u32, y: u32| {
        calls.push((x, y));
        if (x, y) == (0, 0) {
            WHITE
        } else {
            BLACK
        }
    };
    let corners = [WHITE, BLACK, BLACK, BLACK];
    let (colour, split) = square(&aa(0.3, 2), (0, 0), 4, 0, corners, &mut sample);
    assert_eq!(colour, Color::splat(1.0 / 64.0));
    assert_eq!(
        split,
        Split {
            leaves: 7,
            deepest: 2
        }
    );
    // 5 points for the first split, 5 for the second.
    assert_eq!(calls.len(), 10);
    assert!(calls.contains(&(2, 2)) && calls.contains(&(1, 1)));
    // At depth 0 the same corners are a leaf: their mean.
    let mut never = |_: u32, _: u32| -> Color { panic!("a leaf split") };
    let (colour, _) = square(&aa(0.3, 0), (0, 0), 4, 0, corners, &mut never);
    assert_eq!(colour, Color::splat(0.25));
}

#[test]
fn edge_weighs_a_difference_by_the_side_of_its_square() {
    // As above, depth 2, only the top-left point white: every pair with it differs by 3.
    // Under `edge` the pixel (side 1) splits at T = 1.6 (3 > 1.6), but its top-left quarter
    // (side 1/2: 3 · 1/2 = 1.5 ≤ 1.6) is a leaf with corners W, B, B, B, mean 1/4: the
    // pixel is 1/4 · 1/4 = 1/16 over 4 leaves. At T = 1.4 (1.5 > 1.4) the quarter splits
    // as the sum measure splits it: 1/64 over 7 leaves.
    let sample = |x: u32, y: u32| if (x, y) == (0, 0) { WHITE } else { BLACK };
    let corners = [WHITE, BLACK, BLACK, BLACK];
    let (colour, split) = square(&edge(1.6, 2), (0, 0), 4, 0, corners, &mut { sample });
    assert_eq!(
        (colour, split.leaves, split.deepest),
        (Color::splat(1.0 / 16.0), 4, 1)
    );
    let (colour, split) = square(&edge(1.4, 2), (0, 0), 4, 0, corners, &mut { sample });
    assert_eq!(
        (colour, split.leaves, split.deepest),
        (Color::splat(1.0 / 64.0), 7, 2)
    );
    let (colour, split) = square(&aa(1.6, 2), (0, 0), 4, 0, corners, &mut { sample });
    assert_eq!((colour, split.leaves), (Color::splat(1.0 / 64.0), 7));
}

#[test]
fn under_edge_a_pixel_amid_two_splitting_neighbours_splits() {
    // 3×3 pixels, a 4×4 corner lattice, black but for corners (0, 1) and (3, 1): the
    // pixels left and right of the middle one (and those above them) differ; the middle
    // pixel's own corners agree, but two of its neighbours split, and so do the top
    // middle pixel's (top-left, top-right). The bottom row has at most one such neighbour.
    let mut corners = vec![BLACK; 16];
    corners[4] = WHITE;
    corners[7] = WHITE;
    let splits = |a: Adaptive| {
        let (mut own, mut split) = ([false; 9], [true; 9]);
        lattice::first_splits(&corners, (3, 3), &a, &mut own, &mut split);
        split
    };
    let (t, f) = (true, false);
    assert_eq!(splits(aa(0.5, 2)), [t, f, t, t, f, t, f, f, f]);
    assert_eq!(splits(edge(0.5, 2)), [t, t, t, t, t, t, f, f, f]);
    // Depth 0 splits nothing; above the difference, nothing splits and nothing spreads.
    assert_eq!(splits(edge(0.5, 0)), [f; 9]);
    assert_eq!(splits(edge(3.0, 2)), [f; 9]);
}

/// Four by three pixels of one plane in ambient light only: every sample the same.
const FLAT: &str = "4 3  0 0 5  0 0 0  0 0  0 1 0 0\n\
                    0 0 0  0 0 1  1 0.3 0.6 0.9  1 0 0 1 0 0\n";

/// A white sphere of radius 1 at the origin seen from z = 5, lit from the eye.
const SPHERE: &str = "8 8  0 0 5  0 0 0  0 0  1 0 0 1\n\
                      1 0 0 0  1 1 1 1  1 0 0 1 0 0\n\
                      0 0 5  1 1 1  1\n";

fn traced(text: &str, a: Adaptive, band: u32) -> Adaptively {
    let scene = Scene::parse(text, "t.txt").unwrap();
    let tracer = Tracer::new(&scene);
    trace(&tracer, &scene.camera(), scene.width, scene.height, a, band)
}

#[test]
fn a_flat_scene_casts_only_its_corner_rays() {
    let out = traced(FLAT, aa(0.0, 3), BAND);
    assert_eq!(out.rays.primary, 5 * 4);
    assert_eq!(out.rays.total(), 5 * 4);
    let c = Color::new(0.3, 0.6, 0.9) * 0.2;
    assert!(out
        .colors
        .iter()
        .all(|p| (*p - c).abs().max_element() < 1e-15));
    assert!(out.leaves.iter().all(|&n| n == 1));
}

#[test]
fn a_pixel_on_the_sphere_edge_splits_to_the_depth() {
    // The sphere's silhouette crosses the middle row at x ≈ 0.204 of the 0.25 half-width,
    // inside pixel 7: pixel (7, 4) has its left corners on the sphere, its right ones in
    // the black sky.
    for depth in [1, 3, 4] {
        let out = traced(SPHERE, aa(0.1, depth), BAND);
        let at = 4 * 8 + 7;
        assert_eq!(out.deepest[at], depth, "depth {depth}");
        assert!(out.leaves[at] > 3 * depth);
        // The sky in the corner and the sphere's middle do not split.
        assert_eq!(out.leaves[0], 1);
        assert_eq!(out.deepest[0], 0);
        assert_eq!(out.colors[0], BLACK);
    }
}

#[test]
fn same_colours_and_rays_whatever_the_tiles_and_threads() {
    let mut scene = Scene::load(std::path::Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../scenes/08-procedural-textures.txt"
    )))
    .unwrap();
    let (w, h) = (37, 23);
    (scene.width, scene.height) = (w, h);
    let tracer = Tracer::new(&scene);
    let camera = scene.camera();
    let pool = |n| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(n)
            .build()
            .unwrap()
    };
    for a in [aa(0.1, 3), edge(0.1, 3), edge(0.05, 2)] {
        let reference = pool(1).install(|| trace(&tracer, &camera, w, h, a, 1));
        assert!(reference.leaves.iter().any(|&n| n > 1));
        for (threads, band) in [(1, 32), (2, 1), (2, 5), (2, 32), (3, 7)] {
            let out = pool(threads).install(|| trace(&tracer, &camera, w, h, a, band));
            assert_eq!(
                out.colors, reference.colors,
                "{a:?}: {threads} threads, band {band}"
            );
            assert_eq!(out.leaves, reference.leaves);
            assert_eq!(out.rays, reference.rays);
        }
    }
}

#[test]
fn shared_samples_are_traced_once() {
    // The corners cost one ray per lattice point (81), and every split at most 5 new
    // samples; quarters and pixels that split side by side share their edge samples, so
    // the primary rays beyond the corners are fewer than 5 a split.
    let out = traced(SPHERE, aa(0.1, 3), BAND);
    let splits: u64 = out.leaves.iter().map(|&n| u64::from(n - 1) / 3).sum();
    let finer = out.rays.primary - 81;
    assert!(
        finer > 0 && finer < 5 * splits,
        "{finer} vs {splits} splits"
    );
}

#[test]
fn grid_dispatch_is_render() {
    use crate::render::{grid, render, Options, Picture, Sum};
    let scene = Scene::parse(SPHERE, "t.txt").unwrap();
    let tracer = Tracer::new(&scene);
    let camera = scene.camera();
    for n in [1, 3] {
        let options = Options::grid(8, 8, n);
        assert_eq!(
            render(&tracer, &camera, &options, Picture::new()),
            grid::picture(&tracer, &camera, 8, 8, n)
        );
        let mut a = vec![Color::ZERO; 64];
        let mut b = vec![Color::ZERO; 64];
        render(&tracer, &camera, &options, Sum(&mut a));
        grid::add(&tracer, &camera, 8, 8, n, &mut b);
        assert_eq!(a, b);
    }
    let adaptive = Options::new(8, 8, Antialias::Adaptive(aa(0.1, 3)));
    let (frame, rays) = render(&tracer, &camera, &adaptive, Picture::new());
    let mut sum = vec![Color::ZERO; 64];
    assert_eq!(render(&tracer, &camera, &adaptive, Sum(&mut sum)), rays);
    assert_eq!(Frame::from_sum(&sum, 1, 8, 8), frame);
}
