//! One pass over an OBJ file's lines before and after `tobj` reads it: the counts that
//! keep a file within the budgets before anything is allocated (vertices, faces, the
//! triangles their corners fan into), the statements the tracer does not use (one
//! warning per kind), and, when `tobj` refuses a file for what it only finds at the end
//! (an index past the list), the line to blame, in one more pass rather than parsing the
//! file again and again.

use crate::limits::{MAX_MESH_TRIANGLES, MAX_MESH_VERTICES};

/// What one pass counts.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Counts {
    /// `v` lines.
    pub positions: u64,
    /// `vt` lines.
    pub texcoords: u64,
    /// `vn` lines.
    pub normals: u64,
    /// `f` lines (empty ones included: the reader keeps a record of each).
    pub faces: u64,
    /// The triangles the `f` lines fan into.
    pub triangles: u64,
    /// `l` and `p` lines, which tobj also keeps until it drops them.
    pub others: u64,
    /// Statements read past, each with its count and first line (`s`, `vp`, `curv`…).
    pub unused: Vec<(String, u64, usize)>,
}

/// The lines of `bytes` with their 1-based numbers (a trailing `\r` removed).
pub fn lines(bytes: &[u8]) -> impl Iterator<Item = (usize, &[u8])> {
    bytes.split(|&b| b == b'\n').enumerate().map(|(i, l)| {
        let l = l.strip_suffix(b"\r").unwrap_or(l);
        (i + 1, l)
    })
}

fn words(line: &[u8]) -> impl Iterator<Item = &[u8]> {
    line.split(|b| b.is_ascii_whitespace())
        .filter(|w| !w.is_empty())
}

/// Statements `tobj` reads (or skips as comments and names).
const READ: [&[u8]; 10] = [
    b"v", b"vt", b"vn", b"f", b"o", b"g", b"mtllib", b"usemtl", b"l", b"p",
];

/// Counts the file's statements in one pass.
pub fn count(bytes: &[u8]) -> Counts {
    let mut c = Counts::default();
    for (line, text) in lines(bytes) {
        let mut w = words(text);
        let Some(first) = w.next() else { continue };
        match first {
            b"v" => c.positions += 1,
            b"vt" => c.texcoords += 1,
            b"vn" => c.normals += 1,
            b"f" => {
                c.faces += 1;
                c.triangles += (w.count() as u64).saturating_sub(2);
            }
            b"l" | b"p" => c.others += 1,
            _ if first.starts_with(b"#") || READ.contains(&first) => {}
            // `s off` and `s 0` ask for nothing.
            b"s" if matches!(w.next(), Some(b"off" | b"0")) => {}
            _ => {
                let name = String::from_utf8_lossy(first).into_owned();
                match c.unused.iter().position(|(n, ..)| *n == name) {
                    Some(k) => c.unused[k].1 += 1,
                    None if c.unused.len() < 32 => c.unused.push((name, 1, line)),
                    None => {}
                }
            }
        }
    }
    c
}

impl Counts {
    /// Why the file is over a budget, if it is.
    pub fn over_budget(&self) -> Option<String> {
        let records = self.faces + self.others;
        if records > MAX_MESH_TRIANGLES || self.triangles > MAX_MESH_TRIANGLES {
            return Some(format!(
                "the file has {} 'f', 'l' and 'p' lines fanning into {} triangles, over the budget of {MAX_MESH_TRIANGLES} triangles a mesh",
                records, self.triangles
            ));
        }
        let vertices = self.positions.max(self.texcoords).max(self.normals);
        (vertices > MAX_MESH_VERTICES).then(|| {
            format!(
                "the file has {vertices} 'v', 'vt' or 'vn' lines, over the budget of {MAX_MESH_VERTICES} vertices a mesh"
            )
        })
    }
}

/// An OBJ index as written (`3`, `-1`) resolved against `count` entries so far and
/// `total` in the file, 0-based; `None` when it points past the list.
fn resolve(word: &[u8], so_far: u64, total: u64) -> Option<u64> {
    let i: i64 = std::str::from_utf8(word).ok()?.parse().ok()?;
    if i > 0 && i.unsigned_abs() <= total {
        Some(i.unsigned_abs() - 1)
    } else if i < 0 && i.unsigned_abs() <= so_far {
        Some(so_far - i.unsigned_abs())
    } else {
        None
    }
}

