//! `whitted`: a Whitted ray tracer faithful to the student report
//! `rapport-raytracing.txt`, as a library. The `raytrace` and `animate` commands (crate
//! `whitted-cli`) and the animation pipeline (crate `whitted-anim`) are built on this
//! crate's public API alone, so a program of your own draws exactly their pixels.
//!
//! The library reads a Scene.txt (`scene`), places the report's camera (`camera`),
//! intersects spheres, planes and quadric cylinders (`shapes`) through acceleration
//! structures (`accel`), colours hits with solid textures (`texture`, `noise`) and bump
//! mapping (`bump`), lights them (`shading`), follows reflection and refraction (`trace`,
//! `optics`), fogs primary rays (`fog`), renders images in parallel (`render`), records
//! passes for compositing (`passes`) and writes RAW, PNG, JPEG, PPM or OpenEXR (`output`).
//! `still` is `raytrace`'s whole run as one call.
//!
//! A Scene.txt to a PNG, as `raytrace Scene.txt -o picture.png` draws it:
//!
//! ```
//! use whitted::still::{Job, Request};
//!
//! # fn main() -> Result<(), Box<dyn std::error::Error>> {
//! # let dir = tempfile::tempdir()?;
//! # let scene = dir.path().join("Scene.txt");
//! # std::fs::write(&scene, "32 24  0 0 5  0 0 0  0 0  1 0 0 1\n1 0 0 0  1 1 0 0  1 0 0 1 0 0\n0 5 5  1 1 1  1\n")?;
//! # let png = dir.path().join("picture.png");
//! let request = Request {
//!     scene: scene.clone(),   // the report's text format (docs/scene-format.md)
//!     out: Some(png.clone()), // the format follows the extension
//!     samples: 1,             // n×n samples a pixel
//!     ..Request::default()
//! };
//! let done = Job::prepare(&request)?.run()?; // on rayon's global pool
//! assert_eq!(done.size, (32, 24));
//! assert!(std::fs::read(&png)?.starts_with(b"\x89PNG"));
//! # Ok(())
//! # }
//! ```
//!
//! The same, step by step, with the pixels in memory:
//!
//! ```
//! use whitted::render::{render, Options, Picture};
//! use whitted::{trace::Tracer, Scene};
//!
//! // 4×3 pixels, eye at z = 5 looking at the origin, no fog, one red sphere, one light.
//! let scene = Scene::parse(
//!     "4 3  0 0 5  0 0 0  0 0  1 0 0 1
//!      1 0 0 0  1 1 0 0  1 0 0 1 0 0
//!      0 5 5  1 1 1  1",
//!     "example.txt",
//! )
//! .unwrap();
//! let tracer = Tracer::new(&scene);
//! let (frame, rays) = render(&tracer, &scene.camera(), &Options::grid(4, 3, 1), Picture::new());
//! assert_eq!(frame.pixels.len(), 4 * 3 * 3);
//! // The centre of the image sees the lit red sphere: red, no green or blue.
//! let centre = &frame.pixels[(1 * 4 + 1) * 3..][..3];
//! assert!(centre[0] > 100 && centre[1] == 0 && centre[2] == 0, "{centre:?}");
//! assert!(rays.primary == 12);
//! ```

#![warn(missing_docs)]

pub mod accel;
pub mod base;
pub mod bump;
pub mod camera;
pub mod display;
pub mod exit;
pub mod fileloc;
pub mod fog;
pub mod gltf;
pub mod info;
pub mod input;
pub mod lights;
pub mod limits;
pub mod load;
pub mod mesh;
pub mod noise;
pub mod object;
pub mod optics;
pub mod output;
pub mod passes;
pub mod pick;
pub mod record;
pub mod render;
pub mod scene;
pub mod shading;
pub mod shapes;
pub mod spd;
pub mod still;
pub mod texture;
pub mod trace;

pub use base::{Color, Frame};
pub use camera::Camera;
pub use fileloc::FileLoc;
pub use render::render;
pub use scene::{Scene, SceneError};
