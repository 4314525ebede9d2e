//! Four triangles of a leaf tested at once in f32 lanes, as a filter in front of the
//! exact test: a leaf of the shapes' tree whose primitives are all triangles (an NFF's
//! polygons and patches, a mesh's faces) holds a copy of them rounded to f32, laid out by
//! lane (`TriPacket`); a query tests the four in one go and runs the exact scalar f64
//! test (`Triangle::uvt_of`) only on the lanes that pass. The filter never drops a
//! triangle the exact test would hit (see below), so every answer stays the exact
//! test's, bit for bit; it only spares the exact test the triangles the ray clearly
//! misses, and a mesh's faces are read from the leaf instead of through their vertex
//! indices.
//!
//! The lanes compute Möller and Trumbore's quantities without the division: with
//! s = O − A, P = D × E2 and Q = s × E1, det = E1·P, u′ = s·P and v′ = D·Q; the exact
//! test hits when, with the sign of det taken out, u′ ≥ 0, v′ ≥ 0 and u′ + v′ ≤ |det|.
//! A lane passes when u′ ≥ −M, v′ ≥ −M and u′ + v′ ≤ |det| + M, the margin
//! M = 2⁻¹⁴·D·E·R, where D bounds |D|'s components, E the edges' (E1's and E2's)
//! components, and R = |O|∞ + A with A the largest coordinate of the triangle's
//! corners.
//!
//! Why M suffices (u = 2⁻²⁴, f32's rounding unit; no fused operations): rounding O, A,
//! E1, E2 and D to f32 and computing s moves each s_i by at most 2uR; each component of
//! P then errs by at most 8uDE and of Q by 10uRE; the three dot products add their own
//! rounding (3u of the sum of their terms' magnitudes), so u′ and v′ err by at most
//! 54uRDE each and det by 48uDE² ≤ 96uRDE (E ≤ 2A). Where det's computed sign may be
//! wrong (|det| ≤ 96uRDE), an exact hit has |u′|, |v′| ≤ |det| and so both lie within
//! 150uRDE of zero either way round; otherwise the sum test errs by at most
//! 54 + 54 + 96 = 204uRDE. The f64 test's own rounding (2⁻⁵³) is lost in these. So
//! 300uRDE bounds every error, and M = 1024uRDE is more than three times that. Bounds
//! on the magnitudes keep the lanes away from f32's overflow and underflow
//! (`MAX_COORD`, `MIN_EDGE`, `Ray32::new`): a triangle outside them stays out of any
//! packet, and a ray outside them takes the exact test on every primitive.

use super::{Accel, ShapePrim};
use crate::optics::Ray;
use glam::DVec3;
use wide::{f32x4, CmpGe, CmpLe};

/// The margin's factor, 2⁻¹⁴ (see the module's text).
const K: f32 = 1.0 / 16384.0;
/// Triangles with a corner coordinate above this, and rays starting farther out, take
/// the exact test alone (every product of the lanes stays far below f32's range).
pub(super) const MAX_COORD: f64 = 1e12;
/// Triangles whose largest edge component is below this take the exact test alone
/// (every product of the lanes stays far above f32's subnormal range).
const MIN_EDGE: f64 = 1e-12;

/// A leaf's triangles, up to four, rounded to f32 and laid out by lane.
#[derive(Clone, Copy, Debug)]
pub(super) struct TriPacket {
    /// Corner A, per axis.
    a: [f32x4; 3],
    /// B − A, per axis.
    e1: [f32x4; 3],
    /// C − A, per axis.
    e2: [f32x4; 3],
    /// E: the largest |component| of E1 and E2.
    e: f32x4,
    /// E·A: E times the largest |coordinate| of the three corners.
    ea: f32x4,
    /// How many lanes hold a triangle (the first ones).
    pub count: u32,
}

/// A ray prepared for the packets' lanes.
#[derive(Clone, Copy, Debug)]
pub(super) struct Ray32 {
    o: [f32x4; 3],
    d: [f32x4; 3],
    /// K·D·|O|∞ and K·D: the margin is `ko`·E + `kd`·E·A.
    ko: f32x4,
    kd: f32x4,
}

