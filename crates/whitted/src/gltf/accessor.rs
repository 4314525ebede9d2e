//! Reading an accessor's values, checked before anything is allocated: the count against
//! the caller's budget, the element's size and the view's stride against the view, the
//! view against its buffer, and every sparse index against the count (glTF 2.0 §3.6).
//! Components are widened to f64, normalised integers mapped to 0..1 (unsigned) or
//! −1..1 (signed) as the specification says; an accessor without a buffer view holds
//! zeros, then its sparse values. A fault is a refusal naming `accessors[i].field`.

use super::error::{at, GltfError};
use gltf::accessor::{DataType, Dimensions};

/// The buffers of one glTF file, to read accessors from.
pub struct Buffers<'a> {
    /// The glTF file's name, for messages.
    pub file: &'a str,
    /// Each buffer's bytes, at least its `byteLength`.
    pub data: &'a [Vec<u8>],
}

/// How many components an element of `d` has.
fn width(d: Dimensions) -> usize {
    match d {
        Dimensions::Scalar => 1,
        Dimensions::Vec2 => 2,
        Dimensions::Vec3 => 3,
        Dimensions::Vec4 | Dimensions::Mat2 => 4,
        Dimensions::Mat3 => 9,
        Dimensions::Mat4 => 16,
    }
}

/// The bytes of one component of `t`.
fn size(t: DataType) -> usize {
    match t {
        DataType::I8 | DataType::U8 => 1,
        DataType::I16 | DataType::U16 => 2,
        DataType::U32 | DataType::F32 => 4,
    }
}

/// Component `k` of the element at `bytes`, widened (and normalised when asked).
fn component(bytes: &[u8], t: DataType, normalized: bool) -> f64 {
    let b = bytes;
    match t {
        DataType::I8 => {
            let v = f64::from(b[0] as i8);
            if normalized {
                (v / 127.0).max(-1.0)
            } else {
                v
            }
        }
        DataType::U8 => {
            let v = f64::from(b[0]);
            if normalized {
                v / 255.0
            } else {
                v
            }
        }
        DataType::I16 => {
            let v = f64::from(i16::from_le_bytes([b[0], b[1]]));
            if normalized {
                (v / 32767.0).max(-1.0)
            } else {
                v
            }
        }
        DataType::U16 => {
            let v = f64::from(u16::from_le_bytes([b[0], b[1]]));
            if normalized {
                v / 65535.0
            } else {
                v
            }
        }
        DataType::U32 => f64::from(u32::from_le_bytes([b[0], b[1], b[2], b[3]])),
        DataType::F32 => f64::from(f32::from_le_bytes([b[0], b[1], b[2], b[3]])),
    }
}

