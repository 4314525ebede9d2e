//! Recording passes: `Sample` hears one camera ray (`trace::Record`), `PixelSum` adds the
//! samples of a pixel (over its n×n grid and every motion-blur sub-frame), `Sums` holds a
//! frame's (only the beauty colours and hit counts, `BeautySum`, heard by `Hit`, when no
//! pass is asked), and `finish` turns them into its `Layers`.
//!
//! Alpha is coverage: the fraction of a pixel's camera samples whose ray hit an object
//! (a miss counts for nothing, fog or not).
//!
//! The light split: the tracer's colour at a hit is ambient + Σ lights (diffuse +
//! specular, each times the light's shadow transmission) + reflection + transmission, and
//! fog makes the beauty `colour·(1 − f) + white·f`. Each of the five terms is stored times
//! (1 − f) and the `fog` layer is `f·white`, so the six layers sum to the beauty (to
//! rounding, 1e-5 relative being the contract). A ray that hits nothing has only fog, and
//! the scene's background times (1 − f): a scene whose background is not black (a
//! `background` record, an NFF's `b`) gains a `background` layer beside the light split
//! (`BACKGROUND`), so that the seven still sum to the beauty; a black one writes none,
//! and its files keep their bytes. A glTF scene whose materials emit gains an `emission`
//! layer the same way (`EMISSION`). Behind a surface that covers part of the ray (glTF
//! BLEND, α), the surface's terms, fog and emission weigh α and what lies behind goes,
//! as a whole, to the transmission layer. In a scene in linear light each part is stored
//! times the sample's display value over its linear colour, so that the parts sum to
//! the display value as they do in the report's scenes (and, decoded, to the linear
//! beauty: see `output::colour`).

use super::crypto::{self, Ranked};
use super::{CameraMatrices, Channel, CryptoHeader, Layers, Pass, PassSet};
use crate::base::Color;
use crate::scene::Scene;
use crate::trace::Record;
use glam::DVec3;

/// What one camera ray told: zeroed for every sample.
#[derive(Clone, Copy, Debug, Default)]
pub struct Sample {
    /// The object hit (file order) and the distance to it.
    pub hit: Option<(usize, f64)>,
    /// The hit point.
    pub p: DVec3,
    /// The shading normal.
    pub n: DVec3,
    /// The texture colour.
    pub albedo: Color,
    /// ambient, diffuse, specular, reflection, transmission, before fog.
    pub terms: [Color; 5],
    /// The fog fraction.
    pub fog: f64,
    /// The background seen by a ray that hit nothing, before fog.
    pub background: Color,
    /// The light the surface emits (a glTF material's), before fog.
    pub emission: Color,
    /// The share α of the first surface when it covers only part of the ray (a glTF
    /// BLEND material): its terms, fog and emission weigh α.
    pub cover: Option<f64>,
    /// What lies behind such a surface: (1 − α) × its colour, fogged (it goes to the
    /// transmission layer).
    pub behind: Color,
    /// In a scene in linear light, per channel: the stored display value over the
    /// linear colour the terms sum to (each term is stored times it).
    pub scale: Option<Color>,
}

impl Record for Sample {
    const ACTIVE: bool = true;
    fn object(&mut self, index: usize, t: f64) {
        self.hit = Some((index, t));
    }
    fn surface(&mut self, p: DVec3, n: DVec3, albedo: Color) {
        (self.p, self.n, self.albedo) = (p, n, albedo);
    }
    fn ambient(&mut self, c: Color) {
        self.terms[0] += c;
    }
    fn light(&mut self, diffuse: Color, specular: Color) {
        self.terms[1] += diffuse;
        self.terms[2] += specular;
    }
    fn reflection(&mut self, c: Color) {
        self.terms[3] += c;
    }
    fn transmission(&mut self, c: Color) {
        self.terms[4] += c;
    }
    fn fog(&mut self, f: f64) {
        self.fog = f;
    }
    fn background(&mut self, c: Color) {
        self.background = c;
    }
    fn emission(&mut self, c: Color) {
        self.emission += c;
    }
    fn cover(&mut self, alpha: f64) {
        self.cover = Some(alpha);
    }
    fn behind(&mut self, c: Color) {
        self.behind += c;
    }
    fn encoded(&mut self, linear: Color, shown: Color) {
        let ratio = |l: f64, s: f64| if l > 0.0 { s / l } else { 1.0 };
        self.scale = Some(Color::new(
            ratio(linear.x, shown.x),
            ratio(linear.y, shown.y),
            ratio(linear.z, shown.z),
        ));
    }
}

