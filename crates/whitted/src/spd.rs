//! The Standard Procedural Databases' testing procedure (Haines, SPD README, "Testing
//! Procedures" 6 to 10; SPEC §17) as a render setting, beside the report's rules:
//!
//! - 513 × 513 eye rays through the pixel corners of a 512 × 512 picture, each pixel the
//!   average of its four corners (each corner clamped to 0..1 first, as supersamples
//!   are): `render::Options::corners`. The corner rays are the pixel centres of a
//!   513 × 513 view, so an NFF's `angle` spans the outer corner rays;
//! - a tree depth of 5 with the eye ray at depth 1 (4 bounces after it), and no weight
//!   cut-off: `Rules::spd`;
//! - every ray hitting a reflective (Ks > 0) or transmitting (T > 0) surface spawns a
//!   reflection ray, and a transmitting one a refraction ray too; on total internal
//!   reflection there is no refracted ray, the reflection ray carries the transmitted
//!   weight as well, and the refraction is still counted (that is the SPD table's count:
//!   see docs/decisions.md): `Tracer::spawn_spd`;
//! - shadow rays only to the lights the (ray-facing) shading normal faces, as always.

pub use crate::trace::rules::{Rules, SPD_DEPTH};

/// The SPD's picture size, 512 × 512.
pub const SPD_SIZE: u32 = 512;
