//! Tracks on the extension's records: numbering after the report's, names, each field
//! written into the record as the file would say it, and the records' joint bounds.

use super::*;
use crate::manifest::Manifest;
use crate::timeline::Timeline;
use std::path::Path;

/// Two report spheres and two report lights, then extension records.
const SCENE: &str = "8 6  0 2 10  0 1 0  0 0  2 0 0 2
1.0  0 1 0   1 0.9 0.1 0.1   0.7 0.3 0 1 0 0
0.5  2 0.5 0   1 0.2 0.2 0.9   0.8 0 0 1 0 0
5 10 5  1 1 1  0.9
-6 8 4  0.6 0.6 0.8  0.6
box -1 0 -1  1 2 1   1 0.8 0.2 0.2  0.7 0 0 1 0 0  name crate
torus 0 1 0  0 1 0  1.2 0.3   1 0.2 0.8 0.2  0.6 0 0 1 0 0
cone 3 0 0 1  3 2 0 0.2   1 0.2 0.3 0.9  0.6 0 0 1 0 0
sphere 0 3 0 0.5   1 1 1 1  0.5 0 0 1 0 0
spot -4 8 6  0 0 0  1 1 1 0.6  15 25 1  fade 10 2
area 4 8 6  1 0 0  0 0 1  4 4  1 1 1 0.5
point 0 9 0  1 1 1 0.4  name lamp
focus 0.2 8 3";

fn scene() -> Scene {
    Scene::parse(SCENE, "t.txt").unwrap()
}

#[test]
fn extension_records_continue_the_reports_numbering_and_take_names() {
    let s = scene();
    let t = |text: &str| Target::parse(text, &s).unwrap_or_else(|e| panic!("{text}: {e}"));
    let ext = |t: Target| match t.field {
        Field::Ext(f) => (f.record, f.name, f.kind),
        other => panic!("{other:?}"),
    };
    // sphere 3 is the first `sphere` record after the report's two: object 5.
    assert_eq!(t("sphere 3 center").index, 5);
    assert_eq!(
        ext(t("sphere 3 center")),
        (Record::Object(3), "center", Kind::Vector)
    );
    assert_eq!(
        ext(t("box 1 max")),
        (Record::Object(0), "max", Kind::Vector)
    );
    assert_eq!(ext(t("crate max")), ext(t("box 1 max")));
    assert_eq!(ext(t("torus 1 minor")).2, Kind::Number);
    assert_eq!(ext(t("cone 1 rb")), (Record::Object(2), "rb", Kind::Number));
    // Lights: light 3 is the `point` record after the report's two; its name too.
    assert_eq!(
        ext(t("light 3 position")),
        (Record::Light(2), "p", Kind::Vector)
    );
    assert_eq!(ext(t("lamp p")), ext(t("light 3 p")));
    assert_eq!(t("light 2 position").field, Field::Position);
    assert_eq!(ext(t("spot 1 falloff")).0, Record::Light(0));
    assert_eq!(ext(t("spot 1 distance")).1, "distance");
    assert_eq!(ext(t("area 1 a1")), (Record::Light(1), "a1", Kind::Vector));
    assert_eq!(
        ext(t("focus distance")),
        (Record::Focus, "distance", Kind::Number)
    );
    // The report's material fields on an extension object.
    assert_eq!((t("box 1 kd").field, t("box 1 kd").index), (Field::Kd, 2));
    assert!(t("box 1 max").moves_geometry() && t("crate translate").is_position());
    assert!(!t("spot 1 falloff").moves_geometry());
    assert_eq!(
        subject_point(parse_subject("lamp", &s).unwrap(), &s),
        DVec3::new(0.0, 9.0, 0.0)
    );
    assert_eq!(
        subject_point(parse_subject("box 1", &s).unwrap(), &s),
        DVec3::new(0.0, 1.0, 0.0)
    );
}

#[test]
fn bad_extension_targets_say_why() {
    let s = scene();
    let err = |text: &str| Target::parse(text, &s).unwrap_err();
    assert!(err("box 2 max").contains("box 2 does not exist: the scene has 1"));
    assert!(
        err("box 1 maxx").contains("did you mean `max`"),
        "{}",
        err("box 1 maxx")
    );
    assert!(err("area 1 n1").contains("expected one of p, position, a1, a2"));
    assert!(err("spto 1 radius").contains("did you mean `spot`"));
    assert!(err("crate").contains("KIND N FIELD"));
    assert!(
        err("lamp power").contains("expected one of"),
        "no fade on the lamp"
    );
    assert!(err("focus samples").contains("expected one of aperture, distance"));
    let plain = Scene::parse(SCENE.split("\nbox").next().unwrap(), "t.txt").unwrap();
    assert!(Target::parse("focus distance", &plain)
        .unwrap_err()
        .contains("no `focus` record"));
}

