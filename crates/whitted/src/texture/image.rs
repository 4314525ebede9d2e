//! Image textures (SPEC §16): TEXTURE `3 "file" Map Interp Size`, an image whose colour
//! replaces C. The pixels are read once per scene (`load`) and shared, behind an `Arc`,
//! by every object that names the file, every frame and every thread.
//!
//! (u, v) come from the map (`map`) and wrap (u − ⌊u⌋); row 0 is the image's top:
//! - `nearest` takes column ⌊u·W⌋ and row ⌊(1 − v)·H⌋;
//! - `bilinear` blends the four nearest pixel centres (centre of column i at u = (i+½)/W),
//!   wrapping across the image's edges, as POV-Ray's `interpolate 2` does.
//!
//! An image with an alpha channel keeps it beside its colours (`Pixels::alpha_at`, read
//! at the same (u, v) with the same filter): a glTF material's coverage (SPEC §18).
//! The colours never depend on it.

use super::map;
use super::map_kind::MapKind;
use super::Color;
use crate::shapes::Shape;
use glam::DVec3;
use std::sync::Arc;

/// How a colour is read between pixels.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Interp {
    /// The pixel the point falls in.
    Nearest,
    /// The four nearest pixel centres, blended.
    Bilinear,
}

impl Interp {
    /// The keywords a TEXTURE record names them by.
    pub const NAMES: [&'static str; 2] = ["nearest", "bilinear"];

    /// The interpolation a keyword names.
    pub fn from_name(word: &str) -> Option<Interp> {
        match word {
            "nearest" => Some(Interp::Nearest),
            "bilinear" => Some(Interp::Bilinear),
            _ => None,
        }
    }

    /// Its keyword.
    pub fn name(self) -> &'static str {
        Self::NAMES[self as usize]
    }
}

/// How (u, v) outside 0..1 read the image (glTF's sampler; §16's images repeat).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Wrap {
    /// u − ⌊u⌋.
    #[default]
    Repeat,
    /// Clamped to the edge pixels.
    Clamp,
    /// Repeated, every other copy mirrored.
    Mirror,
}

impl Wrap {
    /// `x` brought into 0..1 by this mode.
    fn apply(self, x: f64) -> f64 {
        match self {
            Wrap::Repeat => x - x.floor(),
            Wrap::Clamp => x.clamp(0.0, 1.0),
            Wrap::Mirror => {
                let m = x.rem_euclid(2.0);
                if m > 1.0 {
                    2.0 - m
                } else {
                    m
                }
            }
        }
    }
}

/// An image's display colours, rows top to bottom, channels 0..1.
#[derive(Clone, PartialEq)]
pub struct Pixels {
    width: u32,
    height: u32,
    data: Vec<[f32; 3]>,
    /// The alpha channel, one value a pixel, when the image has one (else opaque).
    alpha: Option<Vec<f32>>,
    /// How u and v wrap (repeat, unless a glTF sampler says otherwise).
    wrap: [Wrap; 2],
    /// The SHA-256 of the file they were read from (zeros when made in memory).
    source: [u8; 32],
}

impl std::fmt::Debug for Pixels {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Pixels({}×{})", self.width, self.height)
    }
}

impl Pixels {
    /// `data` as a `width`×`height` image; `None` when the sizes disagree or one is 0.
    pub fn new(width: u32, height: u32, data: Vec<[f32; 3]>) -> Option<Pixels> {
        let ok = width > 0 && height > 0 && data.len() == width as usize * height as usize;
        ok.then_some(Pixels {
            width,
            height,
            data,
            alpha: None,
            wrap: [Wrap::Repeat; 2],
            source: [0; 32],
        })
    }

    /// The same image with the alpha channel `alpha` (one value a pixel; `None` when its
    /// length is not the pixel count).
    pub fn with_alpha(self, alpha: Vec<f32>) -> Option<Pixels> {
        (alpha.len() == self.data.len()).then_some(Pixels {
            alpha: Some(alpha),
            ..self
        })
    }

    /// Whether the image has an alpha channel.
    pub fn has_alpha(&self) -> bool {
        self.alpha.is_some()
    }

    /// The same image, each pixel mapped by `f` (a glTF scene's linear colours).
    pub fn mapped(&self, f: impl Fn([f32; 3]) -> [f32; 3]) -> Pixels {
        Pixels {
            data: self.data.iter().map(|&p| f(p)).collect(),
            ..self.clone()
        }
    }

    /// The same image, u and v wrapping as `wrap` says.
    pub fn wrapping(self, wrap: [Wrap; 2]) -> Pixels {
        Pixels { wrap, ..self }
    }

    /// The same pixels, read from a file whose bytes have the SHA-256 `source`.
    pub fn with_source(self, source: [u8; 32]) -> Pixels {
        Pixels { source, ..self }
    }