/// The recorder of the beauty-only path: whether the camera ray hit an object.
#[derive(Clone, Copy, Debug, Default)]
pub struct Hit(pub bool);

impl Record for Hit {
    const ACTIVE: bool = true;
    fn object(&mut self, _index: usize, _t: f64) {
        self.0 = true;
    }
}

/// The sums of one pixel's samples when no pass is asked: colour and hits.
#[derive(Clone, Copy, Debug, Default)]
pub struct BeautySum {
    /// Σ unclamped beauty.
    pub colour: Color,
    /// The samples that hit an object.
    pub hits: u32,
}

/// The sums of one pixel's samples.
#[derive(Clone, Debug, Default)]
pub struct PixelSum {
    /// Σ unclamped beauty.
    pub beauty: Color,
    /// Σ depth (+∞ once any sample missed).
    pub depth: f64,
    /// Σ position.
    pub p: DVec3,
    /// Σ normal.
    pub n: DVec3,
    /// Σ albedo.
    pub albedo: Color,
    /// Σ of the light split's six layers.
    pub light: [Color; 6],
    /// Σ background seen by the samples that hit nothing, times (1 − f).
    pub background: Color,
    /// Σ emission, times (1 − f).
    pub emission: Color,
    /// (object index, samples) for each object seen, when a Cryptomatte is asked for.
    pub objects: Vec<(usize, u32)>,
    /// The samples that hit an object.
    pub hits: u32,
}

impl PixelSum {
    /// Adds one sample: its beauty `c` and what it recorded; `forward` is the camera's
    /// view axis and `dir` the ray's direction (depth = t·dir·forward).
    #[inline]
    pub fn add(&mut self, c: Color, s: &Sample, dir: DVec3, forward: DVec3, crypto: bool) {
        self.beauty += c;
        // Both 1 but for a partly covering surface and a scene in linear light: then
        // every part is its share times α, and stored times the display's scale.
        let (cover, scale) = (s.cover.unwrap_or(1.0), s.scale.unwrap_or(Color::ONE));
        let keep = (1.0 - s.fog) * cover;
        for (sum, term) in self.light.iter_mut().zip(s.terms) {
            *sum += term * keep * scale;
        }
        self.light[5] += Color::splat(s.fog * cover) * scale;
        self.background += s.background * keep * scale;
        self.emission += s.emission * keep * scale;
        if s.cover.is_some() {
            self.light[4] += s.behind * scale;
        }
        match s.hit {
            Some((index, t)) => {
                self.hits += 1;
                self.depth += t * dir.dot(forward);
                self.p += s.p;
                self.n += s.n;
                self.albedo += s.albedo;
                if crypto {
                    match self.objects.iter_mut().find(|(i, _)| *i == index) {
                        Some((_, k)) => *k += 1,
                        None => self.objects.push((index, 1)),
                    }
                }
            }
            None => self.depth = f64::INFINITY,
        }
    }
}

/// The running sums of a frame of layers, one a pixel (rows top to bottom): the beauty
/// colours and hit counts alone when no pass is asked (32 bytes a pixel), else every
/// pass's `PixelSum`.
#[derive(Clone, Debug)]
pub enum Sums {
    /// Σ unclamped beauty and hits only.
    Beauty(Vec<BeautySum>),
    /// Everything the passes need.
    Passes(Vec<PixelSum>),
}

impl Sums {
    /// Zeroed sums for `pixels` pixels of a frame carrying `passes`.
    pub fn new(pixels: usize, passes: PassSet) -> Sums {
        if passes.is_empty() {
            Sums::Beauty(vec![BeautySum::default(); pixels])
        } else {
            Sums::Passes(vec![PixelSum::default(); pixels])
        }
    }
}

