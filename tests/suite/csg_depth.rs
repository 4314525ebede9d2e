//! Deeply nested CSG blocks (issue 57, point 2): 5,000 nested `union`s used to overflow
//! the stack (exit 134); the depth is now capped (`limits::MAX_CSG_DEPTH`) with a
//! located error naming the cap, the reader keeps its open blocks on a stack of its own,
//! and a chain of one operation is one flat block, so that 1,000 nested unions cost
//! what their 1,001 spheres cost (the nested tree walked every level for every
//! crossing: 6.4 s for 5,500 rays). The files are generated into a temporary folder.

use crate::common::{entries, raytrace_in, write_file};
use whitted::limits::MAX_CSG_DEPTH;
use whitted::shapes::csg::{Node, Op};
use whitted::shapes::Shape;
use whitted::Scene;

/// A scene of `depth` nested blocks: level d is `ops[d % ops.len()]` over a sphere of
/// radius 1 + d/depth and the block of level d + 1; the innermost holds two spheres.
/// The camera looks at the spheres' common centre.
fn nested(depth: usize, ops: &[&str]) -> String {
    let mut s = String::from("8 6\n0 0 12\n0 0 0\n0 1\n0 0 0 1\n5 5 10  1 1 1  1\n");
    for d in 0..depth {
        let r = 1.0 + d as f64 / depth as f64;
        s += &format!(
            "{}\n  sphere 0 0 0 {r}  1 0.8 0.2 0.2  0.7 0 0 1 0 0\n",
            ops[d % ops.len()]
        );
    }
    s += "  sphere 0 0 0 0.5  1 0.2 0.2 0.8  0.7 0 0 1 0 0\n";
    s += &"end\n".repeat(depth);
    s
}

#[test]
fn five_thousand_nested_unions_are_a_located_error_naming_the_cap() {
    let dir = tempfile::tempdir().unwrap();
    write_file(dir.path(), "deep.txt", nested(5000, &["union"]));
    let out = raytrace_in(dir.path())
        .args(["deep.txt", "-o", "deep.png"])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    // Level d's keyword is on line 7 + 2d: the refused block is level MAX + 1.
    let line = 7 + 2 * MAX_CSG_DEPTH;
    assert!(
        err.contains(&format!("deep.txt:{line}:1: ")),
        "not located at the block past the cap: {err}"
    );
    assert!(
        err.contains(&format!("at most {MAX_CSG_DEPTH} deep")),
        "the cap is not said: {err}"
    );
    assert!(!err.contains("overflow"), "{err}");
    assert_eq!(entries(dir.path()), ["deep.txt"], "an image was written");
}

#[test]
fn the_cap_itself_is_accepted_and_renders() {
    let dir = tempfile::tempdir().unwrap();
    write_file(dir.path(), "cap.txt", nested(MAX_CSG_DEPTH, &["union"]));
    raytrace_in(dir.path())
        .args(["cap.txt", "-o", "cap.png", "--quiet"])
        .assert()
        .success();
    assert!(dir.path().join("cap.png").is_file());
}

#[test]
fn alternating_operations_at_the_cap_render_without_overflowing() {
    // Union over intersection does not flatten: the tree stays MAX deep when traced.
    let dir = tempfile::tempdir().unwrap();
    let src = nested(MAX_CSG_DEPTH, &["union", "intersection", "difference"]);
    write_file(dir.path(), "mixed.txt", src);
    raytrace_in(dir.path())
        .args(["mixed.txt", "-o", "mixed.png", "--quiet", "--threads", "2"])
        .assert()
        .success();
}

/// The solids and blocks of a block's tree, counted level by level: (leaves at the top
/// level, nested blocks at the top level).
fn top_level(scene: &Scene) -> (Op, usize, usize) {
    let Shape::Csg(c) = &scene.objects[0].shape else {
        panic!("the object is not a CSG block");
    };
    let leaves = c
        .children()
        .iter()
        .filter(|n| matches!(n, Node::Leaf(_)))
        .count();
    (c.op(), leaves, c.children().len() - leaves)
}

#[test]
fn a_chain_of_one_operation_is_one_flat_block() {
    // 1,000 nested unions: one union of 1,001 spheres (was 2 children, 999 levels down).
    let scene = Scene::parse(&nested(1000, &["union"]), "u.txt").unwrap();
    assert_eq!(top_level(&scene), (Op::Union, 1001, 0));
    let scene = Scene::parse(&nested(300, &["intersection"]), "i.txt").unwrap();
    assert_eq!(top_level(&scene), (Op::Intersection, 301, 0));
    // A difference joins its parent only as the first child: here the inner block is
    // the second child, so each level keeps its own block.
    let scene = Scene::parse(&nested(3, &["difference"]), "d.txt").unwrap();
    assert_eq!(top_level(&scene), (Op::Difference, 1, 1));
    // …and as the first child, ((a − b) − c) − d is a − b − c − d.
    let src = "8 6\n0 0 12\n0 0 0\n0 1\n0 0 0 1\n5 5 10  1 1 1  1\n\
        difference difference difference\n\
        sphere 0 0 0 2  1 1 0 0  0.7 0 0 1 0 0\n\
        sphere 1 0 0 1  1 0 1 0  0.7 0 0 1 0 0  end\n\
        sphere 0 1 0 1  1 0 0 1  0.7 0 0 1 0 0  end\n\
        sphere 0 0 1 1  1 1 1 0  0.7 0 0 1 0 0  end\n";
    let scene = Scene::parse(src, "f.txt").unwrap();
    assert_eq!(top_level(&scene), (Op::Difference, 4, 0));
}

#[test]
fn a_flattened_chain_draws_what_the_nested_blocks_draw() {
    // ((a ∪ b) ∪ c) with a frame on the inner block and a ∪ b ∪ c with that frame put
    // on a and b by hand: the same picture, byte for byte.
    let head = "24 18\n0 1 8\n0 0 0\n0 1\n0 0 0 1\n5 5 10  1 1 1  1\n";
    let a = "sphere -1 0 0 1  1 0.8 0.2 0.2  0.7 0 0 1 0 0";
    let b = "box 0 -1 -1 1.5 1 1  1 0.2 0.8 0.2  0.7 0 0 1 0 0";
    let c = "sphere 1 1 0 0.7  1 0.2 0.2 0.8  0.7 0 0 1 0 0";
    let nested = format!("{head}union\n union\n  {a}\n  {b}\n end translate 0 0.5 0\n {c}\nend\n");
    let flat = format!("{head}union\n {a} translate 0 0.5 0\n {b} translate 0 0.5 0\n {c}\nend\n");
    let dir = tempfile::tempdir().unwrap();
    write_file(dir.path(), "nested.txt", nested);
    write_file(dir.path(), "flat.txt", flat);
    for name in ["nested", "flat"] {
        raytrace_in(dir.path())
            .args([
                &format!("{name}.txt"),
                "-o",
                &format!("{name}.ppm"),
                "--quiet",
            ])
            .assert()
            .success();
    }
    let read = |n: &str| std::fs::read(dir.path().join(n)).unwrap();
    assert_eq!(read("nested.ppm"), read("flat.ppm"));
}
