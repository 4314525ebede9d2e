//! What shading sees at a hit on a mesh's triangle (SPEC §18): the triangle as a shape
//! of its own (smooth where the mesh has normals), and its TEXTURE and MATERIAL: the
//! file's material where it gives one for the face (`.mtl`), else the record's; the
//! `uv` image map read at the (u, v) interpolated over the triangle; and the colour
//! times the vertex colours interpolated there. A colour found at the hit is handed on
//! as a one-colour texture, so the rest of shading is the same as for any object.

use super::{Mesh, RECORD_LOOK};
use crate::object::{Material, Object};
use crate::shapes::{Shape, SmoothTriangle, Triangle};
use crate::texture::{MapKind, Texture};
use glam::DVec3;

impl Mesh {
    /// Triangle `k` as a shape of its own: smooth where the mesh has normals, flat
    /// otherwise (what shading asks for the normal at a hit).
    pub fn shape(&self, k: u32) -> Shape {
        let corners = self.corners(k);
        let flat = Triangle::new(corners[0], corners[1], corners[2])
            .expect("Mesh::from_raw keeps only triangles of non-zero area");
        if self.normals.is_empty() {
            return Shape::Triangle(flat);
        }
        let [a, b, c] = self.triangles[k as usize];
        let n = &self.normals;
        Shape::Smooth(SmoothTriangle {
            flat,
            normals: [n[a as usize], n[b as usize], n[c as usize]],
        })
    }

    /// The weights of triangle `k`'s corners at its point `p` (barycentric).
    pub(super) fn weights(&self, k: u32, p: DVec3) -> [f64; 3] {
        let [a, b, c] = self.corners(k);
        let (e1, e2, d) = (b - a, c - a, p - a);
        let (d11, d12, d22) = (e1.dot(e1), e1.dot(e2), e2.dot(e2));
        let (d1, d2) = (d.dot(e1), d.dot(e2));
        let den = d11 * d22 - d12 * d12;
        let u = (d22 * d1 - d12 * d2) / den;
        let v = (d11 * d2 - d12 * d1) / den;
        [1.0 - u - v, u, v]
    }

    /// The (u, v) of the file's coordinates at the point `p` of triangle `k`.
    pub fn uv_at(&self, k: u32, p: DVec3) -> Option<(f64, f64)> {
        if self.uvs.is_empty() {
            return None;
        }
        let w = self.weights(k, p);
        let t = self.triangles[k as usize];
        let (mut u, mut v) = (0.0, 0.0);
        for i in 0..3 {
            let c = self.uvs[t[i] as usize];
            u += w[i] * c[0];
            v += w[i] * c[1];
        }
        Some((u, v))
    }

    /// The MATERIAL triangle `k` is drawn with: its file material's (`.mtl`) where the
    /// file gives one for the face, else the record's `material`.
    #[inline]
    pub fn face_material<'a>(&'a self, k: u32, material: &'a Material) -> &'a Material {
        match self.face_looks.get(k as usize) {
            Some(&i) if i != RECORD_LOOK => &self.looks[i as usize].material,
            _ => material,
        }
    }

    /// Whether every triangle is drawn with the record's own TEXTURE and MATERIAL alone:
    /// no file materials, no vertex colours, no `uv` image (what a shadow ray's filter
    /// then needs is the record's, as for any object).
    #[inline]
    pub fn plain(&self, texture: &Texture) -> bool {
        self.face_looks.is_empty()
            && self.colors.is_empty()
            && !self.has_coverage()
            && !matches!(texture, Texture::Image(image) if image.map == MapKind::Uv)
    }

    /// What a shadow ray crossing triangle `k` at `p` lets through (§2's Kt × colour), the
    /// triangle drawn as `surface` draws it: its own material, `uv` image and vertex
    /// colours; on a glTF mesh with coverage, what the point's alpha lets through of it
    /// (`shadow_through`: all where MASK leaves the point out, (1 − α)·white + α·own
    /// through BLEND).
    pub fn filter(&self, k: u32, p: DVec3, texture: &Texture, material: &Material) -> DVec3 {
        let face = self.surface(k, p, texture, material);
        let own = face.material.kt * face.texture.color_at(p);
        if !self.has_coverage() {
            return own;
        }
        let own = if face.material.kt > 0.0 {
            own
        } else {
            DVec3::ZERO
        };
        self.shadow_through(k, p, own)
    }

    /// Triangle `k` hit at `p` as the object shading draws, for a mesh object of
    /// `texture` and `material`.
    pub fn surface(&self, k: u32, p: DVec3, texture: &Texture, material: &Material) -> Object {
        let shape = self.shape(k);
        let (texture, material) = match self.face_looks.get(k as usize) {
            Some(&i) if i != RECORD_LOOK => {
                let look = &self.looks[i as usize];
                (&look.texture, &look.material)
            }
            _ => (texture, material),
        };
        let image_uv = match texture {
            Texture::Image(image) if image.map == MapKind::Uv => Some(image),
            _ => None,
        };
        let mut object = Object {
            shape,
            texture: texture.clone(),
            material: *material,
        };
        if image_uv.is_none() && self.colors.is_empty() {
            return object;
        }
        let mut colour = match image_uv {
            Some(image) => {
                let (u, v) = self.uv_at(k, p).unwrap_or_default();
                image
                    .pixels
                    .sample(u / image.size, v / image.size, image.interp)
            }
            None => object.color_at(p),
        };
        if !self.colors.is_empty() {
            let w = self.weights(k, p);
            let t = self.triangles[k as usize];
            colour *= (0..3)
                .map(|i| w[i] * self.colors[t[i] as usize])
                .sum::<DVec3>();
        }
        object.texture = Texture::Uniform(colour);
        object
    }
}
