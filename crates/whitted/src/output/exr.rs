//! `.exr`: OpenEXR through the `exr` crate, one scan-line part holding every layer, as
//! Blender's and Arnold's single-part EXRs do (SPEC §12):
//!
//! - beauty `R G B`, half unless `exr_depth = "float"`, not clamped; each value is the
//!   nearest half (or float) whose clamp-and-round is the tracer's byte, so that
//!   `round(255·clamp(beauty))` is the PNG's byte exactly (it differs from plain rounding
//!   only on a byte's edge, by one unit in the last place);
//! - the passes' channels (`Z`, `P.X`…, `N.X`…, `albedo.R`…, `diffuse.R`…,
//!   `crypto_object00.R`…), 32-bit float always (Cryptomatte needs it, and the light split
//!   must sum to the beauty to 1e-5);
//! - header: `chromaticities` (Rec.709 primaries, D65 white), `worldToCamera`,
//!   `worldToNDC`, `software`, the frame's provenance as string attributes under their
//!   stamp keywords (`whitted:digest`, … UTF-8), and each Cryptomatte's
//!   `cryptomatte/<key>/name|hash|conversion|manifest`;
//! - compression ZIP (16 lines a block) unless set; increasing line order, and header
//!   attributes sorted by name (the crate keeps them in a hash map), so the same frame is
//!   the same bytes on every run.

use super::{ExrCompression, ExrDepth, ExrOptions, OutputError};
use crate::passes::{crypto, Layers};
use crate::render::to_byte;
use exr::meta::attribute::Chromaticities;
use exr::prelude::*;
use std::io::Write;
use std::result::Result;

/// Encodes `layers` with `meta` as string attributes. The layers are taken: their
/// channels' values move into the image instead of being copied (a frame's passes are
/// most of its memory).
pub(super) fn encode(
    layers: Layers,
    options: ExrOptions,
    meta: &[(String, String)],
    out: &mut dyn Write,
) -> Result<(), OutputError> {
    let Layers {
        width,
        height,
        beauty,
        channels: passes,
        crypto: crypto_headers,
        camera,
    } = layers;
    let size = (width as usize, height as usize);
    let mut channels: SmallVec<[AnyChannel<FlatSamples>; 4]> = SmallVec::new();
    for (axis, name) in ["R", "G", "B"].into_iter().enumerate() {
        let values = beauty.iter().map(|c| c[axis]);
        let samples = match options.depth {
            ExrDepth::Half => FlatSamples::F16(values.map(half_keeping_byte).collect()),
            ExrDepth::Float => FlatSamples::F32(values.map(float_keeping_byte).collect()),
        };
        channels.push(AnyChannel::new(name, samples));
    }
    drop(beauty);
    for ch in passes {
        channels.push(AnyChannel::new(text(&ch.name), FlatSamples::F32(ch.values)));
    }
    let mut attributes = LayerAttributes {
        software_name: Some(text(&format!("whitted {}", env!("CARGO_PKG_VERSION")))),
        ..Default::default()
    };
    if let Some(cam) = camera {
        attributes.world_to_camera = Some(cam.world_to_camera);
        attributes.world_to_normalized_device = Some(cam.world_to_ndc);
    }
    let mut put = |k: &str, v: &str| {
        attributes
            .other
            .insert(text(k), AttributeValue::Text(text(v)));
    };
    for (k, v) in meta {
        put(k, v);
    }
    for c in &crypto_headers {
        let key = format!("cryptomatte/{}", crypto::key(&c.name));
        put(&format!("{key}/name"), &c.name);
        put(&format!("{key}/hash"), "MurmurHash3_32");
        put(&format!("{key}/conversion"), "uint32_to_float32");
        put(
            &format!("{key}/manifest"),
            &crypto::manifest_json(&c.manifest),
        );
    }
    let compression = match options.compression {
        ExrCompression::None => Compression::Uncompressed,
        ExrCompression::Rle => Compression::RLE,
        ExrCompression::Zips => Compression::ZIP1,
        ExrCompression::Zip => Compression::ZIP16,
        ExrCompression::Piz => Compression::PIZ,
    };
    let encoding = Encoding {
        compression,
        blocks: Blocks::ScanLines,
        line_order: LineOrder::Increasing,
    };
    let layer = Layer::new(size, attributes, encoding, AnyChannels::sort(channels));
    let mut image = Image::from_layer(layer);
    image.attributes.chromaticities = Some(Chromaticities {
        red: Vec2(0.64, 0.33),
        green: Vec2(0.30, 0.60),
        blue: Vec2(0.15, 0.06),
        white: Vec2(0.3127, 0.3290),
    });
    let mut bytes = std::io::Cursor::new(Vec::new());
    image
        .write()
        .non_parallel()
        .to_buffered(&mut bytes)
        .map_err(exr_error)?;
    let mut bytes = bytes.into_inner();
    sort_header(&mut bytes).map_err(|m| OutputError::Stream(std::io::Error::other(m)))?;
    out.write_all(&bytes)?;
    Ok(())
}

