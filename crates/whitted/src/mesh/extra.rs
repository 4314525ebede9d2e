//! What a glTF primitive's triangles carry beyond their TEXTURE and MATERIAL (SPEC §18):
//! the material's coverage (`alphaMode`) and its emissive texture. Every other mesh has
//! none (`Mesh::extra` is `None`), and the tracer asks for them only at a hit on a mesh
//! that has them.
//!
//! - **Alpha** at a point of a triangle is α = `baseColorFactor`.a × the base colour
//!   texture's alpha at the point's (u, v) × COLOR_0's alpha interpolated there, each
//!   factor 1 where the file gives none.
//! - **`OPAQUE`** ignores it; **`MASK`** draws the hit when α ≥ `alphaCutoff` (0.5 by
//!   default) and ignores it otherwise, for every ray, shadow rays included;
//!   **`BLEND`** is coverage: α × the surface + (1 − α) × what lies behind it, the ray
//!   going on past the hit unbent and unfiltered.
//! - **Shadow rays** take the same rule: through a point of coverage α whose own
//!   surface lets `own` through (black for an opaque one, Kt·C for a transmissive one),
//!   a shadow ray keeps (1 − α)·white + α·own (grey and unfiltered where the surface is
//!   opaque); through a masked-out point, all of it.
//! - **Emission** with an `emissiveTexture`: `emissiveFactor` (× strength) times the
//!   texture's colour (decoded from sRGB) at the point, read on the coordinates its
//!   `texCoord` names.

use super::Mesh;
use crate::base::Color;
use crate::texture::ImageTexture;
use glam::DVec3;
use std::sync::Arc;

/// glTF's `alphaMode`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum AlphaMode {
    /// Alpha is ignored.
    #[default]
    Opaque,
    /// Hits of alpha below the cutoff are ignored.
    Mask(f64),
    /// Coverage: α × the surface + (1 − α) × what lies behind.
    Blend,
}

/// What a ray does at a hit on a triangle of a mesh with an `Extra`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Seen {
    /// It stops there, as at any surface.
    Solid,
    /// It passes as if nothing were there (a masked-out point).
    Skip,
    /// α of the colour is the surface's, the rest what lies behind.
    Blend(f64),
}

/// An emissive texture: `emissiveFactor` (× strength) times the texture's colour.
#[derive(Clone, Debug, PartialEq)]
pub struct Emissive {
    /// The texture (linear colours, on its sampler's wrap and filter).
    pub texture: Arc<ImageTexture>,
    /// The factor it is multiplied by.
    pub factor: Color,
    /// The (u, v) it is read on, one per vertex (v pointing up the image).
    pub uvs: Vec<[f64; 2]>,
}

/// A glTF primitive's coverage and emissive texture.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Extra {
    /// The material's `alphaMode`.
    pub mode: AlphaMode,
    /// `baseColorFactor`'s alpha.
    pub factor: f64,
    /// The base colour texture, whose alpha is read on the mesh's (u, v).
    pub texture: Option<Arc<ImageTexture>>,
    /// COLOR_0's alpha, one per vertex, or none.
    pub vertex: Vec<f32>,
    /// The emissive texture, if any.
    pub emissive: Option<Emissive>,
}

/// The value of one attribute interpolated at weights `w` over triangle `t`'s corners.
fn blend<T: Copy>(w: [f64; 3], t: [u32; 3], values: &[T], f: impl Fn(T) -> DVec3) -> DVec3 {
    (0..3).map(|i| w[i] * f(values[t[i] as usize])).sum()
}

impl Mesh {
    /// Alpha at the point `p` of triangle `k` (1 on a mesh without an `Extra`).
    pub fn alpha_at(&self, k: u32, p: DVec3) -> f64 {
        let Some(x) = &self.extra else {
            return 1.0;
        };
        let mut alpha = x.factor;
        let t = self.triangles[k as usize];
        if let Some(image) = &x.texture {
            if let Some((u, v)) = self.uv_at(k, p) {
                let (u, v) = (u / image.size, v / image.size);
                alpha *= image.pixels.alpha_at(u, v, image.interp);
            }
        }
        if x.vertex.len() == self.vertices.len() {
            let w = self.weights(k, p);
            alpha *= blend(w, t, &x.vertex, |a| DVec3::splat(f64::from(a))).x;
        }
        alpha.clamp(0.0, 1.0)
    }

