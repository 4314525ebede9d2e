//! Cryptomatte 1.1 (Psyop's specification), as Blender writes it: every name gets a
//! 32-bit id, MurmurHash3 (x86, 32 bits, seed 0) of its UTF-8 bytes, stored as the float
//! with those bits after the exponent is kept off 0 and 255 (no denormal, inf or NaN):
//! `uint32_to_float32`. A layer `NAME` has three RGBA channel groups `NAME00..02` holding
//! six ranks, (id, coverage) in R,G and B,A, the largest coverage first; the header
//! carries `cryptomatte/<key>/name|hash|conversion|manifest`, key = the first 7 hex digits
//! of the hash of NAME, manifest = `{"sphere 1":"3f7a09c2", …}` (the ids' float bits).
//!
//! Names: objects `sphere 3`, `plane 1`, `cylinder 2` (numbered from 1 per kind in file
//! order, as tracks name them); materials `material Kd Kr Kt Ior BumpType BumpValue`, the
//! Scene.txt record of the material (objects with equal coefficients share it).

use super::Channel;
use crate::scene::Scene;

/// Ranks a Cryptomatte layer stores (three RGBA groups of two).
pub const RANKS: usize = 6;

/// MurmurHash3 x86-32 of `name`'s UTF-8 bytes, seed 0 (PyPI `mmh3.hash(name, signed=False)`).
pub fn hash(name: &str) -> u32 {
    mur3::murmurhash3_x86_32(name.as_bytes(), 0)
}

/// The id of `name`: its hash with the exponent bits clamped to 1..=254, as float bits.
pub fn id(name: &str) -> u32 {
    let h = hash(name);
    let exponent = ((h >> 23) & 0xff).clamp(1, 254);
    (h & 0x807f_ffff) | (exponent << 23)
}

/// The header key of a layer named `layer`: the first 7 hex digits of its hash.
pub fn key(layer: &str) -> String {
    format!("{:08x}", hash(layer))[..7].to_string()
}

/// The object names, one per object in file order (`Scene::object_names`).
pub fn object_names(scene: &Scene) -> Vec<String> {
    scene.object_names().collect()
}

/// The material names, one per object in file order.
pub fn material_names(scene: &Scene) -> Vec<String> {
    scene
        .objects
        .iter()
        .map(|o| {
            let m = &o.material;
            let (kind, eps) = m.bump.record();
            format!("material {} {} {} {} {kind} {eps}", m.kd, m.kr, m.kt, m.ior)
        })
        .collect()
}

/// The manifest: each distinct name with its id, sorted by name.
pub fn manifest(names: &[String]) -> Vec<(String, u32)> {
    let mut all: Vec<(String, u32)> = names.iter().map(|n| (n.clone(), id(n))).collect();
    all.sort();
    all.dedup();
    all
}

/// The manifest as the header's JSON text.
pub fn manifest_json(manifest: &[(String, u32)]) -> String {
    let entries: Vec<String> = manifest
        .iter()
        .map(|(name, id)| {
            let name = serde_json::to_string(name).unwrap_or_default();
            format!("{name}:\"{id:08x}\"")
        })
        .collect();
    format!("{{{}}}", entries.join(","))
}

/// The six largest coverages of a pixel, (id, coverage), largest first, ties by id.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Ranked(pub [(u32, f32); RANKS]);

impl Ranked {
    /// The ranks of a pixel whose `samples` samples hit the ids of `cover` (id, number of
    /// samples; an id may come more than once, from objects sharing a material).
    pub fn of(cover: impl Iterator<Item = (u32, u32)>, samples: u32) -> Ranked {
        let mut ids: Vec<(u32, u32)> = Vec::new();
        for (id, n) in cover {
            match ids.iter_mut().find(|(i, _)| *i == id) {
                Some((_, k)) => *k += n,
                None => ids.push((id, n)),
            }
        }
        ids.sort_by(|a, b| b.1.cmp(&a.1).then(a.0.cmp(&b.0)));
        let mut out = [(0, 0.0); RANKS];
        for (slot, (id, n)) in out.iter_mut().zip(ids) {
            *slot = (id, (f64::from(n) / f64::from(samples.max(1))) as f32);
        }
        Ranked(out)
    }
}

