//! Where an error is in the manifest text: the dotted key path (`camera.keys[1].frame`) of the value at an offset, so that
//! serde's messages ("invalid type: string \"big\", expected a number") say which key
//! they are about. For example, in
//!
//! ```toml
//! [camera]
//! radius = "big"     # camera.radius
//! keys = [{ frame = 0, fov = 2 }]   # an error at `fov` is in camera.keys[0]
//! ```

use toml::de::{DeTable, DeValue};
use toml::Spanned;

/// The key path of the innermost value holding byte `offset` (the table, for an offset
/// on a key), or `None` at the top level or when the text does not parse.
pub(super) fn key_path(text: &str, offset: usize) -> Option<String> {
    let root = DeTable::parse(text).ok()?;
    let mut path = Vec::new();
    in_table(root.get_ref(), offset, &mut path);
    (!path.is_empty()).then(|| path.concat())
}

/// Pushes the path of `offset` within `table`; whether it was found there.
fn in_table(table: &DeTable<'_>, offset: usize, path: &mut Vec<String>) -> bool {
    for (key, value) in table.iter() {
        if key.span().contains(&offset) {
            return true;
        }
        let name = quoted(key.get_ref());
        let segment = if path.is_empty() {
            name
        } else {
            format!(".{name}")
        };
        path.push(segment);
        if in_value(value, offset, path) {
            return true;
        }
        path.pop();
    }
    false
}

fn in_value(value: &Spanned<DeValue<'_>>, offset: usize, path: &mut Vec<String>) -> bool {
    // A `[table]`'s span may be its header only, so tables are searched whatever it is.
    let inner = match value.get_ref() {
        DeValue::Table(table) => in_table(table, offset, path),
        DeValue::Array(items) => items.iter().enumerate().any(|(i, item)| {
            path.push(format!("[{i}]"));
            let found = in_value(item, offset, path);
            if !found {
                path.pop();
            }
            found
        }),
        _ => false,
    };
    inner || value.span().contains(&offset)
}

/// A key as TOML writes it: bare when it can be, quoted otherwise.
fn quoted(key: &str) -> String {
    let bare = |c: char| c.is_ascii_alphanumeric() || c == '_' || c == '-';
    if !key.is_empty() && key.chars().all(bare) {
        key.to_string()
    } else {
        format!("{key:?}")
    }
}
