//! The camera's rays checked by hand: the centre pixel, the corners, the roll, the
//! lens's plane and the parallel rays of an orthographic view.
use super::*;

fn close(a: DVec3, b: DVec3) -> bool {
    (a - b).length() < 1e-12
}

#[test]
fn parallel_rays_span_the_view_height_by_hand() {
    // The report's plane, 0.5 × 0.35 at distance 1, spread over a height of 2: the
    // scale is 2 / 0.35, so the top-left corner's ray leaves (−0.25, 0.175)·2/0.35 =
    // (−1/0.7, 1) and every ray runs along the axis.
    let cam = Camera::new(DVec3::ZERO, -DVec3::Z, 2, 2).unwrap();
    let r = cam.parallel_ray(0.0, 0.0, 2.0);
    assert!(
        close(r.origin, DVec3::new(-1.0 / 0.7, 1.0, 0.0)),
        "{}",
        r.origin
    );
    assert!(close(r.dir, -DVec3::Z), "{}", r.dir);
    let c = cam.parallel_ray(1.0, 1.0, 2.0);
    assert!(close(c.origin, DVec3::ZERO) && close(c.dir, -DVec3::Z));
}

#[test]
fn centre_pixel_looks_straight_ahead() {
    // 2×2 image: the centre of the image is the corner shared by the four pixels.
    let cam = Camera::new(DVec3::ZERO, -DVec3::Z, 2, 2).unwrap();
    let r = cam.ray(1.0, 1.0);
    assert!(close(r.dir, -DVec3::Z), "{}", r.dir);
    assert_eq!(r.origin, DVec3::ZERO);
}

#[test]
fn corner_pixel_by_hand() {
    // 640×480 looking down −z: D = +x, H' = +y. Pixel (0,0) centre:
    // x = −0.25 + 0.5·0.5/640 = −0.24960937500, y = 0.175 − 0.35·0.5/480 = 0.17463541666…
    let cam = Camera::new(DVec3::ZERO, -DVec3::Z, 640, 480).unwrap();
    let r = cam.ray(0.5, 0.5);
    let raw = DVec3::new(-0.2496093750, 0.175 - 0.35 * 0.5 / 480.0, -1.0);
    assert!(close(r.dir, raw.normalize()), "{}", r.dir);
    // Bottom-right pixel mirrors it: the image is not mirrored left-right.
    let r = cam.ray(639.5, 479.5);
    let raw = DVec3::new(0.2496093750, -(0.175 - 0.35 * 0.5 / 480.0), -1.0);
    assert!(close(r.dir, raw.normalize()), "{}", r.dir);
}

#[test]
fn looking_down_falls_back_to_z_up() {
    let cam = Camera::new(DVec3::new(0.0, 10.0, 0.0), DVec3::ZERO, 4, 4).unwrap();
    let r = cam.ray(2.0, 2.0);
    assert!(close(r.dir, -DVec3::Y));
    // U = −y, fallback H = +z: D = U × H = (−y) × z = −x, H' = D × U = (−x) × (−y) = +z.
    // The top-left pixel therefore leans towards +x and +z.
    let tl = cam.ray(0.5, 0.5).dir;
    assert!(tl.x > 0.0 && tl.z > 0.0, "{tl}");
    let cam = Camera::new(DVec3::ZERO, DVec3::new(0.0, 5.0, 0.0), 4, 4).unwrap();
    assert!(close(cam.ray(2.0, 2.0).dir, DVec3::Y));
}

#[test]
fn eye_on_target_is_refused() {
    assert!(Camera::new(DVec3::ONE, DVec3::ONE, 4, 4).is_none());
}

