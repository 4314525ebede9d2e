//! The packets of tev's IPC protocol that a renderer sends, encoded as tev's own
//! `include/tev/Ipc.h` and `src/Ipc.cpp` define them (written from that description; no
//! code copied). Every packet is
//!
//! ```text
//! u32 size (of the whole packet, these 4 bytes included) · u8 type · payload
//! ```
//!
//! little-endian, strings as their bytes and a NUL, bools as one byte 0/1:
//!
//! | type | packet | payload |
//! |---|---|---|
//! | 4 | CreateImage | bool grabFocus · name · i32 width · i32 height · i32 nChannels · nChannels names |
//! | 6 | UpdateImage (v3) | bool grabFocus · name · i32 nChannels · names · i32 x · i32 y · i32 w · i32 h · i64 offsets[n] · i64 strides[n] · f32 data |
//! | 2 | CloseImage | name |
//!
//! In an UpdateImage, channel c of tile pixel k (row-major in the w×h tile) is
//! `data[offset[c] + k·stride[c]]`: interleaved RGB is offsets 0, 1, 2 and strides 3.
//!
//! **Bytes to floats**: tev takes floats in linear light and shows them through the sRGB
//! curve, so it receives what an EXR frame holds (SPEC §12): a frame's byte b is sent as
//! `Transfer::store(b/255)`, by default the display value decoded with the sRGB EOTF (tev's
//! sRGB view then shows the PNG's byte), or b/255 under `colour = "linear"`. The byte is
//! recovered exactly as `Transfer::byte(f)` (round(255·encode(f))): `byte_to_float` and
//! `float_to_byte` below, tested for all 256 values in both encodings.

/// tev's packet types (`IpcPacket::EType`).
pub mod kind {
    /// Close an image by name.
    pub const CLOSE_IMAGE: u8 = 2;
    /// Create an empty image with named channels.
    pub const CREATE_IMAGE: u8 = 4;
    /// A rectangle of pixels, with channel offsets and strides.
    pub const UPDATE_IMAGE_V3: u8 = 6;
}

use crate::base::Transfer;

/// The float tev receives for byte `b` under `colour`: `colour.store(b/255)`.
pub fn byte_to_float(b: u8, colour: Transfer) -> f32 {
    colour.store(f64::from(b) / 255.0) as f32
}

/// The byte a float received from `byte_to_float` came from (what tev's sRGB view shows
/// of it; only the tests need it here).
#[cfg(test)]
fn float_to_byte(f: f32, colour: Transfer) -> u8 {
    colour.byte(f64::from(f))
}

/// A packet under construction: the size is filled in by `finish`.
struct Out(Vec<u8>);

impl Out {
    fn new(kind: u8) -> Out {
        let mut v = vec![0u8; 4];
        v.push(kind);
        Out(v)
    }
    fn bool(mut self, b: bool) -> Out {
        self.0.push(u8::from(b));
        self
    }
    fn str(mut self, s: &str) -> Out {
        // A NUL inside a name would end it early on tev's side: drop it.
        self.0.extend(s.bytes().filter(|&b| b != 0));
        self.0.push(0);
        self
    }
    fn i32(mut self, v: i32) -> Out {
        self.0.extend(v.to_le_bytes());
        self
    }
    fn i64(mut self, v: i64) -> Out {
        self.0.extend(v.to_le_bytes());
        self
    }
    fn finish(mut self) -> Vec<u8> {
        let n = self.0.len() as u32;
        self.0[..4].copy_from_slice(&n.to_le_bytes());
        self.0
    }
}

/// CreateImage: an image `name` of `width`×`height` with the given channels.
pub fn create_image(
    name: &str,
    grab_focus: bool,
    width: u32,
    height: u32,
    channels: &[&str],
) -> Vec<u8> {
    let mut p = Out::new(kind::CREATE_IMAGE)
        .bool(grab_focus)
        .str(name)
        .i32(width as i32)
        .i32(height as i32)
        .i32(channels.len() as i32);
    for c in channels {
        p = p.str(c);
    }
    p.finish()
}

/// UpdateImage (v3): the `width`×`height` rectangle at (x, y) of image `name`, from
/// interleaved RGB bytes (`rgb.len()` = width·height·3), as floats `byte_to_float`.
pub fn update_rgb(
    name: &str,
    (x, y, width, height): (u32, u32, u32, u32),
    rgb: &[u8],
    colour: Transfer,
) -> Vec<u8> {
    let mut p = Out::new(kind::UPDATE_IMAGE_V3).bool(false).str(name).i32(3);
    for c in ["R", "G", "B"] {
        p = p.str(c);
    }
    p = p
        .i32(x as i32)
        .i32(y as i32)
        .i32(width as i32)
        .i32(height as i32);
    for offset in 0..3 {
        p = p.i64(offset);
    }
    for _ in 0..3 {
        p = p.i64(3);
    }
    p.0.reserve(rgb.len() * 4);
    let floats: [f32; 256] = std::array::from_fn(|b| byte_to_float(b as u8, colour));
    for &b in rgb {
        p.0.extend(floats[usize::from(b)].to_le_bytes());
    }
    p.finish()
}

/// CloseImage: remove image `name` from the viewer.
pub fn close_image(name: &str) -> Vec<u8> {
    Out::new(kind::CLOSE_IMAGE).str(name).finish()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_byte_survives_the_float() {
        for colour in [Transfer::Srgb, Transfer::Linear] {
            for b in 0..=255u8 {
                assert_eq!(float_to_byte(byte_to_float(b, colour), colour), b);
            }
            assert_eq!(byte_to_float(255, colour), 1.0);
            assert_eq!(byte_to_float(0, colour), 0.0);
        }
        // 51/255 = 0.2 in f32; decoded, ((0.2 + 0.055)/1.055)^2.4 = 0.0331048.
        assert_eq!(byte_to_float(51, Transfer::Linear), 0.2f32);
        assert!((byte_to_float(51, Transfer::Srgb) - 0.033_104_8).abs() < 1e-7);
    }

    #[test]
    fn create_image_by_hand() {
        let p = create_image("ab", true, 2, 3, &["R"]);
        let want: Vec<u8> = [
            &[23, 0, 0, 0, 4, 1, b'a', b'b', 0][..],
            &[2, 0, 0, 0, 3, 0, 0, 0, 1, 0, 0, 0, b'R', 0],
        ]
        .concat();
        assert_eq!(p, want);
    }

    #[test]
    fn update_image_layout() {
        let p = update_rgb("i", (1, 2, 1, 1), &[0, 51, 255], Transfer::Linear);
        // 4 size + 1 type + 1 bool + 2 name + 4 n + 6 names + 16 rect + 48 offsets and
        // strides + 12 data.
        assert_eq!(p.len(), 94);
        assert_eq!(u32::from_le_bytes(p[..4].try_into().unwrap()), 94);
        assert_eq!(p[4], kind::UPDATE_IMAGE_V3);
        let data = &p[82..];
        let f = |k: usize| f32::from_le_bytes(data[k * 4..k * 4 + 4].try_into().unwrap());
        assert_eq!((f(0), f(1), f(2)), (0.0, 0.2, 1.0));
        assert_eq!(&p[18..22], &1i32.to_le_bytes());
        assert_eq!(&p[34..42], &0i64.to_le_bytes());
        assert_eq!(&p[58..66], &3i64.to_le_bytes());
    }
}
