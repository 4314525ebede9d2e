//! The figures of `animate stats` by hand.

use super::*;

fn cost(frame: u32, wall_s: f64, cpu_s: Option<f64>, mem: u64, eye: u64) -> FrameCost {
    FrameCost {
        frame,
        digest: String::new(),
        wall_s,
        cpu_s,
        peak_memory_bytes: Some(mem),
        eye,
        eye_hits: eye / 2,
        reflect: 1,
        refract: 2,
        shadow: 3,
    }
}

#[test]
fn totals_add_and_take_the_largest_peak() {
    let c = [
        cost(0, 1.0, Some(2.0), 100, 10),
        cost(1, 3.0, Some(4.0), 300, 30),
    ];
    let t = totals(&c);
    assert_eq!(t.frames, 2);
    assert_eq!(t.wall_s, 4.0);
    assert_eq!(t.cpu_s, Some(6.0));
    assert_eq!(t.peak_memory_bytes, Some(300));
    assert_eq!(
        (t.eye, t.eye_hits, t.reflect, t.refract, t.shadow),
        (40, 20, 2, 4, 6)
    );
    // 40 + 2 + 4 + 6 = 52 rays in 4 s.
    assert_eq!(t.rays_per_second, 13.0);
    let unknown = [cost(0, 1.0, None, 1, 1), cost(1, 1.0, Some(1.0), 1, 1)];
    assert_eq!(totals(&unknown).cpu_s, None);
}

#[test]
fn predictions_share_the_measured_total_by_prepass_rays() {
    // Pre-pass 1, 1, 2: the 8 s measured split 2, 2, 4. Frame 1 took 5 s: 2.5x, off.
    let c = [
        cost(0, 2.0, None, 1, 1),
        cost(1, 5.0, None, 1, 1),
        cost(2, 1.0, None, 1, 1),
    ];
    let r = rows(&c, &[1, 1, 2]);
    let predicted: Vec<f64> = r.iter().map(|r| r.predicted_s).collect();
    assert_eq!(predicted, [2.0, 2.0, 4.0]);
    assert_eq!(r[1].ratio, 2.5);
    assert_eq!(r[2].ratio, 0.25);
    let flagged: Vec<u32> = r.iter().filter(|r| off(r)).map(|r| r.frame).collect();
    assert_eq!(flagged, [1, 2]);
    assert!(!off(&r[0]));
}

#[test]
fn the_plot_draws_both_lines() {
    let c = [cost(0, 1.0, None, 1, 1), cost(1, 2.0, None, 1, 1)];
    let picture = plot::draw(&rows(&c, &[1, 1])).unwrap();
    let has = |rgb: [u8; 3]| picture.pixels.chunks(3).any(|p| p == rgb);
    assert!(has([30, 90, 200]), "no measured line");
    assert!(has([230, 120, 0]), "no predicted line");
}