/// The twelve channels `NAME00.R` … `NAME02.A` of a layer from each pixel's ranks.
pub fn channels(layer: &str, pixels: impl Iterator<Item = Ranked>) -> Vec<Channel> {
    let mut out: Vec<Channel> = (0..RANKS / 2)
        .flat_map(|g| {
            ["R", "G", "B", "A"].map(|c| Channel {
                name: format!("{layer}{g:02}.{c}"),
                values: Vec::new(),
            })
        })
        .collect();
    for Ranked(ranks) in pixels {
        for (r, (id, cover)) in ranks.into_iter().enumerate() {
            out[2 * r].values.push(f32::from_bits(id));
            out[2 * r + 1].values.push(cover);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_by_kind_and_material_record() {
        // Two spheres (the second bumped, water 0.25) and a plane.
        let scene = crate::Scene::parse(
            "4 3  0 0 5  0 0 0  0 0  2 1 0 1\n\
             1 0 0 0  1 1 0 0  0.5 0.3 0 1 0 0\n\
             1 2 0 0  1 1 0 0  0.7 0 0.2 1.5 2 0.25\n\
             0 -1 0  0 1 0  1 1 1 1  1 0 0 1 0 0\n\
             0 5 5  1 1 1  1",
            "t.txt",
        )
        .unwrap();
        assert_eq!(object_names(&scene), ["sphere 1", "sphere 2", "plane 1"]);
        assert_eq!(scene.object_name(2).as_deref(), Some("plane 1"));
        assert_eq!(scene.object_name(3), None);
        assert_eq!(
            material_names(&scene),
            [
                "material 0.5 0.3 0 1 0 0",
                "material 0.7 0 0.2 1.5 2 0.25",
                "material 1 0 0 1 0 0"
            ]
        );
    }

    #[test]
    fn ids_are_murmur3_with_a_safe_exponent() {
        // mmh3.hash("hello", signed=False) = 613153351 = 0x248bfa47 (exponent 73: kept).
        assert_eq!(hash("hello"), 0x248b_fa47);
        assert_eq!(id("hello"), 0x248b_fa47);
        // mmh3.hash("", signed=False) = 0.
        assert_eq!(hash(""), 0);
        // Exponent 0 becomes 1: 0 → 0x00800000, a normal float.
        assert_eq!(id(""), 0x0080_0000);
        assert!(f32::from_bits(id("")).is_normal());
        assert_eq!(key("hello"), "248bfa4");
    }

    #[test]
    fn ranks_sort_by_coverage_and_fill_with_zeros() {
        let r = Ranked::of([(7, 1), (3, 2), (9, 1), (7, 0)].into_iter(), 4);
        assert_eq!(r.0[0], (3, 0.5));
        assert_eq!(r.0[1], (7, 0.25));
        assert_eq!(r.0[2], (9, 0.25));
        assert_eq!(r.0[3], (0, 0.0));
        let ch = channels("crypto_object", [r].into_iter());
        assert_eq!(ch.len(), 12);
        assert_eq!(ch[0].name, "crypto_object00.R");
        assert_eq!(ch[11].name, "crypto_object02.A");
        assert_eq!(ch[0].values[0].to_bits(), 3);
        assert_eq!(ch[3].values[0], 0.25);
    }

    #[test]
    fn manifest_json_is_sorted_and_escaped() {
        let m = manifest(&["b".into(), "a\"".into(), "b".into()]);
        assert_eq!(m.len(), 2);
        let json = manifest_json(&m);
        assert!(json.starts_with("{\"a\\\"\":\""), "{json}");
        let back: serde_json::Value = serde_json::from_str(&json).unwrap();
        assert_eq!(back["b"], format!("{:08x}", id("b")));
    }
}
