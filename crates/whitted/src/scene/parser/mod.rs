//! The Scene.txt grammar: records in a fixed order (SPEC §1), checked as they are read.
//! Every error points at the token that broke a rule and names its place in the
//! structure; nothing is rendered from a scene that failed. When a record fails on a line
//! that holds a record of another kind, the error is put on the count to blame
//! (`counts`); when a record was short of a value on its line, at the end of that line
//! (`missing`). After the last light come the extension records of SPEC §16 (`ext`).

mod counts;
mod ext;
mod missing;
mod place;
mod texture;

use super::error::{FileLoc, SceneError};
use super::lexer::{Lexer, Token};
use super::{ObjectSpec, Scene, ShapeSpec, MAX_INTENSITY, MAX_PIXELS, MAX_SIDE};
use crate::base::Color;
use crate::bump::Bump;
use crate::camera::Camera;
use crate::fog::Fog;
use crate::input::quote;
use crate::lights::PointLight;
use crate::object::{Material, Object};
use counts::{read_counts, Record};
use glam::DVec3;
use place::Place;

struct Parser<'a> {
    lexer: Lexer<'a>,
    file: &'a str,
    place: Place,
    images: texture::Images,
    layout: missing::Layout<'a>,
}

type Result<T> = std::result::Result<T, SceneError>;

impl<'a> Parser<'a> {
    fn error_at(&self, line: usize, column: usize, message: String, field: &str) -> SceneError {
        SceneError::Syntax {
            loc: FileLoc {
                file: self.file.to_string(),
                line,
                column,
            },
            message,
            context: self.place.describe(field),
        }
    }

    fn error(&self, tok: &Token, message: String, field: &str) -> SceneError {
        self.error_at(tok.line, tok.column, message, field)
    }

