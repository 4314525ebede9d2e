//! Tokens of an NFF file with their places, read as the records need them: numbers,
//! vectors, counts and keywords, each failure a `SceneError::Syntax` at the offending
//! token (or at the end of the file) naming the record it belongs to. Messages are
//! written only when there is an error: a file of 10,000 polygons reads 170,000
//! numbers, and spelling each one's message in advance cost more than reading them.

use crate::input::quote;
use crate::scene::error::{FileLoc, SceneError};
use crate::scene::lexer::{Lexer, Token};
use glam::DVec3;
use std::fmt::{self, Display};

pub(super) type Result<T> = std::result::Result<T, SceneError>;

/// The record being read, for messages: a record's keyword and line, or the file.
#[derive(Clone, Copy, Debug)]
pub(super) enum Context<'a> {
    /// Before the first record.
    TopLevel,
    /// Within the record starting with this keyword on this line.
    Record(&'a str, usize),
    /// A check on the whole file once it is read.
    WholeFile,
}

impl Display for Context<'_> {
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        match self {
            Context::TopLevel => f.write_str("top level"),
            Context::Record(word, line) => write!(f, "'{word}' record on line {line}"),
            Context::WholeFile => f.write_str("the whole file"),
        }
    }
}

/// A vector's component, named as "FIELD x" in messages.
struct Component<'f, F: Display>(&'f F, char);

impl<F: Display> Display for Component<'_, F> {
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        write!(f, "{} {}", self.0, self.1)
    }
}

/// The token stream and the record being read (for messages).
pub(super) struct Reader<'a> {
    lexer: Lexer<'a>,
    file: &'a str,
    /// The record being read.
    pub(super) context: Context<'a>,
}

impl<'a> Reader<'a> {
    pub(super) fn new(src: &'a str, file: &'a str) -> Reader<'a> {
        Reader {
            lexer: Lexer::new(src),
            file,
            context: Context::TopLevel,
        }
    }

    /// An error at line, column.
    pub(super) fn error_at(&self, (line, column): (usize, usize), message: String) -> SceneError {
        SceneError::Syntax {
            loc: FileLoc {
                file: self.file.to_string(),
                line,
                column,
            },
            message,
            context: self.context.to_string(),
        }
    }

    /// An error at a token.
    pub(super) fn error(&self, tok: &Token, message: String) -> SceneError {
        self.error_at((tok.line, tok.column), message)
    }

    /// Where the end of the file is.
    pub(super) fn end(&self) -> (usize, usize) {
        self.lexer.position()
    }

    /// The next token, if any.
    pub(super) fn next(&mut self) -> Option<Token<'a>> {
        self.lexer.next()
    }

    /// The next token without taking it.
    pub(super) fn peek(&self) -> Option<Token<'a>> {
        self.lexer.clone().next()
    }

    /// The next token, or an error at the end of the file saying what was expected.
    pub(super) fn token(&mut self, what: impl Display) -> Result<Token<'a>> {
        match self.lexer.next() {
            Some(tok) => Ok(tok),
            None => {
                let msg = format!("expected {what}, found the end of the file");
                Err(self.error_at(self.end(), msg))
            }
        }
    }

    /// The next token, or an error at the end of the file: "expected a number for
    /// FIELD" and the like (`article`, then `field`).
    fn token_for(&mut self, article: &str, field: impl Display) -> Result<Token<'a>> {
        match self.lexer.next() {
            Some(tok) => Ok(tok),
            None => {
                let msg = format!("expected {article} for {field}, found the end of the file");
                Err(self.error_at(self.end(), msg))
            }
        }
    }

    /// A finite number for `field`.
    pub(super) fn number(&mut self, field: impl Display) -> Result<f64> {
        let tok = self.token_for("a number", &field)?;
        match tok.text.parse::<f64>() {
            Ok(v) if v.is_finite() => Ok(v),
            Ok(_) => {
                let msg = format!(
                    "expected a finite number for {field}, found '{}'",
                    quote(tok.text)
                );
                Err(self.error(&tok, msg))
            }
            Err(_) => {
                let msg = format!("expected a number for {field}, found '{}'", quote(tok.text));
                Err(self.error(&tok, msg))
            }
        }
    }

    /// Three numbers: `field` x, y, z.
    pub(super) fn vector(&mut self, field: impl Display) -> Result<DVec3> {
        let x = self.number(Component(&field, 'x'))?;
        let y = self.number(Component(&field, 'y'))?;
        let z = self.number(Component(&field, 'z'))?;
        Ok(DVec3::new(x, y, z))
    }

    /// An integer literal in lo..=hi for `field`.
    pub(super) fn integer(&mut self, field: impl Display, lo: u64, hi: u64) -> Result<u64> {
        let tok = self.token_for("an integer", &field)?;
        match tok.text.parse::<u64>() {
            Ok(v) if (lo..=hi).contains(&v) => Ok(v),
            _ => {
                let msg = format!(
                    "expected an integer from {lo} to {hi} for {field}, found '{}'",
                    quote(tok.text)
                );
                Err(self.error(&tok, msg))
            }
        }
    }

    /// The keyword `word` (a view's `from`, `at` ...).
    pub(super) fn keyword(&mut self, word: &str) -> Result<()> {
        let tok = self.token(format_args!("'{word}'"))?;
        if tok.text == word {
            Ok(())
        } else {
            let msg = format!("expected '{word}', found '{}'", quote(tok.text));
            Err(self.error(&tok, msg))
        }
    }

    /// Whether the next token is a number (an optional light colour follows).
    pub(super) fn number_follows(&self) -> bool {
        self.peek().is_some_and(|t| t.text.parse::<f64>().is_ok())
    }
}
