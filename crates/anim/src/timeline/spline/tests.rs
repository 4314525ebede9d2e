//! Unit tests of the camera spline, with hand-computed values.

use super::*;

const EPS: f64 = 1e-12;

fn key(frame: u32, p: [f64; 3]) -> Key {
    Key {
        frame,
        position: DVec3::from_array(p),
        look_at: None,
        ease: Default::default(),
    }
}

fn key_look(frame: u32, p: [f64; 3], look: [f64; 3]) -> Key {
    Key {
        look_at: Some(DVec3::from_array(look)),
        ..key(frame, p)
    }
}

fn close(a: DVec3, b: DVec3) -> bool {
    a.distance(b) <= EPS
}

fn eye(s: &Spline, frame: u32, frames: u32) -> DVec3 {
    s.at(f64::from(frame), frames, DVec3::ZERO).0
}

#[test]
fn uniform_knots_give_the_classic_catmull_rom_midpoint() {
    // Unit square: every knot interval is 1, so this is the uniform Catmull-Rom:
    // 0.5·(2P1 + (P2−P0)/2 + (2P0−5P1+4P2−P3)/4 + (−P0+3P1−3P2+P3)/8) = (1.125, 0.5, 0).
    let p = [
        DVec3::new(0.0, 0.0, 0.0),
        DVec3::new(1.0, 0.0, 0.0),
        DVec3::new(1.0, 1.0, 0.0),
        DVec3::new(0.0, 1.0, 0.0),
    ];
    assert!(close(catmull_rom(p, 0.5), DVec3::new(1.125, 0.5, 0.0)));
}

#[test]
fn centripetal_knots_follow_the_square_roots_of_the_distances() {
    // Distances 1, 4, 1: knots 0, 1, 3, 4; u = 0.25 is t = 1.5. By hand:
    // A1 = (1.5, 0), A2 = (1, 1), A3 = (−0.5, 4); B1 = (1.25, 0.5), B2 = (0.75, 1.5);
    // C = (1.125, 0.75). A uniform spline would give (1.03125, 0.84375).
    let p = [
        DVec3::new(0.0, 0.0, 0.0),
        DVec3::new(1.0, 0.0, 0.0),
        DVec3::new(1.0, 4.0, 0.0),
        DVec3::new(2.0, 4.0, 0.0),
    ];
    assert!(close(catmull_rom(p, 0.25), DVec3::new(1.125, 0.75, 0.0)));
}

#[test]
fn passes_through_every_key_exactly_on_its_frame() {
    let keys = vec![
        key(0, [0.0, 3.0, 12.0]),
        key(37, [10.0, 6.0, 0.3]),
        key(120, [-4.0, 1.0, 7.0]),
        key(249, [0.0, 2.0, -12.0]),
    ];
    for closed in [false, true] {
        let s = Spline::new(keys.clone(), closed, false, None).unwrap();
        for k in &keys {
            assert_eq!(eye(&s, k.frame, 250), k.position, "closed = {closed}");
        }
    }
}

#[test]
fn two_keys_move_in_a_straight_line_at_even_speed() {
    // Reflected phantoms make four evenly spaced collinear points: a straight line.
    let s = Spline::new(
        vec![key(0, [0.0; 3]), key(10, [4.0, 0.0, 0.0])],
        false,
        false,
        None,
    );
    let s = s.unwrap();
    assert!(close(eye(&s, 5, 11), DVec3::new(2.0, 0.0, 0.0)));
    assert!(close(eye(&s, 2, 11), DVec3::new(0.8, 0.0, 0.0)));
}

