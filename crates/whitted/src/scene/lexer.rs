//! Splits Scene.txt into tokens: runs of characters between spaces, tabs and newlines.
//! `#` starts a comment that runs to the end of the line (an extension; the report's files
//! have none). A token that starts with `"` is a quoted string (SPEC §16: a file path) and
//! runs to its closing quote, spaces and `#` included. Each token keeps its 1-based line
//! and column for error messages.

/// One token and where it starts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Token<'a> {
    pub text: &'a str,
    pub line: usize,
    pub column: usize,
}

/// An iterator over the tokens of a source text (cloned to look ahead).
#[derive(Clone)]
pub struct Lexer<'a> {
    src: &'a str,
    pos: usize,
    line: usize,
    column: usize,
}

impl<'a> Lexer<'a> {
    pub fn new(src: &'a str) -> Lexer<'a> {
        // A byte-order mark (Windows editors write one) is not part of the first token,
        // and editors do not count it as a column.
        let pos = if src.starts_with('\u{feff}') { 3 } else { 0 };
        Lexer {
            src,
            pos,
            line: 1,
            column: 1,
        }
    }

    /// Line and column just past the last character read: where "end of file" is.
    pub fn position(&self) -> (usize, usize) {
        (self.line, self.column)
    }

    /// A quoted string (SPEC §16): from the opening `"` to the closing one, `\"` and
    /// `\\` escaped, spaces and `#` included; an unclosed string stops before the end of
    /// its line, and the reader (`unquote`) says so.
    fn quoted(&mut self) {
        self.bump('"');
        let mut escaped = false;
        while let Some(c) = self.src[self.pos..].chars().next() {
            if c == '\n' || c == '\r' {
                break;
            }
            self.bump(c);
            if escaped {
                escaped = false;
            } else if c == '\\' {
                escaped = true;
            } else if c == '"' {
                break;
            }
        }
    }

    fn bump(&mut self, c: char) {
        self.pos += c.len_utf8();
        if c == '\n' {
            self.line += 1;
            self.column = 1;
        } else {
            self.column += 1;
        }
    }
}

/// Whether an ASCII byte is a blank: what `char::is_whitespace` says of it (tab, line
/// feed, vertical tab, form feed, carriage return, space).
fn is_blank(b: u8) -> bool {
    matches!(b, b'\t' | b'\n' | 0x0b | 0x0c | b'\r' | b' ')
}

impl Lexer<'_> {
    /// The character at the cursor when it is not ASCII (whose bytes are read as they
    /// are).
    fn wide_char(&self) -> char {
        self.src[self.pos..].chars().next().unwrap_or('\0')
    }

    /// Moves past blanks and comments to the next token's first character.
    fn skip_blanks(&mut self) {
        let bytes = self.src.as_bytes();
        let mut in_comment = false;
        while let Some(&b) = bytes.get(self.pos) {
            if b >= 0x80 {
                let c = self.wide_char();
                if !in_comment && !c.is_whitespace() {
                    break;
                }
                self.bump(c);
            } else if b == b'\n' {
                in_comment = false;
                self.bump('\n');
            } else {
                if b == b'#' {
                    in_comment = true;
                } else if !in_comment && !is_blank(b) {
                    break;
                }
                self.pos += 1;
                self.column += 1;
            }
        }
    }

    /// Moves past a token that is not quoted: up to a blank or a `#`.
    fn skip_word(&mut self) {
        let bytes = self.src.as_bytes();
        while let Some(&b) = bytes.get(self.pos) {
            if b >= 0x80 {
                let c = self.wide_char();
                if c.is_whitespace() {
                    break;
                }
                self.bump(c);
            } else if is_blank(b) || b == b'#' {
                break;
            } else {
                self.pos += 1;
                self.column += 1;
            }
        }
    }
}

impl<'a> Iterator for Lexer<'a> {
    type Item = Token<'a>;

