//! What a scene holds, told without drawing it (`raytrace SCENE --info`, SPEC §18): each
//! object with its number, name, kind, triangle count and world bounds (after its
//! modifiers, `fit` and `pivot`), each light with its number, name, kind and place, and
//! the camera (eye, look-at, size, vertical field of view); and the warnings that help
//! place a model: the camera inside an object's bounds, an object that would cover less
//! than one pixel.
//!
//! ```text
//! let info = describe(&request)?;    // the scene loaded as `raytrace` would, nothing drawn
//! print!("{info}");                  // object 1  sphere 1  sphere  -  [-1, 0, -1] to [1, 2, 1]
//! info.warnings                      // "the camera … is inside the bounds of object 3 (bunny) …"
//! ```
//!
//! An object under a pixel: with s the length of its bounds' diagonal, d the distance
//! from the eye to the bounds' centre, and p = H / h the view plane's height at
//! distance 1 over the picture's height in pixels (one pixel's footprint at distance 1),
//! the object spans at most s / (d·p) pixels; below 1 it is warned about.

mod show;
#[cfg(test)]
mod tests;

use crate::camera::Lens;
use crate::scene::Scene;
use crate::shapes::Shape;
use crate::still::{Request, StillError};
use glam::DVec3;

/// One object of the scene, as `--info` tells it.
#[derive(Clone, Debug, PartialEq)]
pub struct ObjectInfo {
    /// Its number, from 1 in the scene's order (the report's objects first).
    pub number: usize,
    /// Its name (`sphere 3`, or the record's `name`).
    pub name: String,
    /// Its kind (`sphere`, `mesh`, `csg`, …).
    pub kind: &'static str,
    /// Its triangles (a mesh's, 1 for a triangle); `None` for the other shapes.
    pub triangles: Option<usize>,
    /// Its world box, low and high corners; `None` for an unbounded object.
    pub bounds: Option<(DVec3, DVec3)>,
}

/// Where a light is, by its kind.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LightPlace {
    /// A point, spot or area light's position (an area light's centre).
    At(DVec3),
    /// A directional light's direction of travel.
    Towards(DVec3),
}

/// One light of the scene, as `--info` tells it.
#[derive(Clone, Debug, PartialEq)]
pub struct LightInfo {
    /// Its number, from 1 in the order the tracer lights with them.
    pub number: usize,
    /// Its name (`light 2`, `spot 1`, or the record's `name`).
    pub name: String,
    /// Its kind: `point`, `spot`, `area` or `directional`.
    pub kind: &'static str,
    /// Where it is.
    pub place: LightPlace,
}

/// The camera `raytrace` would draw through.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CameraInfo {
    /// The eye.
    pub eye: DVec3,
    /// The point looked at.
    pub look_at: DVec3,
    /// The picture's size in pixels.
    pub size: (u32, u32),
    /// The view plane's width and height at distance 1.
    pub plane: (f64, f64),
}

impl CameraInfo {
    /// The vertical field of view in degrees: the angle between the picture's top and
    /// bottom edges.
    pub fn fov(&self) -> f64 {
        2.0 * (self.plane.1 / 2.0).atan().to_degrees()
    }

    /// The horizontal field of view in degrees.
    pub fn fov_horizontal(&self) -> f64 {
        2.0 * (self.plane.0 / 2.0).atan().to_degrees()
    }

    /// How many pixels of the picture's height a length `s`, seen square-on at distance
    /// `d` from the eye, spans.
    pub fn pixels_spanned(&self, s: f64, d: f64) -> f64 {
        let footprint = self.plane.1 / f64::from(self.size.1.max(1));
        s / (d * footprint)
    }
}

/// Everything `--info` prints: objects, lights, camera, and the warnings.
#[derive(Clone, Debug, PartialEq)]
pub struct Info {
    /// The objects, in the scene's order.
    pub objects: Vec<ObjectInfo>,
    /// The lights, in the order the tracer lights with them.
    pub lights: Vec<LightInfo>,
    /// The camera.
    pub camera: CameraInfo,
    /// The scene's mesh warnings, then the camera inside an object's bounds and the
    /// objects under a pixel.
    pub warnings: Vec<String>,
}