impl Ray32 {
    /// `None` when the ray starts too far out (or not at a finite point) for the lanes'
    /// bounds: its queries then run the exact test on every primitive.
    #[inline]
    pub(super) fn new(ray: &Ray) -> Option<Ray32> {
        // (A direction that is not finite: whatever its lanes pass, the exact test then
        // hits nothing, so nothing is lost.)
        let reach = ray.origin.abs().max_element();
        if reach.partial_cmp(&MAX_COORD) != Some(std::cmp::Ordering::Less) {
            return None;
        }
        let lanes = |v: DVec3| [v.x, v.y, v.z].map(|x| f32x4::splat(x as f32));
        // D rounded up a little, so that the margin's own rounding costs nothing.
        let kd = K as f64 * ray.dir.abs().max_element() * (1.0 + 1e-6);
        Some(Ray32 {
            o: lanes(ray.origin),
            d: lanes(ray.dir),
            ko: f32x4::splat((kd * reach) as f32),
            kd: f32x4::splat(kd as f32),
        })
    }
}

impl TriPacket {
    /// The packet of up to four triangles given by corner A and edges E1 = B − A,
    /// E2 = C − A (in the exact test's own f64 values); `None` when there are none, more
    /// than four, or one lies outside the lanes' bounds.
    pub(super) fn new(tris: &[[DVec3; 3]]) -> Option<TriPacket> {
        if tris.is_empty() || tris.len() > 4 {
            return None;
        }
        let mut lane = [[[0.0f32; 4]; 3]; 3];
        let (mut e, mut ea) = ([0.0f32; 4], [0.0f32; 4]);
        for (k, &[a, e1, e2]) in tris.iter().enumerate() {
            let corner = a
                .abs()
                .max((a + e1).abs())
                .max((a + e2).abs())
                .max_element();
            let edge = e1.abs().max(e2.abs()).max_element();
            if !(corner < MAX_COORD && (MIN_EDGE..MAX_COORD).contains(&edge)) {
                return None;
            }
            for (i, v) in [a, e1, e2].into_iter().enumerate() {
                for axis in 0..3 {
                    lane[i][axis][k] = v[axis] as f32;
                }
            }
            // Rounded up a little: the margin only grows.
            e[k] = (edge * (1.0 + 1e-6)) as f32;
            ea[k] = (edge * corner * (1.0 + 1e-6)) as f32;
        }
        let axes = |m: [[f32; 4]; 3]| m.map(f32x4::from);
        Some(TriPacket {
            a: axes(lane[0]),
            e1: axes(lane[1]),
            e2: axes(lane[2]),
            e: f32x4::from(e),
            ea: f32x4::from(ea),
            count: tris.len() as u32,
        })
    }

    /// The lanes (bit k for triangle k) whose triangle the ray's line may cross: every
    /// triangle the exact test hits at any t is among them.
    #[inline(always)]
    pub(super) fn candidates(&self, r: &Ray32) -> u32 {
        let [dx, dy, dz] = r.d;
        let s = [0, 1, 2].map(|i| r.o[i] - self.a[i]);
        let [e1x, e1y, e1z] = self.e1;
        let [e2x, e2y, e2z] = self.e2;
        // P = D × E2, det = E1·P, u′ = s·P.
        let (px, py, pz) = (
            dy * e2z - dz * e2y,
            dz * e2x - dx * e2z,
            dx * e2y - dy * e2x,
        );
        let det = e1x * px + e1y * py + e1z * pz;
        let u = s[0] * px + s[1] * py + s[2] * pz;
        // Q = s × E1, v′ = D·Q.
        let qx = s[1] * e1z - s[2] * e1y;
        let qy = s[2] * e1x - s[0] * e1z;
        let qz = s[0] * e1y - s[1] * e1x;
        let v = dx * qx + dy * qy + dz * qz;
        // det's sign taken out of u′ and v′.
        let sign = det & f32x4::splat(-0.0);
        let (u, v, adet) = (u ^ sign, v ^ sign, det ^ sign);
        let m = r.ko * self.e + r.kd * self.ea;
        let pass = u.cmp_ge(-m) & v.cmp_ge(-m) & (u + v).cmp_le(adet + m);
        pass.move_mask() as u32 & ((1u32 << self.count) - 1)
    }
}

/// Leaves of fewer triangles than this get no packet: the lanes' test of a packet
/// costs about what the exact test of two triangles does (callgrind on the SPD: with
/// packets of two, tree and rings counted 11 to 13 % more instructions).
const PACKET_MIN: usize = 3;

/// `Accel::packet_at` of a leaf without a packet.
pub(super) const NO_PACKET: u32 = u32::MAX;

