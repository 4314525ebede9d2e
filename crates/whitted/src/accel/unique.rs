//! The triangles of an opaque mesh that the shapes' tree needs: each set of triangles
//! with the same three corners, in the same order, bit for bit, is met by every ray at
//! the same t (`Mesh::line_hit` reads nothing else), and the nearest-hit rule then keeps
//! the one first in the file; a shadow ray stops at any of them. So the later copies can
//! never answer a query, and the tree leaves them out: a mesh of a million copies of one
//! triangle (reliability round four) is one triangle to the tree, where all million shared one
//! box, could not be split, and were all tested by every ray that met it. A glass mesh
//! keeps its copies (each crossing of a shadow ray multiplies the light through it).

use crate::mesh::Mesh;
use std::collections::HashMap;
use std::hash::{BuildHasherDefault, Hasher};

/// The map's hasher: the key is already a mixed 64-bit hash (`key`), taken as it is
/// (the standard SipHash over it was a tenth of this check's time on a million
/// triangles).
#[derive(Default)]
struct Prehashed(u64);

impl Hasher for Prehashed {
    fn write(&mut self, bytes: &[u8]) {
        // Only `write_u64` is used (u64 keys); any other input is folded in.
        for &b in bytes {
            self.0 = (self.0.rotate_left(8) ^ u64::from(b)).wrapping_mul(MIX);
        }
    }
    fn write_u64(&mut self, x: u64) {
        self.0 = x;
    }
    fn finish(&self) -> u64 {
        self.0
    }
}

/// FxHash's multiplier.
const MIX: u64 = 0x51_7c_c1_b7_27_22_0a_95;

/// The indices of `mesh`'s triangles that are not a copy of an earlier one, ascending.
pub(super) fn triangles(mesh: &Mesh) -> Vec<u32> {
    let n = mesh.triangles.len() as u32;
    // Keyed by a hash of the corners' bits (16 bytes an entry, not 72); a hash shared by
    // different corners only keeps both (the check below), never drops one.
    let mut first: HashMap<u64, u32, BuildHasherDefault<Prehashed>> =
        HashMap::with_capacity_and_hasher(n as usize, Default::default());
    let mut keep = Vec::with_capacity(n as usize);
    for k in 0..n {
        let corners = mesh.corners(k);
        let bits = corners.map(|c| c.to_array().map(f64::to_bits));
        match first.entry(key(&bits)) {
            std::collections::hash_map::Entry::Vacant(e) => {
                e.insert(k);
                keep.push(k);
            }
            std::collections::hash_map::Entry::Occupied(e) => {
                let other = mesh
                    .corners(*e.get())
                    .map(|c| c.to_array().map(f64::to_bits));
                if other != bits {
                    keep.push(k);
                }
            }
        }
    }
    keep
}

/// A quick hash of the nine coordinates' bits (multiply and rotate, as FxHash does): the
/// map's own hash then runs on 8 bytes, not 72.
fn key(bits: &[[u64; 3]; 3]) -> u64 {
    bits.iter()
        .flatten()
        .fold(0u64, |h, &w| (h.rotate_left(5) ^ w).wrapping_mul(MIX))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::mesh::Raw;
    use crate::shapes::Transform;
    use glam::DVec3;

    #[test]
    fn copies_of_a_triangle_are_left_out_and_the_first_kept() {
        let positions = vec![
            DVec3::ZERO,
            DVec3::X,
            DVec3::Y,
            DVec3::Z,
            // A second vertex at the first one's place: a copy by value.
            DVec3::ZERO,
        ];
        // 0: (0,1,2); 1: the same; 2: (1,2,0), the same corners in another order (kept:
        // its test may round differently); 3: (4,1,2), 0's by value; 4: (0,1,3).
        let triangles = vec![[0, 1, 2], [0, 1, 2], [1, 2, 0], [4, 1, 2], [0, 1, 3]];
        let raw = Raw {
            positions,
            triangles,
            ..Raw::default()
        };
        let flat = Some(crate::mesh::Shading::Flat);
        let mesh = Mesh::from_raw(raw, &Transform::IDENTITY, flat).unwrap();
        assert_eq!(super::triangles(&mesh), vec![0, 2, 4]);
    }

    #[test]
    fn the_maps_hasher_takes_a_u64_key_as_it_is() {
        use std::hash::BuildHasher;
        let b = BuildHasherDefault::<Prehashed>::default();
        assert_eq!(b.hash_one(0x1234_5678_9abc_def0_u64), 0x1234_5678_9abc_def0);
        // Bytes are folded in: one byte 1 from 0 gives (0 ^ 1) · MIX.
        let mut h = Prehashed::default();
        h.write(&[1]);
        assert_eq!(h.finish(), MIX);
    }
}
