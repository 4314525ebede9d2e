//! A Whitted ray tracer faithful to the student report `rapport-raytracing.txt`, and the
//! animation pipeline around it.
//!
//! The library reads a Scene.txt (`scene`), places the report's camera (`camera`),
//! intersects spheres, planes and quadric cylinders (`shapes`), colours hits with solid
//! textures (`texture`, `noise`) and bump mapping (`bump`), lights them (`shading`),
//! follows reflection and refraction (`trace`, `optics`), fogs primary rays (`fog`) and
//! renders images in parallel (`render`) that `output` writes as RAW, PNG, JPEG or PPM.
//! `raytrace` (one image) and `animate` (frame sequences) are thin binaries over it, so
//! both draw exactly the same pixels.

pub mod accel;
pub mod anim;
pub mod bump;
pub mod camera;
pub mod fog;
pub mod noise;
pub mod object;
pub mod optics;
pub mod output;
pub mod render;
pub mod scene;
pub mod shading;
pub mod shapes;
pub mod texture;
pub mod trace;

pub use camera::Camera;
pub use render::{render, Frame};
pub use scene::{Scene, SceneError};
