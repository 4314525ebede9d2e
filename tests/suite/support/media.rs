//! Reading what the binaries wrote with outside readers, not the library's: a video's
//! frames as ffmpeg decodes them, an EXR file's channels as the `exr` crate reads them.

use exr::prelude::*;
use std::collections::HashMap;
use std::path::Path;
use std::process::Command;

/// The RGB bytes of every frame of a video, as ffmpeg decodes them.
pub fn decoded(video: &Path) -> Vec<u8> {
    let out = Command::new("ffmpeg")
        .args(["-v", "error", "-i"])
        .arg(video)
        .args(["-f", "rawvideo", "-pix_fmt", "rgb24", "-"])
        .output()
        .unwrap();
    super::stdout_ok(out)
}

/// Every channel of an EXR file by name, as floats.
pub fn exr_channels(path: &Path) -> HashMap<String, Vec<f32>> {
    let image = read()
        .no_deep_data()
        .largest_resolution_level()
        .all_channels()
        .first_valid_layer()
        .all_attributes()
        .from_file(path)
        .unwrap();
    image
        .layer_data
        .channel_data
        .list
        .iter()
        .map(|c| {
            let name = String::from_utf8_lossy(c.name.bytes()).into_owned();
            (name, c.sample_data.values_as_f32().collect())
        })
        .collect()
}

/// The byte an sRGB view shows of a linear value: the sRGB encoding (IEC 61966-2-1,
/// written here from the standard: 12.92·v up to 0.0031308, else 1.055·v^(1/2.4) − 0.055)
/// of the value clamped to 0..1, times 255, rounded.
pub fn srgb_byte(v: f32) -> u8 {
    let v = f64::from(v).clamp(0.0, 1.0);
    let e = if v <= 0.0031308 {
        12.92 * v
    } else {
        1.055 * v.powf(1.0 / 2.4) - 0.055
    };
    (e * 255.0).round() as u8
}