/// The first `f` line with a corner's position, texture coordinate or normal index past
/// its list: its number, and which index.
pub fn bad_index(bytes: &[u8], totals: &Counts) -> Option<(usize, String)> {
    let mut so_far = [0u64; 3];
    let total = [totals.positions, totals.texcoords, totals.normals];
    const WHAT: [&str; 3] = ["vertex", "texture coordinate (vt)", "normal (vn)"];
    for (line, text) in lines(bytes) {
        let mut w = words(text);
        match w.next() {
            Some(b"v") => so_far[0] += 1,
            Some(b"vt") => so_far[1] += 1,
            Some(b"vn") => so_far[2] += 1,
            Some(b"f") => {
                for corner in w {
                    for (k, index) in corner.split(|&b| b == b'/').enumerate().take(3) {
                        if index.is_empty() {
                            continue;
                        }
                        if resolve(index, so_far[k], total[k]).is_none() {
                            let shown = String::from_utf8_lossy(index);
                            let msg = format!(
                                "the {} index {shown} is past the list ({} in the file)",
                                WHAT[k], total[k]
                            );
                            return Some((line, msg));
                        }
                    }
                }
            }
            _ => {}
        }
    }
    None
}

/// The first `v` line with a coordinate that reads as a number but not a finite one (NaN,
/// or out of range as 1e400 is); what does not read as a number is tobj's to refuse.
pub fn non_finite(bytes: &[u8]) -> Option<usize> {
    lines(bytes).find_map(|(line, text)| {
        let mut w = words(text);
        (w.next() == Some(b"v")).then_some(())?;
        let bad = w.take(3).any(|x| {
            std::str::from_utf8(x)
                .ok()
                .and_then(|s| s.parse::<f64>().ok())
                .is_some_and(|v| !v.is_finite())
        });
        bad.then_some(line)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_faces_triangles_and_unused_statements() {
        let src = b"v 0 0 0\nv 1 0 0\r\nv 0 1 0\nvt 0 0\nf 1 2 3\nf\nf 1 2 3 1\ns 1\ns off\nl 1 2\nvp 0.5\ns 2\n";
        let c = count(src);
        assert_eq!((c.positions, c.texcoords, c.normals), (3, 1, 0));
        assert_eq!((c.faces, c.triangles, c.others), (3, 3, 1));
        assert_eq!(
            c.unused,
            vec![("s".to_string(), 2, 8), ("vp".to_string(), 1, 11)]
        );
        assert_eq!(c.over_budget(), None);
        let many = Counts {
            faces: MAX_MESH_TRIANGLES + 1,
            ..Counts::default()
        };
        assert!(many.over_budget().unwrap().contains("over the budget"));
    }

    #[test]
    fn finds_the_line_of_an_index_past_the_list() {
        let src = b"v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1 2 3\nf 1/1 2/1 3/1\nf 1/2 2 3\n";
        let c = count(src);
        let (line, msg) = bad_index(src, &c).unwrap();
        assert_eq!(line, 7);
        assert!(msg.contains("texture coordinate (vt) index 2"), "{msg}");
        // Negative indices count back from the line: -4 before the 4th v is past.
        let src = b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\nf -4 -2 -1\n";
        assert_eq!(bad_index(src, &count(src)).unwrap().0, 5);
        assert_eq!(bad_index(b"v 0 0 0\nf 1 1 1\n", &count(b"v 0 0 0\n")), None);
    }

    #[test]
    fn finds_a_vertex_that_is_not_finite() {
        assert_eq!(non_finite(b"v 0 0 0\nv 1 nan 0\n"), Some(2));
        assert_eq!(non_finite(b"# c\nv 0 0 1e400\n"), Some(2));
        assert_eq!(non_finite(b"v 0 0 0\nvt 0 nan\n"), None);
        assert_eq!(non_finite(b"v 0 x 0\n"), None);
    }
}