    /// Reads ASCII a byte at a time (every scene file is ASCII but for its strings), and
    /// other characters as characters: the same tokens and columns as reading every
    /// character as a `char`.
    fn next(&mut self) -> Option<Token<'a>> {
        self.skip_blanks();
        let start = self.pos;
        let (line, column) = (self.line, self.column);
        if self.src[self.pos..].starts_with('"') {
            self.quoted();
        } else {
            self.skip_word();
        }
        (self.pos > start).then(|| Token {
            text: &self.src[start..self.pos],
            line,
            column,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tokens_with_positions_and_comments() {
        let src = "640 480 # resolution\n\t0.0  1.5#tight\n  # only a comment\r\n-3e2";
        let toks: Vec<_> = Lexer::new(src)
            .map(|t| (t.text, t.line, t.column))
            .collect();
        assert_eq!(
            toks,
            vec![
                ("640", 1, 1),
                ("480", 1, 5),
                ("0.0", 2, 2),
                ("1.5", 2, 7),
                ("-3e2", 4, 1)
            ]
        );
    }

    #[test]
    fn end_position_after_trailing_blanks() {
        let mut lex = Lexer::new("1 2\n\n");
        assert_eq!(lex.by_ref().count(), 2);
        assert_eq!(lex.position(), (3, 1));
    }

    #[test]
    fn a_leading_byte_order_mark_is_skipped() {
        let toks: Vec<_> = Lexer::new("\u{feff}640 480")
            .map(|t| (t.text, t.line, t.column))
            .collect();
        assert_eq!(toks, vec![("640", 1, 1), ("480", 1, 5)]);
    }

    #[test]
    fn quoted_strings_are_one_token_with_spaces_escapes_and_hashes() {
        let src = "mesh \"my models/a#1.obj\" 1\nx \"say \\\"hi\\\" \\\\\" 2\n\"open 3";
        let toks: Vec<_> = Lexer::new(src)
            .map(|t| (t.text, t.line, t.column))
            .collect();
        assert_eq!(
            toks,
            vec![
                ("mesh", 1, 1),
                ("\"my models/a#1.obj\"", 1, 6),
                ("1", 1, 26),
                ("x", 2, 1),
                ("\"say \\\"hi\\\" \\\\\"", 2, 3),
                ("2", 2, 19),
                ("\"open 3", 3, 1),
            ]
        );
    }

    /// The tokens of reading every character as a `char` (the lexer before its ASCII
    /// path), quoted strings aside.
    fn by_chars(src: &str) -> Vec<(String, usize, usize)> {
        let (mut out, mut line, mut column) = (Vec::new(), 1, 1);
        let (mut word, mut at, mut in_comment) = (String::new(), (1, 1), false);
        for c in src.chars().chain(['\n']) {
            let ends = c.is_whitespace() || c == '#';
            if ends && !word.is_empty() {
                out.push((std::mem::take(&mut word), at.0, at.1));
            }
            if c == '\n' {
                in_comment = false;
            } else if c == '#' {
                in_comment = true;
            } else if !in_comment && !ends {
                if word.is_empty() {
                    at = (line, column);
                }
                word.push(c);
            }
            (line, column) = if c == '\n' {
                (line + 1, 1)
            } else {
                (line, column + 1)
            };
        }
        out
    }

    proptest::proptest! {
        /// Text of ASCII and other blanks and letters, comments and line ends: the same
        /// tokens at the same lines and columns as reading it character by character.
        #[test]
        fn the_ascii_path_reads_as_characters_do(
            parts in proptest::collection::vec(proptest::sample::select(vec![
                "1", "-2.5e3", " ", "\t", "\n", "\r", "\u{b}", "\u{c}", "#", "é", "\u{a0}",
                "\u{2003}", "\u{85}", "x\u{3000}y", "ß7",
            ]), 0..60),
        ) {
            let src: String = parts.concat();
            let got: Vec<_> = Lexer::new(&src)
                .map(|t| (t.text.to_string(), t.line, t.column))
                .collect();
            proptest::prop_assert_eq!(got, by_chars(&src));
        }
    }

    #[test]
    fn columns_count_characters_not_bytes() {
        let toks: Vec<_> = Lexer::new("é 2").map(|t| t.column).collect();
        assert_eq!(toks, vec![1, 3]);
    }
}
