//! The path plot's legend: one row of keys under both views, each key a small swatch of
//! how the thing is drawn and its name, in the order first drawn, each name once.

use super::font::FAMILY;
use plotters::coord::Shift;
use plotters::prelude::*;

/// How a key's swatch is drawn.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Swatch {
    /// A translucent filled square (spheres, cylinders).
    Fill(RGBColor),
    /// A line (paths).
    Line(RGBColor),
    /// A dashed line (planes seen edge-on).
    Dashed(RGBColor),
    /// A cross (look-at points).
    Cross(RGBColor),
    /// A filled dot (lights).
    Dot(RGBColor),
}

/// The keys of a legend.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Legend {
    pub keys: Vec<(String, Swatch)>,
}

impl Legend {
    /// Adds a key unless one of that name is already there.
    pub fn add(&mut self, name: &str, swatch: Swatch) {
        if !self.keys.iter().any(|(n, _)| n == name) {
            self.keys.push((name.to_string(), swatch));
        }
    }

    /// Draws the keys left to right, centred vertically in `area`.
    pub fn draw<DB: DrawingBackend>(&self, area: &DrawingArea<DB, Shift>) -> Result<(), String> {
        let (_, h) = area.dim_in_pixel();
        let y = h as i32 / 2;
        let font = (FAMILY, 14).into_font();
        let err = |e: DrawingAreaErrorKind<DB::ErrorType>| format!("{e:?}");
        let mut x = 16;
        for (name, swatch) in &self.keys {
            match *swatch {
                Swatch::Fill(c) => area
                    .draw(&Rectangle::new(
                        [(x, y - 6), (x + 16, y + 6)],
                        c.mix(0.55).filled(),
                    ))
                    .map_err(err)?,
                Swatch::Line(c) => area
                    .draw(&PathElement::new([(x, y), (x + 16, y)], c.stroke_width(2)))
                    .map_err(err)?,
                Swatch::Dashed(c) => {
                    for s in [0, 7, 14] {
                        let seg = [(x + s, y), (x + (s + 4).min(16), y)];
                        area.draw(&PathElement::new(seg, c.stroke_width(2)))
                            .map_err(err)?;
                    }
                }
                Swatch::Cross(c) => area
                    .draw(&Cross::new((x + 8, y), 5, c.stroke_width(2)))
                    .map_err(err)?,
                Swatch::Dot(c) => area
                    .draw(&Circle::new((x + 8, y), 6, c.filled()))
                    .map_err(err)?,
            }
            let text = Text::new(name.clone(), (x + 22, y - 8), font.clone());
            area.draw(&text).map_err(err)?;
            let (tw, _) = area
                .estimate_text_size(name, &TextStyle::from(font.clone()))
                .map_err(err)?;
            x += 22 + tw as i32 + 24;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_name_is_kept_once_in_first_order() {
        let mut l = Legend::default();
        l.add("camera path", Swatch::Line(BLUE));
        l.add("lights", Swatch::Dot(RED));
        l.add("camera path", Swatch::Line(GREEN));
        let names: Vec<&str> = l.keys.iter().map(|(n, _)| n.as_str()).collect();
        assert_eq!(names, ["camera path", "lights"]);
        assert_eq!(l.keys[0].1, Swatch::Line(BLUE));
    }
}
