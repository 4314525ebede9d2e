//! What the passes hear of a camera ray (`Record`), and the recorder that hears nothing
//! (`NoRecord`). Its own home so that both the trace loop (`trace`) and the light loop
//! (`shading`) can call the hooks without importing each other; `trace` re-exports both.

use crate::base::Color;
use glam::DVec3;

/// What the passes hear of a camera ray: its first hit and the parts its colour is the
/// sum of. Only the camera ray's own shading calls these (the rays it spawns are traced
/// with `NoRecord`), and only when `ACTIVE`.
pub trait Record {
    /// False for the no-op recorder: every hook call is then compiled out.
    const ACTIVE: bool;
    /// The ray hit object number `index` (file order) at distance `t`.
    fn object(&mut self, _index: usize, _t: f64) {}
    /// The hit's point, shading normal (after bump, facing the ray) and texture colour.
    fn surface(&mut self, _p: DVec3, _n: DVec3, _albedo: Color) {}
    /// The ambient term.
    fn ambient(&mut self, _c: Color) {}
    /// The light the surface emits (a glTF material's emission).
    fn emission(&mut self, _c: Color) {}
    /// One light's diffuse and specular terms, each already times its shadow transmission.
    fn light(&mut self, _diffuse: Color, _specular: Color) {}
    /// The reflected ray's term, Kr·trace(R).
    fn reflection(&mut self, _c: Color) {}
    /// The refracted ray's term (or, on total internal reflection, Kt·trace(R)).
    fn transmission(&mut self, _c: Color) {}
    /// The fog fraction f at the hit (1 − f scales every term; f·white is added).
    fn fog(&mut self, _f: f64) {}
    /// The ray hit nothing and sees the scene's background colour `c` (before fog).
    fn background(&mut self, _c: Color) {}
    /// The first surface the ray sees covers α of it (a glTF BLEND material): the terms
    /// heard next, fog included, are that surface's, and weigh α.
    fn cover(&mut self, _alpha: f64) {}
    /// What the ray sees behind a surface that covers part of it, already weighted
    /// (1 − α) and fogged: heard after that surface's terms.
    fn behind(&mut self, _c: Color) {}
    /// A scene in linear light: the sample's colour `linear`, as its terms sum to it, is
    /// stored as the display value `shown` (each channel sRGB-encoded).
    fn encoded(&mut self, _linear: Color, _shown: Color) {}
}

/// The recorder of the beauty-only path: zero-sized, hears nothing.
#[derive(Clone, Copy, Debug, Default)]
pub struct NoRecord;

impl Record for NoRecord {
    const ACTIVE: bool = false;
}
