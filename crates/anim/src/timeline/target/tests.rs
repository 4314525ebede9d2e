use super::*;

const SCENE: &str = "8 6  0 2 10  0 1 0  1 30  2 1 1 2
1.0  0 1 0   1 0.9 0.1 0.1   0.7 0.3 0 1 0 0
0.5  2 0.5 0   2 2 0.1 0.2 0.3 0.4 0.5 0.6 0.7 0.8 0.9   0.8 0 0.5 1.5 1 0.2
0 0 0  0 1 0   2 1 1 1 1 0 0 0 0 0 0   0.9 0 0 1 0 0
0 1 0  -2 0 -2  0.3   1 0.2 0.5 0.8   0.7 0 0 1 0 0
5 10 5  1 1 1  0.9
-6 8 4  0.6 0.6 0.8  0.6";

fn scene() -> Scene {
    Scene::parse(SCENE, "t.txt").unwrap()
}

#[test]
fn targets_resolve_to_their_object_or_light() {
    let s = scene();
    let t = Target::parse("sphere 2 radius", &s).unwrap();
    assert_eq!(
        (t.field, t.index, t.kind()),
        (Field::Radius, 1, Kind::Number)
    );
    // Objects are spheres, then planes, then cylinders: cylinder 1 is object 3.
    let t = Target::parse("cylinder 1 axis", &s).unwrap();
    assert_eq!((t.field, t.index, t.kind()), (Field::Axis, 3, Kind::Vector));
    let t = Target::parse("plane 1 kd", &s).unwrap();
    assert_eq!((t.field, t.index), (Field::Kd, 2));
    let t = Target::parse("light 2 intensity", &s).unwrap();
    assert_eq!((t.field, t.index), (Field::Intensity, 1));
    let t = Target::parse("  fog   distance ", &s).unwrap();
    assert_eq!(t.field, Field::FogDistance);
}

#[test]
fn bad_targets_say_why() {
    let s = scene();
    let err = |text: &str| Target::parse(text, &s).unwrap_err();
    assert!(err("sphere 3 center").contains("sphere 3 does not exist: the scene has 2"));
    assert!(err("sphere 0 center").contains("does not exist"));
    assert!(err("cube 1 center").contains("unknown kind `cube`"));
    assert!(err("sphere 1 normal").contains("expected one of center, radius, color"));
    assert!(err("sphere one center").contains("found `one`"));
    assert!(err("sphere 1").contains("KIND N FIELD"));
    assert!(err("fog 1 distance").contains("KIND N FIELD"));
    // Fields the record does not carry.
    assert!(err("sphere 2 color").contains("procedural"));
    assert!(err("sphere 1 color1").contains("one colour"));
    assert!(err("plane 1 color3").contains("Perlin"));
    assert!(err("sphere 1 bump").contains("no bump mapping"));
}

#[test]
fn bounds_of_spec_section_1() {
    let s = scene();
    let t = |text: &str| Target::parse(text, &s).unwrap();
    let n = |x: f64| DVec3::new(x, 0.0, 0.0);
    assert!(t("sphere 1 radius").check(n(0.5)).is_ok());
    assert!(t("sphere 1 radius").check(n(0.0)).is_err());
    assert!(t("sphere 1 color").check(DVec3::new(0.0, 1.0, 0.5)).is_ok());
    assert!(t("sphere 1 color")
        .check(DVec3::new(0.0, 1.01, 0.5))
        .is_err());
    assert!(t("plane 1 normal").check(DVec3::ZERO).is_err());
    assert!(t("plane 1 normal")
        .check(DVec3::new(0.0, -3.0, 0.0))
        .is_ok());
    assert!(t("sphere 1 kt").check(n(-0.1)).is_err());
    assert!(t("sphere 1 ior").check(n(0.0)).is_err());
    assert!(t("light 1 intensity").check(n(1000.0)).is_ok());
    assert!(t("light 1 intensity").check(n(1000.5)).is_err());
    assert!(t("fog distance").check(n(-1.0)).is_err());
    assert!(t("sphere 1 center")
        .check(DVec3::new(f64::INFINITY, 0.0, 0.0))
        .is_err());
}

