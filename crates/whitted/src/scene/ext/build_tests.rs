//! Tests of `build`: hand-made extension records drawn, numbered and named.

use super::*;
use crate::bump::Bump;
use crate::object::{Highlight, Material};
use crate::optics::Ray;
use crate::scene::Scene;
use crate::texture::Texture;

fn record(shape: ShapeSpec, mods: Modifiers) -> ExtItem {
    ExtItem::Shape(ExtObject {
        shape,
        texture: Texture::Uniform(DVec3::ONE),
        material: Material {
            kd: 1.0,
            kr: 0.0,
            kt: 0.0,
            ior: 1.0,
            bump: Bump::None,
            highlight: Highlight::Report,
        },
        mods,
        loc: FileLoc {
            file: "s.txt".into(),
            line: 9,
            column: 1,
        },
    })
}

fn named(name: &str) -> Modifiers {
    Modifiers {
        name: Some(name.into()),
        ..Modifiers::default()
    }
}

#[test]
fn a_moved_box_is_hit_where_it_was_moved() {
    let mods = Modifiers {
        translate: Some(DVec3::new(0.0, 0.0, -10.0)),
        ..Modifiers::default()
    };
    let ext = Extension {
        objects: vec![record(
            ShapeSpec::Box {
                min: DVec3::splat(-1.0),
                max: DVec3::splat(1.0),
            },
            mods,
        )],
        ..Extension::default()
    };
    let built = objects(&ext).unwrap().objects;
    let (obj, spec) = &built[0];
    assert_eq!(spec.kind(), "box");
    assert_eq!(spec.anchor(), DVec3::new(0.0, 0.0, -10.0));
    // From the origin down −z: the face z = −9 at t = 9, normal +z.
    let ray = Ray::new(DVec3::ZERO, -DVec3::Z);
    assert_eq!(obj.shape.hit(&ray, f64::INFINITY), Some(9.0));
    assert_eq!(obj.shape.normal(DVec3::new(0.0, 0.0, -9.0)), DVec3::Z);
}

#[test]
fn plain_spheres_stay_spheres_and_open_drops_caps() {
    let ext = Extension {
        objects: vec![
            record(
                ShapeSpec::Sphere {
                    center: DVec3::ZERO,
                    radius: 1.0,
                },
                Modifiers::default(),
            ),
            record(
                ShapeSpec::Cylinder {
                    a: DVec3::ZERO,
                    b: DVec3::Y,
                    radius: 1.0,
                },
                Modifiers {
                    open: true,
                    ..Modifiers::default()
                },
            ),
        ],
        ..Extension::default()
    };
    let built = objects(&ext).unwrap().objects;
    assert!(matches!(built[0].0.shape, Shape::Sphere(_)));
    // Open: straight down the axis meets nothing.
    let ray = Ray::new(DVec3::new(0.0, 5.0, 0.0), -DVec3::Y);
    assert_eq!(built[1].0.shape.hit(&ray, f64::INFINITY), None);
}

#[test]
fn numbering_continues_the_reports_and_names_replace_it() {
    let mut scene = Scene::parse(
        "10 10\n0 0 5\n0 0 0\n0 0\n1 0 0 1\n1 0 0 0 1 1 1 1 1 0 0 1 0 0\n0 5 5 1 1 1 1\n",
        "s.txt",
    )
    .unwrap();
    scene.ext.objects = vec![
        record(
            ShapeSpec::Sphere {
                center: DVec3::X,
                radius: 1.0,
            },
            Modifiers::default(),
        ),
        record(
            ShapeSpec::Torus {
                center: DVec3::ZERO,
                axis: DVec3::Y,
                major: 2.0,
                minor: 0.5,
            },
            named("ring"),
        ),
        record(
            ShapeSpec::Sphere {
                center: DVec3::Y,
                radius: 1.0,
            },
            Modifiers::default(),
        ),
    ];
    for (o, s) in objects(&scene.ext).unwrap().objects {
        scene.objects.push(o);
        scene.specs.push(s);
    }
    let names: Vec<String> = scene.object_names().collect();
    assert_eq!(names, ["sphere 1", "sphere 2", "ring", "sphere 3"]);
}

#[test]
fn unbuilt_records_are_located_errors() {
    let ext = Extension {
        objects: vec![record(
            ShapeSpec::Mesh {
                path: "m.obj".into(),
                written: "m.obj".into(),
            },
            Modifiers::default(),
        )],
        ..Extension::default()
    };
    let err = objects(&ext).unwrap_err();
    assert_eq!(err.loc().map(|l| l.line), Some(9));
    assert!(err.to_string().contains("mesh"), "{err}");
}

