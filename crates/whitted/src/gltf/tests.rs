//! The reader on the Khronos samples and the generated files kept in tests/data/gltf
//! (their licences are in tests/data/gltf/LICENSE.md), with values worked out by hand
//! from the files' JSON and buffers.

use super::*;
use glam::DVec3;
use std::path::PathBuf;

fn sample(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../tests/data/gltf")
        .join(name)
}

fn model(name: &str) -> Result<Model, GltfError> {
    let path = sample(name);
    let bytes = std::fs::read(&path).unwrap();
    Model::read(&path, &bytes, Options::default())
}

fn close(a: DVec3, b: DVec3) -> bool {
    (a - b).length() < 1e-6
}

#[test]
fn box_reads_its_24_vertices_and_12_triangles() {
    let m = model("Box.gltf").unwrap();
    let prim = &m.rig.meshes[0][0];
    assert_eq!(prim.positions.len(), 24);
    assert_eq!(prim.normals.len(), 24);
    assert_eq!(prim.triangles.len(), 12);
    // The root turns −90° about x: the ±0.5 box stays the ±0.5 box.
    let scene = m.scene_at(0.0, &[], &[]).unwrap();
    let (lo, hi) = scene.meshes[0].extent();
    assert!(close(lo, DVec3::splat(-0.5)) && close(hi, DVec3::splat(0.5)));
    // No node name: known by its number; one default light, since the file has none.
    assert_eq!(scene.object_names().collect::<Vec<_>>(), ["gltf 1"]);
    assert_eq!(scene.ext.lights.len(), 1);
    assert!(scene.linear);
}

#[test]
fn a_zero_normal_makes_its_primitive_flat_with_a_warning() {
    // Box with its first normal zeroed: flat (no normals kept), not smoothed at 30°.
    let m = model("Box.gltf").unwrap();
    let mut rig = (*m.rig).clone();
    rig.meshes[0][0].normals[0] = DVec3::ZERO;
    let m = Model {
        rig: std::sync::Arc::new(rig),
        ..m
    };
    let scene = m.scene_at(0.0, &[], &[]).unwrap();
    let mesh = &scene.meshes[0];
    assert!(mesh.normals.is_empty());
    assert_eq!((mesh.vertices.len(), mesh.triangles.len()), (24, 12));
    assert!(mesh.warnings.iter().any(|w| w
        .ends_with("meshes[0].primitives[0] has a zero or non-finite normal; it is drawn flat")));
}

#[test]
fn a_sparse_accessor_replaces_its_three_positions() {
    let m = model("SimpleSparseAccessor.gltf").unwrap();
    let p = &m.rig.meshes[0][0].positions;
    // The base holds (i mod 7, i div 7, 0); indices 8, 10, 12 become (1, 2), (3, 3), (5, 4).
    assert_eq!(p[7], DVec3::new(0.0, 1.0, 0.0));
    assert_eq!(p[8], DVec3::new(1.0, 2.0, 0.0));
    assert_eq!(p[10], DVec3::new(3.0, 3.0, 0.0));
    assert_eq!(p[12], DVec3::new(5.0, 4.0, 0.0));
    assert_eq!(p[13], DVec3::new(6.0, 1.0, 0.0));
}

#[test]
fn linear_blend_skinning_by_hand() {
    // At t = 1 s joint 2 is turned 90° about z about (0, 1, 0); both inverse binds are
    // T(0, −1, 0). Vertex 4, (−0.5, 1, 0), weighs ½ on each joint: ½·(−0.5, 1, 0) +
    // ½·(0, 0.5, 0) = (−0.25, 0.75, 0). Vertex 0 follows joint 1 alone and stays.
    let m = model("SimpleSkin.gltf").unwrap();
    let scene = m.scene_at(1.0, &m.all_clips(), &[]).unwrap();
    let v = &scene.meshes[0].vertices;
    assert!(close(v[4], DVec3::new(-0.25, 0.75, 0.0)), "{:?}", v[4]);
    assert!(close(v[0], DVec3::new(-0.5, 0.0, 0.0)), "{:?}", v[0]);
    // At rest (no animation) the mesh is where the file puts it.
    let rest = m.scene_at(1.0, &[], &[]).unwrap();
    assert!(close(
        rest.meshes[0].vertices[4],
        DVec3::new(-0.5, 1.0, 0.0)
    ));
}