#[test]
fn an_extension_value_is_written_into_its_record() {
    let n = |x: f64| DVec3::new(x, 0.0, 0.0);
    let cases = [
        (
            "box 1 max",
            DVec3::new(2.0, 3.0, 2.0),
            "1 2 1   1 0.8",
            "2 3 2   1 0.8",
        ),
        ("torus 1 major", n(1.5), "1.2 0.3", "1.5 0.3"),
        ("cone 1 ra", n(0.75), "3 0 0 1  3", "3 0 0 0.75  3"),
        (
            "sphere 3 center",
            DVec3::new(1.0, 2.0, 3.0),
            "0 3 0 0.5",
            "1 2 3 0.5",
        ),
        (
            "crate rotate",
            DVec3::new(0.0, 30.0, 0.0),
            "name crate",
            "name crate rotate 0 30 0",
        ),
        ("spot 1 falloff", n(40.0), "15 25 1", "15 40 1"),
        ("spot 1 power", n(1.0), "fade 10 2", "fade 10 1"),
        (
            "area 1 a1",
            DVec3::new(2.0, 0.0, 0.0),
            "1 0 0  0 0 1",
            "2 0 0  0 0 1",
        ),
        (
            "light 3 position",
            DVec3::new(1.0, 9.0, 1.0),
            "point 0 9 0",
            "point 1 9 1",
        ),
        ("focus distance", n(12.0), "focus 0.2 8", "focus 0.2 12"),
        (
            "box 1 kd",
            n(0.25),
            "0.7 0 0 1 0 0  name",
            "0.25 0 0 1 0 0  name",
        ),
    ];
    for (target, value, from, to) in cases {
        let mut tracked = scene();
        let t = Target::parse(target, &tracked).unwrap();
        assert!(t.check(value).is_ok(), "{target}");
        t.apply(&mut tracked, value);
        assert_eq!(SCENE.matches(from).count(), 1, "{from}");
        let by_hand = Scene::parse(&SCENE.replacen(from, to, 1), "t.txt").unwrap();
        assert_eq!(tracked, by_hand, "{target}");
        assert_eq!(t.read(&tracked), value, "{target}");
    }
}

fn timeline(tracks: &str) -> Result<Timeline, String> {
    let text = format!("scene = \"s.txt\"\nframes = 11\n{tracks}");
    let m = Manifest::parse(&text, Path::new("m.toml")).map_err(|e| e.to_string())?;
    Timeline::new(scene(), &m).map_err(|e| e.to_string())
}

fn keys(target: &str, from: &str, to: &str) -> String {
    format!(
        "[[track]]\ntarget = \"{target}\"\nkeys = [{{ frame = 0, value = {from} }}, {{ frame = 10, value = {to} }}]\n"
    )
}

#[test]
fn a_records_bounds_hold_with_all_its_tracks_at_every_frame() {
    // Min and Max move together and never cross: accepted.
    let both = keys("box 1 min", "[-1.0, 0.0, -1.0]", "[0.0, 1.0, 0.0]")
        + &keys("crate max", "[1.0, 2.0, 1.0]", "[2.0, 3.0, 2.0]");
    let t = timeline(&both).unwrap();
    let moved = t.at(10.0);
    assert_eq!(moved.scene, {
        let s = SCENE.replacen("box -1 0 -1  1 2 1", "box 0 1 0  2 3 2", 1);
        std::borrow::Cow::Owned(Scene::parse(&s, "t.txt").unwrap())
    });
    // Max alone runs below Min on y from frame 6 on: refused at that frame, naming it.
    let e = timeline(&keys("box 1 max", "[1.0, 2.0, 1.0]", "[1.0, -1.0, 1.0]")).unwrap_err();
    assert!(e.contains("track 1 (`box 1 max`): at frame 7"), "{e}");
    assert!(e.contains("Min must be below Max"), "{e}");
    // The tube grows past the ring: the minor radius's track is blamed.
    let e = timeline(&keys("torus 1 minor", "0.3", "1.5")).unwrap_err();
    assert!(
        e.contains("`torus 1 minor`") && e.contains("at frame"),
        "{e}"
    );
    let e = timeline(&keys("spot 1 radius", "15.0", "30.0")).unwrap_err();
    assert!(e.contains("below Falloff"), "{e}");
    let e = timeline(&keys("focus aperture", "0.2", "-0.1")).unwrap_err();
    assert!(e.contains("Aperture must be greater than 0"), "{e}");
}
