//! Reading and writing a track's value in a scene: `Target::read` gives what the base
//! scene holds, `Target::apply` puts a value in (numbers travel as `(x, 0, 0)`), through
//! the fog's distance and a texture's colours as the report's records lay them out; an
//! extension record's field through `ext`.

use super::{Field, Target};
use glam::DVec3;
use whitted::bump::Bump;
use whitted::fog::Fog;
use whitted::scene::ext::ExtItem;
use whitted::scene::{direction, ObjectSpec, Scene, ShapeSpec};
use whitted::texture::Texture;

impl Target {
    /// The value the base scene holds (as `(x, 0, 0)` for a number).
    pub fn read(&self, scene: &Scene) -> DVec3 {
        let num = |x: f64| DVec3::new(x, 0.0, 0.0);
        let i = self.index;
        let obj = scene.objects.get(i);
        let spec = scene.specs.get(i).and_then(|s| s.record());
        let (c1, c2, c3) = obj.map_or((DVec3::ZERO, DVec3::ZERO, DVec3::ZERO), |o| {
            colors(&o.texture)
        });
        match (self.field, spec) {
            (Field::Ext(f), _) => super::ext::read(&scene.ext, &f),
            (f, _) if super::camera::is_camera(f) => super::camera::read(f, scene),
            (Field::Center, Some(ShapeSpec::Sphere { center, .. })) => *center,
            (Field::Radius, Some(ShapeSpec::Sphere { radius, .. }))
            | (Field::Radius, Some(ShapeSpec::InfiniteCylinder { radius, .. })) => num(*radius),
            (Field::Point, Some(ShapeSpec::Plane { point, .. }))
            | (Field::Point, Some(ShapeSpec::InfiniteCylinder { point, .. })) => *point,
            (Field::Normal, Some(ShapeSpec::Plane { normal, .. })) => *normal,
            (Field::Axis, Some(ShapeSpec::InfiniteCylinder { axis, .. })) => *axis,
            (Field::Color | Field::Color1, _) => c1,
            (Field::Color2, _) => c2,
            (Field::Color3, _) => c3,
            (Field::Kd, _) => num(obj.map_or(0.0, |o| o.material.kd)),
            (Field::Kr, _) => num(obj.map_or(0.0, |o| o.material.kr)),
            (Field::Kt, _) => num(obj.map_or(0.0, |o| o.material.kt)),
            (Field::Ior, _) => num(obj.map_or(1.0, |o| o.material.ior)),
            (Field::TextureScale, _) => num(obj.map_or(1.0, |o| o.texture.scale())),
            (Field::Bump, _) => num(match obj.map(|o| o.material.bump) {
                Some(Bump::Uniform(e) | Bump::Water(e)) => e,
                _ => 0.0,
            }),
            (Field::Position, _) => scene.lights[i].position,
            (Field::LightColor, _) => scene.lights[i].color,
            (Field::Intensity, _) => num(scene.lights[i].intensity),
            (Field::FogDistance, _) => num(fog_distance(scene.fog)),
            _ => DVec3::ZERO,
        }
    }

    /// Puts `v` into `scene` (checked with `check` beforehand), rebuilding the shape from
    /// its record when the field is geometric.
    pub fn apply(&self, scene: &mut Scene, v: DVec3) {
        if super::camera::is_camera(self.field) {
            return super::camera::put(self.field, scene, v);
        }
        self.put(scene, v);
        // An extension object's record says what its object says, as the file would.
        if let Some(item) = scene.specs.get(self.index).and_then(ObjectSpec::item) {
            let on_object = !matches!(
                self.field,
                Field::Ext(_) | Field::Position | Field::LightColor | Field::Intensity
            );
            if let (true, Some(ExtItem::Shape(o))) = (on_object, scene.ext.objects.get_mut(item)) {
                o.texture = scene.objects[self.index].texture.clone();
                o.material = scene.objects[self.index].material;
            }
        }
    }

