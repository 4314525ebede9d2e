//! An OBJ's `.mtl` materials (read by tobj's `.mtl` reader) as the TEXTURE and MATERIAL
//! of §2 that replace the record's on the faces that use them (SPEC §18):
//!
//! - colour C: `Kd` (0.8 grey without it), or the `map_Kd` image on the `uv` map
//!   (bilinear, Size 1), which replaces Kd;
//! - Kd = 1 (the colour is the diffuse term), the Phong highlight of NFF (§17) with
//!   Ks = the mean of `Ks` and Shine = `Ns`; none for `illum` 0 and 1;
//! - Kr = the mean of `Ks` for `illum` 3 and above (reflection on), else 0;
//! - Kt = 1 − `d` (or `Tr` where there is no `d`), Ior = `Ni` (1 without it).
//!
//! A `.mtl` or `map_Kd` file that cannot be read is a warning that names it (the faces
//! keep the record's TEXTURE and MATERIAL, or Kd); keys the tracer does not use are named
//! in one warning.

use super::Look;
use crate::bump::Bump;
use crate::limits::MAX_MESH_BYTES;
use crate::object::{Highlight, Material};
use crate::texture::{ImageTexture, Interp, MapKind, Texture};
use glam::DVec3;
use std::path::Path;
use std::sync::Arc;

/// tobj's material loader: the `.mtl` file `name` beside the OBJ, or a warning.
pub fn read(dir: &Path, name: &Path, obj: &str, warnings: &mut Vec<String>) -> tobj::MTLLoadResult {
    let file = dir.join(name);
    let bytes = crate::input::read_regular(&file, MAX_MESH_BYTES, "material file");
    let result = bytes
        .map_err(|e| e.to_string())
        .and_then(|b| tobj::load_mtl_buf(&mut b.as_slice()).map_err(|e| e.to_string()));
    if let Err(why) = &result {
        warnings.push(format!(
            "{obj}: mtllib '{}' cannot be read ({why}): its faces keep the record's TEXTURE and MATERIAL",
            name.display()
        ));
    }
    result.map_err(|_| tobj::LoadError::OpenFileFailed)
}

fn mean(c: [f64; 3]) -> f64 {
    (c[0] + c[1] + c[2]) / 3.0
}

/// The looks of `materials`; `dir` is where their images are.
pub fn looks(
    materials: &[tobj::Material],
    dir: &Path,
    obj: &str,
    uvs: bool,
    warnings: &mut Vec<String>,
) -> Vec<Look> {
    let mut unused: Vec<String> = Vec::new();
    let mut loaded: Vec<(String, Arc<crate::texture::Pixels>)> = Vec::new();
    let mut used = 0u64;
    let out = materials
        .iter()
        .map(|m| {
            let kd = DVec3::from_array(m.diffuse.unwrap_or([0.8; 3]));
            let mut texture = Texture::Uniform(kd);
            if let (Some(name), false) = (&m.diffuse_texture, uvs) {
                warnings.push(format!(
                    "{obj}: material '{}': map_Kd '{name}' needs the file's texture coordinates (vt), which it lacks: Kd stands",
                    m.name
                ));
            }
            if let (Some(name), true) = (&m.diffuse_texture, uvs) {
                let pixels = match loaded.iter().find(|(n, _)| n == name) {
                    Some((_, p)) => Some(Arc::clone(p)),
                    // The file's own images count against the scene's image budget
                    // among themselves (the records' images are checked apart).
                    None => match crate::texture::load(&dir.join(name), used) {
                        Ok(p) => {
                            let (w, h) = p.size();
                            used += u64::from(w) * u64::from(h);
                            loaded.push((name.clone(), Arc::new(p)));
                            loaded.last().map(|(_, p)| Arc::clone(p))
                        }
                        Err(why) => {
                            warnings.push(format!(
                                "{obj}: material '{}': map_Kd '{name}' cannot be read ({why}): Kd stands",
                                m.name
                            ));
                            None
                        }
                    },
                };
                if let Some(pixels) = pixels {
                    texture = Texture::Image(Arc::new(ImageTexture {
                        file: name.clone(),
                        map: MapKind::Uv,
                        interp: Interp::Bilinear,
                        size: 1.0,
                        pixels,
                    }));
                }
            }
            let illum = m.illumination_model.unwrap_or(2);
            let ks = mean(m.specular.unwrap_or([0.0; 3]));
            let d = m.dissolve.or_else(|| {
                let tr: f64 = m.unknown_param.get("Tr")?.trim().parse().ok()?;
                Some(1.0 - tr)
            });
            let highlight = Highlight::Phong {
                ks: if illum <= 1 { 0.0 } else { ks },
                shine: m.shininess.unwrap_or(0.0).max(0.0),
            };
            let material = Material {
                kd: 1.0,
                kr: if illum >= 3 { ks } else { 0.0 },
                kt: (1.0 - d.unwrap_or(1.0)).clamp(0.0, 1.0),
                ior: m.optical_density.filter(|&n| n > 0.0).unwrap_or(1.0),
                bump: Bump::None,
                highlight,
            };
            let mut keys: Vec<&str> = m
                .unknown_param
                .keys()
                .map(String::as_str)
                .filter(|&k| k != "Tr")
                .collect();
            let textures = [
                ("map_Ka", &m.ambient_texture),
                ("map_Ks", &m.specular_texture),
                ("map_Bump", &m.normal_texture),
                ("map_Ns", &m.shininess_texture),
                ("map_d", &m.dissolve_texture),
            ];
            keys.extend(textures.iter().filter(|(_, t)| t.is_some()).map(|(k, _)| *k));
            if m.ambient.is_some() {
                keys.push("Ka");
            }
            for k in keys {
                if !unused.iter().any(|u| u == k) {
                    unused.push(k.to_string());
                }
            }
            Look { texture, material }
        })
        .collect();
    if !unused.is_empty() {
        unused.sort();
        warnings.push(format!(
            "{obj}: not used: material keys {} (the tracer reads Kd, Ks, Ns, d, Tr, Ni, map_Kd, illum)",
            unused.join(", ")
        ));
    }
    out
}