/// A UTF-8 string as an EXR text (OpenEXR strings are bytes; UTF-8 is the convention).
fn text(s: &str) -> Text {
    Text::from_slice_unchecked(s.as_bytes())
}

fn exr_error(e: exr::error::Error) -> OutputError {
    OutputError::Stream(std::io::Error::other(e.to_string()))
}

/// Rewrites the attributes of a single-part header in name order. The header keeps its
/// length, so the offset table after it stays right.
fn sort_header(bytes: &mut [u8]) -> Result<(), &'static str> {
    let mut at = 8;
    let mut attrs: Vec<&[u8]> = Vec::new();
    let nul = |b: &[u8], from: usize| b[from..].iter().position(|&c| c == 0).map(|p| from + p);
    loop {
        let name_end = nul(bytes, at).ok_or("header without end")?;
        if name_end == at {
            break;
        }
        let type_end = nul(bytes, name_end + 1).ok_or("attribute without type")?;
        let size_at = type_end + 1;
        let size = bytes
            .get(size_at..size_at + 4)
            .ok_or("attribute without size")?;
        let size = u32::from_le_bytes([size[0], size[1], size[2], size[3]]) as usize;
        let end = size_at + 4 + size;
        attrs.push(bytes.get(at..end).ok_or("attribute past the file")?);
        at = end;
    }
    let mut sorted: Vec<Vec<u8>> = attrs.into_iter().map(<[u8]>::to_vec).collect();
    let name = |a: &Vec<u8>| a[..a.iter().position(|&c| c == 0).unwrap_or(0)].to_vec();
    sorted.sort_by_key(name);
    let flat: Vec<u8> = sorted.concat();
    bytes[8..8 + flat.len()].copy_from_slice(&flat);
    Ok(())
}

/// The float nearest `c` whose clamp-and-round is `c`'s byte.
pub(crate) fn float_keeping_byte(c: f64) -> f32 {
    let want = to_byte(c);
    let mut v = c as f32;
    for _ in 0..4 {
        if to_byte(f64::from(v)) == want {
            break;
        }
        v = if f64::from(v) < c {
            v.next_up()
        } else {
            v.next_down()
        };
    }
    v
}

/// The half nearest `c` whose clamp-and-round is `c`'s byte (halves are 8 to a byte's
/// width of 1/255 below 1, so there always is one).
pub(crate) fn half_keeping_byte(c: f64) -> f16 {
    let want = to_byte(c);
    let mut v = f16::from_f64(c);
    for _ in 0..4 {
        let x = v.to_f64();
        if to_byte(x) == want || !x.is_finite() {
            break;
        }
        // Halves of one sign are ordered like their bits' magnitudes.
        let up = x < c;
        let bits = v.to_bits();
        let away_from_zero = up == (x >= 0.0);
        v = match (away_from_zero, bits & 0x7fff) {
            (true, _) => f16::from_bits(bits + 1),
            (false, 0) => f16::from_bits(if up { 0x0001 } else { 0x8001 }),
            (false, _) => f16::from_bits(bits - 1),
        };
    }
    v
}

