//! glTF's metallic-roughness materials on §2's terms (SPEC §18; the reasons are in
//! docs/gltf.md). With base colour C (factor × texture, linear), metallic m and
//! roughness r:
//!
//! - Kr = m·(1 − r): a smooth metal is a mirror, tinted by C (`Pbr::tint` = (1 − m)·1 +
//!   m·C); a rough one cannot reflect sharply in a Whitted tracer and gives its energy
//!   to the diffuse term instead;
//! - Kd = 1 − Kr − Kt, so `metallic 0, roughness 1` is purely diffuse and the default
//!   material (metallic 1, roughness 1) a matte grey;
//! - a Phong highlight of weight Ks = (1 − r)² and exponent 2/α² − 2 (α = r², Blinn's
//!   equivalence), capped at 1000, so rougher surfaces have wider, weaker highlights;
//! - `KHR_materials_transmission` is Kt; thin-walled (ior 1: rays pass unbent) unless
//!   `KHR_materials_volume` gives a thickness, then `KHR_materials_ior` (1.5 without);
//! - `emissiveFactor` (× `emissiveStrength`) × `emissiveTexture` is added unlit (the
//!   factor alone in `Pbr::emission`; with a texture, by the mesh's `Extra` at the hit);
//! - `alphaMode`, `alphaCutoff` and the base colour's alpha go to the mesh's `Extra`
//!   (`mesh::extra`: MASK and BLEND).
//!
//! Colour textures are decoded from sRGB to linear light (`texture`); the base colour
//! factor is folded into the pixels; the sampler's wrap modes and magnification filter
//! are kept; a texture on TEXCOORD_1 is read on it.

use crate::base::Color;
use crate::bump::Bump;
use crate::object::{Highlight, Material, Pbr};
use glam::DVec3;
#[cfg(feature = "gltf")]
pub use reading::read;

/// The largest Phong exponent a smooth surface takes.
pub const MAX_SHINE: f64 = 1000.0;

/// §2's terms of a material with these factors, its tint and emission (none) being
/// entry `look` of the scene's `Scene::pbr`.
pub fn terms(
    base: Color,
    metallic: f64,
    roughness: f64,
    kt: f64,
    ior: f64,
    look: u32,
) -> (Material, Pbr) {
    let (m, r) = (metallic.clamp(0.0, 1.0), roughness.clamp(0.0, 1.0));
    let kt = kt.clamp(0.0, 1.0) * (1.0 - m);
    let kr = m * (1.0 - r);
    let alpha = (r * r).max(1e-6);
    let shine = (2.0 / (alpha * alpha) - 2.0).clamp(1.0, MAX_SHINE);
    let material = Material {
        kd: (1.0 - kr - kt).max(0.0),
        kr,
        kt,
        ior,
        bump: Bump::None,
        highlight: Highlight::Gltf {
            ks: ((1.0 - r) * (1.0 - r)) as f32,
            shine: shine as f32,
            look,
        },
    };
    let pbr = Pbr {
        tint: DVec3::splat(1.0 - m) + m * base,
        emission: Color::ZERO,
    };
    (material, pbr)
}

/// Reading the file's materials (with the `gltf` crate; images in `texture`).
#[cfg(feature = "gltf")]
mod reading {
    use super::terms;
    use crate::base::Color;
    use crate::gltf::accessor::Buffers;
    use crate::gltf::error::GltfError;
    use crate::gltf::rig::{LookExtra, Rig};
    use crate::gltf::source::{Named, Origin};
    use crate::gltf::texture::Images;
    use crate::mesh::extra::AlphaMode;
    use crate::mesh::Look;
    use crate::texture::Texture;
    use glam::DVec3;

    fn v3(a: [f32; 3]) -> DVec3 {
        DVec3::new(f64::from(a[0]), f64::from(a[1]), f64::from(a[2]))
    }

    /// The coordinate set a texture is read on: its `texCoord` when the tracer reads
    /// that set (0 or 1), else 0 with a warning.
    fn set(rig: &mut Rig, file: &str, tex_coord: u32) -> usize {
        if tex_coord > 1 {
            rig.warn(format!(
                "{file}: textures on TEXCOORD_{tex_coord} are read on TEXCOORD_0"
            ));
            return 0;
        }
        tex_coord as usize
    }

