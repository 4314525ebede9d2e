//! The extension reader on hand-written files: what each record reads to, and where each
//! kind of mistake is reported.

use crate::scene::ext::{ExtItem, LightKind};
use crate::scene::ShapeSpec;
use crate::scene::{Scene, SceneError};
use crate::shapes::csg::Op;
use glam::DVec3;

/// The report's part of a file: one sphere and one light, then `rest`.
fn file(rest: &str) -> String {
    format!("8 6\n0 0 10\n0 0 0\n0 0\n1 0 0 1\n1 0 0 0 1 1 1 1 1 0 0 1 0 0\n5 5 5 1 1 1 1\n{rest}")
}

fn parse(rest: &str) -> Scene {
    crate::scene::parser::read(&file(rest), "dir/s.txt").unwrap_or_else(|e| panic!("{e}"))
}

/// The error's text and its line:column.
fn error(rest: &str) -> (String, usize, usize) {
    match Scene::parse(&file(rest), "s.txt") {
        Err(e @ SceneError::Syntax { .. }) => {
            let loc = e.loc().expect("located").clone();
            (e.to_string(), loc.line, loc.column)
        }
        other => panic!("expected a syntax error, got {other:?}"),
    }
}

const T: &str = "1 1 0 0  0.7 0 0 1 0 0";

#[test]
fn every_shape_record_reads_its_fields_in_order() {
    let src = format!(
        "box -1 0 -1 1 2 1 {T} name crate rotate 0 45 0\n\
         cylinder 0 0 0 0 2 0 0.5 {T} open\n\
         cone 0 0 0 1 0 3 0 0.25 {T}\n\
         disc 0 0 0 0 1 0 2 0.5 {T}\n\
         torus 0 1 0 0 1 0 2 0.5 {T}\n\
         triangle 0 0 0 1 0 0 0 1 0 {T}\n\
         sphere 1 2 3 4 {T}\n\
         mesh \"models/tea pot.obj\" {T} scale 2 2 2\n"
    );
    let scene = parse(&src);
    let o = &scene.ext.objects;
    assert_eq!(o.len(), 8);
    let ExtItem::Shape(b) = &o[0] else { panic!() };
    assert_eq!(
        b.shape,
        ShapeSpec::Box {
            min: DVec3::new(-1.0, 0.0, -1.0),
            max: DVec3::new(1.0, 2.0, 1.0)
        }
    );
    assert_eq!(b.mods.name.as_deref(), Some("crate"));
    assert_eq!(b.mods.rotate, Some(DVec3::new(0.0, 45.0, 0.0)));
    assert_eq!((b.loc.line, b.loc.column), (8, 1));
    let ExtItem::Shape(c) = &o[1] else { panic!() };
    assert!(c.mods.open);
    let ExtItem::Shape(k) = &o[2] else { panic!() };
    assert_eq!(
        k.shape,
        ShapeSpec::Cone {
            a: DVec3::ZERO,
            ra: 1.0,
            b: DVec3::new(0.0, 3.0, 0.0),
            rb: 0.25
        }
    );
    let ExtItem::Shape(s) = &o[6] else { panic!() };
    assert_eq!(
        s.shape,
        ShapeSpec::Sphere {
            center: DVec3::new(1.0, 2.0, 3.0),
            radius: 4.0
        }
    );
    let ExtItem::Shape(m) = &o[7] else { panic!() };
    let ShapeSpec::Mesh { path, written } = &m.shape else {
        panic!()
    };
    assert_eq!(written, "models/tea pot.obj");
    assert_eq!(
        path,
        &std::path::Path::new("dir").join("models/tea pot.obj")
    );
    // The report's part is untouched.
    assert_eq!(scene.objects.len(), 1);
    assert_eq!(scene.lights.len(), 1);
}

#[test]
fn csg_blocks_nest_and_take_modifiers_after_end() {
    let src = format!(
        "difference\n sphere 0 1 0 1 {T}\n union\n  box -2 1 -2 2 3 2 {T}\n  cylinder 0 0 0 0 3 0 0.2 {T}\n end\nend name bowl translate 0 1 0\n"
    );
    let scene = parse(&src);
    let [ExtItem::Csg(csg)] = &scene.ext.objects[..] else {
        panic!()
    };
    assert_eq!(csg.op, Op::Difference);
    assert_eq!(csg.children.len(), 2);
    assert!(
        matches!(&csg.children[1], ExtItem::Csg(u) if u.op == Op::Union && u.children.len() == 2)
    );
    assert_eq!(csg.mods.name.as_deref(), Some("bowl"));
    assert_eq!(csg.mods.translate, Some(DVec3::Y));
}

#[test]
fn light_records_and_focus() {
    let src = "directional 0 -1 0 1 1 1 0.5\n\
               spot 0 5 0 0 0 0 1 0.5 0 1 20 30 2 name key fade 10 2\n\
               point 1 2 3 1 1 1 1\n\
               area 0 6 0 2 0 0 0 0 2 4 2 1 1 1 1\n\
               focus 0.2 8 3\n";
    let scene = parse(src);
    let l = &scene.ext.lights;
    assert_eq!(l.len(), 4);
    assert_eq!(
        l[0].kind,
        LightKind::Directional {
            direction: -DVec3::Y
        }
    );
    assert_eq!(l[0].intensity, 0.5);
    assert_eq!(
        l[1].kind,
        LightKind::Spot {
            position: DVec3::new(0.0, 5.0, 0.0),
            target: DVec3::ZERO,
            radius: 20.0,
            falloff: 30.0,
            tightness: 2.0
        }
    );
    assert_eq!(l[1].color, DVec3::new(1.0, 0.5, 0.0));
    assert_eq!(l[1].mods.fade, Some((10.0, 2.0)));
    assert!(matches!(l[3].kind, LightKind::Area { n1: 4, n2: 2, .. }));
    let f = scene.ext.focus.expect("focus");
    assert_eq!((f.aperture, f.distance, f.samples), (0.2, 8.0, 3));
}