impl Accel {
    /// The packets of the shapes' tree's leaves that hold only triangles (each the leaf's
    /// triangles in the leaf's order), and for each primitive slot the packet of the leaf
    /// starting there (`NO_PACKET` elsewhere).
    pub(super) fn build_packets(&mut self) {
        let prims = self.shapes.prims();
        let mut at = vec![NO_PACKET; prims.len()];
        let leaves = self.shapes.leaves();
        // At most one packet a leaf: sized first rather than grown by doubling.
        let mut packets = Vec::with_capacity(leaves.len());
        for (first, count) in leaves {
            let tris: Option<Vec<[DVec3; 3]>> = prims[first..first + count]
                .iter()
                .map(|p| match p.mesh {
                    ShapePrim::TRI => Some(self.tris[p.part as usize]),
                    ShapePrim::SOLO | ShapePrim::SPHERE => None,
                    _ => Some(self.mesh_tris[p.slot as usize]),
                })
                .collect();
            // Fewer than `PACKET_MIN` triangles are tested faster one by one.
            if count < PACKET_MIN {
                continue;
            }
            if let Some(packet) = tris.as_deref().and_then(TriPacket::new) {
                at[first] = packets.len() as u32;
                packets.push(packet);
            }
        }
        self.packets = packets;
        self.packet_at = at;
    }

    /// `Bvh::traverse` over the shapes' tree, `visit` called only on the primitives the
    /// ray may hit: in a leaf with a packet, those its lanes pass (every one the exact
    /// test hits, in the leaf's order); elsewhere, or for a ray beyond the lanes' bounds,
    /// every one. A scene without packets walks exactly as before there were any (the
    /// SPD's rings and tree counted 4 % more instructions through the leaf walk).
    #[inline(always)]
    pub(super) fn shapes_traverse(
        &self,
        ray: &Ray,
        limit: f64,
        visit: impl FnMut(&ShapePrim, f64) -> Option<f64>,
    ) {
        self.shapes_query::<true>(ray, limit, visit)
    }

    /// `shapes_traverse` in whatever order the tree gives (`Bvh::traverse_any`).
    #[inline(always)]
    pub(super) fn shapes_traverse_any(
        &self,
        ray: &Ray,
        limit: f64,
        visit: impl FnMut(&ShapePrim, f64) -> Option<f64>,
    ) {
        self.shapes_query::<false>(ray, limit, visit)
    }

    #[inline(always)]
    fn shapes_query<const ORDERED: bool>(
        &self,
        ray: &Ray,
        limit: f64,
        mut visit: impl FnMut(&ShapePrim, f64) -> Option<f64>,
    ) {
        if self.packets.is_empty() {
            return match ORDERED {
                true => self.shapes.traverse(ray, limit, visit),
                false => self.shapes.traverse_any(ray, limit, visit),
            };
        }
        // The ray prepared for the lanes, made at the first packet the walk meets (a
        // shadow ray that meets none pays nothing for it).
        let mut r32: Option<Option<Ray32>> = None;
        self.shapes.query_leaves::<ORDERED>(
            ray,
            limit,
            #[inline(always)]
            |first, count, limit| self.shapes_leaf(&mut r32, ray, first, count, limit, &mut visit),
        )
    }

    /// `shapes_traverse_any` over the leaves of one node: the one that holds the leaf of
    /// the shapes' primitive at `at` (`Bvh::holder_leaves`).
    #[inline(always)]
    pub(super) fn shapes_holder(
        &self,
        at: usize,
        ray: &Ray,
        limit: f64,
        mut visit: impl FnMut(&ShapePrim, f64) -> Option<f64>,
    ) {
        let mut r32: Option<Option<Ray32>> = None;
        self.shapes
            .holder_leaves(at, ray, limit, |first, count, limit| {
                self.shapes_leaf(&mut r32, ray, first, count, limit, &mut visit)
            })
    }

    /// One leaf of the shapes' tree: `visit` on the primitives `first..first + count`
    /// that the leaf's packet passes (all of them without one, or for a ray beyond the
    /// lanes' bounds; `r32` is the lanes' ray, made the first time it is needed).
    #[inline(always)]
    fn shapes_leaf(
        &self,
        r32: &mut Option<Option<Ray32>>,
        ray: &Ray,
        first: usize,
        count: usize,
        mut limit: f64,
        visit: &mut impl FnMut(&ShapePrim, f64) -> Option<f64>,
    ) -> Option<f64> {
        let prims = self.shapes.prims();
        let k = self.packet_at.get(first).copied().unwrap_or(NO_PACKET);
        if k != NO_PACKET && self.packets[k as usize].count as usize == count {
            if let Some(r) = r32.get_or_insert_with(|| Ray32::new(ray)) {
                let mut mask = self.packets[k as usize].candidates(r);
                while mask != 0 {
                    let lane = mask.trailing_zeros() as usize;
                    mask &= mask - 1;
                    limit = visit(&prims[first + lane], limit)?;
                }
                return Some(limit);
            }
        }
        for prim in &prims[first..first + count] {
            limit = visit(prim, limit)?;
        }
        Some(limit)
    }
}