    /// The SHA-256 of the file the pixels were read from (zeros when made in memory).
    pub fn source(&self) -> [u8; 32] {
        self.source
    }

    /// The width and height.
    pub fn size(&self) -> (u32, u32) {
        (self.width, self.height)
    }

    /// How many pixels it holds.
    pub fn count(&self) -> u64 {
        u64::from(self.width) * u64::from(self.height)
    }

    /// The index of the pixel at column `i`, row `j` (both wrapped into the image).
    fn index(&self, i: i64, j: i64) -> usize {
        let (w, h) = (i64::from(self.width), i64::from(self.height));
        let (i, j) = match self.wrap {
            [Wrap::Repeat, Wrap::Repeat] => (i.rem_euclid(w), j.rem_euclid(h)),
            [a, b] => (edge(a, i, w), edge(b, j, h)),
        };
        j as usize * self.width as usize + i as usize
    }

    /// The pixel at column `i`, row `j` (both wrapped into the image).
    fn at(&self, i: i64, j: i64) -> Color {
        let [r, g, b] = self.data[self.index(i, j)];
        DVec3::new(f64::from(r), f64::from(g), f64::from(b))
    }

    /// The alpha at (u, v), read as `sample` reads the colour there (1 for an image
    /// without an alpha channel).
    pub fn alpha_at(&self, u: f64, v: f64, interp: Interp) -> f64 {
        match &self.alpha {
            None => 1.0,
            Some(alpha) => self.filter(u, v, interp, |i, j| f64::from(alpha[self.index(i, j)])),
        }
    }

    /// The colour at (u, v) (any values: they wrap).
    pub fn sample(&self, u: f64, v: f64, interp: Interp) -> Color {
        self.filter(u, v, interp, |i, j| self.at(i, j))
    }

    /// The value `at(i, j)` gives, read at (u, v) by `interp`: the pixel the point falls
    /// in, or its four nearest pixel centres blended (u and v wrapped by `wrap`).
    #[inline(always)]
    fn filter<T>(&self, u: f64, v: f64, interp: Interp, at: impl Fn(i64, i64) -> T) -> T
    where
        T: std::ops::Mul<f64, Output = T> + std::ops::Add<Output = T>,
    {
        if !(u.is_finite() && v.is_finite()) {
            return at(0, 0);
        }
        let (u, v) = match self.wrap {
            [Wrap::Repeat, Wrap::Repeat] => (u - u.floor(), v - v.floor()),
            [a, b] => (a.apply(u).min(0.999_999_999), b.apply(v).min(0.999_999_999)),
        };
        let (w, h) = (f64::from(self.width), f64::from(self.height));
        match interp {
            Interp::Nearest => at((u * w) as i64, ((1.0 - v) * h) as i64),
            Interp::Bilinear => {
                let x = u * w - 0.5;
                let y = (1.0 - v) * h - 0.5;
                let (i, j) = (x.floor(), y.floor());
                let (tx, ty) = (x - i, y - j);
                let (i, j) = (i as i64, j as i64);
                let top = at(i, j) * (1.0 - tx) + at(i + 1, j) * tx;
                let bottom = at(i, j + 1) * (1.0 - tx) + at(i + 1, j + 1) * tx;
                top * (1.0 - ty) + bottom * ty
            }
        }
    }
}

/// Column or row `i` of `n` for a neighbour of bilinear filtering: wrapped around
/// (repeat), else held at the edge.
fn edge(wrap: Wrap, i: i64, n: i64) -> i64 {
    match wrap {
        Wrap::Repeat => i.rem_euclid(n),
        Wrap::Clamp | Wrap::Mirror => i.clamp(0, n - 1),
    }
}

/// One image texture: its file, map, interpolation, Size and the shared pixels.
#[derive(Clone, Debug)]
pub struct ImageTexture {
    /// The file name as the record quotes it.
    pub file: String,
    /// How the image wraps the object.
    pub map: MapKind,
    /// How colours are read between pixels.
    pub interp: Interp,
    /// The map frame's length of one image (> 0; unused by `spherical`).
    pub size: f64,
    /// The pixels, shared by every record naming the file.
    pub pixels: Arc<Pixels>,
}

impl PartialEq for ImageTexture {
    fn eq(&self, o: &Self) -> bool {
        (self.file.as_str(), self.map, self.interp, self.size)
            == (o.file.as_str(), o.map, o.interp, o.size)
            && (Arc::ptr_eq(&self.pixels, &o.pixels) || self.pixels == o.pixels)
    }
}

