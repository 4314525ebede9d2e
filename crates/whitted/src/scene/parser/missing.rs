//! Where a missing value is. Scene.txt is a stream of tokens, but the report writes each
//! record on a line of its own (the header's five, then one per object and light), so a
//! record short of a value reads on into the next line, the next record then starts in
//! the middle of a line, and the error surfaces lines later. `Layout` follows the reader
//! token by token; when an error comes after such a crossing, it is put at the end of
//! the line that is short, naming the value missing there:
//!
//! ```text
//! 0 3          # scene.txt:2:4: z is missing at the end of this line: the camera
//! 0 1 0        #   position has 2 values here, so reading on took '0' from line 3 for
//! 2 40         #   it (and then failed at 4:3: expected 0 (none), 1, 2 or 3 …)
//! ```
//!
//! A file laid out otherwise (two records on a line, one record over several lines that
//! ends with its line) is left alone: only a record that crosses a line and is followed
//! by one that starts mid-line, or that fails on what it took from the next line, is
//! blamed. The extension's records (keyword-led) are not followed.

use super::super::error::{FileLoc, SceneError};
use super::super::lexer::Token;

impl<'a> super::Parser<'a> {
    /// The next token, whatever it is (the extension's keywords), or `None` at the end;
    /// followed as `token`'s are, so that the end of the file is just past it.
    pub(super) fn next(&mut self) -> Option<Token<'a>> {
        let tok = self.lexer.next()?;
        self.layout.took(tok, "", String::new);
        Some(tok)
    }
}

/// A record that read on past the end of its line.
#[derive(Clone, Debug)]
struct Crossing {
    /// Just past the last value on the short line.
    line: usize,
    column: usize,
    /// The field read from the next line, and where in the structure it is.
    field: String,
    context: String,
    /// The record's values on its own line.
    values: usize,
    /// The token taken from the next line, and that line.
    took: String,
    took_line: usize,
}

/// The record being read.
struct Record {
    values: usize,
    crossing: Option<Crossing>,
}

/// Follows the report's one-record-a-line layout through the tokens read.
pub(super) struct Layout<'a> {
    /// Whether the file has kept the layout so far (and the reader is in the report's part).
    active: bool,
    /// The next token starts a record.
    starting: bool,
    prev: Option<Token<'a>>,
    record: Option<Record>,
    /// The first record that crossed a line before one that started mid-line.
    suspect: Option<Crossing>,
}

/// Line and column just past `tok`.
pub(super) fn end_of(tok: &Token) -> (usize, usize) {
    (tok.line, tok.column + tok.text.chars().count())
}

impl<'a> Layout<'a> {
    pub(super) fn new() -> Layout<'a> {
        Layout {
            active: true,
            starting: true,
            prev: None,
            record: None,
            suspect: None,
        }
    }

    /// The last token read, if any.
    pub(super) fn prev(&self) -> Option<Token<'a>> {
        self.prev
    }

    /// The next token starts a record.
    pub(super) fn start(&mut self) {
        self.starting = true;
    }

    /// No more records to follow (the extension's start).
    pub(super) fn stop(&mut self) {
        self.active = false;
    }

    /// `tok` was read for `field` (`context` its place in the structure).
    pub(super) fn took(&mut self, tok: Token<'a>, field: &str, context: impl FnOnce() -> String) {
        let prev = self.prev.replace(tok);
        if !self.active || self.suspect.is_some() {
            return;
        }
        let same_line = prev.is_some_and(|p| p.line == tok.line);
        if std::mem::take(&mut self.starting) {
            let before = self.record.take();
            if same_line {
                // Two records on one line: the layout holds only if the one before ran
                // on into this line, short of a value on its own.
                match before.and_then(|r| r.crossing) {
                    Some(c) => self.suspect = Some(c),
                    None => self.active = false,
                }
            }
            self.record = Some(Record {
                values: 1,
                crossing: None,
            });
            return;
        }
        let (Some(record), Some(prev)) = (self.record.as_mut(), prev) else {
            return;
        };
        if same_line {
            if record.crossing.is_none() {
                record.values += 1;
            }
        } else if record.crossing.is_none() {
            let (line, column) = end_of(&prev);
            record.crossing = Some(Crossing {
                line,
                column,
                field: field.to_string(),
                context: context(),
                values: record.values,
                took: tok.text.to_string(),
                took_line: tok.line,
            });
        }
    }

    /// `error`, put at the end of the short line when a record crossed one before it
    /// (or the record that failed did, and failed past its line); unchanged otherwise.
    pub(super) fn blame(&self, error: SceneError) -> SceneError {
        let crossing = match (&self.suspect, &self.record) {
            (Some(c), _) => c,
            (
                None,
                Some(Record {
                    crossing: Some(c), ..
                }),
            ) if self.active => c,
            _ => return error,
        };
        let SceneError::Syntax { loc, message, .. } = &error else {
            return error;
        };
        // Only an error past the short line (not one the counts were blamed for).
        if (loc.line, loc.column) <= (crossing.line, crossing.column) {
            return error;
        }
        let record = crossing.context.split(',').next().unwrap_or_default();
        let values = match crossing.values {
            1 => "1 value".to_string(),
            n => format!("{n} values"),
        };
        let message = format!(
            "{} is missing at the end of this line: the {record} has {values} here, so reading on took '{}' from line {} for it (and then failed at {}:{}: {message})",
            crossing.field,
            crate::input::quote(&crossing.took),
            crossing.took_line,
            loc.line,
            loc.column,
        );
        SceneError::Syntax {
            loc: FileLoc {
                file: loc.file.clone(),
                line: crossing.line,
                column: crossing.column,
            },
            message,
            context: crossing.context.clone(),
        }
    }
}