#[test]
fn the_tree_finds_what_a_linear_scan_finds() {
    // A row of tori, boxes and cones, turned and moved: every ray's nearest hit from the
    // BVH is the linear scan's (smallest t, then the first object).
    let mut items = Vec::new();
    for i in 0..12 {
        let x = f64::from(i) * 1.5 - 9.0;
        let mods = Modifiers {
            rotate: Some(DVec3::new(f64::from(i) * 17.0, f64::from(i) * 29.0, 5.0)),
            translate: Some(DVec3::new(x, 0.0, -6.0)),
            ..Modifiers::default()
        };
        let shape = match i % 3 {
            0 => ShapeSpec::Torus {
                center: DVec3::ZERO,
                axis: DVec3::Y,
                major: 0.6,
                minor: 0.2,
            },
            1 => ShapeSpec::Box {
                min: DVec3::splat(-0.4),
                max: DVec3::splat(0.4),
            },
            _ => ShapeSpec::Cone {
                a: DVec3::ZERO,
                ra: 0.5,
                b: DVec3::Y,
                rb: 0.1,
            },
        };
        items.push(record(shape, mods));
    }
    let ext = Extension {
        objects: items,
        ..Extension::default()
    };
    let objs: Vec<Object> = objects(&ext)
        .unwrap()
        .objects
        .into_iter()
        .map(|(o, _)| o)
        .collect();
    let accel = crate::accel::Accel::new(&objs);
    let mut hits = 0;
    for k in 0..400 {
        let a = f64::from(k) * 0.0157;
        let dir = DVec3::new(a.sin() * 0.9, (a * 3.1).cos() * 0.03, -1.0).normalize();
        let ray = Ray::new(DVec3::new(0.0, 0.0, 2.0), dir);
        let mut best: Option<(f64, usize)> = None;
        for (i, o) in objs.iter().enumerate() {
            if let Some(t) = o.shape.hit(&ray, f64::INFINITY) {
                if best.is_none_or(|(b, _)| t < b) {
                    best = Some((t, i));
                }
            }
        }
        hits += usize::from(best.is_some());
        assert_eq!(accel.nearest(&ray), best, "ray {k}");
    }
    assert!(hits > 50, "only {hits} rays hit");
}

/// A report part with no object and one light, then `rest`.
fn with_ext(rest: &str) -> Scene {
    let src = format!("8 6\n0 0 10\n0 0 0\n0 0\n0 0 0 1\n5 5 5 1 1 1 1\n{rest}");
    Scene::parse(&src, "s.txt").unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn a_csg_block_is_one_object_in_its_frame_shaded_by_the_child_hit() {
    // The unit ball minus the box x ≥ 0, moved to z = −10; then an unnamed union.
    let scene = with_ext(
        "difference\n\
           sphere 0 0 0 1  1 1 0 0  1 0 0 1 0 0\n\
           box 0 -2 -2 2 2 2  1 0 1 0  1 0 0 1 0 0\n\
         end name bowl translate 0 0 -10\n\
         union\n\
           sphere 0 5 0 1  1 1 1 1  1 0 0 1 0 0\n\
           intersection sphere 0 6 0 1 1 1 1 1 1 0 0 1 0 0 plane 0 6 0 0 1 0 1 1 1 1 1 0 0 1 0 0 end\n\
         end\n",
    );
    assert_eq!(scene.objects.len(), 2);
    let names: Vec<String> = scene.object_names().collect();
    // Numbered in file order, the named block counting: the second is `csg 2`.
    assert_eq!(names, ["bowl", "csg 2"]);
    assert_eq!(scene.specs[0].anchor(), DVec3::new(0.0, 0.0, -10.0));
    // From +x towards the block: the cut face x = 0 at t = 5, green, normal +x.
    let tracer = crate::trace::Tracer::new(&scene);
    let ray = Ray::new(DVec3::new(5.0, 0.0, -10.0), -DVec3::X).with_t_min(scene.t_min);
    let (t, i) = tracer.nearest_index(&ray).unwrap();
    assert_eq!((t, i), (5.0, 0));
    let (leaf, n) = crate::trace::surface_at(&scene.objects[i], &ray, ray.at(t));
    assert_eq!(n, DVec3::X);
    assert_eq!(leaf.texture, Texture::Uniform(DVec3::new(0.0, 1.0, 0.0)));
    // From −x: the ball's red side at x = −1.
    let ray = Ray::new(DVec3::new(-5.0, 0.0, -10.0), DVec3::X).with_t_min(scene.t_min);
    let (leaf, n) = crate::trace::surface_at(&scene.objects[0], &ray, ray.at(4.0));
    assert_eq!(
        (n, leaf.texture.clone()),
        (-DVec3::X, Texture::Uniform(DVec3::X))
    );
    // The union's nested half ball (y ≤ 6) is capped by the plane: from above at x = 0
    // the upper ball's top y = 6 is cut, the flat cap is at y = 6 too, then nothing
    // above the lower ball's top at 6: the first hit is at y = 6 (t = 4).
    let ray = Ray::new(DVec3::new(0.0, 10.0, 0.0), -DVec3::Y);
    assert_eq!(scene.objects[1].shape.hit(&ray, f64::INFINITY), Some(4.0));
}

#[test]
fn a_shell_inside_a_block_is_refused_where_it_is_written() {
    let src = "8 6\n0 0 10\n0 0 0\n0 0\n0 0 0 1\n5 5 5 1 1 1 1\n\
               union\n sphere 0 0 0 1 1 1 1 1 1 0 0 1 0 0\n\
               cylinder 0 0 0 0 1 0 1 1 1 1 1 1 0 0 1 0 0 open\nend\n";
    let e = Scene::parse(src, "s.txt").unwrap_err();
    let loc = e.loc().unwrap();
    assert_eq!((loc.line, loc.column), (9, 1), "{e}");
}