/// The layers of a frame from its pixels' sums over `samples` samples each (`passes`: the
/// set the sums were made for).
pub fn finish(
    sums: &Sums,
    samples: u32,
    width: u32,
    height: u32,
    passes: PassSet,
    scene: &Scene,
    camera: Option<CameraMatrices>,
) -> Layers {
    let k = f64::from(samples.max(1));
    let sums = match sums {
        Sums::Beauty(beauty) => {
            return Layers {
                width,
                height,
                beauty: beauty.iter().map(|s| s.colour / k).collect(),
                channels: Vec::new(),
                crypto: Vec::new(),
                camera,
                alpha: Some(beauty.iter().map(|s| coverage(s.hits, k)).collect()),
            };
        }
        Sums::Passes(sums) => sums,
    };
    let beauty = sums.iter().map(|s| s.beauty / k).collect();
    let mut channels = Vec::new();
    let push3 = |channels: &mut Vec<Channel>, pass: Pass, get: &dyn Fn(&PixelSum) -> DVec3| {
        let vals: Vec<DVec3> = sums.iter().map(|s| get(s) / k).collect();
        for (axis, name) in pass.channels().into_iter().enumerate() {
            let values = vals.iter().map(|v| v[axis] as f32).collect();
            channels.push(Channel { name, values });
        }
    };
    let light_index = |p: Pass| Pass::LIGHT.iter().position(|&q| q == p).unwrap_or(0);
    let mut crypto_headers = Vec::new();
    let mut crypto_channels = Vec::new();
    for pass in passes.iter() {
        match pass {
            Pass::Depth => channels.push(Channel {
                name: "Z".into(),
                values: sums.iter().map(|s| (s.depth / k) as f32).collect(),
            }),
            Pass::Position => push3(&mut channels, pass, &|s| s.p),
            Pass::Normal => push3(&mut channels, pass, &|s| s.n),
            Pass::Albedo => push3(&mut channels, pass, &|s| s.albedo),
            Pass::CryptoObject | Pass::CryptoMaterial => {
                let names = if pass == Pass::CryptoObject {
                    crypto::object_names(scene)
                } else {
                    crypto::material_names(scene)
                };
                let ids: Vec<u32> = names.iter().map(|n| crypto::id(n)).collect();
                let ranked = sums.iter().map(|s| {
                    let cover = s.objects.iter().map(|&(i, n)| (ids[i], n));
                    Ranked::of(cover, samples.max(1))
                });
                crypto_channels.extend(crypto::channels(pass.name(), ranked));
                crypto_headers.push(CryptoHeader {
                    name: pass.name().into(),
                    manifest: crypto::manifest(&names),
                });
            }
            light => {
                let i = light_index(light);
                push3(&mut channels, light, &|s| s.light[i]);
            }
        }
    }
    let light = Pass::LIGHT.iter().any(|&p| passes.has(p));
    let mut extra = |names: [&str; 3], get: &dyn Fn(&PixelSum) -> Color| {
        let vals: Vec<Color> = sums.iter().map(|s| get(s) / k).collect();
        for (axis, name) in names.iter().enumerate() {
            let values = vals.iter().map(|v| v[axis] as f32).collect();
            channels.push(Channel {
                name: name.to_string(),
                values,
            });
        }
    };
    if light && scene.background != Color::ZERO {
        extra(BACKGROUND, &|s| s.background);
    }
    if light && emits(scene) {
        extra(EMISSION, &|s| s.emission);
    }
    channels.extend(crypto_channels);
    Layers {
        width,
        height,
        beauty,
        channels,
        crypto: crypto_headers,
        camera,
        alpha: Some(sums.iter().map(|s| coverage(s.hits, k)).collect()),
    }
}

/// The channels of the `background` layer a frame of the light split gains when its
/// scene's background is not black.
pub const BACKGROUND: [&str; 3] = ["background.R", "background.G", "background.B"];

/// The channels of the `emission` layer a frame of the light split gains when its
/// scene has an emissive material (`emits`).
pub const EMISSION: [&str; 3] = ["emission.R", "emission.G", "emission.B"];

/// Whether a material of `scene` emits light (a glTF `emissiveFactor`).
pub fn emits(scene: &Scene) -> bool {
    let textured = |m: &crate::mesh::Mesh| m.extra.as_ref().is_some_and(|x| x.emissive.is_some());
    scene.pbr.iter().any(|p| p.emission != Color::ZERO) || scene.meshes.iter().any(|m| textured(m))
}

/// `hits` of `k` samples as a fraction.
fn coverage(hits: u32, k: f64) -> f32 {
    (f64::from(hits) / k) as f32
}

#[cfg(test)]
#[path = "record_tests.rs"]
mod tests;
