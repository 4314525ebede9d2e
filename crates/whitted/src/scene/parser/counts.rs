//! When a record does not fit, whether the counts are to blame. Scene.txt writes each
//! object or light on a line of its own, and the four kinds have different numbers of
//! values (a sphere 14 or 21, a plane 16 or 23, a cylinder 17 or 24, a light 7, for a
//! one-colour or a procedural texture, one more than the first for an image, whose file
//! name is the line's quoted value). So when sphere 5 of 5 fails on a line of 16
//! values, that line is a plane: the counts announced a sphere too many (or one is
//! missing), and the error is put on the count, saying what it announced:
//!
//! ```text
//! 3 1 0 1        # scene.txt:5:1: the counts announce 3 spheres, but line 9, read as
//! ...            #   sphere 3 of 3, holds 16 values, as a plane does ...
//! ```

use super::super::error::{FileLoc, SceneError};
use super::super::lexer::{Lexer, Token};
use super::super::MAX_COUNT;
use super::Parser;
use crate::limits::MAX_SCENE_OBJECTS;

/// The kinds of records in file order: name, plural, count field, values per line.
const KINDS: [(&str, &str, &str, [usize; 2]); 4] = [
    ("sphere", "spheres", "NSpheres", [14, 21]),
    ("plane", "planes", "NPlanes", [16, 23]),
    ("cylinder", "cylinders", "NCylinders", [17, 24]),
    ("light", "lights", "NLights", [7, 7]),
];

/// The four counts and where each is written.
pub(super) struct Counts<'a> {
    pub n: [u64; 4],
    pub at: [Token<'a>; 4],
}

/// The four counts (NSpheres NPlanes NCylinders NLights), each from 0 to `MAX_COUNT`,
/// whose objects together stay within the scene's budget (`MAX_SCENE_OBJECTS`).
pub(super) fn read_counts<'a>(p: &mut Parser<'a>) -> Result<Counts<'a>, SceneError> {
    p.enter("counts", None);
    let count = format!("a count from 0 to {MAX_COUNT}");
    let (ns, s_at) = p.integer("NSpheres", 0, MAX_COUNT, &count)?;
    let (np, p_at) = p.integer("NPlanes", 0, MAX_COUNT, &count)?;
    let (nc, c_at) = p.integer("NCylinders", 0, MAX_COUNT, &count)?;
    let (nl, l_at) = p.integer("NLights", 0, MAX_COUNT, &count)?;
    if ns + np + nc > MAX_SCENE_OBJECTS {
        let msg = format!(
            "the counts announce {} objects: a scene may have {MAX_SCENE_OBJECTS} in all",
            ns + np + nc
        );
        return Err(p.error(&s_at, msg, "NSpheres"));
    }
    Ok(Counts {
        n: [ns, np, nc, nl],
        at: [s_at, p_at, c_at, l_at],
    })
}

/// Where a failing record was: its kind (index into the four), its 1-based index, and
/// its first token (`None` at the end of the file). `kind` 4 is "after the last light".
pub(super) struct Record<'a> {
    pub kind: usize,
    pub index: u64,
    pub first: Option<Token<'a>>,
}

impl Counts<'_> {
    /// `error`, raised while reading `record`, moved onto the count to blame when the
    /// record's line has as many values as a record of another kind; unchanged otherwise.
    pub(super) fn explain(
        &self,
        src: &str,
        file: &str,
        record: Record,
        error: SceneError,
    ) -> SceneError {
        let Some(first) = record.first else {
            return error;
        };
        // A record cut short by the end of the file (its error just past the file's last
        // value) says nothing of the counts.
        let end = Lexer::new(src).last().map(|t| super::missing::end_of(&t));
        if end.is_some() && error.loc().map(|l| (l.line, l.column)) == end {
            return error;
        }
        let on_line: Vec<Token> = Lexer::new(src).filter(|t| t.line == first.line).collect();
        // The record must begin its line for the line to be a record.
        if on_line.first() != Some(&first) {
            return error;
        }
        let values = on_line.len();
        let image = on_line.iter().any(|t| t.text.starts_with('"'));
        let fits = |k: usize| match image {
            false => KINDS[k].3.contains(&values),
            true => k < 3 && KINDS[k].3[0] + 1 == values,
        };
        if record.kind < 4 && fits(record.kind) {
            return error;
        }
        let Some(like) = (0..4).find(|&k| fits(k)) else {
            return error;
        };
        // Only a record of the next section that has any (or of the one before, read as
        // the first record of this one) can have run across.
        let (lo, hi) = (like.min(record.kind), like.max(record.kind));
        let next_door = (lo + 1..hi.min(4)).all(|k| self.n[k] == 0);
        if !next_door || (like < record.kind && record.index != 1) {
            return error;
        }
        // Records of a later kind: this kind's count is too high. Of an earlier kind (or
        // after the last light): that kind's count is too low.
        let blamed = if like > record.kind {
            record.kind
        } else {
            like
        };
        let (name, plural, field, _) = KINDS[blamed];
        let n = self.n[blamed];
        let read_as = match KINDS.get(record.kind) {
            Some((kind, ..)) => {
                let of = self.n[record.kind];
                format!("read as {kind} {} of {of},", record.index)
            }
            None => "after the last record,".to_string(),
        };
        let announced = if n == 1 { name } else { plural };
        let advice = if like > record.kind {
            format!("is a {name} missing, or should {field} be {}?", n - 1)
        } else {
            format!(
                "should {field} be {}, or is this {name} out of place?",
                n + 1
            )
        };
        // What went wrong on that line, unless it is only that the file goes on.
        let original = match &error {
            SceneError::Syntax { loc, message, .. } if record.kind < 4 => {
                format!(" (the error there, {}:{}: {message})", loc.line, loc.column)
            }
            _ => String::new(),
        };
        let (like_name, ..) = KINDS[like];
        let at = self.at[blamed];
        SceneError::Syntax {
            loc: FileLoc {
                file: file.to_string(),
                line: at.line,
                column: at.column,
            },
            message: format!(
                "the counts announce {n} {announced}, but line {}, {read_as} holds {values} values, as a {like_name} does: {advice}{original}",
                first.line
            ),
            context: format!("counts, field {field}"),
        }
    }
}
