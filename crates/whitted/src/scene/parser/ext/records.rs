//! The fields of each extension record (the table in `ext`'s module doc) and the
//! modifiers after it, each checked against §16's bounds as soon as it is read.

use super::super::super::ext::{check, ExtLight, ExtObject, Focus, LightKind, Modifiers};
use super::super::Result;
use super::{keywords, Ext};
use crate::input::quote;
use crate::limits::{MAX_AREA_SIDE, MAX_LENS_SAMPLES};
use crate::mesh::{Pivot, Shading};
use crate::scene::lexer::Token;
use crate::scene::ShapeSpec;

impl<'a> Ext<'_, 'a> {
    /// A shape record whose `keyword` is at `tok` (top level, or inside CSG block
    /// `within`).
    pub(super) fn shape(
        &mut self,
        tok: Token<'a>,
        keyword: &'static str,
        within: Option<u64>,
    ) -> Result<ExtObject> {
        let index = within.is_none().then(|| self.number(keyword));
        self.enter(keyword, index, within);
        let shape = match keyword {
            "sphere" => {
                let center = self.vec3("C", ["Cx", "Cy", "Cz"])?;
                let radius = self.num("Radius")?;
                ShapeSpec::Sphere { center, radius }
            }
            "plane" => ShapeSpec::Plane {
                point: self.vec3("P", ["Px", "Py", "Pz"])?,
                normal: self.vec3("N", ["Nx", "Ny", "Nz"])?,
            },
            "box" => ShapeSpec::Box {
                min: self.vec3("Min", ["Minx", "Miny", "Minz"])?,
                max: self.vec3("Max", ["Maxx", "Maxy", "Maxz"])?,
            },
            "cylinder" => ShapeSpec::Cylinder {
                a: self.vec3("A", ["Ax", "Ay", "Az"])?,
                b: self.vec3("B", ["Bx", "By", "Bz"])?,
                radius: self.num("Radius")?,
            },
            "cone" => ShapeSpec::Cone {
                a: self.vec3("A", ["Ax", "Ay", "Az"])?,
                ra: self.num("Ra")?,
                b: self.vec3("B", ["Bx", "By", "Bz"])?,
                rb: self.num("Rb")?,
            },
            "disc" => ShapeSpec::Disc {
                center: self.vec3("C", ["Cx", "Cy", "Cz"])?,
                normal: self.vec3("N", ["Nx", "Ny", "Nz"])?,
                radius: self.num("Radius")?,
                hole: self.num("Hole")?,
            },
            "torus" => ShapeSpec::Torus {
                center: self.vec3("C", ["Cx", "Cy", "Cz"])?,
                axis: self.vec3("Axis", ["Axisx", "Axisy", "Axisz"])?,
                major: self.num("R")?,
                minor: self.num("r")?,
            },
            "triangle" => ShapeSpec::Triangle {
                corners: [
                    self.vec3("P1", ["P1x", "P1y", "P1z"])?,
                    self.vec3("P2", ["P2x", "P2y", "P2z"])?,
                    self.vec3("P3", ["P3x", "P3y", "P3z"])?,
                ],
            },
            _ => self.mesh()?,
        };
        if let Err(v) = check::shape(&shape) {
            return Err(self.violation(v, &tok));
        }
        let texture = self.p.texture()?;
        let material = self.p.material()?;
        let allowed: &[&str] = match keyword {
            "cylinder" | "cone" => &[
                "name",
                "open",
                "scale",
                "rotate",
                "translate",
                "fit",
                "pivot",
            ],
            "plane" => &["name", "scale", "rotate", "translate"],
            "mesh" => &[
                "name",
                "scale",
                "rotate",
                "translate",
                "smooth",
                "flat",
                "fit",
                "pivot",
            ],
            _ => &["name", "scale", "rotate", "translate", "fit", "pivot"],
        };
        let mods = self.modifiers(allowed, within.is_some())?;
        Ok(ExtObject {
            shape,
            texture,
            material,
            mods,
            loc: self.loc(&tok),
        })
    }

    /// `mesh "file"`: the path resolved against the scene's folder.
    fn mesh(&mut self) -> Result<ShapeSpec> {
        let tok = self.p.token("file", "a quoted file name")?;
        let written = keywords::unquote(tok.text).map_err(|why| {
            let msg = format!("{why}, found '{}'", quote(tok.text));
            self.p.error(&tok, msg, "file")
        })?;
        if written.is_empty() {
            return Err(self
                .p
                .error(&tok, "the mesh's file name is empty".into(), "file"));
        }
        Ok(ShapeSpec::Mesh {
            path: self.base.join(&written),
            written,
        })
    }

    /// A light record whose `keyword` is at `tok`.
    pub(super) fn light(&mut self, tok: Token<'a>, keyword: &'static str) -> Result<ExtLight> {
        let counted = if keyword == "point" { "light" } else { keyword };
        let index = self.number(counted);
        self.enter(counted, Some(index), None);
        let position = match keyword {
            "directional" => None,
            _ => Some(self.vec3("P", ["Px", "Py", "Pz"])?),
        };
        let mut kind = match keyword {
            "directional" => LightKind::Directional {
                direction: self.vec3("D", ["Dx", "Dy", "Dz"])?,
            },
            "spot" => LightKind::Spot {
                position: position.unwrap_or_default(),
                target: self.vec3("Target", ["Tx", "Ty", "Tz"])?,
                radius: 0.0,
                falloff: 0.0,
                tightness: 0.0,
            },
            "point" => LightKind::Point {
                position: position.unwrap_or_default(),
            },
            _ => {
                let a1 = self.vec3("A1", ["A1x", "A1y", "A1z"])?;
                let a2 = self.vec3("A2", ["A2x", "A2y", "A2z"])?;
                let what = format!("an integer from 1 to {MAX_AREA_SIDE}");
                let (n1, _) = self.p.integer("N1", 1, MAX_AREA_SIDE, &what)?;
                let (n2, _) = self.p.integer("N2", 1, MAX_AREA_SIDE, &what)?;
                LightKind::Area {
                    position: position.unwrap_or_default(),
                    a1,
                    a2,
                    n1: n1 as u32,
                    n2: n2 as u32,
                }
            }
        };
        let color = self.p.color(["R", "G", "B"])?;
        let intensity = self.num("Intensity")?;
        if let LightKind::Spot {
            radius,
            falloff,
            tightness,
            ..
        } = &mut kind
        {
            *radius = self.num("Radius")?;
            *falloff = self.num("Falloff")?;
            *tightness = self.num("Tightness")?;
        }
        let allowed: &[&str] = if keyword == "directional" {
            &["name"]
        } else {
            &["name", "fade"]
        };
        let mods = self.modifiers(allowed, false)?;
        let light = ExtLight {
            kind,
            color,
            intensity,
            mods,
            loc: self.loc(&tok),
        };
        match check::light(&light) {
            Ok(()) => Ok(light),
            Err(v) => Err(self.violation(v, &tok)),
        }
    }

    /// The `focus` record (at most one).
    pub(super) fn focus(&mut self, tok: Token<'a>) -> Result<()> {
        self.enter("focus", None, None);
        if self.out.focus.is_some() {
            let msg = "the file has a second focus record (at most one)".to_string();
            return Err(self.p.error(&tok, msg, ""));
        }
        let aperture = self.num("Aperture")?;
        let distance = self.num("Distance")?;
        let what = format!("an integer from 1 to {MAX_LENS_SAMPLES}");
        let (samples, _) = self.p.integer("Samples", 1, MAX_LENS_SAMPLES, &what)?;
        let focus = Focus {
            aperture,
            distance,
            samples: samples as u32,
        };
        check::focus(&focus).map_err(|v| self.violation(v, &tok))?;
        self.out.focus = Some(focus);
        Ok(())
    }

    /// The `background R G B` record (at most one), each in 0..1.
    pub(super) fn background(&mut self, tok: Token<'a>) -> Result<()> {
        self.enter("background", None, None);
        if self.out.background.is_some() {
            let msg = "the file has a second background record (at most one)".to_string();
            return Err(self.p.error(&tok, msg, ""));
        }
        self.out.background = Some(self.p.color(["R", "G", "B"])?);
        Ok(())
    }

    /// The modifiers after a record: any of `allowed`, each at most once, in any order.
    /// Inside a CSG block (`in_csg`) a child takes no name (the block is what is named).
    pub(super) fn modifiers(&mut self, allowed: &[&str], in_csg: bool) -> Result<Modifiers> {
        let mut mods = Modifiers::default();
        let mut seen: Vec<&str> = Vec::new();
        let record = self.p.place.record;
        while let Some(tok) = self.p.lexer.clone().next() {
            let Some(word) = keywords::find(keywords::MODIFIERS, tok.text) else {
                break;
            };
            self.p.next();
            if !allowed.contains(&word) {
                let msg = match word {
                    "fade" if record == "directional" => {
                        "fade does not apply to a directional light (it is infinitely far)"
                            .to_string()
                    }
                    "fit" | "pivot" if record == "plane" => {
                        format!("'{word}' does not apply to a plane: it is unbounded (fit and pivot need an object with bounds)")
                    }
                    _ => format!("'{word}' does not apply to a {record} record"),
                };
                return Err(self.p.error(&tok, msg, word));
            }
            if seen.contains(&word) {
                let msg = format!("'{word}' is given twice (each modifier at most once)");
                return Err(self.p.error(&tok, msg, word));
            }
            if let Some(other) = [("smooth", "flat"), ("flat", "smooth")]
                .iter()
                .find(|(w, o)| *w == word && seen.contains(o))
                .map(|(_, o)| *o)
            {
                let msg = format!("'{word}' and '{other}' exclude each other (give one)");
                return Err(self.p.error(&tok, msg, word));
            }
            seen.push(word);
            self.marks.push((word, tok));
            match word {
                "name" if in_csg => {
                    let msg =
                        "a solid inside a CSG block takes no name: name the block after its 'end'"
                            .to_string();
                    return Err(self.p.error(&tok, msg, "name"));
                }
                "name" => mods.name = Some(self.name()?),
                "open" => mods.open = true,
                "scale" => mods.scale = Some(self.vec3("scale", ["x", "y", "z"])?),
                "rotate" => mods.rotate = Some(self.vec3("rotate", ["x", "y", "z"])?),
                "translate" => mods.translate = Some(self.vec3("translate", ["x", "y", "z"])?),
                "smooth" => mods.shading = Some(Shading::Smooth(self.num("Angle")?)),
                "flat" => mods.shading = Some(Shading::Flat),
                "fit" => mods.placing.fit = Some(self.num("Size")?),
                "pivot" => {
                    let center = self
                        .p
                        .lexer
                        .clone()
                        .next()
                        .is_some_and(|t| t.text == "center");
                    mods.placing.pivot = Some(if center {
                        self.p.next();
                        Pivot::Center
                    } else {
                        Pivot::Point(self.vec3("pivot", ["x", "y", "z"])?)
                    });
                }
                _ => mods.fade = Some((self.num("Distance")?, self.num("Power")?)),
            }
        }
        check::modifiers(&mods).map_err(|v| {
            let keyword = self.marks.last().map(|(_, t)| *t);
            self.violation(v, &keyword.expect("a modifier was read"))
        })?;
        Ok(mods)
    }

    /// A name after `name`: an identifier, not a keyword, not used before in the file.
    fn name(&mut self) -> Result<String> {
        let tok = self.p.token("name", "a name")?;
        if !keywords::is_name(tok.text) {
            let why = if keywords::is_keyword(tok.text) {
                "is a keyword"
            } else {
                "is not a name (a letter or _, then letters, digits, _ or -)"
            };
            let msg = format!("'{}' {why}", quote(tok.text));
            return Err(self.p.error(&tok, msg, "name"));
        }
        if let Some((_, line)) = self.names.iter().find(|(n, _)| n == tok.text) {
            let msg = format!("the name '{}' is already given on line {line}", tok.text);
            return Err(self.p.error(&tok, msg, "name"));
        }
        self.names.push((tok.text.to_string(), tok.line));
        Ok(tok.text.to_string())
    }
}