    /// The next token, or an error naming what was expected at the end of the file (just
    /// past its last value: the end of the line where a value is missing).
    fn token(&mut self, field: &str, what: &str) -> Result<Token<'a>> {
        match self.lexer.next() {
            Some(tok) => {
                let place = self.place;
                self.layout.took(tok, field, || place.describe(field));
                Ok(tok)
            }
            None => {
                let end = self.layout.prev().map(|t| missing::end_of(&t));
                let (line, column) = end.unwrap_or(self.lexer.position());
                let msg = format!("expected {what} for {field}, found the end of the file");
                Err(self.error_at(line, column, msg, field))
            }
        }
    }

    /// A finite floating-point number.
    fn number(&mut self, field: &str) -> Result<(f64, Token<'a>)> {
        let tok = self.token(field, "a number")?;
        match tok.text.parse::<f64>() {
            Ok(v) if v.is_finite() => Ok((v, tok)),
            Ok(_) => Err(self.error(
                &tok,
                format!(
                    "expected a finite number for {field}, found '{}'",
                    quote(tok.text)
                ),
                field,
            )),
            Err(_) => Err(self.error(
                &tok,
                format!("expected a number for {field}, found '{}'", quote(tok.text)),
                field,
            )),
        }
    }

    /// A number that must be > 0.
    fn positive(&mut self, field: &str) -> Result<f64> {
        let (v, tok) = self.number(field)?;
        if v > 0.0 {
            Ok(v)
        } else {
            let msg = format!(
                "{field} must be greater than 0, found '{}'",
                quote(tok.text)
            );
            Err(self.error(&tok, msg, field))
        }
    }

    /// An integer literal within `lo..=hi`; `what` describes the allowed values.
    fn integer(&mut self, field: &str, lo: u64, hi: u64, what: &str) -> Result<(u64, Token<'a>)> {
        let tok = self.token(field, what)?;
        let v = tok.text.strip_prefix('+').unwrap_or(tok.text);
        let bad = |p: &Self, m: String| Err(p.error(&tok, m, field));
        // A negative integer is an integer, only out of range: say so below, not here.
        let digits = tok.text.strip_prefix(['+', '-']).unwrap_or(tok.text);
        if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
            let kind = if tok.text.parse::<f64>().is_ok() {
                "an integer"
            } else {
                "a number"
            };
            return bad(
                self,
                format!(
                    "expected {what} for {field}, found '{}' (not {kind})",
                    quote(tok.text)
                ),
            );
        }
        match v.parse::<u64>() {
            Ok(n) if (lo..=hi).contains(&n) => Ok((n, tok)),
            _ => bad(
                self,
                format!("expected {what} for {field}, found '{}'", quote(tok.text)),
            ),
        }
    }

    fn vector(&mut self, fields: [&str; 3]) -> Result<(DVec3, Token<'a>)> {
        let (x, tok) = self.number(fields[0])?;
        let (y, _) = self.number(fields[1])?;
        let (z, _) = self.number(fields[2])?;
        Ok((DVec3::new(x, y, z), tok))
    }

    /// A vector that must not be zero (a normal or an axis).
    fn direction(&mut self, fields: [&str; 3], name: &str) -> Result<DVec3> {
        let (v, tok) = self.vector(fields)?;
        // A tiny or huge v that is not zero is scaled (see `spec::direction`).
        super::spec::direction(v).ok_or_else(|| {
            let msg = format!("the {name} ({} {} {}) has zero length", v.x, v.y, v.z);
            self.error(&tok, msg, fields[0])
        })
    }

    /// A number within `lo..=hi`.
    fn ranged(&mut self, field: &str, lo: f64, hi: f64) -> Result<f64> {
        let (v, tok) = self.number(field)?;
        if (lo..=hi).contains(&v) {
            Ok(v)
        } else {
            let msg = format!(
                "{field} must be from {lo} to {hi}, found '{}'",
                quote(tok.text)
            );
            Err(self.error(&tok, msg, field))
        }
    }

    /// A colour: three channels from 0 to 1 (SPEC §1).
    fn color(&mut self, fields: [&str; 3]) -> Result<Color> {
        let r = self.ranged(fields[0], 0.0, 1.0)?;
        let g = self.ranged(fields[1], 0.0, 1.0)?;
        let b = self.ranged(fields[2], 0.0, 1.0)?;
        Ok(Color::new(r, g, b))
    }

    fn material(&mut self) -> Result<Material> {
        self.place.part = Some("material");
        let kd = self.ranged("Kd", 0.0, 1.0)?;
        let kr = self.ranged("Kr", 0.0, 1.0)?;
        let kt = self.ranged("Kt", 0.0, 1.0)?;
        let ior = self.positive("Ior")?;
        let what = "0 (none), 1 (uniform) or 2 (plane/water)";
        let (bump_type, _) = self.integer("BumpType", 0, 2, what)?;
        let (eps, _) = self.number("BumpValue")?;
        self.place.part = None;
        let bump = match bump_type {
            0 => Bump::None,
            1 => Bump::Uniform(eps),
            _ => Bump::Water(eps),
        };
        Ok(Material {
            kd,
            kr,
            kt,
            ior,
            bump,
            highlight: Default::default(),
        })
    }

    fn object(&mut self, spec: ShapeSpec, specs: &mut Vec<ObjectSpec>) -> Result<Object> {
        let texture = self.texture()?;
        let material = self.material()?;
        let shape = spec.build().expect("a report record");
        specs.push(ObjectSpec::Record(spec));
        Ok(Object {
            shape,
            texture,
            material,
        })
    }

    fn sphere(&mut self, i: u64, n: u64, specs: &mut Vec<ObjectSpec>) -> Result<Object> {
        self.enter("sphere", Some((i, n)));
        let radius = self.positive("Radius")?;
        let (center, _) = self.vector(["Cx", "Cy", "Cz"])?;
        self.object(ShapeSpec::Sphere { center, radius }, specs)
    }

    fn plane(&mut self, i: u64, n: u64, specs: &mut Vec<ObjectSpec>) -> Result<Object> {
        self.enter("plane", Some((i, n)));
        let (point, _) = self.vector(["Px", "Py", "Pz"])?;
        let normal = self.direction(["Nx", "Ny", "Nz"], "normal")?;
        self.object(ShapeSpec::Plane { point, normal }, specs)
    }

    fn cylinder(&mut self, i: u64, n: u64, specs: &mut Vec<ObjectSpec>) -> Result<Object> {
        self.enter("cylinder", Some((i, n)));
        let axis = self.direction(["Ax", "Ay", "Az"], "axis")?;
        let (point, _) = self.vector(["Px", "Py", "Pz"])?;
        let radius = self.positive("Radius")?;
        let cylinder = ShapeSpec::InfiniteCylinder {
            axis,
            point,
            radius,
        };
        self.object(cylinder, specs)
    }

    fn light(&mut self, i: u64, n: u64) -> Result<PointLight> {
        self.enter("light", Some((i, n)));
        let (position, _) = self.vector(["Lx", "Ly", "Lz"])?;
        let color = self.color(["R", "G", "B"])?;
        let intensity = self.ranged("Intensity", 0.0, MAX_INTENSITY)?;
        Ok(PointLight {
            position,
            color,
            intensity,
        })
    }

    fn enter(&mut self, record: &'static str, index: Option<(u64, u64)>) {
        self.layout.start();
        self.place = Place {
            record,
            index,
            part: None,
            within: None,
        };
    }
}