#[test]
fn morph_targets_take_the_mesh_weights_then_the_animation() {
    // Vertex 2 is (0.5, 0.5, 0); the targets move it by (−1, 1, 0) and (1, 1, 0); the
    // mesh's weights are ½ and ½: (0.5, 1.5, 0).
    let m = model("SimpleMorph.gltf").unwrap();
    let still = m.scene_at(0.0, &[], &[]).unwrap();
    assert!(close(
        still.meshes[0].vertices[2],
        DVec3::new(0.5, 1.5, 0.0)
    ));
    // With the animation, the channel's own weights at t.
    let clip = &m.rig.clips[0];
    for t in [0.5, 1.5, 2.5] {
        let w = clip.channels[0].sample(t);
        let want = DVec3::new(0.5, 0.5, 0.0)
            + w[0] * DVec3::new(-1.0, 1.0, 0.0)
            + w[1] * DVec3::new(1.0, 1.0, 0.0);
        let moved = m.scene_at(t, &[0], &[]).unwrap();
        assert!(close(moved.meshes[0].vertices[2], want), "t = {t}");
    }
}

#[test]
fn primitives_are_named_by_their_node_and_strips_and_fans_cut() {
    let m = model("generated/two_primitives.glb").unwrap();
    let scene = m.scene_at(0.0, &[], &[]).unwrap();
    let names: Vec<String> = scene.object_names().collect();
    // The second "Wheel" node's name is used twice: its primitives go by number.
    assert_eq!(names, ["Wheel", "Wheel#2", "gltf 3", "gltf 4", "Mirror"]);
    // A strip of 4 corners is 2 triangles, a fan of 5 is 3.
    assert_eq!(m.rig.meshes[0][0].triangles.len(), 2);
    assert_eq!(m.rig.meshes[0][1].triangles.len(), 3);
    assert!(scene.meshes[0].warnings.iter().any(|w| w.contains("Wheel")));
}

#[test]
fn a_mirroring_node_turns_its_triangles() {
    let m = model("generated/two_primitives.glb").unwrap();
    let scene = m.scene_at(0.0, &[], &[]).unwrap();
    let mirror = scene.meshes.last().unwrap();
    let file = &m.rig.meshes.last().unwrap()[0].triangles;
    assert_eq!(mirror.triangles[0], [file[0][0], file[0][2], file[0][1]]);
}

#[test]
fn cameras_frame_by_their_node_and_aspect() {
    let m = model("Cameras.gltf").unwrap();
    let scene = m.scene_at(0.0, &[], &[]).unwrap();
    // The first camera: at (0.5, 0.5, 3) looking down −z, yfov 0.7 rad, aspect 1.
    assert_eq!(scene.eye, DVec3::new(0.5, 0.5, 3.0));
    assert!(close(scene.look_at, DVec3::new(0.5, 0.5, 2.0)));
    assert_eq!((scene.width, scene.height), (480, 480));
    // yfov is stored as an f32: 0.7 to within its rounding.
    assert!((scene.lens.fov.unwrap() - 0.7f64.to_degrees()).abs() < 1e-5);
    let e = scene.through_camera("nothing").unwrap_err();
    assert!(e.contains("camera 1") && e.contains("camera 2"), "{e}");
}

#[test]
fn hostile_files_are_refused_at_their_json_path() {
    let cases = [
        ("bad/missing_buffer.gltf", "nothere.bin"),
        ("bad/index_past.gltf", "the index 7 is past the 3"),
        ("bad/nan_position.gltf", "not a finite number"),
        ("bad/huge_count.gltf", "accessors[0].count"),
        ("bad/climbs.gltf", "buffers[0].uri"),
        ("bad/requires_unknown.gltf", "KHR_draco_mesh_compression"),
        ("bad/cycle.gltf", "node 0"),
    ];
    for (file, want) in cases {
        let e = model(file).unwrap_err().to_string();
        assert!(e.contains(want), "{file}: {e}");
    }
    let m = model("bad/skin_joint_outside.gltf").unwrap();
    let e = m.scene_at(0.0, &[], &[]).unwrap_err().to_string();
    assert!(e.contains("skins[0].joints"), "{e}");
}

#[test]
fn frames_run_to_the_last_key_both_ends_included() {
    let m = model("generated/interpolation.gltf").unwrap();
    // Keys to t = 2 s: at 4 fps 9 frames; looped, 8; at 24 fps, 49.
    let all = m.all_clips();
    assert_eq!(m.frames(&all, 4.0, false), 9);
    assert_eq!(m.frames(&all, 4.0, true), 8);
    assert_eq!(m.frames(&all, 24.0, false), 49);
    assert_eq!(m.select(Some(&["Spin".to_string()])).unwrap(), vec![1]);
    let e = m.select(Some(&["Walk".to_string()])).unwrap_err();
    assert!(e.contains("Move, Spin"), "{e}");
}

