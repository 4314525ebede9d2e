//! The ground floor: the values every other part of the tracer shares, which import
//! nothing of the crate above them: a colour (`Color`), an 8-bit image and the
//! clamp-and-round that fills it (`Frame`, `to_byte`), and the sRGB curve with the two
//! encodings of a float frame (`srgb`). Readers, shapes, lights, the renderer, the passes
//! and the writers all stand on it, so no arrow runs back up from here.

pub mod color;
pub mod image;
pub mod srgb;

pub use color::Color;
pub use image::{to_byte, to_rgb, Frame};
pub use srgb::Transfer;
