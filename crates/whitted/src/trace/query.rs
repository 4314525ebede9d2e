//! Making a tracer for a scene, and what callers ask of it besides a camera ray's
//! colour: its rules and tree, the nearest object along a ray (picking, the passes'
//! tests) and a shadow ray's transmission, each exactly as the trace itself finds them.

use super::{Rules, Tracer};
use crate::accel::{Accel, Hit, LightBuffer};
use crate::base::Color;
use crate::object::Object;
use crate::optics::Ray;
use crate::scene::Scene;
use glam::DVec3;
use std::sync::Arc;

#[cfg(test)]
thread_local! {
    /// Tracers made on this thread, for tests that ask how many a call builds.
    pub(crate) static MADE: std::cell::Cell<usize> = const { std::cell::Cell::new(0) };
}

impl<'a> Tracer<'a> {
    /// The scene this tracer draws.
    pub fn scene(&self) -> &'a Scene {
        self.scene
    }

    /// Prepares `scene` for tracing: builds its BVH (once; every frame shares it).
    pub fn new(scene: &'a Scene) -> Tracer<'a> {
        #[cfg(test)]
        MADE.with(|m| m.set(m.get() + 1));
        Tracer::with_accel(scene, Arc::new(Accel::for_scene(scene)))
    }

    /// A tracer for `scene` that reuses `accel`, built by `Accel::new` from objects with
    /// the same shapes and the same transparency (Kt > 0 or not) as `scene`'s: only
    /// colours, other coefficients and lights may differ. The caller guarantees it. (The
    /// light buffer, which depends on the lights too, is built here from `scene`.)
    pub fn with_accel(scene: &'a Scene, accel: Arc<Accel>) -> Tracer<'a> {
        Tracer {
            scene,
            accel,
            lights: LightBuffer::for_scene(scene),
            ext_lights: crate::scene::ext::build::lights(&scene.ext),
            rules: Rules::default(),
        }
    }

    /// This tracer with other limits (the SPD's testing procedure: `Rules::spd`).
    pub fn with_rules(mut self, rules: Rules) -> Tracer<'a> {
        self.rules = rules;
        self
    }

    /// The limits this tracer follows.
    pub fn rules(&self) -> Rules {
        self.rules
    }

    /// The acceleration structure, to share with `with_accel`.
    pub fn accel(&self) -> &Arc<Accel> {
        &self.accel
    }

    /// The nearest object hit, with its t: the first object in file order among those at
    /// the smallest t, exactly as a linear scan in file order finds it.
    #[inline]
    pub fn nearest(&self, ray: &Ray) -> Option<(f64, &'a Object)> {
        let objects = &self.scene.objects;
        self.nearest_index(ray).map(|(t, i)| (t, &objects[i]))
    }

    /// `nearest`, naming the object by its index in the scene's objects.
    #[inline]
    pub fn nearest_index(&self, ray: &Ray) -> Option<(f64, usize)> {
        self.accel.nearest(ray)
    }

    /// `nearest_index` with, on a mesh, the triangle hit (`accel::Hit`).
    #[inline]
    pub fn nearest_hit(&self, ray: &Ray) -> Option<Hit> {
        self.accel.nearest_hit(ray)
    }

    /// What a shadow ray from `p` towards a light `dist` away along the unit `to_light`
    /// lets through: exactly `shading::transmission(&scene.objects, ..)`.
    #[inline]
    pub fn transmission(&self, p: DVec3, to_light: DVec3, dist: f64) -> Color {
        self.accel
            .transmission(&self.scene.objects, p, to_light, dist)
    }
}
