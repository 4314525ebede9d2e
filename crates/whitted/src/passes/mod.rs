//! The passes of a frame for compositing (SPEC §12): what the camera ray's first hit tells
//! besides the beauty, recorded by the tracer in the same traversal and kept beside it as
//! a frame of layers (`Layers`), which the EXR writer stores and `--pass` shows.
//!
//! ```toml
//! [output]
//! format = "exr"
//! passes = ["depth", "position", "normal", "albedo",
//!           "ambient", "diffuse", "specular", "reflection", "transmission", "fog",
//!           "crypto_object", "crypto_material"]
//! ```
//!
//! - `record`: the per-sample recorder the tracer calls (`trace::Record`) and the per-pixel
//!   sums it feeds; a frame without passes uses the tracer's no-op recorder instead.
//! - `crypto`: Cryptomatte 1.1 ids, ranks and manifests.
//! - `visible`: one pass as an 8-bit picture (`raytrace --pass NAME`).
//!
//! Every pass is the mean over the pixel's samples (and motion-blur sub-frames) of the
//! camera ray's first hit; a sample that hits nothing gives 0 (depth: +∞).

pub mod crypto;
pub mod record;
pub mod visible;

use crate::base::Color;
use std::fmt;

/// One pass a frame can carry besides its beauty.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Pass {
    /// `Z`: distance from the eye along the view axis.
    Depth,
    /// `P.X P.Y P.Z`: the world position of the hit.
    Position,
    /// `N.X N.Y N.Z`: the world shading normal (after bump, facing the ray).
    Normal,
    /// `albedo.R G B`: the texture colour at the hit.
    Albedo,
    /// `ambient.R G B`: 0.2·C, fogged.
    Ambient,
    /// `diffuse.R G B`: every light's diffuse term times its shadow transmission, fogged.
    Diffuse,
    /// `specular.R G B`: every light's specular term times its shadow transmission, fogged.
    Specular,
    /// `reflection.R G B`: Kr·trace(reflected ray), fogged.
    Reflection,
    /// `transmission.R G B`: Kt·C⊙trace(refracted ray) (or Kt·trace(reflected) on total
    /// internal reflection), fogged.
    Transmission,
    /// `fog.R G B`: the fog's own white, f·(1, 1, 1).
    Fog,
    /// `crypto_object00..02`: Cryptomatte of the object names (`sphere 3`).
    CryptoObject,
    /// `crypto_material00..02`: Cryptomatte of the material names.
    CryptoMaterial,
}

impl Pass {
    /// Every pass, in the order the names list them.
    pub const ALL: [Pass; 12] = [
        Pass::Depth,
        Pass::Position,
        Pass::Normal,
        Pass::Albedo,
        Pass::Ambient,
        Pass::Diffuse,
        Pass::Specular,
        Pass::Reflection,
        Pass::Transmission,
        Pass::Fog,
        Pass::CryptoObject,
        Pass::CryptoMaterial,
    ];

    /// The light split, whose layers sum to the beauty.
    pub const LIGHT: [Pass; 6] = [
        Pass::Ambient,
        Pass::Diffuse,
        Pass::Specular,
        Pass::Reflection,
        Pass::Transmission,
        Pass::Fog,
    ];

    /// The name a manifest or `--pass` gives it.
    pub fn name(self) -> &'static str {
        match self {
            Pass::Depth => "depth",
            Pass::Position => "position",
            Pass::Normal => "normal",
            Pass::Albedo => "albedo",
            Pass::Ambient => "ambient",
            Pass::Diffuse => "diffuse",
            Pass::Specular => "specular",
            Pass::Reflection => "reflection",
            Pass::Transmission => "transmission",
            Pass::Fog => "fog",
            Pass::CryptoObject => "crypto_object",
            Pass::CryptoMaterial => "crypto_material",
        }
    }

    /// The pass a name gives, `None` for an unknown name.
    pub fn from_name(name: &str) -> Option<Pass> {
        Pass::ALL.into_iter().find(|p| p.name() == name)
    }

    /// The EXR channel names of a pass that is not a Cryptomatte (those have three RGBA
    /// layers, see `crypto`).
    pub fn channels(self) -> [String; 3] {
        let (layer, axes) = match self {
            Pass::Depth => return ["Z".into(), String::new(), String::new()],
            Pass::Position => ("P", ["X", "Y", "Z"]),
            Pass::Normal => ("N", ["X", "Y", "Z"]),
            other => (other.name(), ["R", "G", "B"]),
        };
        axes.map(|a| format!("{layer}.{a}"))
    }

    fn bit(self) -> u16 {
        1 << Pass::ALL.iter().position(|&p| p == self).unwrap_or(0)
    }
}