/// The size of the first part of the EXR file `read` gives, from its header alone (nothing
/// of its pixels is read or allocated).
pub(super) fn header_size(read: impl std::io::Read) -> Result<(u32, u32), String> {
    let meta = exr::meta::MetaData::read_from_buffered(read, false).map_err(|e| e.to_string())?;
    let header = meta.headers.first().ok_or("no part in the file")?;
    let size = header.layer_size;
    let side = |v: usize| u32::try_from(v).map_err(|_| format!("a side of {v} pixels"));
    Ok((side(size.width())?, side(size.height())?))
}

/// The beauty of the EXR file `bytes` as RGB floats, rows top to bottom, with its size
/// (`read::read_beauty` reads the file).
pub(super) fn read_beauty(bytes: &[u8]) -> Result<(u32, u32, Vec<[f32; 3]>), String> {
    let image = read()
        .no_deep_data()
        .largest_resolution_level()
        .all_channels()
        .first_valid_layer()
        .all_attributes()
        .from_buffered(std::io::Cursor::new(bytes))
        .map_err(|e| e.to_string())?;
    let layer = &image.layer_data;
    let find = |name: &str| {
        layer
            .channel_data
            .list
            .iter()
            .find(|c| c.name.eq(name))
            .map(|c| c.sample_data.values_as_f32().collect::<Vec<f32>>())
            .ok_or_else(|| format!("no {name} channel"))
    };
    let (r, g, b) = (find("R")?, find("G")?, find("B")?);
    let (w, h) = (layer.size.width() as u32, layer.size.height() as u32);
    let pixels = r
        .into_iter()
        .zip(g)
        .zip(b)
        .map(|((r, g), b)| [r, g, b])
        .collect();
    Ok((w, h, pixels))
}

/// The string attributes of the header of the EXR file `file` reads, of `width`×`height`,
/// when it is whole (its header reads, with that size, and its offset table and blocks
/// are consistent: `exr_offsets`); `None` otherwise.
pub fn texts_if_whole(
    mut file: impl std::io::Read + std::io::Seek,
    width: u32,
    height: u32,
) -> Option<Vec<(String, String)>> {
    let reader = exr::block::reader::Reader::read_from_buffered(&mut file, false).ok()?;
    let header = reader.headers().first()?;
    if header.layer_size != Vec2(width as usize, height as usize) {
        return None;
    }
    let texts = header
        .own_attributes
        .other
        .iter()
        .filter_map(|(name, value)| match value {
            AttributeValue::Text(t) => Some((
                String::from_utf8_lossy(name.bytes()).into_owned(),
                String::from_utf8_lossy(t.bytes()).into_owned(),
            )),
            _ => None,
        })
        .collect();
    drop(reader);
    file.rewind().ok()?;
    super::exr_offsets::check(&mut file).ok()?;
    Some(texts)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stored_values_keep_their_byte() {
        // 0.5/255 + a hair rounds to 1 in f64; plain half rounding may give 0.
        for k in 0..=2550 {
            let c = (k as f64 + 0.5) / 2550.0 * 1.1 - 0.05;
            for c in [
                c,
                (k as f64 / 10.0 + 0.5) / 255.0,
                ((k as f64 / 10.0 + 0.5) / 255.0).next_down(),
            ] {
                let want = to_byte(c);
                let h = half_keeping_byte(c);
                assert_eq!(to_byte(h.to_f64()), want, "{c:e} → half {h}");
                assert!(
                    (h.to_f64() - c).abs() <= 2.0 * (c.abs() * 2f64.powi(-11) + 6e-8),
                    "{c} {h}"
                );
                let f = float_keeping_byte(c);
                assert_eq!(to_byte(f64::from(f)), want, "{c:e} → float {f}");
                assert!((f64::from(f) - c).abs() <= 2.0 * c.abs() * 2f64.powi(-24) + 1e-40);
            }
        }
        assert_eq!(half_keeping_byte(3.0).to_f64(), 3.0);
    }
}
