//! The words of the extension grammar (SPEC §16): record keywords, modifiers, `end`;
//! which words a `name` may be; a quoted string's text; and the keyword nearest to a
//! misspelt one (`bxo` → `box`), for the error that refuses it.

/// Shape records.
pub(super) const SHAPES: [&str; 9] = [
    "sphere", "plane", "box", "cylinder", "cone", "disc", "torus", "triangle", "mesh",
];
/// CSG blocks.
pub(super) const CSG: [&str; 3] = ["union", "intersection", "difference"];
/// Light records.
pub(super) const LIGHTS: [&str; 4] = ["directional", "spot", "point", "area"];
/// Modifiers.
pub(super) const MODIFIERS: [&str; 10] = [
    "name",
    "open",
    "scale",
    "rotate",
    "translate",
    "fade",
    "smooth",
    "flat",
    "fit",
    "pivot",
];
/// Every other word of the grammar.
pub(super) const OTHERS: [&str; 3] = ["focus", "background", "end"];

/// Every keyword of the extension grammar.
pub(super) fn all() -> impl Iterator<Item = &'static str> {
    SHAPES
        .into_iter()
        .chain(CSG)
        .chain(LIGHTS)
        .chain(MODIFIERS)
        .chain(OTHERS)
}

/// `word` as it is written in `list`, with the list's lifetime (for marks and places).
pub(super) fn find<const N: usize>(list: [&'static str; N], word: &str) -> Option<&'static str> {
    list.into_iter().find(|k| *k == word)
}

/// True for a keyword of the grammar.
pub(super) fn is_keyword(word: &str) -> bool {
    all().any(|k| k == word)
}

/// True when `word` reads as a name: `[A-Za-z_][A-Za-z0-9_-]*` and not a keyword.
pub(super) fn is_name(word: &str) -> bool {
    let mut chars = word.chars();
    let first = chars
        .next()
        .is_some_and(|c| c.is_ascii_alphabetic() || c == '_');
    first && chars.all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-') && !is_keyword(word)
}

/// The text of a quoted string token (`"a \"b\" c\\d"` → `a "b" c\d`), or why it is not
/// one.
pub(in crate::scene::parser) fn unquote(token: &str) -> Result<String, String> {
    let Some(body) = token.strip_prefix('"') else {
        return Err("expected a quoted file name (\"…\")".to_string());
    };
    let mut out = String::new();
    let mut chars = body.chars();
    while let Some(c) = chars.next() {
        match c {
            '"' => {
                return if chars.as_str().is_empty() {
                    Ok(out)
                } else {
                    Err("text follows the closing quote".to_string())
                };
            }
            '\\' => match chars.next() {
                Some(e @ ('"' | '\\')) => out.push(e),
                Some(e) => return Err(format!("unknown escape '\\{e}' (only \\\" and \\\\)")),
                None => break,
            },
            c => out.push(c),
        }
    }
    Err("the quoted string is not closed on its line".to_string())
}

/// Levenshtein distance between two short words.
fn distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut prev = row[0];
        row[0] = i + 1;
        for (j, cb) in b.iter().enumerate() {
            let cost = usize::from(ca != *cb);
            let next = (row[j] + 1).min(row[j + 1] + 1).min(prev + cost);
            prev = row[j + 1];
            row[j + 1] = next;
        }
    }
    row[b.len()]
}

/// The keyword nearest to `word` among `candidates`, if it is close enough to be a
/// likely misspelling (at most 2 edits, and fewer than the word's length).
pub(in crate::scene::parser) fn nearest<'k>(
    word: &str,
    candidates: impl Iterator<Item = &'k str>,
) -> Option<&'k str> {
    let word = word.to_ascii_lowercase();
    let limit = 2.min(word.chars().count().saturating_sub(1));
    candidates
        .map(|k| (distance(&word, k), k))
        .filter(|(d, _)| *d <= limit)
        .min_by_key(|(d, _)| *d)
        .map(|(_, k)| k)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nearest_keyword_by_hand() {
        assert_eq!(distance("bxo", "box"), 2);
        assert_eq!(distance("kitten", "sitting"), 3);
        assert_eq!(nearest("bxo", all()), Some("box"));
        assert_eq!(nearest("Sphere", all()), Some("sphere"));
        assert_eq!(nearest("toru", all()), Some("torus"));
        assert_eq!(nearest("xyzzy", all()), None);
        assert_eq!(nearest("q", all()), None);
    }

    #[test]
    fn names_and_quoted_strings() {
        assert!(is_name("teapot") && is_name("_a-1") && is_name("Lamp2"));
        assert!(!is_name("box") && !is_name("2a") && !is_name("a.b") && !is_name(""));
        assert_eq!(unquote(r#""a b.obj""#), Ok("a b.obj".to_string()));
        assert_eq!(
            unquote(r#""say \"hi\" \\""#),
            Ok(r#"say "hi" \"#.to_string())
        );
        assert!(unquote(r#""open"#).unwrap_err().contains("not closed"));
        assert!(unquote(r#""a\n""#).unwrap_err().contains("unknown escape"));
        assert!(unquote("plain").unwrap_err().contains("quoted"));
    }
}
