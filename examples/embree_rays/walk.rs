//! The rays a frame casts, found again through the tracer's public queries: the walk the
//! trace loop (`whitted::trace`, the report's rules) takes through a picture of one
//! pinhole ray a pixel, casting the same rays in the same order, each handed to a sink
//! with the answer our accelerator gives for it.
//!
//! - a camera ray through each pixel centre, rows top to bottom, with the scene's epsilon;
//! - at each hit, in the light loop's order, a shadow ray to each point light the shading
//!   normal faces (N·L > 0), over (epsilon, distance to the light);
//! - then, below `MAX_DEPTH` bounces, a reflection ray where Kr > 0 and a refraction ray
//!   where Kt > 0 (a total internal reflection's ray counted as a refraction), each only
//!   while the path's weight stays at least `MIN_WEIGHT`.
//!
//! The trace loop is not touched: this walk repeats its decisions with the same public
//! functions (`surface_at`, `facing`, `reflect`, `refract`, `Ray::spawn`,
//! `LightSource::incident`), and a test holds its per-kind counts to the `RayCount` the
//! real render reports. Scenes the walk does not follow (extension lights, a `focus`
//! record, the SPD's rules) are refused.

use glam::DVec3;
use whitted::camera::{Camera, Lens};
use whitted::lights::LightSource;
use whitted::optics::{reflect, refract, Ray};
use whitted::render::rays_per_sample;
use whitted::trace::{facing, surface_at, RayCount, Rules, Tracer};
use whitted::Scene;

/// What a ray is for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// Through a pixel centre.
    Camera = 0,
    /// A mirror reflection.
    Reflect = 1,
    /// A refraction, or the reflection a total internal reflection turns it into.
    Refract = 2,
    /// Towards a light, over a bounded range.
    Shadow = 3,
}

/// One ray cast, and what our accelerator answers for it: the nearest hit over
/// (`ray.t_min`, ∞) as (t, object index), for a shadow ray too (it is blocked when that t
/// is below `t_max`).
#[derive(Clone, Copy, Debug)]
pub struct Cast {
    /// Its purpose.
    pub kind: Kind,
    /// Origin, unit direction, and the start of its range.
    pub ray: Ray,
    /// The end of its range: infinity, or a shadow ray's distance to the light.
    pub t_max: f64,
    /// Our nearest hit past `ray.t_min`, with no upper bound.
    pub hit: Option<(f64, usize)>,
}

/// Why a scene cannot be walked.
#[derive(Debug, PartialEq, Eq)]
pub struct Unsupported(pub &'static str);

impl std::fmt::Display for Unsupported {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "the ray walk does not follow {}", self.0)
    }
}

impl std::error::Error for Unsupported {}

/// The camera `raytrace SCENE` draws through: the scene's own size and lens.
pub fn camera(scene: &Scene) -> Option<Camera> {
    let native = (scene.width, scene.height);
    let lens: Lens = scene.lens.overridden(None, 0.0);
    Camera::framed(scene.eye, scene.look_at, native, native, &lens)
}

/// Walks every ray of the picture `tracer` draws through `camera` at `width` × `height`,
/// one ray a pixel, handing each to `sink`; returns the rays counted as the tracer counts
/// them.
pub fn walk(
    tracer: &Tracer,
    camera: &Camera,
    width: u32,
    height: u32,
    sink: &mut dyn FnMut(&Cast),
) -> Result<RayCount, Unsupported> {
    let scene = tracer.scene();
    if !scene.ext.lights.is_empty() {
        return Err(Unsupported("the extension's light records"));
    }
    if rays_per_sample(scene) != 1 {
        return Err(Unsupported("a focus record"));
    }
    if tracer.rules() != Rules::default() {
        return Err(Unsupported("the SPD's rules"));
    }
    let mut w = Walker {
        tracer,
        count: RayCount::default(),
        sink,
    };
    for j in 0..height {
        for i in 0..width {
            let ray = camera.ray(i as f64 + 0.5, j as f64 + 0.5);
            w.primary(&ray.with_t_min(scene.t_min));
        }
    }
    Ok(w.count)
}

struct Walker<'t, 's> {
    tracer: &'t Tracer<'s>,
    count: RayCount,
    sink: &'t mut dyn FnMut(&Cast),
}

impl Walker<'_, '_> {
    /// The nearest hit of `ray` (t, object, mesh triangle), handed to the sink as a ray
    /// of `kind` (unbounded).
    fn cast(&mut self, kind: Kind, ray: &Ray) -> Option<(f64, usize, u32)> {
        let hit = self.tracer.nearest_hit(ray).map(|h| (h.t, h.index, h.part));
        (self.sink)(&Cast {
            kind,
            ray: *ray,
            t_max: f64::INFINITY,
            hit: hit.map(|(t, i, _)| (t, i)),
        });
        hit
    }

    fn primary(&mut self, ray: &Ray) {
        self.count.primary += 1;
        if let Some(hit) = self.cast(Kind::Camera, ray) {
            self.count.eye_hits += 1;
            self.shade(ray, hit, 0, 1.0);
        }
    }

    fn secondary(&mut self, kind: Kind, ray: &Ray, depth: u32, weight: f64) {
        self.count.secondary += 1;
        if let Some(hit) = self.cast(kind, ray) {
            self.shade(ray, hit, depth, weight);
        }
    }

    /// The rays spawned at the hit (t, object, mesh triangle) of `ray`:
    /// `Tracer::shade_rec`'s.
    fn shade(&mut self, ray: &Ray, (t, index, part): (f64, usize, u32), depth: u32, weight: f64) {
        let tracer = self.tracer;
        let scene = tracer.scene();
        let p = ray.at(t);
        let surface = tracer.surface_of(&scene.objects[index], part, p);
        let v = ray.dir;
        let (obj, outward) = surface_at(&surface, ray, p);
        let m = obj.material;
        let (n, entering) = facing(obj, outward, p, v);
        for light in &scene.lights {
            let Some(inc) = light.incident(p) else {
                continue;
            };
            if n.dot(inc.l) <= 0.0 {
                continue;
            }
            self.shadow(p, inc.l, inc.dist);
        }
        let rules = tracer.rules();
        if depth >= rules.max_depth {
            return;
        }
        if m.kr > 0.0 && weight * m.kr >= rules.min_weight {
            self.count.reflect += 1;
            let r = ray.spawn(p, reflect(v, n).normalize());
            self.secondary(Kind::Reflect, &r, depth + 1, weight * m.kr);
        }
        if m.kt > 0.0 && weight * m.kt >= rules.min_weight {
            let eta = if entering { 1.0 / m.ior } else { m.ior };
            self.count.refract += 1;
            let dir = refract(v, n, eta).unwrap_or_else(|| reflect(v, n));
            let r = ray.spawn(p, dir.normalize());
            self.secondary(Kind::Refract, &r, depth + 1, weight * m.kt);
        }
    }

    /// A shadow ray from `p` along the unit `l` over (epsilon, `dist`), as the
    /// accelerator casts it (`Ray::new` with the scene's epsilon).
    fn shadow(&mut self, p: DVec3, l: DVec3, dist: f64) {
        self.count.shadow += 1;
        let ray = Ray::new(p, l).with_t_min(self.tracer.scene().t_min);
        let hit = self.tracer.nearest_hit(&ray).map(|h| (h.t, h.index));
        (self.sink)(&Cast {
            kind: Kind::Shadow,
            ray,
            t_max: dist,
            hit,
        });
    }
}
