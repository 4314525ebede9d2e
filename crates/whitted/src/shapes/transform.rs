//! An object's own frame (SPEC §16's `scale`, `rotate`, `translate`): the affine map from
//! object space to the world, scale first, then rotations about x, then y, then z (in
//! degrees, right-handed), then translation, whatever order the file writes them in.
//!
//! A ray is carried into object space as O' = M⁻¹O, D' = M⁻¹D: the same parameter t names
//! the same point in both spaces, so roots found in object space are the world's roots.
//! A normal goes back with the inverse transpose, (M⁻¹)ᵀN', normalised.

use glam::{DAffine3, DMat3, DVec3};

/// An invertible affine map from object space to world space, with its inverse.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Transform {
    to_world: DAffine3,
    to_local: DAffine3,
}

impl Transform {
    /// The identity: object space is the world.
    pub const IDENTITY: Transform = Transform {
        to_world: DAffine3::IDENTITY,
        to_local: DAffine3::IDENTITY,
    };

    /// The frame of the modifiers: scale, then rotate (degrees about x, y, z), then
    /// translate; `None` for a zero or non-finite scale, or a non-finite angle or offset.
    pub fn new(scale: DVec3, rotate_deg: DVec3, translate: DVec3) -> Option<Transform> {
        let r = rotate_deg * (std::f64::consts::PI / 180.0);
        let rot =
            DMat3::from_rotation_z(r.z) * DMat3::from_rotation_y(r.y) * DMat3::from_rotation_x(r.x);
        let m = DAffine3::from_mat3_translation(rot * DMat3::from_diagonal(scale), translate);
        Transform::from_affine(m)
    }

    /// The frame of an affine map; `None` when it is singular or not finite.
    pub fn from_affine(to_world: DAffine3) -> Option<Transform> {
        let det = to_world.matrix3.determinant();
        if !(to_world.is_finite() && det.is_normal()) {
            return None;
        }
        let to_local = to_world.inverse();
        to_local
            .is_finite()
            .then_some(Transform { to_world, to_local })
    }

    /// First `self`, then `outer` (an object inside a CSG block moved by the block's own
    /// modifiers); `None` if the product is singular.
    pub fn then(&self, outer: &Transform) -> Option<Transform> {
        Transform::from_affine(outer.to_world * self.to_world)
    }

    /// True when the map is the identity.
    pub fn is_identity(&self) -> bool {
        self.to_world == DAffine3::IDENTITY
    }

    /// A world point in object space.
    #[inline]
    pub fn point_to_local(&self, p: DVec3) -> DVec3 {
        self.to_local.transform_point3(p)
    }

    /// A world direction in object space (not normalised: t is kept).
    #[inline]
    pub fn vector_to_local(&self, v: DVec3) -> DVec3 {
        self.to_local.transform_vector3(v)
    }

    /// An object-space point in the world.
    #[inline]
    pub fn point_to_world(&self, p: DVec3) -> DVec3 {
        self.to_world.transform_point3(p)
    }

    /// An object-space normal as a world unit normal: (M⁻¹)ᵀN, normalised.
    #[inline]
    pub fn normal_to_world(&self, n: DVec3) -> DVec3 {
        let v = self.to_local.matrix3.transpose() * n;
        v.try_normalize().unwrap_or(n)
    }

    /// The world box around an object-space box (its eight corners mapped).
    pub fn bounds_to_world(&self, (lo, hi): (DVec3, DVec3)) -> (DVec3, DVec3) {
        let mut out = (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY));
        for i in 0..8 {
            let c = DVec3::new(
                if i & 1 == 0 { lo.x } else { hi.x },
                if i & 2 == 0 { lo.y } else { hi.y },
                if i & 4 == 0 { lo.z } else { hi.z },
            );
            let w = self.point_to_world(c);
            out = (out.0.min(w), out.1.max(w));
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: DVec3, b: DVec3) -> bool {
        (a - b).length() < 1e-12
    }

    #[test]
    fn scale_then_rotate_then_translate() {
        // (1, 0, 0) scaled by 2 → (2, 0, 0); 90° about z → (0, 2, 0); moved by (1, 1, 1).
        let f = Transform::new(
            DVec3::new(2.0, 1.0, 1.0),
            DVec3::new(0.0, 0.0, 90.0),
            DVec3::ONE,
        )
        .unwrap();
        assert!(close(f.point_to_world(DVec3::X), DVec3::new(1.0, 3.0, 1.0)));
        assert!(close(f.point_to_local(DVec3::new(1.0, 3.0, 1.0)), DVec3::X));
        // Rotations about x first, then y: (0, 1, 0) → x 90° → (0, 0, 1) → y 90° → (1, 0, 0).
        let f = Transform::new(DVec3::ONE, DVec3::new(90.0, 90.0, 0.0), DVec3::ZERO).unwrap();
        assert!(close(f.point_to_world(DVec3::Y), DVec3::X));
    }

    #[test]
    fn normals_use_the_inverse_transpose() {
        // The plane x + y = 0 (normal (1,1,0)/√2) stretched by 2 along x becomes
        // x/2 + y = 0, whose normal is (1, 2, 0)/√5.
        let f = Transform::new(DVec3::new(2.0, 1.0, 1.0), DVec3::ZERO, DVec3::ZERO).unwrap();
        let n = f.normal_to_world(DVec3::new(1.0, 1.0, 0.0).normalize());
        assert!(close(n, DVec3::new(1.0, 2.0, 0.0) / 5f64.sqrt()));
    }

    #[test]
    fn singular_frames_are_refused() {
        assert!(Transform::new(DVec3::new(1.0, 0.0, 1.0), DVec3::ZERO, DVec3::ZERO).is_none());
        assert!(Transform::new(DVec3::ONE, DVec3::new(f64::NAN, 0.0, 0.0), DVec3::ZERO).is_none());
        assert!(Transform::IDENTITY.is_identity());
    }

    #[test]
    fn world_bounds_of_a_rotated_box() {
        // The unit cube turned 45° about z spans ±√2/2·… : x in [−√2/2, √2/2].
        let f = Transform::new(DVec3::ONE, DVec3::new(0.0, 0.0, 45.0), DVec3::ZERO).unwrap();
        let (lo, hi) = f.bounds_to_world((DVec3::splat(-0.5), DVec3::splat(0.5)));
        let h = 0.5f64.sqrt();
        assert!(close(lo, DVec3::new(-h, -h, -0.5)) && close(hi, DVec3::new(h, h, 0.5)));
    }
}
