//! The files the Embree harness (`benches/embree/cast.py`) reads, written into one folder:
//!
//! ```text
//! triangles.f64   n × 9 little-endian f64: the corners of object i (file order), so that
//!                 Embree's primitive number is our object index
//! rays.f64        m × 11 little-endian f64, one ray a row in the order it was cast:
//!                 kind (0 camera, 1 reflect, 2 refract, 3 shadow), origin xyz,
//!                 direction xyz, t_min, t_max (inf but for shadow rays),
//!                 our nearest t past t_min (inf: none), our object index (-1: none)
//! counts.json     rays of each kind, eye hits, triangles, the image size
//! ```
//!
//! Every value is the tracer's f64, written as it is: the harness rounds to Embree's f32.
//! Only a scene of triangles (NFF polygons and patches: flat triangles with the same
//! corners) can be written: anything else is refused with its object's number.

use super::walk::{Cast, Kind};
use std::io::{self, Write};
use whitted::scene::ShapeSpec;
use whitted::trace::RayCount;
use whitted::Scene;

/// Floats a ray's row holds.
pub const RAY_FLOATS: usize = 11;

/// Each object's three corners, in file order; `Err(i)` names the first object that is
/// not a triangle.
pub fn triangles(scene: &Scene) -> Result<Vec<[f64; 9]>, usize> {
    scene
        .specs
        .iter()
        .enumerate()
        .map(|(i, spec)| match spec.record() {
            Some(ShapeSpec::Triangle { corners } | ShapeSpec::Patch { corners, .. }) => {
                let mut row = [0.0; 9];
                for (k, c) in corners.iter().enumerate() {
                    row[3 * k..3 * k + 3].copy_from_slice(&c.to_array());
                }
                Ok(row)
            }
            _ => Err(i),
        })
        .collect()
}

/// A cast's row of `rays.f64`.
pub fn row(c: &Cast) -> [f64; RAY_FLOATS] {
    let (o, d) = (c.ray.origin, c.ray.dir);
    let (t, i) = c.hit.map_or((f64::INFINITY, -1.0), |(t, i)| (t, i as f64));
    let kind = match c.kind {
        Kind::Camera => 0.0,
        Kind::Reflect => 1.0,
        Kind::Refract => 2.0,
        Kind::Shadow => 3.0,
    };
    [
        kind,
        o.x,
        o.y,
        o.z,
        d.x,
        d.y,
        d.z,
        c.ray.t_min,
        c.t_max,
        t,
        i,
    ]
}

/// Writes `values` as little-endian f64.
pub fn write_f64s(out: &mut impl Write, values: &[f64]) -> io::Result<()> {
    for v in values {
        out.write_all(&v.to_le_bytes())?;
    }
    Ok(())
}

/// `counts.json`: the walk's counts by kind, as the tracer names them.
pub fn counts_json(count: &RayCount, triangles: usize, size: (u32, u32)) -> serde_json::Value {
    serde_json::json!({
        "camera": count.primary,
        "reflect": count.reflect,
        "refract": count.refract,
        "shadow": count.shadow,
        "eye_hits": count.eye_hits,
        "triangles": triangles,
        "width": size.0,
        "height": size.1,
    })
}

/// The rays written, by kind (the records of `rays.f64`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Tally {
    /// Camera rays.
    pub camera: u64,
    /// Reflection rays.
    pub reflect: u64,
    /// Refraction rays (total internal reflections included).
    pub refract: u64,
    /// Shadow rays.
    pub shadow: u64,
    /// Camera rays that hit.
    pub eye_hits: u64,
}

impl Tally {
    fn add(&mut self, c: &Cast) {
        match c.kind {
            Kind::Camera => {
                self.camera += 1;
                self.eye_hits += u64::from(c.hit.is_some());
            }
            Kind::Reflect => self.reflect += 1,
            Kind::Refract => self.refract += 1,
            Kind::Shadow => self.shadow += 1,
        }
    }

    /// As the tracer counts: `secondary` is every reflected and refracted ray.
    pub fn as_count(&self) -> RayCount {
        RayCount {
            primary: self.camera,
            secondary: self.reflect + self.refract,
            shadow: self.shadow,
            eye_hits: self.eye_hits,
            reflect: self.reflect,
            refract: self.refract,
        }
    }
}

/// Writes the three files of the picture `raytrace SCENE` draws into `dir` (which must
/// exist): the triangles, every ray the walk casts, and the counts. Returns the rays
/// written by kind.
pub fn dump(scene: &Scene, dir: &std::path::Path) -> anyhow::Result<Tally> {
    use anyhow::Context;
    let tris = triangles(scene).map_err(|i| {
        anyhow::anyhow!(
            "object {} is not a triangle: Embree is given triangles only",
            i + 1
        )
    })?;
    let tracer = whitted::trace::Tracer::new(scene);
    let camera = super::walk::camera(scene).context("the eye is on its look-at point")?;
    let open = |name: &str| -> anyhow::Result<io::BufWriter<std::fs::File>> {
        let path = dir.join(name);
        let file = std::fs::File::create(&path).with_context(|| path.display().to_string())?;
        Ok(io::BufWriter::with_capacity(1 << 20, file))
    };
    let mut out = open("triangles.f64")?;
    for t in &tris {
        write_f64s(&mut out, t)?;
    }
    out.flush()?;
    let mut out = open("rays.f64")?;
    let mut tally = Tally::default();
    let mut failed = None;
    let (w, h) = (scene.width, scene.height);
    super::walk::walk(&tracer, &camera, w, h, &mut |c| {
        tally.add(c);
        if failed.is_none() {
            failed = write_f64s(&mut out, &row(c)).err();
        }
    })?;
    if let Some(e) = failed {
        return Err(e).context("writing rays.f64");
    }
    out.flush()?;
    let json = counts_json(&tally.as_count(), tris.len(), (w, h));
    let text = serde_json::to_string_pretty(&json)? + "\n";
    std::fs::write(dir.join("counts.json"), text)?;
    Ok(tally)
}
