//! Where the Scene.txt parser is in the structure, for its messages.

/// Where the parser is in the structure, for messages: a record (with its index among
/// its kind), an optional part (texture, material), and the field.
#[derive(Clone, Copy)]
pub(super) struct Place {
    pub(super) record: &'static str,
    pub(super) index: Option<(u64, u64)>,
    pub(super) part: Option<&'static str>,
}

impl Place {
    pub(super) fn describe(&self, field: &str) -> String {
        let mut s = self.record.to_string();
        if let Some((i, n)) = self.index {
            s += &format!(" {i} of {n}");
        }
        if let Some(part) = self.part {
            s += &format!(", {part}");
        }
        if !field.is_empty() {
            s += &format!(", field {field}");
        }
        s
    }
}
