//! Picking: what the camera ray through pixel (x, y) hits, answered by the tracer that
//! draws the picture (`Tracer::nearest` on `Camera::ray` at the pixel's centre, the ray
//! pixel (x, y) samples with one sample), never by a second tracer. The answer names the
//! object as Scene.txt numbers it and a manifest's tracks target it (`sphere 3`: the
//! third sphere of the file, from 1), gives its texture and material values, the distance
//! along the ray to the hit, the world hit point and the shading normal: the outward
//! normal after bump, turned to face the ray, exactly as `trace` shades it.
//!
//! ```text
//! pick(&tracer, &camera, 120, 80) → Pick { object: "sphere 2", distance: 9.41, … }
//! ```

use crate::base::Color;
use crate::camera::Camera;
use crate::object::Object;
use crate::texture::Texture;
use crate::trace::{facing, surface_at, Tracer};
use serde::Serialize;

/// What the camera ray through one pixel hits first.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Pick {
    /// `KIND N` as Scene.txt numbers it and tracks target it: `sphere 3`.
    pub object: String,
    /// The object's index among all objects (spheres, then planes, then cylinders).
    pub index: usize,
    /// The texture as Scene.txt writes it: its kind and colours.
    pub texture: TextureInfo,
    /// `Kd Kr Kt Ior BumpType BumpValue`.
    pub material: MaterialInfo,
    /// The distance along the (unit) camera ray to the hit: its t.
    pub distance: f64,
    /// The world hit point.
    pub point: [f64; 3],
    /// The shading normal: outward, bumped, turned to face the ray (unit).
    pub normal: [f64; 3],
}

/// A texture's kind and colours.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct TextureInfo {
    /// `uniform`, `checker`, `perlin`, `wood`, `marble` or `image`.
    pub kind: &'static str,
    /// Its colours, C1 (C2, C3) as the file gives them.
    pub colors: Vec<[f64; 3]>,
}

/// A material's values as Scene.txt writes them.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct MaterialInfo {
    /// Diffuse coefficient.
    pub kd: f64,
    /// Reflection coefficient.
    pub kr: f64,
    /// Refraction coefficient.
    pub kt: f64,
    /// Refraction index.
    pub ior: f64,
    /// Bump type: 0 none, 1 uniform, 2 plane/water.
    pub bump_type: u8,
    /// Bump ε.
    pub bump_value: f64,
}

fn rgb(c: Color) -> [f64; 3] {
    c.to_array()
}

impl TextureInfo {
    fn of(t: &Texture) -> TextureInfo {
        let (kind, _, colors) = t.record();
        let colors = colors.into_iter().map(rgb).collect();
        TextureInfo { kind, colors }
    }
}

impl MaterialInfo {
    fn of(o: &Object) -> MaterialInfo {
        let m = &o.material;
        let (bump_type, bump_value) = m.bump.record();
        MaterialInfo {
            kd: m.kd,
            kr: m.kr,
            kt: m.kt,
            ior: m.ior,
            bump_type,
            bump_value,
        }
    }
}

