//! One pass as an 8-bit picture, for a quick look (`raytrace --pass NAME -o x.png`):
//!
//! - `depth`: inverse depth, `near / z` with `near` the frame's nearest depth: the
//!   nearest point white, twice as far half grey, the horizon of an infinite plane fading
//!   to black rather than squashing everything else white; no hit (+∞) is black;
//! - `position`: each axis through `0.5 + 0.5·x/(1 + |x|)`: the origin mid-grey, positive
//!   coordinates brighter, bounded however far a plane goes (no hit: the origin's grey);
//! - `normal`: `(N + 1)/2` per axis, the usual normal-map colours (+x red, +y green,
//!   +z blue);
//! - `albedo` and the light split: their colours through the clamp-and-round of §2;
//! - `crypto_object` / `crypto_material`: the rank-0 id's low three bytes as a colour,
//!   times its coverage (each name its own flat colour, edges blended).

use super::{Layers, Pass};
use crate::base::{to_byte, Frame};

/// The picture of `pass` of `layers`; `None` when the layers do not carry it.
pub fn picture(layers: &Layers, pass: Pass) -> Option<Frame> {
    let n = layers.width as usize * layers.height as usize;
    let get = |name: &str| layers.channel(name).map(|c| &c.values);
    let mut rgb: Vec<[f64; 3]> = vec![[0.0; 3]; n];
    match pass {
        Pass::Depth => {
            let z = get("Z")?;
            let near = z
                .iter()
                .filter(|v| v.is_finite() && **v > 0.0)
                .fold(f32::INFINITY, |a, &b| a.min(b));
            for (px, &d) in rgb.iter_mut().zip(z) {
                if d.is_finite() && d > 0.0 {
                    *px = [f64::from(near) / f64::from(d); 3];
                }
            }
        }
        Pass::Position | Pass::Normal => {
            let names = pass.channels();
            for (axis, name) in names.iter().enumerate() {
                for (px, &v) in rgb.iter_mut().zip(get(name)?) {
                    let v = f64::from(v);
                    px[axis] = if pass == Pass::Normal {
                        (v + 1.0) / 2.0
                    } else {
                        0.5 + 0.5 * v / (1.0 + v.abs())
                    };
                }
            }
        }
        Pass::CryptoObject | Pass::CryptoMaterial => {
            let ids = get(&format!("{}00.R", pass.name()))?;
            let cover = get(&format!("{}00.G", pass.name()))?;
            for ((px, id), &c) in rgb.iter_mut().zip(ids).zip(cover) {
                let b = id.to_bits().to_le_bytes();
                *px = [0, 1, 2].map(|k| f64::from(b[k]) / 255.0 * f64::from(c));
            }
        }
        colour => {
            let names = colour.channels();
            for (axis, name) in names.iter().enumerate() {
                for (px, &v) in rgb.iter_mut().zip(get(name)?) {
                    px[axis] = f64::from(v);
                }
            }
        }
    }
    Some(Frame {
        width: layers.width,
        height: layers.height,
        pixels: rgb.iter().flat_map(|c| c.map(to_byte)).collect(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::passes::Channel;

    fn layers(channels: Vec<Channel>) -> Layers {
        Layers {
            width: 3,
            height: 1,
            beauty: vec![crate::base::Color::ZERO; 3],
            channels,
            crypto: vec![],
            camera: None,
            alpha: None,
        }
    }

    #[test]
    fn depth_is_inverse_from_the_nearest_and_misses_are_black() {
        let l = layers(vec![Channel {
            name: "Z".into(),
            values: vec![2.0, 4.0, f32::INFINITY],
        }]);
        let f = picture(&l, Pass::Depth).unwrap();
        // near/z: 2/2 = 1 → 255, 2/4 = 0.5 → 128, +inf → 0.
        assert_eq!(f.pixels, [255, 255, 255, 128, 128, 128, 0, 0, 0]);
        assert!(picture(&l, Pass::Normal).is_none());
    }

    #[test]
    fn normals_map_minus_one_to_one_onto_0_to_255() {
        let ch = |name: &str, v: [f32; 3]| Channel {
            name: name.into(),
            values: v.to_vec(),
        };
        let l = layers(vec![
            ch("N.X", [-1.0, 0.0, 1.0]),
            ch("N.Y", [0.0, 0.0, 0.0]),
            ch("N.Z", [1.0, 1.0, 1.0]),
        ]);
        let f = picture(&l, Pass::Normal).unwrap();
        // (−1+1)/2 = 0; (0+1)/2 = 0.5 → 128; (1+1)/2 = 1 → 255.
        assert_eq!(&f.pixels[..6], &[0, 128, 255, 128, 128, 255]);
    }
}
