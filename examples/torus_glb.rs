//! Writes a finely tessellated torus as a binary glTF (`.glb`): the glTF speed goal's
//! mesh, a million triangles by default, with a normal per vertex; with `--skin`, also a
//! two-joint skin (the torus bends about its second joint, weights blending over a
//! quarter turn) and a one-second animation of that joint, for the skinning measure.
//!
//!     cargo run --release --features examples --example torus_glb -- OUT.glb [MAJOR_STEPS MINOR_STEPS] [--skin]
//!
//! The torus of `torus_ply` (radii 1 and 0.4 about the y axis), MAJOR_STEPS ×
//! MINOR_STEPS quads (default 1000 × 500), two triangles each. The GLB container is
//! written here (a JSON chunk and a binary chunk, each padded to four bytes).

use serde_json::json;
use std::f64::consts::TAU;

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let skin = args.iter().any(|a| a == "--skin");
    let rest: Vec<&String> = args.iter().filter(|a| *a != "--skin").collect();
    let out = rest
        .first()
        .expect("usage: torus_glb OUT.glb [MAJOR MINOR] [--skin]");
    let major: usize = rest.get(1).map_or(1000, |s| s.parse().unwrap());
    let minor: usize = rest.get(2).map_or(500, |s| s.parse().unwrap());
    let (mut pos, mut nor, mut joints, mut weights) = (vec![], vec![], vec![], vec![]);
    for i in 0..major {
        let a = TAU * i as f64 / major as f64;
        // The second joint takes the far half, blended over a quarter turn each side.
        let w1 = (((a / TAU) * 4.0 - 1.5).clamp(0.0, 1.0) * std::f64::consts::PI / 2.0).sin();
        for j in 0..minor {
            let b = TAU * j as f64 / minor as f64;
            let (ca, sa, cb, sb) = (a.cos(), a.sin(), b.cos(), b.sin());
            let r = 1.0 + 0.4 * cb;
            pos.extend([r * ca, 0.4 * sb, r * sa].map(|x| x as f32));
            nor.extend([cb * ca, sb, cb * sa].map(|x| x as f32));
            joints.extend([0u16, 1, 0, 0]);
            weights.extend([(1.0 - w1) as f32, w1 as f32, 0.0, 0.0]);
        }
    }
    let mut idx: Vec<u32> = Vec::with_capacity(major * minor * 6);
    let at = |i: usize, j: usize| ((i % major) * minor + (j % minor)) as u32;
    for i in 0..major {
        for j in 0..minor {
            let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
            idx.extend([a, c, b, a, d, c]);
        }
    }
    let n = pos.len() / 3;
    let mut bin: Vec<u8> = Vec::new();
    let mut views = vec![];
    let mut push = |bytes: Vec<u8>| {
        let offset = bin.len();
        views.push(json!({"buffer": 0, "byteOffset": offset, "byteLength": bytes.len()}));
        bin.extend(bytes);
        while !bin.len().is_multiple_of(4) {
            bin.push(0);
        }
        views.len() - 1
    };
    let f32s = |v: &[f32]| v.iter().flat_map(|x| x.to_le_bytes()).collect::<Vec<u8>>();
    let vp = push(f32s(&pos));
    let vn = push(f32s(&nor));
    let vi = push(idx.iter().flat_map(|x| x.to_le_bytes()).collect());
    let (lo, hi) = ([-1.4, -0.4, -1.4], [1.4, 0.4, 1.4]);
    let mut accessors = vec![
        json!({"bufferView": vp, "componentType": 5126, "count": n, "type": "VEC3", "min": lo, "max": hi}),
        json!({"bufferView": vn, "componentType": 5126, "count": n, "type": "VEC3"}),
        json!({"bufferView": vi, "componentType": 5125, "count": idx.len(), "type": "SCALAR"}),
    ];
    let mut attributes = json!({"POSITION": 0, "NORMAL": 1});
    let mut nodes = vec![json!({"name": "Torus", "mesh": 0})];
    let mut extra = json!({});
    if skin {
        let vj = push(joints.iter().flat_map(|x| x.to_le_bytes()).collect());
        let vw = push(f32s(&weights));
        // Inverse binds: joint 0 at the origin, joint 1 at (−1, 0, 0).
        let ibm: Vec<f32> = [0.0f32, 1.0]
            .iter()
            .flat_map(|&x| {
                [
                    1., 0., 0., 0., 0., 1., 0., 0., 0., 0., 1., 0., x, 0., 0., 1.,
                ]
            })
            .collect();
        let vb = push(f32s(&ibm));
        let times: Vec<f32> = vec![0.0, 0.5, 1.0];
        let s = (0.25f64).sin() as f32;
        let c = (0.25f64).cos() as f32;
        let rots: Vec<f32> = vec![0., 0., 0., 1., 0., 0., s, c, 0., 0., 0., 1.];
        let vt = push(f32s(&times));
        let vr = push(f32s(&rots));
        accessors
            .push(json!({"bufferView": vj, "componentType": 5123, "count": n, "type": "VEC4"}));
        accessors
            .push(json!({"bufferView": vw, "componentType": 5126, "count": n, "type": "VEC4"}));
        accessors
            .push(json!({"bufferView": vb, "componentType": 5126, "count": 2, "type": "MAT4"}));
        accessors.push(json!({"bufferView": vt, "componentType": 5126, "count": 3, "type": "SCALAR", "min": [0.0], "max": [1.0]}));
        accessors
            .push(json!({"bufferView": vr, "componentType": 5126, "count": 3, "type": "VEC4"}));
        attributes["JOINTS_0"] = json!(3);
        attributes["WEIGHTS_0"] = json!(4);
        nodes[0]["skin"] = json!(0);
        nodes.push(json!({"name": "Root", "children": [2]}));
        nodes.push(json!({"name": "Bend", "translation": [-1.0, 0.0, 0.0]}));
        extra = json!({
            "skins": [{"joints": [1, 2], "inverseBindMatrices": 5}],
            "animations": [{"name": "Bend", "samplers": [{"input": 6, "output": 7}],
                "channels": [{"sampler": 0, "target": {"node": 2, "path": "rotation"}}]}]
        });
    }
    let mut doc = json!({
        "asset": {"version": "2.0", "generator": "whitted examples/torus_glb.rs"},
        "scene": 0,
        "scenes": [{"nodes": (0..nodes.len()).filter(|&k| k != 2).collect::<Vec<_>>()}],
        "nodes": nodes,
        "meshes": [{"primitives": [{"attributes": attributes, "indices": 2}]}],
        "accessors": accessors,
        "bufferViews": views,
        "buffers": [{"byteLength": bin.len()}],
    });
    if let serde_json::Value::Object(more) = extra {
        for (k, v) in more {
            doc[k] = v;
        }
    }
    let mut text = doc.to_string().into_bytes();
    while !text.len().is_multiple_of(4) {
        text.push(b' ');
    }
    let total = 12 + 8 + text.len() + 8 + bin.len();
    let mut glb: Vec<u8> = Vec::with_capacity(total);
    glb.extend(b"glTF");
    glb.extend(2u32.to_le_bytes());
    glb.extend((total as u32).to_le_bytes());
    glb.extend((text.len() as u32).to_le_bytes());
    glb.extend(b"JSON");
    glb.extend(&text);
    glb.extend((bin.len() as u32).to_le_bytes());
    glb.extend(b"BIN\0");
    glb.extend(&bin);
    std::fs::write(out, glb).unwrap();
    eprintln!("{out}: {} vertices, {} triangles", n, idx.len() / 3);
}