    /// What a ray does at the point `p` of triangle `k`.
    pub fn seen(&self, k: u32, p: DVec3) -> Seen {
        let mode = self.extra.as_ref().map_or(AlphaMode::Opaque, |x| x.mode);
        match mode {
            AlphaMode::Opaque => Seen::Solid,
            AlphaMode::Mask(cutoff) if self.alpha_at(k, p) < cutoff => Seen::Skip,
            AlphaMode::Mask(_) => Seen::Solid,
            AlphaMode::Blend => match self.alpha_at(k, p) {
                a if a >= 1.0 => Seen::Solid,
                a if a <= 0.0 => Seen::Skip,
                a => Seen::Blend(a),
            },
        }
    }

    /// What a shadow ray keeps crossing the point `p` of triangle `k`, whose surface by
    /// itself lets `own` through (black when opaque).
    pub fn shadow_through(&self, k: u32, p: DVec3, own: Color) -> Color {
        match self.seen(k, p) {
            Seen::Solid => own,
            Seen::Skip => Color::ONE,
            Seen::Blend(a) => Color::splat(1.0 - a) + a * own,
        }
    }

    /// Whether shadow rays cross every triangle of this mesh (its alpha mode is not
    /// `OPAQUE`), each crossing letting through what `shadow_through` says, rather than
    /// stop at the first.
    pub fn has_coverage(&self) -> bool {
        self.extra
            .as_ref()
            .is_some_and(|x| x.mode != AlphaMode::Opaque)
    }