#[test]
fn open_paths_hold_their_end_positions() {
    let keys = vec![key(10, [1.0, 2.0, 3.0]), key(50, [4.0, 5.0, 6.0])];
    for constant_speed in [false, true] {
        let s = Spline::new(keys.clone(), false, constant_speed, None).unwrap();
        assert_eq!(eye(&s, 0, 100), DVec3::new(1.0, 2.0, 3.0));
        assert_eq!(eye(&s, 9, 100), DVec3::new(1.0, 2.0, 3.0));
        assert_ne!(eye(&s, 11, 100), DVec3::new(1.0, 2.0, 3.0));
        assert_eq!(eye(&s, 51, 100), DVec3::new(4.0, 5.0, 6.0));
        assert_eq!(eye(&s, 99, 100), DVec3::new(4.0, 5.0, 6.0));
    }
}

fn diamond(closed: bool, constant_speed: bool) -> Spline {
    let keys = vec![
        key(0, [1.0, 0.0, 0.0]),
        key(25, [0.0, 0.0, 1.0]),
        key(50, [-1.0, 0.0, 0.0]),
        key(75, [0.0, 0.0, -1.0]),
    ];
    Spline::new(keys, closed, constant_speed, None).unwrap()
}

#[test]
fn a_closed_loop_comes_back_smoothly_to_its_first_key() {
    let s = diamond(true, false);
    assert_eq!(eye(&s, 100, 100), eye(&s, 0, 100));
    // The loop is symmetric under z → −z with time reversed, so the step into the
    // first key equals the step out of it, and the closing segment mirrors the first.
    let step_in = eye(&s, 99, 100).distance(eye(&s, 0, 100));
    let step_out = eye(&s, 1, 100).distance(eye(&s, 0, 100));
    assert!((step_in - step_out).abs() < 1e-9, "{step_in} vs {step_out}");
    let mirrored = eye(&s, 80, 100) * DVec3::new(1.0, 1.0, -1.0);
    assert!(close(mirrored, eye(&s, 20, 100)));
    // A closed path is not the open one: frame 80 is on the closing segment.
    assert!(eye(&s, 80, 100).x > 0.0 && eye(&s, 80, 100).z < 0.0);
}

#[test]
fn a_closed_loop_has_no_kink_where_it_closes() {
    // An unsymmetric loop, finely timed: the direction into the first key (from the last
    // frame) and out of it agree, as at any key, because the neighbours wrap around.
    let keys = vec![
        key(0, [1.0, 0.0, 0.0]),
        key(2500, [0.0, 0.5, 2.0]),
        key(5000, [-1.0, 0.0, 0.0]),
        key(7500, [0.0, 0.0, -1.0]),
    ];
    let s = Spline::new(keys, true, false, None).unwrap();
    let turn = |f: u32| {
        let into = eye(&s, f, 10_000) - eye(&s, f + 9_999, 10_000);
        let out = eye(&s, f + 1, 10_000) - eye(&s, f, 10_000);
        into.angle_between(out).to_degrees()
    };
    assert!(turn(0) < 0.5, "{}", turn(0));
    assert!(turn(2500) < 0.5, "{}", turn(2500));
}

#[test]
fn frames_before_the_first_key_of_a_closed_path_are_on_the_closing_segment() {
    let keys = vec![
        key(10, [1.0, 0.0, 0.0]),
        key(40, [0.0, 0.0, 1.0]),
        key(70, [-1.0, 0.0, 0.0]),
    ];
    let s = Spline::new(keys, true, false, None).unwrap();
    assert_eq!(eye(&s, 5, 90), eye(&s, 95, 90));
    assert_ne!(eye(&s, 5, 90), DVec3::new(1.0, 0.0, 0.0));
    assert_eq!(eye(&s, 100, 90), DVec3::new(1.0, 0.0, 0.0));
}

/// The largest relative deviation from the mean of the steps between frames 0..=`last`
/// of a `frames`-frame sequence.
fn spacing_spread(s: &Spline, last: u32, frames: u32) -> f64 {
    let steps: Vec<f64> = (0..last)
        .map(|f| eye(s, f, frames).distance(eye(s, f + 1, frames)))
        .collect();
    let mean = steps.iter().sum::<f64>() / steps.len() as f64;
    steps
        .iter()
        .map(|d| (d - mean).abs() / mean)
        .fold(0.0, f64::max)
}