#[test]
fn plane_by_hand() {
    let lens = Lens::default();
    // The scene's own size and any size of its shape: the report's plane, exactly.
    assert_eq!(lens.plane((640, 480), (640, 480)), (0.5, 0.35));
    assert_eq!(lens.plane((640, 480), (160, 120)), (0.5, 0.35));
    // 1920×1080 of a 640×480 scene: 0.35 high, 0.35·1920/1080 = 0.6222… wide.
    let (w, h) = lens.plane((640, 480), (1920, 1080));
    assert_eq!(h, 0.35);
    assert!((w - 0.622_222_222_222_222_2).abs() < 1e-15, "{w}");
    // fov 90°: 2·tan(45°) = 2 high; at 200×100, 4 wide.
    let lens = Lens {
        fov: Some(90.0),
        roll: 0.0,
        ..Lens::default()
    };
    let (w, h) = lens.plane((640, 480), (200, 100));
    assert!(
        (h - 2.0).abs() < 1e-12 && (w - 4.0).abs() < 1e-12,
        "{w} {h}"
    );
}

#[test]
fn native_framing_is_the_report_camera() {
    let (eye, at) = (DVec3::new(0.0, 3.0, 12.0), DVec3::new(0.0, 1.0, 0.0));
    let cam = Camera::framed(eye, at, (640, 480), (640, 480), &Lens::default());
    assert_eq!(cam, Camera::new(eye, at, 640, 480));
}

#[test]
fn wide_frames_have_square_pixels() {
    // Looking down −z at 1920×1080 of a 640×480 scene: one pixel right and one pixel
    // down are the same length, 0.35/1080.
    let cam = Camera::framed(
        DVec3::ZERO,
        -DVec3::Z,
        (640, 480),
        (1920, 1080),
        &Lens::default(),
    )
    .unwrap();
    assert!((cam.step_x.length() - 0.35 / 1080.0).abs() < 1e-15);
    assert!((cam.step_y.length() - 0.35 / 1080.0).abs() < 1e-15);
}

#[test]
fn roll_banks_right() {
    // Roll 90° looking down −z: right becomes −y and up becomes +x, so the top-left
    // pixel of a 2×2 image leans towards +x (up-right of the unrolled view) and +y…
    // by hand: corner = −z + (h/2)·x − (w/2)·(−y) = (0.175, 0.25, −1).
    let lens = Lens {
        roll: 90.0,
        ..Lens::default()
    };
    let cam = Camera::framed(DVec3::ZERO, -DVec3::Z, (2, 2), (2, 2), &lens).unwrap();
    let c = cam.corner;
    assert!((c - DVec3::new(0.175, 0.25, -1.0)).length() < 1e-12, "{c}");
}

#[test]
fn rays_are_unit() {
    let cam = Camera::new(
        DVec3::new(3.0, 2.0, 7.0),
        DVec3::new(-1.0, 0.5, 0.0),
        64,
        48,
    )
    .unwrap();
    for (x, y) in [(0.5, 0.5), (63.5, 0.5), (10.0, 40.0)] {
        assert!((cam.ray(x, y).dir.length() - 1.0).abs() < 1e-12);
    }
}

#[test]
fn nff_angle_between_outer_pixel_centres_and_z_up() {
    // 3×3 pixels, angle 90° between the outer centres, z up, looking along +y: the
    // top-left centre ray leans 45° left and 45° up, (−1, 1, 1)/√3; the centre pixel
    // looks straight ahead.
    let lens = Lens {
        fov: Some(90.0),
        up: DVec3::Z,
        centres: true,
        ..Lens::default()
    };
    let (w, h) = lens.plane((3, 3), (3, 3));
    assert!(
        (h - 3.0).abs() < 1e-12 && (w - 3.0).abs() < 1e-12,
        "{w} {h}"
    );
    let cam = Camera::framed(DVec3::ZERO, DVec3::Y, (3, 3), (3, 3), &lens).unwrap();
    assert!(close(cam.ray(1.5, 1.5).dir, DVec3::Y));
    let want = DVec3::new(-1.0, 1.0, 1.0).normalize();
    assert!(
        close(cam.ray(0.5, 0.5).dir, want),
        "{}",
        cam.ray(0.5, 0.5).dir
    );
    // A user's fov overrides the scene's, and spans the edges again.
    let user = lens.overridden(Some(60.0), 5.0);
    assert_eq!(
        (user.fov, user.centres, user.roll, user.up),
        (Some(60.0), false, 5.0, DVec3::Z)
    );
}
