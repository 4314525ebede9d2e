//! `.exr`: OpenEXR through the `exr` crate, one scan-line part holding every layer, as
//! Blender's and Arnold's single-part EXRs do (SPEC §12):
//!
//! - beauty `R G B`, half unless `exr_depth = "float"`, not clamped, in the encoding
//!   `[output] colour` names (`colour`: by default the display values decoded to linear
//!   light with the sRGB EOTF); each value is the nearest half (or float) whose display
//!   value's clamp-and-round is the tracer's byte, so that the EXR converted to sRGB is
//!   the PNG's bytes exactly (it differs from plain rounding only on a byte's edge, by one
//!   unit in the last place);
//! - `A`, when the frame has it: the fraction of the pixel's camera samples that hit an
//!   object (fog and the background do not count); the colour is not premultiplied by it
//!   (the header's `whitted:alpha` says so);
//! - the passes' channels (`Z`, `P.X`…, `N.X`…, `albedo.R`…, `diffuse.R`…,
//!   `crypto_object00.R`…), 32-bit float always (Cryptomatte needs it, and the light split
//!   must sum to the beauty to 1e-5); the light split and the albedo follow the beauty's
//!   encoding (`colour::follow_beauty`);
//! - header: `whitted:colour` (`srgb` or `linear`), `whitted:alpha`, `chromaticities` (Rec.709 primaries, D65 white), `worldToCamera`,
//!   `worldToNDC`, `software`, the frame's provenance as string attributes under their
//!   stamp keywords (`whitted:digest`, … UTF-8), and each Cryptomatte's
//!   `cryptomatte/<key>/name|hash|conversion|manifest`;
//! - compression ZIP (16 lines a block) unless set; increasing line order, and header
//!   attributes sorted by name (the crate keeps them in a hash map), so the same frame is
//!   the same bytes on every run.

use super::colour::{self, float_keeping_byte, half_keeping_byte};
use super::{ExrCompression, ExrDepth, ExrOptions, OutputError};
use crate::base::srgb::{Transfer, ATTRIBUTE};
use crate::passes::{crypto, Layers};
use exr::meta::attribute::Chromaticities;
use exr::prelude::*;
use std::io::Write;
use std::result::Result;

/// The header attribute that says what `A` is.
pub const ALPHA_ATTRIBUTE: &str = "whitted:alpha";

/// What it says.
pub const ALPHA_MEANING: &str = "coverage: the fraction of the pixel's camera samples that \
    hit an object (fog and the background do not count); colour not premultiplied";

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
        channels: mut passes,
        crypto: crypto_headers,
        camera,
        alpha,
    } = layers;
    let size = (width as usize, height as usize);
    let mut channels: SmallVec<[AnyChannel<FlatSamples>; 4]> = SmallVec::new();
    let encoding = options.colour;
    for (axis, name) in ["R", "G", "B"].into_iter().enumerate() {
        let values = beauty.iter().map(|c| c[axis]);
        let samples = match options.depth {
            ExrDepth::Half => {
                FlatSamples::F16(values.map(|v| half_keeping_byte(v, encoding)).collect())
            }
            ExrDepth::Float => {
                FlatSamples::F32(values.map(|v| float_keeping_byte(v, encoding)).collect())
            }
        };
        channels.push(AnyChannel::new(name, samples));
    }
    colour::follow_beauty(&mut passes, &beauty, encoding);
    drop(beauty);
    let has_alpha = alpha.is_some();
    if let Some(alpha) = alpha {
        let samples = match options.depth {
            ExrDepth::Half => FlatSamples::F16(alpha.into_iter().map(f16::from_f32).collect()),
            ExrDepth::Float => FlatSamples::F32(alpha),
        };
        channels.push(AnyChannel::new("A", samples));
    }
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
    put(ATTRIBUTE, encoding.name());
    if has_alpha {
        put(ALPHA_ATTRIBUTE, ALPHA_MEANING);
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

/// The size of the first part of the EXR file `read` gives, from its header alone (nothing
/// of its pixels is read or allocated).
pub(super) fn header_size(read: impl std::io::Read) -> Result<(u32, u32), String> {
    let meta = exr::meta::MetaData::read_from_buffered(read, false).map_err(|e| e.to_string())?;
    let header = meta.headers.first().ok_or("no part in the file")?;
    let size = header.layer_size;
    let side = |v: usize| u32::try_from(v).map_err(|_| format!("a side of {v} pixels"));
    Ok((side(size.width())?, side(size.height())?))
}

/// A beauty as an EXR file stores it: width, height, RGB rows top to bottom, encoding.
pub(super) type Stored = (u32, u32, Vec<[f32; 3]>, Transfer);

/// The beauty of the EXR file `bytes` as stored (RGB, rows top to bottom), with its size
/// and its encoding: its `whitted:colour`, or `Linear` when the header has no such
/// attribute (frames written before it held the values as they are).
pub(super) fn read_beauty(bytes: &[u8]) -> Result<Stored, String> {
    let stored = super::exr_read::read_rgb_layer(bytes)?;
    let colour = stored.colour.unwrap_or(Transfer::Linear);
    Ok((stored.width, stored.height, stored.pixels, colour))
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
