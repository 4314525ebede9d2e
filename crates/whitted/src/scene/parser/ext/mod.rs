//! The reader of the extension records (SPEC §16): after the report's last light, records
//! that each start with a lowercase keyword, their fields in a fixed order, then
//! modifiers; CSG blocks nest until `end`. The syntax, one record per line by habit (the
//! reader only counts tokens):
//!
//! ```text
//! sphere   Cx Cy Cz Radius                      TEXTURE MATERIAL
//! plane    Px Py Pz Nx Ny Nz                    TEXTURE MATERIAL
//! box      Minx Miny Minz Maxx Maxy Maxz        TEXTURE MATERIAL
//! cylinder Ax Ay Az Bx By Bz Radius             TEXTURE MATERIAL   [open]
//! cone     Ax Ay Az Ra Bx By Bz Rb              TEXTURE MATERIAL   [open]
//! disc     Cx Cy Cz Nx Ny Nz Radius Hole        TEXTURE MATERIAL
//! torus    Cx Cy Cz Ax Ay Az R r                TEXTURE MATERIAL
//! triangle P1(3) P2(3) P3(3)                    TEXTURE MATERIAL
//! mesh     "file.obj|file.ply"                  TEXTURE MATERIAL
//!     then any of: name N | scale x y z | rotate x y z | translate x y z
//!     | fit Size | pivot center | pivot x y z   (not on a plane: it has no bounds)
//!     (a mesh also: smooth Angle | flat)
//! union|intersection|difference  SOLID SOLID… end  [name N] [scale …] [rotate …] [translate …]
//! directional Dx Dy Dz R G B Intensity                              [name N]
//! spot  Px Py Pz Tx Ty Tz R G B Intensity Radius Falloff Tightness  [name N] [fade D P]
//! point Px Py Pz R G B Intensity                                    [name N] [fade D P]
//! area  Px Py Pz A1(3) A2(3) N1 N2 R G B Intensity                  [name N] [fade D P]
//! focus Aperture Distance Samples
//! background R G B
//! ```
//!
//! Each record is checked against §16's bounds (`scene::ext::check`) as soon as it is
//! read, and an error points at the field to blame. Records are numbered per kind after
//! the report's of the same kind (`sphere 5`, `light 3`, `csg 1`) in error contexts.

mod csg;
pub(super) mod keywords;
mod records;
#[cfg(test)]
mod tests;

use super::super::ext::check::Violation;
use super::super::ext::{ExtItem, Extension};
use super::super::lexer::Token;
use super::{Parser, Result};
use crate::fileloc::FileLoc;
use crate::input::quote;
use crate::limits::MAX_SCENE_OBJECTS;
use std::path::PathBuf;

/// The extension reader's state over the report's parser.
pub(super) struct Ext<'p, 'a> {
    p: &'p mut Parser<'a>,
    /// The token of each field read in the current record, for errors found by `check`.
    marks: Vec<(&'static str, Token<'a>)>,
    /// Names given so far and the line of each.
    names: Vec<(String, usize)>,
    /// Records read so far per kind, the report's included (`sphere 5`).
    counters: Vec<(&'static str, u64)>,
    /// The scene file's folder, against which mesh paths are resolved.
    base: PathBuf,
    /// Objects so far, the report's included (a CSG block's solids count one each).
    objects: u64,
    out: Extension,
}

/// Reads every extension record up to the end of the file. `report` is the report's
/// four counts (spheres, planes, cylinders, lights), after which records are numbered.
pub(super) fn read(p: &mut Parser<'_>, report: [u64; 4]) -> Result<Extension> {
    let base = std::path::Path::new(p.file)
        .parent()
        .map(PathBuf::from)
        .unwrap_or_default();
    let counters = vec![
        ("sphere", report[0]),
        ("plane", report[1]),
        ("cylinder", report[2]),
        ("light", report[3]),
    ];
    let mut ext = Ext {
        p,
        marks: Vec::new(),
        names: Vec::new(),
        counters,
        base,
        objects: report[0] + report[1] + report[2],
        out: Extension::default(),
    };
    while let Some(tok) = ext.p.next() {
        ext.record(tok)?;
    }
    Ok(ext.out)
}

impl<'a> Ext<'_, 'a> {
    /// One top-level record starting at `tok`.
    fn record(&mut self, tok: Token<'a>) -> Result<()> {
        let word = tok.text;
        if let Some(keyword) = keywords::find(keywords::SHAPES, word) {
            self.count_object(&tok)?;
            let object = self.shape(tok, keyword, None)?;
            self.out.objects.push(ExtItem::Shape(object));
        } else if let Some(op) = csg::op(word) {
            let csg = self.csg(tok, op)?;
            self.out.objects.push(ExtItem::Csg(csg));
        } else if let Some(keyword) = keywords::find(keywords::LIGHTS, word) {
            let light = self.light(tok, keyword)?;
            self.out.lights.push(light);
        } else if word == "focus" {
            self.focus(tok)?;
        } else if word == "background" {
            self.background(tok)?;
        } else {
            return Err(self.unknown(&tok));
        }
        Ok(())
    }

