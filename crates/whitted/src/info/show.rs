//! `--info`'s text: a table of the objects, one of the lights, then the camera's line.
//! Numbers are shown with at most four decimals, trailing zeros dropped (`0.25`, `-1`,
//! `12.3457`), and in scientific notation below 0.001 (`2.5e-5`), so small models keep
//! their digits.
//!
//! ```text
//! objects:
//!   #  name      kind    triangles  bounds (world)
//!   1  sphere 1  sphere  -          [-1, 0, -1] to [1, 2, 1]
//!   2  bunny     mesh    69451      [-0.5, 0, -0.3878] to [0.5, 0.9679, 0.3878]
//! lights:
//!   #  name     kind   place
//!   1  light 1  point  at [5, 10, 5]
//! camera: eye [0, 2, 10], look-at [0, 1, 0], 640×480 pixels, field of view 19.8525° vertical (28.0725° horizontal)
//! ```

use super::{Info, LightPlace};
use glam::DVec3;
use std::fmt;

/// A number with at most four decimals, trailing zeros dropped; below 0.001 (not 0) in
/// scientific notation with four significant digits.
pub fn num(x: f64) -> String {
    if x != 0.0 && x.abs() < 1e-3 {
        let s = format!("{x:.3e}");
        let (mantissa, exp) = s.split_once('e').unwrap_or((&s, "0"));
        return format!("{}e{exp}", trim(mantissa));
    }
    trim(&format!("{x:.4}"))
}

/// `1.2500` → `1.25`, `2.0000` → `2`, `-0.0000` → `0`.
fn trim(s: &str) -> String {
    let t = if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.')
    } else {
        s
    };
    if t == "-0" {
        "0".into()
    } else {
        t.into()
    }
}

/// `[x, y, z]`, each by `num`.
pub fn point(p: DVec3) -> String {
    format!("[{}, {}, {}]", num(p.x), num(p.y), num(p.z))
}

/// Rows as columns two spaces apart, each as wide as its widest cell (the last one
/// unpadded), each line indented by two spaces.
fn table(f: &mut fmt::Formatter<'_>, rows: &[Vec<String>]) -> fmt::Result {
    let cols = rows.first().map_or(0, Vec::len);
    let width: Vec<usize> = (0..cols)
        .map(|c| rows.iter().map(|r| r[c].chars().count()).max().unwrap_or(0))
        .collect();
    for row in rows {
        let mut line = String::from(" ");
        for (c, cell) in row.iter().enumerate() {
            line.push(' ');
            line.push_str(cell);
            if c + 1 < cols {
                let pad = width[c] - cell.chars().count() + 1;
                line.push_str(&" ".repeat(pad));
            }
        }
        writeln!(f, "{}", line.trim_end())?;
    }
    Ok(())
}

impl fmt::Display for Info {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let head = ["#", "name", "kind", "triangles", "bounds (world)"];
        let mut rows = vec![head.map(String::from).to_vec()];
        for o in &self.objects {
            rows.push(vec![
                o.number.to_string(),
                o.name.clone(),
                o.kind.to_string(),
                o.triangles.map_or("-".into(), |n| n.to_string()),
                o.bounds.map_or("unbounded".into(), |(lo, hi)| {
                    format!("{} to {}", point(lo), point(hi))
                }),
            ]);
        }
        writeln!(f, "objects:")?;
        table(f, &rows)?;
        let mut rows = vec![["#", "name", "kind", "place"].map(String::from).to_vec()];
        for l in &self.lights {
            let place = match l.place {
                LightPlace::At(p) => format!("at {}", point(p)),
                LightPlace::Towards(d) => format!("towards {}", point(d)),
            };
            rows.push(vec![
                l.number.to_string(),
                l.name.clone(),
                l.kind.to_string(),
                place,
            ]);
        }
        writeln!(f, "lights:")?;
        table(f, &rows)?;
        let c = &self.camera;
        writeln!(
            f,
            "camera: eye {}, look-at {}, {}×{} pixels, field of view {}° vertical ({}° horizontal)",
            point(c.eye),
            point(c.look_at),
            c.size.0,
            c.size.1,
            num(c.fov()),
            num(c.fov_horizontal())
        )
    }
}