impl ImageTexture {
    /// The colour at the world point `p` of `shape`.
    pub fn color_at(&self, shape: &Shape, p: DVec3) -> Color {
        let (u, v) = map::uv(self.map, self.size, shape, p);
        self.pixels.sample(u, v, self.interp)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// 2×2: red, green / blue, white (rows top to bottom), in exact binary fractions.
    fn quad() -> Pixels {
        let data = vec![
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
            [1.0, 1.0, 1.0],
        ];
        Pixels::new(2, 2, data).unwrap()
    }

    fn c(r: f64, g: f64, b: f64) -> Color {
        DVec3::new(r, g, b)
    }

    #[test]
    fn nearest_rows_from_the_top_and_wrapping() {
        let p = quad();
        // v near 1 is the top row, v near 0 the bottom one.
        assert_eq!(p.sample(0.25, 0.75, Interp::Nearest), c(1.0, 0.0, 0.0));
        assert_eq!(p.sample(0.75, 0.75, Interp::Nearest), c(0.0, 1.0, 0.0));
        assert_eq!(p.sample(0.25, 0.25, Interp::Nearest), c(0.0, 0.0, 1.0));
        assert_eq!(p.sample(0.75, 0.25, Interp::Nearest), c(1.0, 1.0, 1.0));
        // Wrapped: u = 1.25 is 0.25, v = −0.25 is 0.75; v = 0 is row ⌊2⌋ = 2 ≡ row 0.
        assert_eq!(p.sample(1.25, -0.25, Interp::Nearest), c(1.0, 0.0, 0.0));
        assert_eq!(p.sample(0.25, 0.0, Interp::Nearest), c(1.0, 0.0, 0.0));
        assert_eq!(p.sample(f64::NAN, 0.0, Interp::Nearest), c(1.0, 0.0, 0.0));
    }

    #[test]
    fn bilinear_at_centres_midpoints_and_across_the_edge() {
        let p = quad();
        // At a pixel centre the pixel itself: (u, v) = (¼, ¾) is red's centre.
        assert_eq!(p.sample(0.25, 0.75, Interp::Bilinear), c(1.0, 0.0, 0.0));
        // Half-way between red and green (u = ½, top row's centre): (½, ½, 0).
        assert_eq!(p.sample(0.5, 0.75, Interp::Bilinear), c(0.5, 0.5, 0.0));
        // The image's centre: the mean of all four, (½, ½, ½).
        assert_eq!(p.sample(0.5, 0.5, Interp::Bilinear), c(0.5, 0.5, 0.5));
        // u = 0 on the top row's centre: between green (column −1 ≡ 1) and red.
        assert_eq!(p.sample(0.0, 0.75, Interp::Bilinear), c(0.5, 0.5, 0.0));
        // A quarter of the way from red's centre towards green's: u = 0.375 gives
        // x = 0.375·2 − 0.5 = 0.25, so 0.75 red + 0.25 green.
        assert_eq!(p.sample(0.375, 0.75, Interp::Bilinear), c(0.75, 0.25, 0.0));
        // And a quarter down towards blue (v = 0.625 → y = 0.25): top·0.75 + bottom·0.25,
        // bottom = 0.75 blue + 0.25 white = (0.25, 0.25, 1).
        let got = p.sample(0.375, 0.625, Interp::Bilinear);
        let want = c(0.75, 0.25, 0.0) * 0.75 + c(0.25, 0.25, 1.0) * 0.25;
        assert!((got - want).length() < 1e-15, "{got}");
    }

    #[test]
    fn alpha_reads_like_the_colour() {
        // The quad's alphas: 1, 0.5 / 0, 0.25 (rows top to bottom).
        let p = quad().with_alpha(vec![1.0, 0.5, 0.0, 0.25]).unwrap();
        assert_eq!(p.alpha_at(0.25, 0.75, Interp::Nearest), 1.0);
        assert_eq!(p.alpha_at(0.75, 0.25, Interp::Nearest), 0.25);
        // The centre, bilinear: the mean (1 + 0.5 + 0 + 0.25)/4 = 0.4375.
        assert_eq!(p.alpha_at(0.5, 0.5, Interp::Bilinear), 0.4375);
        // Half-way between the top two: 0.75; clamped at the edge, u = 0 is column 0.
        assert_eq!(p.alpha_at(0.5, 0.75, Interp::Bilinear), 0.75);
        let clamped = p.clone().wrapping([Wrap::Clamp, Wrap::Clamp]);
        assert_eq!(clamped.alpha_at(0.0, 0.75, Interp::Bilinear), 1.0);
        // An image without the channel is opaque.
        assert_eq!(quad().alpha_at(0.5, 0.5, Interp::Bilinear), 1.0);
        assert!(quad().with_alpha(vec![1.0]).is_none());
    }

    #[test]
    fn sizes_must_agree() {
        assert!(Pixels::new(2, 2, vec![[0.0; 3]; 3]).is_none());
        assert!(Pixels::new(0, 0, vec![]).is_none());
        assert_eq!(quad().size(), (2, 2));
    }
}
