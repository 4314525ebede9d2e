//! Where the Scene.txt parser is in the structure, for its messages.

/// Where the parser is in the structure, for messages: a record (with its index among
/// its kind), an optional part (texture, material), the CSG block it is in, and the field.
#[derive(Clone, Copy)]
pub(super) struct Place {
    pub(super) record: &'static str,
    pub(super) index: Option<(u64, u64)>,
    pub(super) part: Option<&'static str>,
    /// Inside CSG block `csg N` (an extension record's child, which has no number).
    pub(super) within: Option<u64>,
}

impl Place {
    pub(super) fn describe(&self, field: &str) -> String {
        let mut s = self.record.to_string();
        match self.index {
            // An extension record's total is not known while it is read.
            Some((i, 0)) => s += &format!(" {i}"),
            Some((i, n)) => s += &format!(" {i} of {n}"),
            None => {}
        }
        if let Some(n) = self.within {
            s += &format!(" in csg {n}");
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
