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
//! - `emissiveFactor` (× `emissiveStrength`) is added unlit.
//!
//! Colour textures are decoded from sRGB to linear light; the base colour factor is
//! folded into the pixels; the sampler's wrap modes and magnification filter are kept.

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

/// Reading the file's materials and images (with the `gltf` crate).
#[cfg(feature = "gltf")]
mod reading {
    use super::terms;
    use crate::base::srgb::decode;
    use crate::base::Color;
    use crate::gltf::accessor::Buffers;
    use crate::gltf::error::{at, GltfError};
    use crate::gltf::rig::Rig;
    use crate::gltf::source::{Named, Origin};
    use crate::mesh::Look;
    use crate::texture::{ImageTexture, Interp, MapKind, Pixels, Texture, Wrap};
    use glam::DVec3;
    use std::sync::Arc;

    fn v3(a: [f32; 3]) -> DVec3 {
        DVec3::new(f64::from(a[0]), f64::from(a[1]), f64::from(a[2]))
    }

    /// Every material of `doc` into `rig.looks`, then the default material.
    pub fn read(
        doc: &gltf::Document,
        b: &Buffers,
        origin: &Origin,
        named: &mut Named,
        rig: &mut Rig,
    ) -> Result<(), GltfError> {
        let mut images: Vec<Option<Arc<Pixels>>> = vec![None; doc.images().len()];
        let mut used = 0u64;
        for mat in doc.materials() {
            let pbr = mat.pbr_metallic_roughness();
            let [r, g, bl, _] = pbr.base_color_factor().map(f64::from);
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
            extra.emission = v3(mat.emissive_factor()) * strength;
            let texture = match pbr.base_color_texture() {
                Some(info) => {
                    if info.tex_coord() != 0 {
                        rig.warn(format!(
                            "{}: textures on TEXCOORD_{} are read on TEXCOORD_0",
                            origin.file,
                            info.tex_coord()
                        ));
                    }
                    let tex = info.texture();
                    let index = tex.source().index();
                    let pixels = match &images[index] {
                        Some(p) => Arc::clone(p),
                        None => {
                            let p = Arc::new(image(doc, b, origin, named, index, used)?);
                            used += p.count();
                            images[index] = Some(Arc::clone(&p));
                            p
                        }
                    };
                    let sampler = tex.sampler();
                    let wrap = |w: gltf::texture::WrappingMode| match w {
                        gltf::texture::WrappingMode::ClampToEdge => Wrap::Clamp,
                        gltf::texture::WrappingMode::MirroredRepeat => Wrap::Mirror,
                        gltf::texture::WrappingMode::Repeat => Wrap::Repeat,
                    };
                    let f = base.as_vec3().to_array();
                    let tinted = pixels
                        .mapped(|p| [p[0] * f[0], p[1] * f[1], p[2] * f[2]])
                        .wrapping([wrap(sampler.wrap_s()), wrap(sampler.wrap_t())]);
                    let interp = match sampler.mag_filter() {
                        Some(gltf::texture::MagFilter::Nearest) => Interp::Nearest,
                        _ => Interp::Bilinear,
                    };
                    Texture::Image(Arc::new(ImageTexture {
                        file: format!("images[{index}]"),
                        map: MapKind::Uv,
                        interp,
                        size: 1.0,
                        pixels: Arc::new(tinted),
                    }))
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
                (
                    mat.emissive_texture().is_some(),
                    "emissiveTexture (the factor alone is used)",
                ),
            ];
            for (_, what) in unused.iter().filter(|(has, _)| *has) {
                rig.warn(format!("{}: materials' {what} is not used", origin.file));
            }
            if mat.alpha_mode() != gltf::material::AlphaMode::Opaque {
                rig.warn(format!(
                    "{}: alphaMode {:?} is drawn opaque",
                    origin.file,
                    mat.alpha_mode()
                ));
            }
            rig.looks.push(Look { texture, material });
            rig.pbr.push(extra);
            rig.double_sided.push(mat.double_sided());
        }
        // glTF's default material: metallic 1, roughness 1, white.
        let (material, extra) = terms(Color::ONE, 1.0, 1.0, 0.0, 1.0, rig.looks.len() as u32);
        rig.looks.push(Look {
            texture: Texture::Uniform(Color::ONE),
            material,
        });
        rig.pbr.push(extra);
        rig.double_sided.push(false);
        Ok(())
    }

    /// Image `index`'s pixels, decoded from sRGB to linear light.
    fn image(
        doc: &gltf::Document,
        b: &Buffers,
        origin: &Origin,
        named: &mut Named,
        index: usize,
        used: u64,
    ) -> Result<Pixels, GltfError> {
        let path = format!("images[{index}]");
        let Some(img) = doc.images().nth(index) else {
            return Err(at(origin.file, path, "no such image"));
        };
        let bytes: Vec<u8> = match img.source() {
            gltf::image::Source::Uri { uri, .. } => {
                origin.uri(uri, &format!("{path}.uri"), named)?
            }
            gltf::image::Source::View { view, .. } => {
                let data = &b.data[view.buffer().index()];
                let end = view.offset().checked_add(view.length());
                match end.filter(|&e| e <= data.len()) {
                    Some(e) => data[view.offset()..e].to_vec(),
                    None => {
                        return Err(at(
                            origin.file,
                            format!("bufferViews[{}]", view.index()),
                            "the image's view ends past its buffer",
                        ))
                    }
                }
            }
        };
        let pixels = crate::texture::from_bytes(&bytes, used)
            .map_err(|why| at(origin.file, path, format!("cannot use the image: {why}")))?;
        Ok(pixels.mapped(|p| p.map(|c| decode(f64::from(c)) as f32)))
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
