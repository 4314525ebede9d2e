//! A glTF material's textures (SPEC §18): each image read once, through the tracer's own
//! bounded reader (from a buffer view, a `data:` URI or a file beside the glTF file),
//! its colours decoded from sRGB to linear light and its alpha channel (linear in glTF)
//! kept as it is; each texture then an image texture on the `uv` map, its colours times
//! a factor, with its sampler's wrap modes (REPEAT, CLAMP_TO_EDGE, MIRRORED_REPEAT) and
//! magnification filter (NEAREST, else bilinear).

use super::accessor::Buffers;
use super::error::{at, GltfError};
use super::source::{Named, Origin};
use crate::base::srgb::decode;
use crate::texture::{ImageTexture, Interp, MapKind, Pixels, Wrap};
use glam::DVec3;
use gltf::texture::{MagFilter, WrappingMode};
use std::sync::Arc;

/// The images of one file, each decoded the first time a texture names it.
pub struct Images<'a> {
    doc: &'a gltf::Document,
    b: &'a Buffers<'a>,
    origin: &'a Origin<'a>,
    cache: Vec<Option<Arc<Pixels>>>,
    /// The pixels decoded so far (the scene's image budget counts them).
    used: u64,
}

impl<'a> Images<'a> {
    /// None of `doc`'s images decoded yet.
    pub fn new(doc: &'a gltf::Document, b: &'a Buffers<'a>, origin: &'a Origin<'a>) -> Self {
        Images {
            doc,
            b,
            origin,
            cache: vec![None; doc.images().len()],
            used: 0,
        }
    }

    /// Texture `tex` as an image texture on the `uv` map, its colours times `factor`.
    pub fn texture(
        &mut self,
        tex: gltf::texture::Texture,
        factor: DVec3,
        named: &mut Named,
    ) -> Result<Arc<ImageTexture>, GltfError> {
        let index = tex.source().index();
        let pixels = match &self.cache[index] {
            Some(p) => Arc::clone(p),
            None => {
                let p = Arc::new(self.image(index, named)?);
                self.used += p.count();
                self.cache[index] = Some(Arc::clone(&p));
                p
            }
        };
        let sampler = tex.sampler();
        let wrap = |w: WrappingMode| match w {
            WrappingMode::ClampToEdge => Wrap::Clamp,
            WrappingMode::MirroredRepeat => Wrap::Mirror,
            WrappingMode::Repeat => Wrap::Repeat,
        };
        let f = factor.as_vec3().to_array();
        let tinted = pixels
            .mapped(|p| [p[0] * f[0], p[1] * f[1], p[2] * f[2]])
            .wrapping([wrap(sampler.wrap_s()), wrap(sampler.wrap_t())]);
        let interp = match sampler.mag_filter() {
            Some(MagFilter::Nearest) => Interp::Nearest,
            _ => Interp::Bilinear,
        };
        Ok(Arc::new(ImageTexture {
            file: format!("images[{index}]"),
            map: MapKind::Uv,
            interp,
            size: 1.0,
            pixels: Arc::new(tinted),
        }))
    }

    /// Image `index`'s pixels, its colours decoded from sRGB to linear light.
    fn image(&self, index: usize, named: &mut Named) -> Result<Pixels, GltfError> {
        let origin = self.origin;
        let path = format!("images[{index}]");
        let Some(img) = self.doc.images().nth(index) else {
            return Err(at(origin.file, path, "no such image"));
        };
        let bytes: Vec<u8> = match img.source() {
            gltf::image::Source::Uri { uri, .. } => {
                origin.uri(uri, &format!("{path}.uri"), named)?
            }
            gltf::image::Source::View { view, .. } => {
                let data = &self.b.data[view.buffer().index()];
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
        let pixels = crate::texture::from_bytes(&bytes, self.used)
            .map_err(|why| at(origin.file, path, format!("cannot use the image: {why}")))?;
        Ok(pixels.mapped(|p| p.map(|c| decode(f64::from(c)) as f32)))
    }
}
