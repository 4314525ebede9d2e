//! The Neutral File Format of Eric Haines' Standard Procedural Databases (SPEC §17), read
//! into the same `Scene` a Scene.txt gives. Records, each starting with its keyword, any
//! number of blanks and newlines between tokens, `#` comments to the end of the line:
//!
//! ```text
//! v                        # the view, exactly once, before any object
//! from 2.1 1.3 1.7         #   the eye
//! at 0 0 0                 #   the point looked at (not the eye)
//! up 0 0 1                 #   the world's up (not zero, not along the view)
//! angle 45                 #   degrees between the outer pixel centres, 0 < angle < 180
//! hither 0.01              #   read and not used (no near clipping)
//! resolution 512 512       #   pixels
//! b 0.078 0.361 0.753      # background colour (default black)
//! l 4 3 2 [1 1 1]          # positional light, optional colour
//! f R G B Kd Ks Shine T ior  # material of the objects after it
//! c                        # open cone or cylinder: base centre and radius, then apex
//! 0 0 0 0.15   0 0 1 0.1   #   (negative radii: taken by their size)
//! s 0 0 0 0.5              # sphere: centre, radius (not 0; negative: by its size)
//! p 3                      # polygon: n ≥ 3 coplanar vertices, convex or not
//! 0 0 0  1 0 0  0 1 0
//! pp 3                     # patch: n ≥ 3 vertices, each with its normal
//! 0 0 0 0 0 1  1 0 0 0 0 1  0 1 0 0 0 1
//! ```
//!
//! Shading (SPEC §17): ambient 0.2·C, diffuse Kd, a Phong highlight Ks with exponent
//! Shine, reflection Ks, transmission T with the index ior (> 0 when T > 0). A light
//! without a colour is white of intensity √n/(2n) for n lights (the SPD's suggestion);
//! with one, that colour at intensity 1. A polygon becomes n − 2 triangles
//! (`polygon`), a patch a fan of smooth triangles, each an object of its own ("triangle
//! N", "patch N"). Hits count past `epsilon`. Errors: an unknown record, a polygon short
//! of vertices, an object before any `f`, no `v`, `nan` or `inf`, a negative colour,
//! degenerate shapes, more than `MAX_SCENE_OBJECTS` objects (a polygon's triangles count
//! one each), all located at file:line:column.

mod ears;
pub mod polygon;
mod reader;

use super::{ObjectSpec, Scene, SceneError, ShapeSpec, MAX_PIXELS, MAX_SIDE};
use crate::base::Color;
use crate::camera::Lens;
use crate::fog::Fog;
use crate::lights::PointLight;
use crate::limits::MAX_SCENE_OBJECTS;
use crate::object::{Highlight, Material, Object};
use crate::shapes::{Cone, SmoothTriangle, Triangle};
use crate::texture::Texture;
use glam::DVec3;
use reader::{Context, Reader, Result};
use std::path::Path;

/// The relative epsilon: a hit counts past `EPSILON_SCALE` times the scene's size.
pub const EPSILON_SCALE: f64 = 1e-7;
/// The most vertices one polygon or patch may have.
pub const MAX_VERTICES: u64 = 1_000_000;

/// Whether `path` names an NFF file (its extension is `nff`, any case).
pub fn is_nff(path: &Path) -> bool {
    path.extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("nff"))
}

/// The scene's hit epsilon: `EPSILON_SCALE` × the largest coordinate magnitude of the
/// eye and of every object's box (1 if that is 0). Rounding moves a hit point by a few
/// ulps of that size (2.2e-16 × it); 1e-7 × it leaves a margin of some 10⁸ ulps against
/// a ray finding the surface it leaves, and swallows nothing larger than a ten-millionth
/// of the scene (the sphereflake's smallest spheres, radius 0.006, are 1/350 of it).
pub fn epsilon(eye: DVec3, objects: &[Object]) -> f64 {
    let mut size = eye.abs().max_element();
    for o in objects {
        if let Some((lo, hi)) = o.shape.bounds() {
            size = size.max(lo.abs().max_element()).max(hi.abs().max_element());
        }
    }
    EPSILON_SCALE * if size > 0.0 { size } else { 1.0 }
}

/// The view record's values.
struct View {
    from: DVec3,
    at: DVec3,
    up: DVec3,
    angle: f64,
    resolution: (u32, u32),
}

