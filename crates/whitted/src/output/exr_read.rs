//! The one reader of an OpenEXR's picture: the first valid part's `R G B` channels (or
//! `Y`, a grey image), rows top to bottom, and the `whitted:colour` attribute that says
//! how its colours are stored. `check`'s references, `encode`'s EXR frames
//! (`output::read`) and image textures (`texture::load`) all read through here; each
//! caller bounds the file's bytes and its header's size before it asks.

use crate::base::srgb::{Transfer, ATTRIBUTE};
use exr::prelude::{read, AttributeValue, ReadChannels, ReadLayers, Text};

/// An EXR's picture as stored: width, height, RGB rows top to bottom, and its
/// `whitted:colour` (`None` when the header has no such attribute).
#[derive(Debug)]
pub struct StoredRgb {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// The stored values, RGB, rows top to bottom.
    pub pixels: Vec<[f32; 3]>,
    /// The encoding its header names, if it names one.
    pub colour: Option<Transfer>,
}

/// The picture of the EXR file `bytes` (see the module's text), or why it has none.
pub fn read_rgb_layer(bytes: &[u8]) -> Result<StoredRgb, String> {
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
        let list = &layer.channel_data.list;
        let found = list.iter().find(|c| c.name.eq(name));
        found.map(|c| c.sample_data.values_as_f32().collect::<Vec<f32>>())
    };
    let (r, g, b) = match (find("R"), find("G"), find("B"), find("Y")) {
        (Some(r), Some(g), Some(b), _) => (r, g, b),
        (_, _, _, Some(y)) => (y.clone(), y.clone(), y),
        _ => return Err("it has neither R, G, B nor Y channels".to_string()),
    };
    let colour = match layer.attributes.other.get(&Text::from(ATTRIBUTE)) {
        Some(AttributeValue::Text(t)) => Some(
            Transfer::from_name(&t.to_string())
                .ok_or_else(|| format!("unknown {ATTRIBUTE} {t}"))?,
        ),
        _ => None,
    };
    let pixels = (r.into_iter().zip(g).zip(b))
        .map(|((r, g), b)| [r, g, b])
        .collect();
    Ok(StoredRgb {
        width: layer.size.width() as u32,
        height: layer.size.height() as u32,
        pixels,
        colour,
    })
}