    fn put(&self, scene: &mut Scene, v: DVec3) {
        let x = v.x;
        let i = self.index;
        match self.field {
            Field::Center | Field::Radius | Field::Point | Field::Normal | Field::Axis => {
                let ObjectSpec::Record(spec) = &mut scene.specs[i] else {
                    return;
                };
                match (self.field, &mut *spec) {
                    (Field::Center, ShapeSpec::Sphere { center, .. }) => *center = v,
                    (Field::Radius, ShapeSpec::Sphere { radius, .. })
                    | (Field::Radius, ShapeSpec::InfiniteCylinder { radius, .. }) => *radius = x,
                    (Field::Point, ShapeSpec::Plane { point, .. })
                    | (Field::Point, ShapeSpec::InfiniteCylinder { point, .. }) => *point = v,
                    (Field::Normal, ShapeSpec::Plane { normal, .. }) => {
                        *normal = direction(v).unwrap_or(v)
                    }
                    (Field::Axis, ShapeSpec::InfiniteCylinder { axis, .. }) => {
                        *axis = direction(v).unwrap_or(v)
                    }
                    _ => {}
                }
                if let Some(shape) = spec.build() {
                    scene.objects[i].shape = shape;
                }
            }
            Field::Color | Field::Color1 | Field::Color2 | Field::Color3 => {
                set_color(&mut scene.objects[i].texture, self.field, v)
            }
            Field::TextureScale => {
                let texture = &mut scene.objects[i].texture;
                *texture = std::mem::replace(texture, Texture::Uniform(DVec3::ZERO)).scaled(x)
            }
            Field::Kd => scene.objects[i].material.kd = x,
            Field::Kr => scene.objects[i].material.kr = x,
            Field::Kt => scene.objects[i].material.kt = x,
            Field::Ior => scene.objects[i].material.ior = x,
            Field::Bump => {
                let bump = &mut scene.objects[i].material.bump;
                *bump = match *bump {
                    Bump::Uniform(_) => Bump::Uniform(x),
                    Bump::Water(_) => Bump::Water(x),
                    Bump::None => Bump::None,
                }
            }
            Field::Position => scene.lights[i].position = v,
            Field::LightColor => scene.lights[i].color = v,
            Field::Intensity => scene.lights[i].intensity = x,
            Field::FogDistance => scene.fog = fog_with_distance(scene.fog, x),
            Field::CameraPosition | Field::CameraLookAt | Field::CameraFov => {
                super::camera::put(self.field, scene, v)
            }
            Field::Ext(f) => {
                super::ext::write(&mut scene.ext, &f, v);
                if let super::Record::Object(item) = f.record {
                    super::ext::rebuild(scene, item);
                }
            }
        }
    }
}

/// The fog's distance D (0 without fog).
fn fog_distance(fog: Fog) -> f64 {
    match fog {
        Fog::None => 0.0,
        Fog::Linear(d) | Fog::Exponential(d) | Fog::ExponentialSquared(d) => d,
    }
}

/// The same kind of fog at distance `d`.
fn fog_with_distance(fog: Fog, d: f64) -> Fog {
    match fog {
        Fog::None => Fog::None,
        Fog::Linear(_) => Fog::Linear(d),
        Fog::Exponential(_) => Fog::Exponential(d),
        Fog::ExponentialSquared(_) => Fog::ExponentialSquared(d),
    }
}

/// A texture's first, second and third colours (zero where it has none).
fn colors(t: &Texture) -> (DVec3, DVec3, DVec3) {
    match *t.pattern() {
        Texture::Uniform(c) => (c, DVec3::ZERO, DVec3::ZERO),
        Texture::Checker(a, b) | Texture::Wood(a, b) | Texture::Marble(a, b) => (a, b, DVec3::ZERO),
        Texture::Perlin(a, b, c) => (a, b, c),
        Texture::Image(_) | Texture::Scaled(..) => (DVec3::ZERO, DVec3::ZERO, DVec3::ZERO),
    }
}

fn set_color(t: &mut Texture, field: Field, v: DVec3) {
    match (t.pattern_mut(), field) {
        (Texture::Uniform(c), Field::Color) => *c = v,
        (
            Texture::Checker(c, _)
            | Texture::Wood(c, _)
            | Texture::Marble(c, _)
            | Texture::Perlin(c, _, _),
            Field::Color1,
        ) => *c = v,
        (
            Texture::Checker(_, c)
            | Texture::Wood(_, c)
            | Texture::Marble(_, c)
            | Texture::Perlin(_, c, _),
            Field::Color2,
        ) => *c = v,
        (Texture::Perlin(_, _, c), Field::Color3) => *c = v,
        _ => {}
    }
}