#[test]
fn an_unknown_keyword_is_located_with_the_nearest_one() {
    let (msg, line, column) = error(&format!("  bxo -1 0 -1 1 2 1 {T}\n"));
    assert_eq!((line, column), (8, 3));
    assert!(
        msg.contains("unknown keyword 'bxo'") && msg.contains("did you mean 'box'?"),
        "{msg}"
    );
    let (msg, line, column) = error(&format!("box 0 0 0 1 1 1 {T} 7\n"));
    assert_eq!((line, column), (8, 40), "{msg}");
    assert!(
        msg.contains("found the number '7' (a surplus field"),
        "{msg}"
    );
    let (msg, ..) = error("frobnicate\n");
    assert!(msg.contains("extension records start with"), "{msg}");
}

#[test]
fn bounds_are_reported_at_the_field_to_blame() {
    let (msg, line, column) = error(&format!("box 0 0 0 1 0 1 {T}\n"));
    assert_eq!((line, column), (8, 11), "{msg}");
    assert!(msg.contains("on y") && msg.contains("box 1"), "{msg}");
    let (msg, _, column) = error(&format!("torus 0 0 0 0 1 0 1 1 {T}\n"));
    assert_eq!(column, 21, "{msg}");
    let (msg, _, column) = error(&format!("triangle 0 0 0 1 0 0 2 0 0 {T}\n"));
    assert!(msg.contains("degenerate") && column == 22, "{msg}");
    let (msg, _, column) = error("spot 0 5 0 0 0 0 1 1 1 1 30 30 1\n");
    assert!(
        msg.contains("Radius (30) must be below Falloff") && column == 29,
        "{msg}"
    );
    let (msg, ..) = error("area 0 6 0 2 0 0 0 0 2 0 4 1 1 1 1\n");
    assert!(msg.contains("N1") && msg.contains("from 1 to 64"), "{msg}");
    let (msg, _, column) = error("focus 0 8 3\n");
    assert!(
        msg.contains("Aperture must be greater than 0") && column == 7,
        "{msg}"
    );
    let (msg, _, column) = error(&format!("sphere 0 0 0 1 {T} scale 1 0 1\n"));
    assert!(msg.contains("scale cannot be 0") && column > 30, "{msg}");
}

#[test]
fn modifier_mistakes() {
    let (msg, ..) = error("directional 0 -1 0 1 1 1 1 fade 5 2\n");
    assert!(
        msg.contains("fade does not apply to a directional light"),
        "{msg}"
    );
    let (msg, ..) = error(&format!("box 0 0 0 1 1 1 {T} open\n"));
    assert!(msg.contains("'open' does not apply to a box"), "{msg}");
    let (msg, ..) = error(&format!(
        "box 0 0 0 1 1 1 {T} translate 1 0 0 translate 2 0 0\n"
    ));
    assert!(msg.contains("given twice"), "{msg}");
    let (msg, line, _) = error(&format!(
        "box 0 0 0 1 1 1 {T} name a\nsphere 0 0 0 1 {T} name a\n"
    ));
    assert!(
        msg.contains("already given on line 8") && line == 9,
        "{msg}"
    );
    let (msg, ..) = error(&format!("box 0 0 0 1 1 1 {T} name torus\n"));
    assert!(msg.contains("'torus' is a keyword"), "{msg}");
}

#[test]
fn csg_mistakes() {
    let (msg, line, _) = error(&format!(
        "union\n sphere 0 0 0 1 {T}\n box 0 0 0 1 1 1 {T}\n"
    ));
    assert!(
        msg.contains("has no 'end'") && msg.contains("line 8") && line == 11,
        "{msg}"
    );
    let (msg, ..) = error(&format!("union sphere 0 0 0 1 {T} end\n"));
    assert!(msg.contains("two or more"), "{msg}");
    let (msg, ..) = error(&format!(
        "union sphere 0 0 0 1 {T} disc 0 0 0 0 1 0 1 0 {T} end\n"
    ));
    assert!(msg.contains("a disc is not a solid"), "{msg}");
    let (msg, ..) = error(&format!(
        "union sphere 0 0 0 1 {T} cylinder 0 0 0 0 1 0 1 {T} open end\n"
    ));
    assert!(msg.contains("an open cylinder is not a solid"), "{msg}");
    let (msg, ..) = error(&format!(
        "union sphere 0 0 0 1 {T} name a box 0 0 0 1 1 1 {T} end\n"
    ));
    assert!(msg.contains("takes no name"), "{msg}");
    let (msg, ..) = error(&format!("union sphere 0 0 0 1 {T} focus 1 1 1 end\n"));
    assert!(
        msg.contains("expected a solid, a CSG block or 'end'"),
        "{msg}"
    );
}

#[test]
fn quoted_file_names_are_checked() {
    let (msg, ..) = error(&format!("mesh teapot.obj {T}\n"));
    assert!(msg.contains("expected a quoted file name"), "{msg}");
    let (msg, ..) = error(&format!("mesh \"teapot.obj {T}\n"));
    assert!(msg.contains("not closed"), "{msg}");
}

#[test]
fn a_number_after_the_last_light_still_blames_the_counts() {
    let (msg, ..) = error("1 2 3 1 1 1 1\n");
    assert!(msg.contains("the counts announce 1 light"), "{msg}");
}