impl fmt::Display for Pass {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A set of passes (a bit set, so that an image format carrying it stays `Copy`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct PassSet(u16);

impl PassSet {
    /// No pass: the beauty alone.
    pub const NONE: PassSet = PassSet(0);

    /// The set holding `passes`.
    pub fn of(passes: &[Pass]) -> PassSet {
        PassSet(passes.iter().fold(0, |s, p| s | p.bit()))
    }

    /// Whether `pass` is in the set.
    pub fn has(self, pass: Pass) -> bool {
        self.0 & pass.bit() != 0
    }

    /// Whether the set is empty.
    pub fn is_empty(self) -> bool {
        self.0 == 0
    }

    /// The passes of the set, in `Pass::ALL` order.
    pub fn iter(self) -> impl Iterator<Item = Pass> {
        Pass::ALL.into_iter().filter(move |&p| self.has(p))
    }
}

/// The set is recorded (in frame digests) as the list of its names.
impl serde::Serialize for PassSet {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_seq(self.iter().map(Pass::name))
    }
}

/// A named float channel of a frame of layers, width·height values, rows top to bottom.
#[derive(Clone, Debug, PartialEq)]
pub struct Channel {
    /// Its EXR name, `Z`, `P.X`, `diffuse.R`, `crypto_object00.A`, …
    pub name: String,
    /// One value per pixel.
    pub values: Vec<f32>,
}

/// A Cryptomatte layer's header: its name and the manifest of the names it hashes.
#[derive(Clone, Debug, PartialEq)]
pub struct CryptoHeader {
    /// The layer name, `crypto_object` or `crypto_material`.
    pub name: String,
    /// Every name of the scene with its id (the float bits of its hash), sorted by name.
    pub manifest: Vec<(String, u32)>,
}

/// The camera of a frame, as the EXR header's `worldToCamera` and `worldToNDC` carry it
/// (row-vector matrices, Imath's convention: p' = p·M; camera space x right, y up, z
/// forward).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CameraMatrices {
    /// World to camera.
    pub world_to_camera: [f32; 16],
    /// World to normalised device coordinates: x and y in −1..1 across the view plane
    /// (y up), z = 1 − near/z with near the tracer's epsilon 0.01.
    pub world_to_ndc: [f32; 16],
}

/// A frame of layers: the unclamped beauty and the passes asked for.
#[derive(Clone, Debug, PartialEq)]
pub struct Layers {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// The beauty, not clamped: the mean of the pixel's unclamped samples.
    pub beauty: Vec<Color>,
    /// The passes' channels, in `Pass::ALL` order.
    pub channels: Vec<Channel>,
    /// The Cryptomatte layers' headers.
    pub crypto: Vec<CryptoHeader>,
    /// The camera the frame was drawn from (at the frame's own time).
    pub camera: Option<CameraMatrices>,
    /// Coverage, when known: the fraction of each pixel's camera samples that hit an
    /// object (fog and the background do not count); the beauty is not premultiplied.
    pub alpha: Option<Vec<f32>>,
}

impl Layers {
    /// The channel named `name`.
    pub fn channel(&self, name: &str) -> Option<&Channel> {
        self.channels.iter().find(|c| c.name == name)
    }

    /// The beauty through the clamp-and-round of SPEC §2: the 8-bit picture.
    pub fn to_frame(&self) -> crate::base::Frame {
        let beauty = self.beauty.iter().copied();
        crate::base::Frame::from_colors(beauty, self.width, self.height)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip_and_sets_hold_what_they_were_given() {
        for p in Pass::ALL {
            assert_eq!(Pass::from_name(p.name()), Some(p));
        }
        assert_eq!(Pass::from_name("beauty"), None);
        let set = PassSet::of(&[Pass::Normal, Pass::Depth]);
        assert!(set.has(Pass::Depth) && set.has(Pass::Normal) && !set.has(Pass::Fog));
        assert_eq!(set.iter().collect::<Vec<_>>(), [Pass::Depth, Pass::Normal]);
        assert_eq!(
            serde_json::to_string(&set).unwrap(),
            r#"["depth","normal"]"#
        );
        assert_eq!(Pass::Position.channels(), ["P.X", "P.Y", "P.Z"]);
        assert_eq!(Pass::Diffuse.channels()[2], "diffuse.B");
    }
}