pub(super) fn parse(src: &str, file: &str) -> Result<Scene> {
    let mut scene = read(src, file)?;
    crate::scene::ext::build::draw(&mut scene)?;
    scene.t_min = crate::scene::ext::epsilon::small_scene(&scene.objects);
    Ok(scene)
}

/// The records as read, the extension's left in `scene.ext` without its objects drawn
/// (what the reader's own tests look at).
pub(super) fn read(src: &str, file: &str) -> Result<Scene> {
    let mut p = Parser {
        lexer: Lexer::new(src),
        file,
        place: Place {
            record: "resolution",
            index: None,
            part: None,
            within: None,
        },
        images: texture::Images::new(file),
        layout: missing::Layout::new(),
    };
    records(&mut p, src, file).map_err(|e| p.layout.blame(e))
}

/// The records of `src`, read by `p`.
fn records<'a>(p: &mut Parser<'a>, src: &'a str, file: &str) -> Result<Scene> {
    let side = format!("an integer from 1 to {MAX_SIDE}");
    let (width, _) = p.integer("ResX", 1, MAX_SIDE as u64, &side)?;
    let (height, tok) = p.integer("ResY", 1, MAX_SIDE as u64, &side)?;
    if width * height > MAX_PIXELS {
        let msg = format!(
            "{width}×{height} is {} pixels, past the limit of {MAX_PIXELS} (2^26): it would need gigabytes",
            width * height
        );
        return Err(p.error(&tok, msg, "ResY"));
    }

    p.enter("camera position", None);
    let (eye, _) = p.vector(["x", "y", "z"])?;
    p.enter("point looked at", None);
    let (look_at, look_tok) = p.vector(["x", "y", "z"])?;
    if Camera::new(eye, look_at, 1, 1).is_none() {
        let msg = if (look_at - eye).is_finite() {
            "the camera is placed on the point it looks at".to_string()
        } else {
            "the camera is too far from the point it looks at (their distance overflows)"
                .to_string()
        };
        return Err(p.error(&look_tok, msg, "x"));
    }

    p.enter("fog", None);
    let (fog_type, _) = p.integer("FogType", 0, 3, "0 (none), 1, 2 or 3")?;
    let (fog_distance, tok) = p.number("FogDistance")?;
    if fog_type != 0 && fog_distance <= 0.0 {
        let msg = format!(
            "FogDistance must be greater than 0 with fog, found '{}'",
            quote(tok.text)
        );
        return Err(p.error(&tok, msg, "FogDistance"));
    }
    let fog = match fog_type {
        0 => Fog::None,
        1 => Fog::Linear(fog_distance),
        2 => Fog::Exponential(fog_distance),
        _ => Fog::ExponentialSquared(fog_distance),
    };

    let counts = read_counts(p)?;

    let mut objects = Vec::new();
    let mut specs = Vec::new();
    let mut lights = Vec::new();
    for (kind, n) in counts.n.into_iter().enumerate() {
        for index in 1..=n {
            let first = p.lexer.clone().next();
            let record = Record { kind, index, first };
            let read = match kind {
                0 => p.sphere(index, n, &mut specs).map(|o| objects.push(o)),
                1 => p.plane(index, n, &mut specs).map(|o| objects.push(o)),
                2 => p.cylinder(index, n, &mut specs).map(|o| objects.push(o)),
                _ => p.light(index, n).map(|l| lights.push(l)),
            };
            read.map_err(|e| counts.explain(src, file, record, e))?;
        }
    }

    let mut extension = Default::default();
    if p.lexer
        .clone()
        .next()
        .filter(ext::starts_extension)
        .is_some()
    {
        p.layout.stop();
        extension = ext::read(p, counts.n)?;
    } else if let Some(tok) = p.lexer.next() {
        p.enter("after the last record", None);
        let msg = format!(
            "expected the end of the file after the last light, found '{}' (do the counts match the records?)",
            quote(tok.text)
        );
        let record = Record {
            kind: 4,
            index: 1,
            first: Some(tok),
        };
        return Err(counts.explain(src, file, record, p.error(&tok, msg, "")));
    }
    let background = extension.background.unwrap_or(Color::ZERO);
    Ok(Scene {
        width: width as u32,
        height: height as u32,
        eye,
        look_at,
        fog,
        objects,
        specs,
        lights,
        background,
        t_min: crate::optics::T_MIN,
        lens: crate::camera::Lens::default(),
        ext: extension,
        meshes: Vec::new(),
        pbr: Vec::new(),
        parallel: None,
        linear: false,
        model: None,
    })
}