    /// The emitted colour from an emissive texture at the point `p` of triangle `k`
    /// (black without one).
    pub fn emission_at(&self, k: u32, p: DVec3) -> Color {
        let Some(e) = self.extra.as_ref().and_then(|x| x.emissive.as_ref()) else {
            return Color::ZERO;
        };
        if e.uvs.len() != self.vertices.len() {
            return e.factor * e.texture.pixels.sample(0.0, 0.0, e.texture.interp);
        }
        let w = self.weights(k, p);
        let t = self.triangles[k as usize];
        let uv = blend(w, t, &e.uvs, |[u, v]| DVec3::new(u, v, 0.0));
        e.factor * e.texture.pixels.sample(uv.x, uv.y, e.texture.interp)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::texture::{Interp, MapKind, Pixels};

    /// One triangle (0,0,0), (1,0,0), (0,1,0) with uvs equal to its x and y, and a
    /// 2×1 texture whose alphas are 1 (left) and 0.5 (right).
    fn triangle(mode: AlphaMode, factor: f64, vertex: Vec<f32>) -> Mesh {
        let pixels = Pixels::new(2, 1, vec![[1.0, 0.5, 0.25], [0.0, 0.0, 1.0]])
            .and_then(|p| p.with_alpha(vec![1.0, 0.5]))
            .unwrap();
        let image = Arc::new(ImageTexture {
            file: "t".into(),
            map: MapKind::Uv,
            interp: Interp::Nearest,
            size: 1.0,
            pixels: Arc::new(pixels),
        });
        Mesh {
            vertices: vec![DVec3::ZERO, DVec3::X, DVec3::Y],
            triangles: vec![[0, 1, 2]],
            uvs: vec![[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]],
            extra: Some(Arc::new(Extra {
                mode,
                factor,
                texture: Some(Arc::clone(&image)),
                vertex,
                emissive: Some(Emissive {
                    texture: image,
                    factor: DVec3::new(2.0, 2.0, 2.0),
                    uvs: vec![[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]],
                }),
            })),
            ..Mesh::default()
        }
    }

    #[test]
    fn alpha_is_factor_times_texture_times_vertex_by_hand() {
        // Vertex alphas 1, 0.2, 0.6; at p = (0.7, 0.1): weights (0.2, 0.7, 0.1), so the
        // vertex alpha is 0.2 + 0.14 + 0.06 = 0.4; u = 0.7 reads the right texel (0.5);
        // the factor 0.8: α = 0.8 × 0.5 × 0.4 = 0.16.
        let m = triangle(AlphaMode::Blend, 0.8, vec![1.0, 0.2, 0.6]);
        let p = DVec3::new(0.7, 0.1, 0.0);
        assert!(
            (m.alpha_at(0, p) - 0.16).abs() < 1e-7,
            "{}",
            m.alpha_at(0, p)
        );
        // At (0.2, 0.1) the left texel (1): weights (0.7, 0.2, 0.1), vertex alpha
        // 0.7 + 0.04 + 0.06 = 0.8, α = 0.8 × 1 × 0.8 = 0.64.
        let q = DVec3::new(0.2, 0.1, 0.0);
        assert!((m.alpha_at(0, q) - 0.64).abs() < 1e-7);
        // No vertex alpha: factor × texture.
        let m = triangle(AlphaMode::Blend, 0.8, Vec::new());
        assert_eq!(m.alpha_at(0, p), 0.4);
        // A mesh without an Extra is opaque.
        assert_eq!(Mesh::default().seen(0, p), Seen::Solid);
    }

    #[test]
    fn modes_and_shadows_by_hand() {
        let p = DVec3::new(0.7, 0.1, 0.0); // α = 0.5 (the right texel, factor 1)
        let q = DVec3::new(0.2, 0.1, 0.0); // α = 1
        let mask = triangle(AlphaMode::Mask(0.6), 1.0, Vec::new());
        assert_eq!(
            (mask.seen(0, p), mask.seen(0, q)),
            (Seen::Skip, Seen::Solid)
        );
        // The cutoff itself passes: α ≥ cutoff is drawn.
        let mask = triangle(AlphaMode::Mask(0.5), 1.0, Vec::new());
        assert_eq!(mask.seen(0, p), Seen::Solid);
        let blend = triangle(AlphaMode::Blend, 1.0, Vec::new());
        assert_eq!(
            (blend.seen(0, p), blend.seen(0, q)),
            (Seen::Blend(0.5), Seen::Solid)
        );
        let opaque = triangle(AlphaMode::Opaque, 0.0, Vec::new());
        assert_eq!(opaque.seen(0, p), Seen::Solid);
        // Shadows: an opaque surface at α = ½ lets half through, grey; a glass one of
        // Kt·C = (0.4, 0.2, 0) lets ½ + ½·own = (0.7, 0.6, 0.5); a masked-out point
        // lets everything through.
        assert_eq!(blend.shadow_through(0, p, Color::ZERO), Color::splat(0.5));
        let own = DVec3::new(0.4, 0.2, 0.0);
        assert_eq!(blend.shadow_through(0, p, own), DVec3::new(0.7, 0.6, 0.5));
        let mask = triangle(AlphaMode::Mask(0.6), 1.0, Vec::new());
        assert_eq!(mask.shadow_through(0, p, Color::ZERO), Color::ONE);
        assert_eq!(mask.shadow_through(0, q, own), own);
        assert!(mask.has_coverage() && !opaque.has_coverage());
    }

    #[test]
    fn emission_is_the_factor_times_the_texture_by_hand() {
        // Factor 2 times the left texel (1, 0.5, 0.25) at u = 0.2, the right one
        // (0, 0, 1) at u = 0.7.
        let m = triangle(AlphaMode::Opaque, 1.0, Vec::new());
        let left = m.emission_at(0, DVec3::new(0.2, 0.1, 0.0));
        assert_eq!(left, DVec3::new(2.0, 1.0, 0.5));
        assert_eq!(
            m.emission_at(0, DVec3::new(0.7, 0.1, 0.0)),
            DVec3::new(0.0, 0.0, 2.0)
        );
        assert_eq!(Mesh::default().emission_at(0, DVec3::ZERO), Color::ZERO);
    }
}