impl Info {
    /// `scene` (whose own size is `native`) as a picture of `size` through `lens`.
    pub fn of(scene: &Scene, native: (u32, u32), size: (u32, u32), lens: &Lens) -> Info {
        let objects = objects(scene);
        let lights = lights(scene);
        let camera = CameraInfo {
            eye: scene.eye,
            look_at: scene.look_at,
            size,
            plane: lens.plane(native, size),
        };
        let mut warnings: Vec<String> = scene
            .meshes
            .iter()
            .flat_map(|m| m.warnings.iter().cloned())
            .collect();
        warnings.extend(placing_warnings(&objects, &camera));
        Info {
            objects,
            lights,
            camera,
            warnings,
        }
    }
}

/// The scene of `request`, loaded as `raytrace` would load it (a manifest refused), told
/// at the request's size and lens; nothing is drawn and no file is written.
pub fn describe(request: &Request) -> Result<Info, StillError> {
    if request.scene.extension().is_some_and(|e| e == "toml") {
        return Err(StillError::NotAScene(request.scene.display().to_string()));
    }
    let scene = Scene::load(&request.scene)?;
    let native = (scene.width, scene.height);
    let spd = (crate::spd::SPD_SIZE, crate::spd::SPD_SIZE);
    let size = if request.spd {
        spd
    } else {
        request.size.unwrap_or(native)
    };
    let lens = (scene.lens).overridden(request.lens.fov, request.lens.roll);
    Ok(Info::of(&scene, native, size, &lens))
}

fn objects(scene: &Scene) -> Vec<ObjectInfo> {
    let names = scene.object_names();
    let specs = scene.objects.iter().zip(&scene.specs).zip(names);
    specs
        .enumerate()
        .map(|(i, ((object, spec), name))| {
            let triangles = match &object.shape {
                Shape::Mesh(m) => scene.meshes.get(m.id as usize).map(|m| m.triangles.len()),
                Shape::Triangle(_) | Shape::Smooth(_) => Some(1),
                _ => None,
            };
            ObjectInfo {
                number: i + 1,
                name,
                kind: spec.kind(),
                triangles,
                bounds: object.shape.bounds(),
            }
        })
        .collect()
}

fn lights(scene: &Scene) -> Vec<LightInfo> {
    let report = scene
        .lights
        .iter()
        .map(|l| ("point", LightPlace::At(l.position)));
    let ext = scene.ext.lights.iter().map(|l| {
        let place = match (l.kind.position(), l.kind.direction()) {
            (Some(position), _) => LightPlace::At(position),
            (None, direction) => LightPlace::Towards(direction.unwrap_or_default()),
        };
        (l.kind.keyword(), place)
    });
    let names = scene.light_names();
    report
        .chain(ext)
        .zip(names)
        .enumerate()
        .map(|(i, ((kind, place), name))| LightInfo {
            number: i + 1,
            name,
            kind,
            place,
        })
        .collect()
}

/// The camera inside an object's bounds, and each object that would cover less than one
/// pixel.
fn placing_warnings(objects: &[ObjectInfo], camera: &CameraInfo) -> Vec<String> {
    let mut out = Vec::new();
    let eye = camera.eye;
    for o in objects {
        let Some((lo, hi)) = o.bounds else { continue };
        let who = format!("object {} ({})", o.number, o.name);
        if eye.cmpgt(lo).all() && eye.cmplt(hi).all() {
            out.push(format!(
                "the camera at {} is inside the bounds of {who}, {} to {}: it sees the object from within, or not at all",
                show::point(eye),
                show::point(lo),
                show::point(hi)
            ));
            continue;
        }
        let (s, d) = ((hi - lo).length(), (0.5 * (lo + hi) - eye).length());
        let spans = camera.pixels_spanned(s, d);
        if spans < 1.0 {
            out.push(format!(
                "{who} would cover less than one pixel: its bounds' diagonal {} at distance {} spans {} pixel of the {}-pixel height (fit, scale or move the camera closer)",
                show::num(s),
                show::num(d),
                show::num(spans),
                camera.size.1
            ));
        }
    }
    out
}