#[test]
fn constant_speed_spaces_frames_evenly() {
    // A far key reached in 10 frames, then a close one 190 frames later.
    let keys = vec![
        key(0, [0.0, 0.0, 0.0]),
        key(10, [100.0, 0.0, 0.0]),
        key(200, [101.0, 0.0, 1.0]),
    ];
    let even = Spline::new(keys.clone(), false, true, None).unwrap();
    assert!(spacing_spread(&even, 200, 201) < 0.02);
    assert_eq!(eye(&even, 0, 201), DVec3::ZERO);
    assert_eq!(eye(&even, 200, 201), DVec3::new(101.0, 0.0, 1.0));
    // Only the ends keep their frames: at frame 10 the camera is far from key 2.
    assert!(eye(&even, 10, 201).x < 10.0);
    let timed = Spline::new(keys, false, false, None).unwrap();
    assert!(spacing_spread(&timed, 200, 201) > 1.0);
}

#[test]
fn constant_speed_on_a_closed_loop_covers_the_loop_evenly() {
    let s = diamond(true, true);
    assert!(spacing_spread(&s, 100, 100) < 0.02);
    assert_eq!(eye(&s, 0, 100), DVec3::new(1.0, 0.0, 0.0));
    assert!(close(eye(&s, 100, 100), eye(&s, 0, 100)));
}

#[test]
fn per_key_look_at_points_follow_their_own_centripetal_curve() {
    // Look-at points of the centripetal example above on frames 0, 4, 8, 12: frame 5 is
    // u = 0.25 of the middle segment, so (1.125, 0.75, 0) whatever the eye does.
    let keys = vec![
        key_look(0, [0.0, 5.0, 0.0], [0.0, 0.0, 0.0]),
        key_look(4, [3.0, 5.0, 0.0], [1.0, 0.0, 0.0]),
        key_look(8, [3.0, 5.0, 9.0], [1.0, 4.0, 0.0]),
        key_look(12, [0.0, 5.0, 9.0], [2.0, 4.0, 0.0]),
    ];
    let s = Spline::new(keys, false, false, None).unwrap();
    let scene = DVec3::splat(99.0);
    assert_eq!(s.at(8.0, 13, scene).1, DVec3::new(1.0, 4.0, 0.0));
    assert!(close(s.at(5.0, 13, scene).1, DVec3::new(1.125, 0.75, 0.0)));
}

#[test]
fn fixed_or_scene_look_at() {
    let keys = vec![key(0, [0.0; 3]), key(9, [1.0, 0.0, 0.0])];
    let scene = DVec3::new(0.0, 1.0, 0.0);
    let fixed = DVec3::new(5.0, 5.0, 5.0);
    let s = Spline::new(keys.clone(), false, false, Some(fixed)).unwrap();
    assert_eq!(s.at(4.0, 10, scene).1, fixed);
    let s = Spline::new(keys, false, false, None).unwrap();
    assert_eq!(s.at(4.0, 10, scene).1, scene);
}

#[test]
fn coincident_keys_never_give_nan() {
    let keys = vec![
        key(0, [0.0; 3]),
        key(10, [0.0; 3]),
        key(20, [5.0, 0.0, 0.0]),
        key(30, [5.0, 0.0, 0.0]),
        key(40, [5.0, 0.0, 0.0]),
    ];
    for (closed, constant_speed) in [(false, false), (false, true), (true, false), (true, true)] {
        let s = Spline::new(keys.clone(), closed, constant_speed, None).unwrap();
        for f in 0..=60 {
            assert!(
                eye(&s, f, 50).is_finite(),
                "frame {f} {closed} {constant_speed}"
            );
        }
        if !constant_speed {
            assert_eq!(eye(&s, 5, 50), DVec3::ZERO);
            assert_eq!(eye(&s, 35, 50), DVec3::new(5.0, 0.0, 0.0));
        }
    }
    let same = vec![key(0, [1.0; 3]), key(5, [1.0; 3])];
    let s = Spline::new(same, true, true, None).unwrap();
    assert_eq!(eye(&s, 3, 10), DVec3::ONE);
}