    /// One more object at `tok`, refused past the scene's budget.
    fn count_object(&mut self, tok: &Token) -> Result<()> {
        self.objects += 1;
        if self.objects > MAX_SCENE_OBJECTS {
            let msg = format!(
                "one object too many: a scene may have {MAX_SCENE_OBJECTS} objects in all (the report's, the extension's and each solid of a CSG block)"
            );
            return Err(self.p.error(tok, msg, ""));
        }
        Ok(())
    }

    /// The next record number of `kind` (`sphere` after the report's spheres).
    fn number(&mut self, kind: &'static str) -> u64 {
        match self.counters.iter_mut().find(|(k, _)| *k == kind) {
            Some((_, n)) => {
                *n += 1;
                *n
            }
            None => {
                self.counters.push((kind, 1));
                1
            }
        }
    }

    /// Enters a record for error contexts: `box 2`, or `box in csg 1` inside a block.
    fn enter(&mut self, record: &'static str, index: Option<u64>, within: Option<u64>) {
        self.p.place = super::place::Place {
            record,
            index: index.map(|i| (i, 0)),
            part: None,
            within,
        };
        self.marks.clear();
    }

    fn loc(&self, tok: &Token) -> FileLoc {
        FileLoc {
            file: self.p.file.to_string(),
            line: tok.line,
            column: tok.column,
        }
    }

    /// A number, remembered as `mark` for `check`'s errors.
    fn num(&mut self, field: &'static str) -> Result<f64> {
        let (v, tok) = self.p.number(field)?;
        self.marks.push((field, tok));
        Ok(v)
    }

    /// Three numbers `{mark}x {mark}y {mark}z`, remembered as `mark`.
    fn vec3(&mut self, mark: &'static str, fields: [&str; 3]) -> Result<glam::DVec3> {
        let (v, tok) = self.p.vector(fields)?;
        self.marks.push((mark, tok));
        Ok(v)
    }

    /// A bound broken: the error at the field to blame (or at the record's keyword).
    fn violation(&self, v: Violation, keyword: &Token) -> super::super::SceneError {
        let tok = self.marks.iter().rev().find(|(f, _)| *f == v.field);
        let tok = tok.map_or(*keyword, |(_, t)| *t);
        self.p.error(&tok, v.message, v.field)
    }

    /// An unknown keyword, with the nearest one suggested.
    fn unknown(&mut self, tok: &Token) -> super::super::SceneError {
        self.enter("after the last light", None, None);
        let mut msg = format!("unknown keyword '{}'", quote(tok.text));
        if tok.text == "end" {
            msg = "'end' with no CSG block open (a block starts with union, intersection or difference; one 'end' too many?)".to_string();
        } else if keywords::find(keywords::MODIFIERS, tok.text).is_some() {
            msg = format!(
                "'{}' is a modifier, and here it follows no record that takes it (given twice, or after a record that does not take it?)",
                tok.text
            );
        } else if let Some(k) = keywords::nearest(tok.text, keywords::all()) {
            msg += &format!(" (did you mean '{k}'?)");
        } else if tok.text.parse::<f64>().is_ok() {
            msg = format!(
                "expected a record keyword, found the number '{}' (a surplus field of the record before?)",
                quote(tok.text)
            );
        } else {
            msg += " (extension records start with sphere, plane, box, cylinder, cone, disc, torus, triangle, mesh, union, intersection, difference, directional, spot, point, area, focus or background)";
        }
        self.p.error(tok, msg, "")
    }
}

/// Whether the token after the last light starts the extension (a word, not a number):
/// a number there means the counts are wrong, which the report's error explains.
pub(super) fn starts_extension(tok: &Token) -> bool {
    tok.text.starts_with(|c: char| c.is_ascii_alphabetic())
}