/// The Khronos triangle turned 180° about y (its back to the camera), with a material
/// `doubleSided` or not: the centre pixel's colour.
fn back_of_triangle(double_sided: bool) -> [u8; 3] {
    let text = std::fs::read_to_string(sample("Triangle.gltf")).unwrap();
    let mut json: serde_json::Value = serde_json::from_str(&text).unwrap();
    json["nodes"][0]["rotation"] = serde_json::json!([0.0, 1.0, 0.0, 0.0]);
    json["materials"] = serde_json::json!([{ "doubleSided": double_sided }]);
    json["meshes"][0]["primitives"][0]["material"] = serde_json::json!(0);
    let bytes = json.to_string().into_bytes();
    let m = Model::read(&sample("Triangle.gltf"), &bytes, Options::default()).unwrap();
    let scene = m.scene_at(0.0, &[], &[]).unwrap();
    let tracer = crate::trace::Tracer::new(&scene);
    let (w, h) = (scene.width, scene.height);
    let grid = crate::render::Options::grid(w, h, 1);
    let (frame, _) = crate::render(
        &tracer,
        &scene.camera(),
        &grid,
        crate::render::Picture::new(),
    );
    // The view is centred on the turned triangle's box, (−0.5, 0.5); its centroid,
    // (−1/3, 1/3), lies right of and below that centre.
    let i = ((h / 2 + 20) * w + w / 2 + 40) as usize * 3;
    [frame.pixels[i], frame.pixels[i + 1], frame.pixels[i + 2]]
}

#[test]
fn camera_rays_do_not_see_the_back_of_a_single_sided_material() {
    assert_ne!(back_of_triangle(true), [0, 0, 0]);
    assert_eq!(back_of_triangle(false), [0, 0, 0]);
}

#[test]
fn a_joint_number_past_its_skin_is_refused() {
    // SimpleSkin's vertices use joints 0 and 1; a skin of one joint has no joint 1.
    let text = std::fs::read_to_string(sample("SimpleSkin.gltf")).unwrap();
    let mut json: serde_json::Value = serde_json::from_str(&text).unwrap();
    json["skins"][0]["joints"] = serde_json::json!([1]);
    json["skins"][0]
        .as_object_mut()
        .unwrap()
        .remove("inverseBindMatrices");
    let bytes = json.to_string().into_bytes();
    let m = Model::read(&sample("SimpleSkin.gltf"), &bytes, Options::default()).unwrap();
    let e = m.scene_at(0.0, &[], &[]).unwrap_err().to_string();
    assert!(
        e.contains("meshes[0].primitives[0].attributes.JOINTS_0"),
        "{e}"
    );
    assert!(e.contains("joint 1 is past the 1 joints"), "{e}");
}

#[test]
fn alpha_modes_cutoffs_and_vertex_alpha_are_read() {
    use crate::mesh::extra::AlphaMode;
    let m = model("generated/alpha_blend.gltf").unwrap();
    let x = &m.rig.extras;
    // Factors and the cutoff are f32 in the file.
    assert_eq!((x[0].mode, x[0].factor), (AlphaMode::Blend, 1.0));
    assert_eq!(
        (x[1].mode, x[1].factor),
        (AlphaMode::Blend, f64::from(0.8f32))
    );
    assert_eq!(x[2].mode, AlphaMode::Mask(f64::from(0.3f32)));
    // The default material is opaque.
    assert_eq!(x.last().unwrap().mode, AlphaMode::Opaque);
    // COLOR_0 is RGBA: its alpha kept apart, its RGB the colour.
    let prim = &m.rig.meshes[1][0];
    assert_eq!(prim.alphas, [0.5; 4]);
    assert_eq!(prim.colors[0], DVec3::ONE);
    let scene = m.scene_at(0.0, &[], &[]).unwrap();
    let extra = scene.meshes[1].extra.as_ref().unwrap();
    assert!(extra.texture.as_ref().unwrap().pixels.has_alpha());
    assert_eq!(extra.vertex.len(), 4);
    // In the left half of "Blend" (inside its first triangle): 0.8 × 1 × 0.5.
    let p = DVec3::new(-0.3, -0.6, 0.0);
    assert!((scene.meshes[1].alpha_at(0, p) - 0.4).abs() < 1e-7);
    // No warning for MASK or BLEND any more.
    assert!(m.rig.warnings.iter().all(|w| !w.contains("alphaMode")));
}

