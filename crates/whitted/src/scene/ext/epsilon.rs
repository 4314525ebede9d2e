//! The hit epsilon of a small scene of meshes (SPEC §18): the report's 0.01 (§2) is a
//! hundredth of a unit, which swallows the contact shadows and thin walls of a model a
//! few hundredths across (a scan kept in its file's metres, a model fitted small). A
//! scene that holds a mesh is measured by s, the largest side of the box around every
//! bounded object (planes and other unbounded shapes left out, and the eye too: the hit
//! points' rounding grows with their coordinates, which the objects' box holds, and a
//! translated model keeps its epsilon); below one unit the epsilon is 0.01·s, so the
//! scene is drawn as its copy scaled up to one unit would be. A scene of one unit or
//! more, and every scene without a mesh (the report's, the NFF's own rule aside), keep
//! 0.01.
//!
//! ```text
//! a cube mesh of side 0.05 on a plane   → s = 0.05, epsilon 0.0005
//! the gallery's meshes (a sky sphere of radius 1000) → 0.01
//! ```

use crate::object::Object;
use crate::optics::T_MIN;
use crate::shapes::Shape;
use glam::DVec3;

/// The size below which a scene of meshes scales its epsilon: one unit.
pub const UNIT: f64 = 1.0;

/// The epsilon of a scene whose objects are `objects`: `T_MIN`·min(1, s/`UNIT`) when one
/// of them is a mesh (s: the largest side of the box around the bounded ones), else
/// `T_MIN`.
pub fn small_scene(objects: &[Object]) -> f64 {
    if !objects.iter().any(|o| matches!(o.shape, Shape::Mesh(_))) {
        return T_MIN;
    }
    let (mut lo, mut hi) = (DVec3::INFINITY, DVec3::NEG_INFINITY);
    for (a, b) in objects.iter().filter_map(|o| o.shape.bounds()) {
        (lo, hi) = (lo.min(a), hi.max(b));
    }
    let s = (hi - lo).max_element();
    if s.is_finite() && s > 0.0 && s < UNIT {
        T_MIN * s / UNIT
    } else {
        T_MIN
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bump::Bump;
    use crate::object::{Highlight, Material};
    use crate::shapes::{MeshRef, Plane, Sphere};
    use crate::texture::Texture;

    fn object(shape: Shape) -> Object {
        let material = Material {
            kd: 1.0,
            kr: 0.0,
            kt: 0.0,
            ior: 1.0,
            bump: Bump::None,
            highlight: Highlight::Report,
        };
        let texture = Texture::Uniform(DVec3::ONE);
        Object {
            shape,
            texture,
            material,
        }
    }

    fn mesh(lo: [f64; 3], hi: [f64; 3]) -> Object {
        let (lo, hi) = (DVec3::from(lo), DVec3::from(hi));
        object(Shape::Mesh(MeshRef { id: 0, lo, hi }))
    }

    #[test]
    fn small_scenes_of_meshes_scale_the_epsilon_by_hand() {
        let floor = object(Shape::Plane(Plane::new(DVec3::ZERO, DVec3::Y)));
        // A cube of side 0.05 far from the origin, on a plane: s = 0.05, 0.01·0.05.
        let cube = mesh([100.0, 0.0, 3.0], [100.05, 0.05, 3.05]);
        let e = small_scene(&[floor.clone(), cube.clone()]);
        assert!((e - 0.0005).abs() < 1e-15, "{e}");
        // With a sphere of radius 0.1 at (100.2, 0, 3): the box runs x 100 to 100.3,
        // y −0.1 to 0.1, z 2.9 to 3.1; s = 0.3, epsilon 0.003.
        let ball = object(Shape::Sphere(Sphere::new(DVec3::new(100.2, 0.0, 3.0), 0.1)));
        let e = small_scene(&[cube.clone(), ball.clone(), floor.clone()]);
        assert!((e - 0.003).abs() < 1e-15, "{e}");
        // Without a mesh, and at a unit or more, the report's 0.01.
        assert_eq!(small_scene(&[ball, floor.clone()]), T_MIN);
        let big = mesh([0.0; 3], [1.0, 0.2, 0.2]);
        assert_eq!(small_scene(&[cube, big, floor]), T_MIN);
    }
}