/// What has been read so far.
#[derive(Default)]
struct Built {
    objects: Vec<Object>,
    specs: Vec<ObjectSpec>,
    /// Positions and colours as given.
    lights: Vec<(DVec3, Option<Color>)>,
    background: Color,
    material: Option<(Texture, Material)>,
}

impl Built {
    fn push(&mut self, spec: ShapeSpec, r: &Reader, start: (usize, usize)) -> Result<()> {
        if self.objects.len() as u64 >= MAX_SCENE_OBJECTS {
            let msg = format!(
                "one object too many: a scene may have {MAX_SCENE_OBJECTS} objects in all (a polygon's triangles count one each)"
            );
            return Err(r.error_at(start, msg));
        }
        let Some((texture, material)) = self.material.clone() else {
            let msg = "an object before any 'f' record: its material is unknown".to_string();
            return Err(r.error_at(start, msg));
        };
        self.objects.push(Object {
            shape: spec.build().expect("an NFF record"),
            texture,
            material,
        });
        self.specs.push(ObjectSpec::Record(spec));
        Ok(())
    }
}

/// Parses NFF source; `file` is the name errors carry.
pub fn parse(src: &str, file: &str) -> std::result::Result<Scene, SceneError> {
    let mut r = Reader::new(src, file);
    let mut b = Built::default();
    let mut view: Option<View> = None;
    while let Some(tok) = r.next() {
        let at = (tok.line, tok.column);
        r.context = Context::Record(tok.text, tok.line);
        match tok.text {
            "v" => {
                if view.is_some() {
                    return Err(r.error_at(at, "a second 'v' record: a file has one view".into()));
                }
                view = Some(read_view(&mut r, at)?);
            }
            "b" => b.background = color(&mut r, "background")?,
            "l" => {
                let p = r.vector("light position")?;
                let c = if r.number_follows() {
                    Some(color(&mut r, "light colour")?)
                } else {
                    None
                };
                b.lights.push((p, c));
            }
            "f" => b.material = Some(read_material(&mut r)?),
            "s" => {
                let center = r.vector("centre")?;
                let radius = r.number("radius")?.abs();
                if radius == 0.0 {
                    return Err(r.error_at(at, "a sphere of radius 0".into()));
                }
                b.push(ShapeSpec::Sphere { center, radius }, &r, at)?;
            }
            "c" => {
                let base = (r.vector("base")?, r.number("base radius")?);
                let apex = (r.vector("apex")?, r.number("apex radius")?);
                if Cone::new(base.0, base.1, apex.0, apex.1).is_none() {
                    let msg = "a degenerate cone: its ends coincide or both radii are 0";
                    return Err(r.error_at(at, msg.into()));
                }
                let (base, apex) = ((base.0, base.1.abs()), (apex.0, apex.1.abs()));
                b.push(ShapeSpec::OpenCone { base, apex }, &r, at)?;
            }
            "p" => read_polygon(&mut r, &mut b, at, false)?,
            "pp" => read_polygon(&mut r, &mut b, at, true)?,
            other => {
                let msg = format!(
                    "unknown record '{}': expected v, b, l, f, c, s, p or pp",
                    crate::input::quote(other)
                );
                return Err(r.error(&tok, msg));
            }
        }
    }
    let Some(v) = view else {
        r.context = Context::WholeFile;
        return Err(r.error_at(r.end(), "no 'v' record: the file has no view".into()));
    };
    let n = b.lights.len() as f64;
    let share = n.sqrt() / (2.0 * n);
    let lights = b
        .lights
        .iter()
        .map(|&(position, c)| PointLight {
            position,
            color: c.unwrap_or(Color::ONE),
            intensity: if c.is_some() { 1.0 } else { share },
        })
        .collect();
    Ok(Scene {
        width: v.resolution.0,
        height: v.resolution.1,
        eye: v.from,
        look_at: v.at,
        fog: Fog::None,
        t_min: epsilon(v.from, &b.objects),
        objects: b.objects,
        specs: b.specs,
        lights,
        background: b.background,
        lens: Lens {
            fov: Some(v.angle),
            roll: 0.0,
            up: v.up.normalize(),
            centres: true,
        },
        ext: Default::default(),
        meshes: Vec::new(),
        pbr: Vec::new(),
        parallel: None,
        linear: false,
        model: None,
    })
}

