//! The tracer's colour: three channels, nominally in 0..1, in the scene's own space
//! (the report's display values for Scene.txt and NFF).

use glam::DVec3;

/// An RGB colour, channels nominally in 0..1.
pub type Color = DVec3;