impl Buffers<'_> {
    /// The bytes of `count` elements of `elem` bytes at `offset` of `view` with its
    /// stride, checked; the slice and the stride.
    fn span<'v>(
        &'v self,
        view: &gltf::buffer::View,
        offset: usize,
        count: usize,
        elem: usize,
        path: &str,
    ) -> Result<(&'v [u8], usize), GltfError> {
        let vpath = format!("bufferViews[{}]", view.index());
        let buffer = &self.data[view.buffer().index()];
        let end = view.offset().checked_add(view.length());
        if end.is_none_or(|e| e > buffer.len()) {
            return Err(at(
                self.file,
                format!("{vpath}.byteLength"),
                format!("the view ends past its buffer ({} bytes)", buffer.len()),
            ));
        }
        let bytes = &buffer[view.offset()..view.offset() + view.length()];
        let stride = view.stride().unwrap_or(elem);
        if stride < elem {
            return Err(at(
                self.file,
                format!("{vpath}.byteStride"),
                format!("a stride of {stride} is shorter than the element's {elem} bytes"),
            ));
        }
        if count == 0 {
            return Ok((&[], stride));
        }
        let need = (count as u128 - 1) * stride as u128 + elem as u128 + offset as u128;
        if need > bytes.len() as u128 {
            return Err(at(
                self.file,
                format!("{path}.count"),
                format!(
                    "{count} elements from byte {offset} need {need} bytes of {vpath}, which has {}",
                    bytes.len()
                ),
            ));
        }
        Ok((&bytes[offset..], stride))
    }

    /// Accessor `acc`'s elements as `N` f64 each, refused unless it has `N` components
    /// and at most `budget` elements.
    pub fn floats<const N: usize>(
        &self,
        acc: &gltf::Accessor,
        budget: u64,
    ) -> Result<Vec<[f64; N]>, GltfError> {
        let path = format!("accessors[{}]", acc.index());
        let (t, dims) = (acc.data_type(), acc.dimensions());
        if width(dims) != N || (N > 4 && t != DataType::F32) {
            return Err(at(
                self.file,
                format!("{path}.type"),
                format!("expected {N} components of floats, found {dims:?} of {t:?}"),
            ));
        }
        let count = acc.count();
        if count as u64 > budget {
            return Err(at(
                self.file,
                format!("{path}.count"),
                format!("{count} elements, over the limit of {budget}"),
            ));
        }
        let (norm, csize) = (acc.normalized(), size(t));
        let elem = csize * N;
        // The view is checked before anything the count asks for is allocated.
        let span = match acc.view() {
            Some(view) => Some(self.span(&view, acc.offset(), count, elem, &path)?),
            None => None,
        };
        let mut out = vec![[0.0; N]; count];
        if let Some((bytes, stride)) = span {
            for (k, o) in out.iter_mut().enumerate() {
                let e = &bytes[k * stride..];
                for (c, v) in o.iter_mut().enumerate() {
                    *v = component(&e[c * csize..], t, norm);
                }
            }
        }
        if let Some(sparse) = acc.sparse() {
            let n = sparse.count();
            if n > count {
                return Err(at(
                    self.file,
                    format!("{path}.sparse.count"),
                    format!("{n} sparse values for {count} elements"),
                ));
            }
            let ix = sparse.indices();
            let it = match ix.index_type() {
                gltf::accessor::sparse::IndexType::U8 => DataType::U8,
                gltf::accessor::sparse::IndexType::U16 => DataType::U16,
                gltf::accessor::sparse::IndexType::U32 => DataType::U32,
            };
            let ipath = format!("{path}.sparse.indices");
            let (ib, istride) = self.span(&ix.view(), ix.offset(), n, size(it), &ipath)?;
            let vals = sparse.values();
            let vpath = format!("{path}.sparse.values");
            let (vb, vstride) = self.span(&vals.view(), vals.offset(), n, elem, &vpath)?;
            let _ = (istride, vstride);
            for k in 0..n {
                let i = component(&ib[k * size(it)..], it, false) as usize;
                let Some(o) = out.get_mut(i) else {
                    return Err(at(
                        self.file,
                        ipath,
                        format!("sparse index {i} is past the accessor's {count} elements"),
                    ));
                };
                for (c, v) in o.iter_mut().enumerate() {
                    *v = component(&vb[k * elem + c * csize..], t, norm);
                }
            }
        }
        Ok(out)
    }

    /// An accessor of unsigned integers (indices, joints), each below `limit`.
    pub fn indices<const N: usize>(
        &self,
        acc: &gltf::Accessor,
        budget: u64,
        limit: u64,
    ) -> Result<Vec<[u32; N]>, GltfError> {
        let path = format!("accessors[{}]", acc.index());
        let t = acc.data_type();
        if !matches!(t, DataType::U8 | DataType::U16 | DataType::U32) || acc.normalized() {
            return Err(at(
                self.file,
                format!("{path}.componentType"),
                format!("expected unsigned integers, found {t:?}"),
            ));
        }
        let values = self.floats::<N>(acc, budget)?;
        let mut out = Vec::with_capacity(values.len());
        for v in values {
            let mut e = [0u32; N];
            for (o, x) in e.iter_mut().zip(v) {
                if x as u64 >= limit {
                    return Err(at(
                        self.file,
                        path,
                        format!("the index {x} is past the {limit} it indexes"),
                    ));
                }
                *o = x as u32;
            }
            out.push(e);
        }
        Ok(out)
    }
}
