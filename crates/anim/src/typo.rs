//! The known name a mistyped one was meant to be ("did you mean `center`?"), for every
//! message that refuses a name: manifest keys and tables, track targets' kinds and fields.
//!
//! ```text
//! camra              → camera
//! sphere 3 centre    → center
//! ```

/// The known name nearest to `name` by edit distance (a transposition counting one), if
/// near enough to be a typo: at most 1 edit for names of up to 4 characters, 2 up to 8,
/// and a third of the length beyond. Ties go to the first known name. Names of more than
/// 40 characters are no typo of a known one (and would cost time to compare).
pub(crate) fn nearest<'a>(name: &str, known: impl Iterator<Item = &'a str>) -> Option<&'a str> {
    let lower = name.to_lowercase();
    let limit = match name.chars().count() {
        0..=4 => 1,
        5..=8 => 2,
        n @ 9..=40 => n / 3,
        _ => return None,
    };
    known
        .map(|k| (strsim::damerau_levenshtein(&lower, k), k))
        .filter(|&(d, _)| d <= limit)
        .min_by_key(|&(d, _)| d)
        .map(|(_, k)| k)
}

/// ` (did you mean `near`?)` for the known name nearest to `name`, or nothing.
pub(crate) fn did_you_mean<'a>(name: &str, known: impl Iterator<Item = &'a str>) -> String {
    nearest(name, known).map_or(String::new(), |near| format!(" (did you mean `{near}`?)"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_british_spelling_finds_the_field() {
        let fields = ["center", "radius", "color", "kd"];
        // centre → center: one transposition; colour → color: one deletion.
        assert_eq!(nearest("centre", fields.iter().copied()), Some("center"));
        assert_eq!(nearest("colour", fields.iter().copied()), Some("color"));
        assert_eq!(
            did_you_mean("raduis", fields.iter().copied()),
            " (did you mean `radius`?)"
        );
        // "zzz" is 3 edits from "kd" and more from the rest: no suggestion.
        assert_eq!(did_you_mean("zzz", fields.iter().copied()), "");
    }
}