    /// Every material of `doc` into `rig.looks`, then the default material.
    pub fn read(
        doc: &gltf::Document,
        b: &Buffers,
        origin: &Origin,
        named: &mut Named,
        rig: &mut Rig,
    ) -> Result<(), GltfError> {
        let mut images = Images::new(doc, b, origin);
        for mat in doc.materials() {
            let pbr = mat.pbr_metallic_roughness();
            let [r, g, bl, alpha] = pbr.base_color_factor().map(f64::from);
            let base = DVec3::new(r, g, bl);
            let kt = mat
                .transmission()
                .map_or(0.0, |t| f64::from(t.transmission_factor()));
            let thick = mat.volume().is_some_and(|v| v.thickness_factor() > 0.0);
            let ior = if thick {
                mat.ior().map_or(1.5, f64::from)
            } else {
                1.0
            };
            let (material, mut extra) = terms(
                base,
                f64::from(pbr.metallic_factor()),
                f64::from(pbr.roughness_factor()),
                kt,
                ior,
                rig.looks.len() as u32,
            );
            let strength = mat.emissive_strength().map_or(1.0, f64::from);
            let emission = v3(mat.emissive_factor()) * strength;
            let mut look = LookExtra {
                mode: match mat.alpha_mode() {
                    gltf::material::AlphaMode::Opaque => AlphaMode::Opaque,
                    gltf::material::AlphaMode::Mask => {
                        AlphaMode::Mask(mat.alpha_cutoff().map_or(0.5, f64::from))
                    }
                    gltf::material::AlphaMode::Blend => AlphaMode::Blend,
                },
                factor: alpha,
                ..LookExtra::default()
            };
            // An emissive texture is added where the hit's coordinates are known (the
            // mesh's `Extra`); the factor alone, in every hit's shading.
            match mat.emissive_texture() {
                Some(info) if emission != Color::ZERO => {
                    let set = set(rig, origin.file, info.tex_coord());
                    let tex = images.texture(info.texture(), Color::ONE, named)?;
                    look.emissive = Some((tex, emission, set));
                }
                _ => extra.emission = emission,
            }
            let texture = match pbr.base_color_texture() {
                Some(info) => {
                    look.base_set = set(rig, origin.file, info.tex_coord());
                    Texture::Image(images.texture(info.texture(), base, named)?)
                }
                None => Texture::Uniform(base),
            };
            let unused = [
                (
                    pbr.metallic_roughness_texture().is_some(),
                    "metallicRoughnessTexture",
                ),
                (mat.normal_texture().is_some(), "normalTexture"),
                (mat.occlusion_texture().is_some(), "occlusionTexture"),
            ];
            for (_, what) in unused.iter().filter(|(has, _)| *has) {
                rig.warn(format!("{}: materials' {what} is not used", origin.file));
            }
            rig.looks.push(Look { texture, material });
            rig.pbr.push(extra);
            rig.double_sided.push(mat.double_sided());
            rig.extras.push(look);
        }
        // glTF's default material: metallic 1, roughness 1, white, opaque.
        let (material, extra) = terms(Color::ONE, 1.0, 1.0, 0.0, 1.0, rig.looks.len() as u32);
        rig.looks.push(Look {
            texture: Texture::Uniform(Color::ONE),
            material,
        });
        rig.pbr.push(extra);
        rig.double_sided.push(false);
        rig.extras.push(LookExtra {
            factor: 1.0,
            ..LookExtra::default()
        });
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The highlight's weight and exponent, widened.
    fn phong(m: &Material) -> (f64, f64) {
        match m.highlight {
            Highlight::Gltf { ks, shine, .. } => (f64::from(ks), f64::from(shine)),
            _ => panic!("a glTF material has a glTF highlight"),
        }
    }

    #[test]
    fn the_corners_of_metallic_and_roughness_by_hand() {
        let c = DVec3::new(0.8, 0.4, 0.2);
        // Dielectric, rough: purely diffuse, no highlight, a white tint.
        let (m, p) = terms(c, 0.0, 1.0, 0.0, 1.0, 7);
        assert_eq!((m.kd, m.kr, m.kt), (1.0, 0.0, 0.0));
        assert_eq!(phong(&m).0, 0.0);
        assert!(matches!(m.highlight, Highlight::Gltf { look: 7, .. }));
        assert_eq!(p.tint, Color::ONE);
        // Smooth metal: a mirror tinted by the base colour, the exponent capped.
        let (m, p) = terms(c, 1.0, 0.0, 0.0, 1.0, 0);
        assert_eq!((m.kd, m.kr), (0.0, 1.0));
        assert_eq!(phong(&m), (1.0, MAX_SHINE));
        assert_eq!(p.tint, c);
        // glTF's default (metallic 1, roughness 1): matte.
        let (m, _) = terms(Color::ONE, 1.0, 1.0, 0.0, 1.0, 0);
        assert_eq!((m.kd, m.kr), (1.0, 0.0));
        // Roughness ½: α = ¼, exponent 2/α² − 2 = 30, Ks = ¼; metallic ½: Kr = ¼.
        let (m, _) = terms(c, 0.5, 0.5, 0.0, 1.0, 0);
        assert_eq!((phong(&m), m.kr, m.kd), ((0.25, 30.0), 0.25, 0.75));
        // Transmission 0.6 on a dielectric.
        let (m, _) = terms(c, 0.0, 1.0, 0.6, 1.5, 0);
        assert_eq!((m.kt, m.ior), (0.6, 1.5));
        assert!((m.kd - 0.4).abs() < 1e-15);
    }
}
