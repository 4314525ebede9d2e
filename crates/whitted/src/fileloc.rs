//! A place in a text file, after pbrt-v4's `FileLoc`: every located error of the library
//! (Scene.txt and manifest alike) carries one and prints it as `file:line:column`, and
//! every message prints a path the same way (`shown`): `animations/../out/orbit` is
//! `out/orbit`.

use std::fmt;

/// A position in a text file: 1-based line and column (in characters).
#[derive(Clone, Debug, PartialEq, Eq, Default)]
pub struct FileLoc {
    /// The file's name as the user gave it (printed through `shown`).
    pub file: String,
    /// The line, from 1.
    pub line: usize,
    /// The column in characters (not bytes), from 1.
    pub column: usize,
}

impl FileLoc {
    /// The location of byte `offset` of `text`, a file named `file`.
    pub fn of_offset(file: &str, text: &str, offset: usize) -> FileLoc {
        let mut end = offset.min(text.len());
        while !text.is_char_boundary(end) {
            end -= 1;
        }
        let before = &text[..end];
        FileLoc {
            file: file.to_string(),
            line: before.matches('\n').count() + 1,
            column: before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1,
        }
    }
}

impl fmt::Display for FileLoc {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let file = shown(std::path::Path::new(&self.file));
        write!(f, "{file}:{}:{}", self.line, self.column)
    }
}

/// `path` as messages print it: `a/./b/../c` is `a/c`, lexically (no link is followed, and
/// the path used to open the file is left as it was). A `..` that would climb past the
/// start of a relative path is kept; one past the root is dropped, like the system does.
pub fn shown(path: &std::path::Path) -> String {
    use std::path::Component;
    let mut parts: Vec<Component> = Vec::new();
    for part in path.components() {
        match part {
            Component::CurDir => {}
            Component::ParentDir => match parts.last() {
                Some(Component::Normal(_)) => {
                    parts.pop();
                }
                Some(Component::RootDir | Component::Prefix(_)) => {}
                _ => parts.push(part),
            },
            _ => parts.push(part),
        }
    }
    if parts.is_empty() {
        return ".".into();
    }
    parts
        .iter()
        .collect::<std::path::PathBuf>()
        .display()
        .to_string()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paths_are_shown_lexically_normal() {
        let s = |p: &str| shown(std::path::Path::new(p));
        assert_eq!(s("animations/../out/orbit"), "out/orbit");
        assert_eq!(s("./a/./b/"), "a/b");
        assert_eq!(s("../a/../../b"), "../../b");
        assert_eq!(s("/../x/y/.."), "/x");
        assert_eq!(s("a/.."), ".");
        let loc = FileLoc {
            file: "anim/../s.txt".into(),
            line: 2,
            column: 3,
        };
        assert_eq!(loc.to_string(), "s.txt:2:3");
    }

    #[test]
    fn offsets_to_lines_and_columns() {
        let text = "ab\ncdé f\n";
        assert_eq!(FileLoc::of_offset("t", text, 0).to_string(), "t:1:1");
        assert_eq!(FileLoc::of_offset("t", text, 4).to_string(), "t:2:2");
        // 'f' is byte 8 (é is two bytes) but column 5.
        assert_eq!(FileLoc::of_offset("t", text, 8).to_string(), "t:2:5");
        // Inside a multi-byte character: the character's own column.
        assert_eq!(FileLoc::of_offset("t", text, 6).to_string(), "t:2:3");
        assert_eq!(FileLoc::of_offset("t", text, 99).to_string(), "t:3:1");
    }
}