/// A colour: three numbers, none negative (as Scene.txt's colours; above 1 is taken, as
/// the SPD's files may brighten a light).
fn color(r: &mut Reader, field: &str) -> Result<Color> {
    let mut c = [0.0; 3];
    for (k, name) in ['x', 'y', 'z'].into_iter().enumerate() {
        let at = r.peek().map(|t| (t.line, t.column));
        let v = r.number(format_args!("{field} {name}"))?;
        if v < 0.0 {
            let msg = format!("a negative {field} component ({v}): colours are 0 or more");
            return Err(r.error_at(at.unwrap_or_else(|| r.end()), msg));
        }
        c[k] = v;
    }
    Ok(Color::from_array(c))
}

fn read_view(r: &mut Reader, at: (usize, usize)) -> Result<View> {
    r.keyword("from")?;
    let from = r.vector("from")?;
    r.keyword("at")?;
    let look = r.vector("at")?;
    r.keyword("up")?;
    let up = r.vector("up")?;
    r.keyword("angle")?;
    let angle = r.number("angle")?;
    r.keyword("hither")?;
    r.number("hither")?;
    r.keyword("resolution")?;
    let w = r.integer("resolution x", 1, u64::from(MAX_SIDE))?;
    let h = r.integer("resolution y", 1, u64::from(MAX_SIDE))?;
    let refuse = |m: &str| Err(r.error_at(at, m.to_string()));
    if w * h > MAX_PIXELS {
        return refuse("the resolution is past 2^26 pixels (it would need gigabytes)");
    }
    if !(angle > 0.0 && angle < 180.0) {
        return refuse("the view's angle must be between 0 and 180 degrees");
    }
    let Some(dir) = (look - from).try_normalize() else {
        return refuse("the view's 'from' is its 'at': there is no direction to look in");
    };
    match up.try_normalize() {
        Some(u) if u.cross(dir).length() > 1e-9 => {}
        _ => return refuse("the view's 'up' is zero or along the direction looked in"),
    }
    Ok(View {
        from,
        at: look,
        up,
        angle,
        resolution: (w as u32, h as u32),
    })
}

fn read_material(r: &mut Reader) -> Result<(Texture, Material)> {
    let c = color(r, "colour")?;
    let kd = r.number("Kd")?;
    let ks = r.number("Ks")?;
    let shine = r.number("Shine")?;
    let kt = r.number("T")?;
    let ior = r.number("index of refraction")?;
    if kt > 0.0 && ior <= 0.0 {
        let msg = "a transmitting material (T > 0) needs an index of refraction > 0";
        return Err(r.error_at(r.end(), msg.into()));
    }
    let material = Material {
        kd,
        kr: ks,
        kt,
        ior,
        bump: crate::bump::Bump::None,
        highlight: Highlight::Phong { ks, shine },
    };
    Ok((Texture::Uniform(c), material))
}

fn read_polygon(r: &mut Reader, b: &mut Built, at: (usize, usize), smooth: bool) -> Result<()> {
    let n = r.integer("the number of vertices", 3, MAX_VERTICES)? as usize;
    let mut v = Vec::with_capacity(n);
    let mut normals = Vec::new();
    for k in 1..=n {
        v.push(r.vector(format_args!("vertex {k} of {n}"))?);
        if smooth {
            normals.push(r.vector(format_args!("normal {k} of {n}"))?);
        }
    }
    let tris = polygon::triangulate(&v);
    if tris.is_empty() {
        let msg = "a polygon without area (its vertices lie on a line)";
        return Err(r.error_at(at, msg.into()));
    }
    for [i, j, k] in tris {
        let corners = [v[i], v[j], v[k]];
        // Sliver triangles whose corners the rounding puts on a line are dropped.
        if Triangle::new(v[i], v[j], v[k]).is_none() {
            continue;
        }
        let spec = if smooth {
            let normals = [normals[i], normals[j], normals[k]];
            if SmoothTriangle::new(corners, normals).is_none() {
                return Err(r.error_at(at, "a patch with a zero normal".into()));
            }
            ShapeSpec::Patch { corners, normals }
        } else {
            ShapeSpec::Triangle { corners }
        };
        b.push(spec, r, at)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests;