#[test]
fn random_keys_never_give_nan() {
    let mut seed = 0x2545_f491_4f6c_dd1d_u64;
    let mut next = move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        // Few distinct values, so that keys often coincide.
        (seed % 5) as f64 - 2.0
    };
    for round in 0..200 {
        let n = 2 + round % 5;
        let keys: Vec<Key> = (0..n)
            .map(|i| key(i as u32 * 3, [next(), next() * 1e-9, next()]))
            .collect();
        let s = Spline::new(keys, round % 2 == 0, round % 3 == 0, None).unwrap();
        for f in 0..40 {
            assert!(eye(&s, f, 30).is_finite(), "round {round} frame {f}");
        }
    }
}

#[test]
fn bad_keys_are_refused() {
    let one = vec![key(0, [0.0; 3])];
    assert_eq!(
        Spline::new(one, false, false, None),
        Err(SplineError::TooFewKeys { count: 1 })
    );
    let order = vec![key(0, [0.0; 3]), key(5, [1.0; 3]), key(5, [2.0; 3])];
    let err = Spline::new(order, false, false, None).unwrap_err();
    assert_eq!(
        err,
        SplineError::FrameOrder {
            index: 2,
            frame: 5,
            previous: 5
        }
    );
    assert!(err.to_string().starts_with("camera.keys[2]: frame 5"));
    let mixed = vec![key_look(0, [0.0; 3], [1.0; 3]), key(5, [1.0; 3])];
    assert_eq!(
        Spline::new(mixed, false, false, None),
        Err(SplineError::MixedLookAt { index: 1 })
    );
    let both = vec![
        key_look(0, [0.0; 3], [1.0; 3]),
        key_look(5, [1.0; 3], [1.0; 3]),
    ];
    let fixed = Some(DVec3::ZERO);
    assert_eq!(
        Spline::new(both, false, false, fixed),
        Err(SplineError::BothLookAts)
    );
    for bad in [f64::NAN, f64::INFINITY, 2e9] {
        let keys = vec![key(0, [0.0; 3]), key(5, [0.0, bad, 0.0])];
        assert_eq!(
            Spline::new(keys, false, false, None),
            Err(SplineError::BadCoordinate { index: 1 })
        );
    }
}

#[test]
fn a_key_eases_the_segment_it_starts() {
    // Keys at frames 0 and 10: eased "in", frame 5 is u = 0.5 → e = 0.25, where the
    // even path is at frame 2.5; "out" gives 1 − 0.5² = 0.75, the even path's 7.5.
    let even = Spline::new(
        vec![key(0, [0.0; 3]), key(10, [4.0, 0.0, 0.0])],
        false,
        false,
        None,
    )
    .unwrap();
    for (ease, at) in [(Ease::In, 2.5), (Ease::Out, 7.5), (Ease::InOut, 5.0)] {
        let mut first = key(0, [0.0; 3]);
        first.ease = ease;
        let eased = Spline::new(vec![first, key(10, [4.0, 0.0, 0.0])], false, false, None).unwrap();
        let (p, _) = eased.at(5.0, 11, DVec3::ZERO);
        let (q, _) = even.at(at, 11, DVec3::ZERO);
        assert!(p.distance(q) < 1e-12, "{ease:?}: {p} vs {q}");
    }
    let mut first = key(0, [0.0; 3]);
    first.ease = Ease::In;
    let refused = Spline::new(vec![first, key(10, [4.0, 0.0, 0.0])], false, true, None);
    assert_eq!(
        refused.unwrap_err(),
        SplineError::EaseWithConstantSpeed { index: 0 }
    );
}