#[test]
fn an_emissive_texture_is_read_on_its_coordinate_set() {
    let m = model("generated/emissive.gltf").unwrap();
    // "Glow": the texture on TEXCOORD_1, the factor (1, 0.5, 0.25) × strength 2; its
    // Pbr emission is left to the texture's hits. "Lit": the factor alone.
    let (_, factor, set) = m.rig.extras[0].emissive.clone().unwrap();
    assert_eq!((factor, set), (DVec3::new(2.0, 1.0, 0.5), 1));
    assert_eq!(m.rig.pbr[0].emission, DVec3::ZERO);
    let lit = m.rig.pbr[1].emission;
    assert!(close(lit, DVec3::new(0.1, 0.2, 0.3)));
    // TEXCOORD_1 mirrors TEXCOORD_0's u; v is flipped in both.
    let prim = &m.rig.meshes[0][0];
    assert_eq!(prim.uvs[0][0], [0.0, 0.0]);
    assert_eq!(prim.uvs[1][0], [1.0, 0.0]);
    let scene = m.scene_at(0.0, &[], &[]).unwrap();
    let glow = &scene.meshes[0];
    assert_eq!(
        glow.extra.as_ref().unwrap().emissive.as_ref().unwrap().uvs,
        prim.uvs[1]
    );
    // At x = −1.225 (u = 0.25 on TEXCOORD_0, 0.75 on TEXCOORD_1) the right texel,
    // (128, 64, 255) decoded: 2 × 0.2158605 in red (y = −0.6: the first triangle).
    let e = glow.emission_at(0, DVec3::new(-1.225, -0.6, 0.0));
    assert!((e.x - 2.0 * 0.215_860_5).abs() < 1e-6, "{e}");
}

/// Where the shadow ray from the floor (y = −1) of alpha_modes.gltf towards its sun
/// crosses the quads' plane z = 0 at `(x, y)`: the light it lets through, the same on
/// both of the accelerator's shadow walks (three transparent objects: the linear loop;
/// with four glass spheres no ray meets, seven: the collecting walk).
fn shadow_through(x: f64, y: f64) -> crate::base::Color {
    let few = shadow_with(x, y, 0);
    assert_eq!(
        few,
        shadow_with(x, y, 4),
        "the two walks differ at ({x}, {y})"
    );
    few
}

fn shadow_with(x: f64, y: f64, far: usize) -> crate::base::Color {
    use crate::lights::punctual::Shape;
    use crate::scene::ext::LightKind;
    let m = model("generated/alpha_modes.gltf").unwrap();
    let mut scene = m.scene_at(0.0, &[], &[]).unwrap();
    for k in 0..far {
        let mut glass = scene.objects[0].clone();
        let centre = DVec3::new(100.0 + 10.0 * k as f64, 100.0, 100.0);
        glass.shape = crate::shapes::Shape::Sphere(crate::shapes::Sphere::new(centre, 1.0));
        glass.material.kt = 0.5;
        scene.objects.push(glass);
    }
    let LightKind::Punctual(Shape::Directional { direction: d }, _) = scene.ext.lights[0].kind
    else {
        panic!("the sun is directional");
    };
    let c = DVec3::new(x, y, 0.0);
    let p = c + (-1.0 - y) / d.y * d;
    assert!((p.y + 1.0).abs() < 1e-12 && p.x > -4.0 && p.z > -3.0, "{p}");
    crate::trace::Tracer::new(&scene).transmission(p, -d, f64::INFINITY)
}

#[test]
fn shadow_rays_through_blend_and_mask_by_hand() {
    // Through the BLEND veil's middle (α = 0.5, opaque): half the light, grey.
    assert_eq!(shadow_through(-2.0, 0.4), DVec3::splat(0.5));
    // Through the textured BLEND quad's texel of alpha 191/255: 64/255 of it.
    let t = shadow_through(0.4, 0.8);
    assert!((t - DVec3::splat(64.0 / 255.0)).length() < 1e-6, "{t}");
    // MASK's top row of cells, 0.4 wide from x = 1.2: the first opaque, the second
    // masked out (all the light), the third opaque.
    assert_eq!(shadow_through(1.4, 1.0), DVec3::ZERO);
    assert_eq!(shadow_through(1.8, 1.0), DVec3::ONE);
    assert_eq!(shadow_through(2.2, 1.0), DVec3::ZERO);
}