#[test]
fn applying_a_value_is_writing_it_into_the_file() {
    // Each tracked scene equals the scene parsed from the file with the value in it.
    let cases = [
        (
            "sphere 1 center",
            DVec3::new(0.5, 2.0, -1.0),
            "1.0  0 1 0",
            "1.0  0.5 2 -1",
        ),
        (
            "sphere 2 radius",
            DVec3::new(0.75, 0.0, 0.0),
            "0.5  2 0.5 0",
            "0.75  2 0.5 0",
        ),
        (
            "plane 1 normal",
            DVec3::new(0.0, 2.0, 0.5),
            "0 0 0  0 1 0",
            "0 0 0  0 2 0.5",
        ),
        (
            "cylinder 1 radius",
            DVec3::new(0.6, 0.0, 0.0),
            "-2 0 -2  0.3",
            "-2 0 -2  0.6",
        ),
        (
            "cylinder 1 axis",
            DVec3::new(1.0, 1.0, 0.0),
            "0 1 0  -2 0 -2",
            "1 1 0  -2 0 -2",
        ),
        (
            "sphere 1 color",
            DVec3::new(0.2, 0.4, 0.6),
            "1 0.9 0.1 0.1",
            "1 0.2 0.4 0.6",
        ),
        (
            "sphere 2 color3",
            DVec3::new(0.0, 0.0, 1.0),
            "0.7 0.8 0.9",
            "0 0 1",
        ),
        (
            "sphere 2 bump",
            DVec3::new(0.05, 0.0, 0.0),
            "1.5 1 0.2",
            "1.5 1 0.05",
        ),
        (
            "plane 1 kr",
            DVec3::new(0.25, 0.0, 0.0),
            "0.9 0 0 1 0 0\n0 1 0",
            "0.9 0.25 0 1 0 0\n0 1 0",
        ),
        (
            "light 2 position",
            DVec3::new(1.0, 2.0, 3.0),
            "-6 8 4",
            "1 2 3",
        ),
        (
            "light 1 color",
            DVec3::new(1.0, 0.5, 0.0),
            "5 10 5  1 1 1",
            "5 10 5  1 0.5 0",
        ),
        ("fog distance", DVec3::new(12.0, 0.0, 0.0), "1 30", "1 12"),
    ];
    for (target, value, from, to) in cases {
        let mut tracked = scene();
        let t = Target::parse(target, &tracked).unwrap();
        assert!(t.check(value).is_ok(), "{target}");
        t.apply(&mut tracked, value);
        assert!(SCENE.contains(from), "{from}");
        let by_hand = Scene::parse(&SCENE.replacen(from, to, 1), "t.txt").unwrap();
        assert_eq!(tracked, by_hand, "{target}");
        assert_eq!(t.read(&tracked), t.read(&by_hand), "{target}");
    }
}

#[test]
fn geometry_and_positions() {
    let s = scene();
    let t = |text: &str| Target::parse(text, &s).unwrap();
    assert!(t("sphere 1 center").moves_geometry());
    assert!(t("sphere 1 kt").moves_geometry());
    assert!(!t("sphere 1 kr").moves_geometry());
    assert!(!t("light 1 position").moves_geometry());
    assert!(t("light 1 position").is_position());
    assert!(!t("plane 1 normal").is_position());
    assert_eq!(parse_subject("light 2", &s).unwrap(), Subject::Light(1));
    assert_eq!(
        subject_point(Subject::Object(1), &s),
        DVec3::new(2.0, 0.5, 0.0)
    );
    assert!(parse_subject("sphere", &s).is_err());
}

#[test]
fn camera_targets_write_the_eye_the_look_at_point_and_the_fov() {
    let s = scene();
    let t = |text: &str| Target::parse(text, &s).unwrap();
    let v = DVec3::new(1.0, 2.0, 3.0);
    let mut tracked = s.clone();
    t("camera position").apply(&mut tracked, v);
    assert_eq!(
        (tracked.eye, t("camera position").kind()),
        (v, Kind::Vector)
    );
    t("camera look_at").apply(&mut tracked, -v);
    assert_eq!(tracked.look_at, -v);
    // The report's plane is 0.35 high at distance 1: 2·atan(0.175) = 19.8524…°.
    let fov = t("camera fov");
    assert_eq!(fov.kind(), Kind::Number);
    assert!(
        (fov.read(&s).x - 19.852_491_01).abs() < 1e-6,
        "{}",
        fov.read(&s)
    );
    fov.apply(&mut tracked, DVec3::new(40.0, 0.0, 0.0));
    assert_eq!(
        (tracked.lens.fov, tracked.lens.centres),
        (Some(40.0), false)
    );
    assert_eq!(fov.read(&tracked).x, 40.0);
    // Bounds: a field of view strictly between 0 and 180, finite points.
    assert!(fov.check(DVec3::new(180.0, 0.0, 0.0)).is_err());
    assert!(fov.check(DVec3::new(0.0, 0.0, 0.0)).is_err());
    assert!(t("camera position").check(DVec3::INFINITY).is_err());
    assert!(t("camera look_at").is_position() && !fov.is_position());
    let e = Target::parse("camera eye", &s).unwrap_err();
    assert!(e.contains("expected one of position, look_at, fov"), "{e}");
}

#[test]
fn texture_scale_scales_a_procedural_pattern_only() {
    let s = scene();
    // Sphere 2 has a procedural texture (2 2: Perlin), sphere 1 one colour.
    let t = Target::parse("sphere 2 texture_scale", &s).unwrap();
    assert_eq!((t.field, t.kind()), (Field::TextureScale, Kind::Number));
    assert_eq!(t.read(&s).x, 1.0);
    let mut tracked = s.clone();
    t.apply(&mut tracked, DVec3::new(2.5, 0.0, 0.0));
    assert_eq!(tracked.objects[1].texture.scale(), 2.5);
    assert_eq!(t.read(&tracked).x, 2.5);
    // Colours still reach the pattern under its scale.
    let c1 = Target::parse("sphere 2 color1", &s).unwrap();
    c1.apply(&mut tracked, DVec3::ONE);
    assert_eq!(c1.read(&tracked), DVec3::ONE);
    assert_eq!(tracked.objects[1].texture.scale(), 2.5);
    // Back to 1: the texture of the file, bytes and all.
    t.apply(&mut tracked, DVec3::new(1.0, 0.0, 0.0));
    assert_eq!(tracked.objects[1].texture.scale(), 1.0);
    assert!(t.check(DVec3::ZERO).is_err());
    let e = Target::parse("sphere 1 texture_scale", &s).unwrap_err();
    assert!(e.contains("no pattern to scale"), "{e}");
}