/// What the camera ray through the centre of pixel (x, y) (x to the right, y down, from
/// 0) hits first, or `None` when it hits nothing (or the pixel is outside the camera's
/// image).
pub fn pick(tracer: &Tracer, camera: &Camera, x: u32, y: u32) -> Option<Pick> {
    // With the scene's epsilon, as the tracer's camera rays have it.
    let ray = camera
        .ray(f64::from(x) + 0.5, f64::from(y) + 0.5)
        .with_t_min(tracer.scene().t_min);
    let hit = tracer.nearest_hit(&ray)?;
    let (t, index) = (hit.t, hit.index);
    let scene = tracer.scene();
    let obj = scene.objects.get(index)?;
    let p = ray.at(t);
    let surface = tracer.surface_of(obj, hit.part, p);
    // A CSG block answers with the leaf the ray met (its texture, material and normal).
    let (obj, outward) = surface_at(&surface, &ray, p);
    let (normal, _) = facing(obj, outward, p, ray.dir);
    Some(Pick {
        object: scene.object_name(index)?,
        index,
        texture: TextureInfo::of(&obj.texture),
        material: MaterialInfo::of(obj),
        distance: t,
        point: p.to_array(),
        normal: normal.to_array(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Scene;
    use glam::DVec3;

    /// 40×30, eye at z = 10 looking at the origin; sphere 1 (r 1) at the origin, sphere 2
    /// (r 0.5, bumped) off to the right at x = 1.5, a floor plane y = −1 (checker).
    const SCENE: &str = "40 30  0 0 10  0 0 0  0 0  2 1 0 1
        1 0 0 0      1 0.9 0.1 0.1   0.7 0.3 0 1 0 0
        0.5 1.5 0 0  1 0.2 0.2 0.9   0.8 0 0.5 1.5 1 0.2
        0 -1 0  0 1 0  2 1 1 1 1 0 0 0 0 0 0   0.9 0 0 1 0 0
        5 10 5  1 1 1  1";

    fn setup() -> Scene {
        Scene::parse(SCENE, "s.txt").unwrap()
    }

    #[test]
    fn the_centre_hits_sphere_1_head_on() {
        let scene = setup();
        let tracer = Tracer::new(&scene);
        let camera = scene.camera();
        // Pixel (20, 15)'s centre: dir ∝ (−0.25 + 0.5·20.5/40, 0.175 − 0.35·15.5/30, −1)
        // = (0.00625, −0.0058333, −1). From the eye 10 away, the ray passes the centre at
        // b = 10·sin θ = 0.085494 (sin θ = |(0.00625, −0.0058333)| / |dir|), so it meets
        // the unit sphere at t = 10·cos θ − √(1 − b²) = 9.999635 − 0.996339 = 9.003296.
        let p = pick(&tracer, &camera, 20, 15).unwrap();
        assert_eq!(p.object, "sphere 1");
        assert_eq!(p.index, 0);
        assert!((p.distance - 9.003296).abs() < 2e-6, "{}", p.distance);
        // The normal of the unit sphere is the hit point: z = 10 − t·cos θ = 0.997033.
        assert!((p.normal[2] - 0.997033).abs() < 2e-6, "{:?}", p.normal);
        assert_eq!(p.normal, p.point);
        assert_eq!(p.texture.kind, "uniform");
        assert_eq!(p.texture.colors, vec![[0.9, 0.1, 0.1]]);
        assert_eq!((p.material.kd, p.material.kr), (0.7, 0.3));
    }

    #[test]
    fn kinds_are_numbered_apart_and_the_normal_is_bumped() {
        let scene = setup();
        let tracer = Tracer::new(&scene);
        let camera = scene.camera();
        // x = 1.5 at distance 10 is 0.15 of the 0.5-wide view right of centre: pixel
        // 20 + 0.15/0.5·40 = 32.
        let p = pick(&tracer, &camera, 32, 15).unwrap();
        assert_eq!(p.object, "sphere 2");
        assert_eq!((p.material.bump_type, p.material.bump_value), (1, 0.2));
        let n = DVec3::from_array(p.normal);
        assert!((n.length() - 1.0).abs() < 1e-9);
        let outward = (DVec3::from_array(p.point) - DVec3::new(1.5, 0.0, 0.0)).normalize();
        assert!(
            n.dot(outward) < 0.9999,
            "bump changed nothing: {n} vs {outward}"
        );
        // The bottom row looks down past the spheres onto the floor: plane 1.
        let p = pick(&tracer, &camera, 5, 29).unwrap();
        assert_eq!(p.object, "plane 1");
        assert_eq!(p.index, 2);
        assert_eq!(p.texture.kind, "checker");
        assert_eq!(p.normal, [0.0, 1.0, 0.0]);
        // The top row sees nothing.
        assert!(pick(&tracer, &camera, 0, 0).is_none());
    }
}
