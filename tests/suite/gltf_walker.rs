//! The README's worked glTF example, `scenes/models/walker.glb` (made by
//! `scenes/models/make_walker.py`): it loads, its "Walk" animation gives 24 frames at
//! 24 fps with `loop = true`, the skinned mesh the reader poses matches a linear-blend
//! skinning written here from the file's own nodes, skin and channels, and the shoes
//! stay on the ground over the loop.

use glam::{DMat4, DQuat, DVec3};
use std::path::Path;
use whitted::gltf::clip::Path as Field;
use whitted::gltf::rig::Local;
use whitted::gltf::{Model, Options, Rig};

fn walker() -> Model {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/models/walker.glb");
    let bytes = std::fs::read(&path).unwrap();
    Model::read(&path, &bytes, Options::default()).unwrap()
}

/// The node named `name`.
fn node(rig: &Rig, name: &str) -> usize {
    let found = rig
        .nodes
        .iter()
        .position(|n| n.name.as_deref() == Some(name));
    found.unwrap()
}

/// Every node's world matrix at `t` with the clips `playing`, composed here: each
/// node's rest T·R·S with the channels' samples put in, multiplied down the tree.
fn world_matrices(rig: &Rig, t: f64, playing: &[usize]) -> Vec<DMat4> {
    let mut trs: Vec<(DVec3, DQuat, DVec3)> = rig
        .nodes
        .iter()
        .map(|n| match n.local {
            Local::Trs { t, r, s } => (t, r, s),
            Local::Matrix(m) => {
                let (s, r, t) = m.to_scale_rotation_translation();
                (t, r, s)
            }
        })
        .collect();
    for &c in playing {
        for ch in &rig.clips[c].channels {
            let v = ch.sample(t);
            let entry = &mut trs[ch.node];
            match ch.path {
                Field::Translation => entry.0 = DVec3::new(v[0], v[1], v[2]),
                // A unit quaternion, as glTF requires (the stored float32 keys are
                // unit only to about 1e-7).
                Field::Rotation => entry.1 = DQuat::from_xyzw(v[0], v[1], v[2], v[3]).normalize(),
                Field::Scale => entry.2 = DVec3::new(v[0], v[1], v[2]),
                _ => {}
            }
        }
    }
    let mut parent = vec![None; rig.nodes.len()];
    for (p, n) in rig.nodes.iter().enumerate() {
        for &c in &n.children {
            parent[c] = Some(p);
        }
    }
    fn world(k: usize, parent: &[Option<usize>], trs: &[(DVec3, DQuat, DVec3)]) -> DMat4 {
        let (t, r, s) = trs[k];
        let local = DMat4::from_translation(t) * DMat4::from_quat(r) * DMat4::from_scale(s);
        match parent[k] {
            Some(p) => world(p, parent, trs) * local,
            None => local,
        }
    }
    (0..rig.nodes.len())
        .map(|k| world(k, &parent, &trs))
        .collect()
}

/// Vertex `v` of primitive `prim` of the skinned node `n`, skinned here:
/// Σ wᵢ·(Jᵢ·IBMᵢ)·p.
fn skinned(rig: &Rig, world: &[DMat4], n: usize, prim: usize, v: usize) -> DVec3 {
    let skin = &rig.skins[rig.nodes[n].skin.unwrap()];
    let p = &rig.meshes[rig.nodes[n].mesh.unwrap()][prim];
    let (js, ws) = (p.joints[v], p.weights[v]);
    (0..4)
        .filter(|&c| ws[c] != 0.0)
        .map(|c| {
            let j = js[c] as usize;
            ws[c] * (world[skin.joints[j]] * skin.inverse_bind[j]).transform_point3(p.positions[v])
        })
        .sum()
}

#[test]
fn the_walk_gives_24_frames_at_24_fps_looped() {
    let model = walker();
    let walk = model.select(Some(&["Walk".to_string()])).unwrap();
    let wave = model.select(Some(&["Wave".to_string()])).unwrap();
    assert_eq!(walk.len(), 1);
    assert_ne!(walk, wave);
    assert_eq!(model.frames(&walk, 24.0, true), 24);
    assert_eq!(model.frames(&walk, 24.0, false), 25);
    assert_eq!(model.frames(&wave, 24.0, false), 49);
    // Twelve joints, one skin; the weights of every vertex sum to 1.
    let rig = &model.rig;
    assert_eq!(rig.skins.len(), 1);
    assert_eq!(rig.skins[0].joints.len(), 12);
    let n = node(rig, "Walker");
    for prim in &rig.meshes[rig.nodes[n].mesh.unwrap()] {
        for w in &prim.weights {
            assert!((w.iter().sum::<f64>() - 1.0).abs() < 1e-6, "{w:?}");
        }
    }
}

#[test]
fn the_posed_mesh_is_the_linear_blend_skinning_of_the_rig() {
    let model = walker();
    let rig = model.rig.clone();
    let walk = model.select(Some(&["Walk".to_string()])).unwrap();
    let n = node(&rig, "Walker");
    let prims = &rig.meshes[rig.nodes[n].mesh.unwrap()];
    assert_eq!(prims.len(), 4);
    for k in [0, 3, 7, 13, 20] {
        let t = k as f64 / 24.0;
        let scene = model.scene_at(t, &walk, &[]).unwrap();
        let world = world_matrices(&rig, t, &walk);
        // The walker's primitives come first (depth-first order), the ground after.
        for (m, prim) in prims.iter().enumerate() {
            let mesh = &scene.meshes[m];
            assert_eq!(mesh.vertices.len(), prim.positions.len());
            let count = prim.positions.len();
            for v in [0, 1, count / 3, count / 2, 2 * count / 3, count - 1] {
                let want = skinned(&rig, &world, n, m, v);
                let got = mesh.vertices[v];
                assert!(
                    (got - want).length() < 1e-9,
                    "frame {k} primitive {m} vertex {v}: {got} against {want}"
                );
            }
        }
        // The skinning moves the vertices (the test would pass on a still mesh too).
        if k == 7 {
            let rest = model.scene_at(0.0, &[], &[]).unwrap();
            let pairs = rest.meshes[2]
                .vertices
                .iter()
                .zip(&scene.meshes[2].vertices);
            let moved = pairs.map(|(a, b)| (*a - *b).length()).fold(0.0, f64::max);
            assert!(moved > 0.1, "the legs moved only {moved} m");
        }
    }
}

#[test]
fn the_shoes_stay_on_the_ground_over_the_loop() {
    let model = walker();
    let walk = model.select(Some(&["Walk".to_string()])).unwrap();
    let (mut lowest, mut highest_low) = (f64::INFINITY, f64::NEG_INFINITY);
    for k in 0..96 {
        let scene = model.scene_at(k as f64 / 96.0, &walk, &[]).unwrap();
        // Primitive 4 of the walker: the shoes.
        let low = scene.meshes[3]
            .vertices
            .iter()
            .map(|v| v.y)
            .fold(f64::INFINITY, f64::min);
        lowest = lowest.min(low);
        highest_low = highest_low.max(low);
    }
    assert!(lowest > -0.05, "a shoe goes {lowest} m below the ground");
    // And the lower shoe never floats: it stays within 5 cm of the ground.
    assert!(
        highest_low < 0.05,
        "both shoes are off the ground: {highest_low} m"
    );
}
