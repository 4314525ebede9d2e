//! TEXTURE, wherever one is read (the report's records and the extension's):
//!
//! ```text
//! 1 R G B                      # one colour
//! 2 Type C1(3) C2(3) C3(3)     # Type 1 checker, 2 Perlin, 3 wood, 4 marble
//! 3 "file" Map Interp Size     # an image (SPEC §16); Map: planar | spherical |
//!                              # cylindrical; Interp: nearest | bilinear; Size > 0
//! ```
//!
//! The file's path is relative to the scene file's folder; each file is read once per
//! scene, its pixels shared by every record that names it. A file that cannot be read or
//! decoded is a located error at its name, which it quotes.

use super::ext::keywords;
use super::{Parser, Result};
use crate::input::quote;
use crate::texture::{ImageTexture, Interp, MapKind, Pixels, Texture};
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// The scene file's folder and the images read so far.
#[derive(Default)]
pub(super) struct Images {
    base: PathBuf,
    loaded: Vec<(PathBuf, Arc<Pixels>)>,
}

impl Images {
    /// For the scene file `file` (its folder is where image paths start).
    pub(super) fn new(file: &str) -> Images {
        let base = Path::new(file).parent().map(PathBuf::from);
        Images {
            base: base.unwrap_or_default(),
            loaded: Vec::new(),
        }
    }
}

impl Parser<'_> {
    pub(super) fn texture(&mut self) -> Result<Texture> {
        self.place.part = Some("texture");
        let what = "1 (one colour), 2 (procedural) or 3 (image)";
        let (kind, _) = self.integer("kind", 1, 3, what)?;
        let tex = if kind == 1 {
            Texture::Uniform(self.color(["R", "G", "B"])?)
        } else if kind == 3 {
            self.image_texture()?
        } else {
            let what = "1 (checker), 2 (Perlin), 3 (wood) or 4 (marble)";
            let (ty, _) = self.integer("Type", 1, 4, what)?;
            let c1 = self.color(["C1.r", "C1.g", "C1.b"])?;
            let c2 = self.color(["C2.r", "C2.g", "C2.b"])?;
            let c3 = self.color(["C3.r", "C3.g", "C3.b"])?;
            match ty {
                1 => Texture::Checker(c1, c2),
                2 => Texture::Perlin(c1, c2, c3),
                3 => Texture::Wood(c1, c2),
                _ => Texture::Marble(c1, c2),
            }
        };
        self.place.part = None;
        Ok(tex)
    }

    /// `"file" Map Interp Size` after the kind 3.
    fn image_texture(&mut self) -> Result<Texture> {
        let tok = self.token("file", "a quoted file name")?;
        let written = keywords::unquote(tok.text).map_err(|why| {
            let msg = format!("{why}, found '{}'", quote(tok.text));
            self.error(&tok, msg, "file")
        })?;
        if written.is_empty() {
            return Err(self.error(&tok, "the image's file name is empty".into(), "file"));
        }
        let path = self.images.base.join(&written);
        let pixels = match self.images.loaded.iter().find(|(p, _)| *p == path) {
            Some((_, pixels)) => Arc::clone(pixels),
            None => {
                let used = self.images.loaded.iter().map(|(_, p)| p.count()).sum();
                let pixels = crate::texture::load(&path, used).map_err(|why| {
                    let msg = format!(
                        "cannot read the image '{}': {why}",
                        quote(&path.display().to_string())
                    );
                    self.error(&tok, msg, "file")
                })?;
                let pixels = Arc::new(pixels);
                self.images.loaded.push((path, Arc::clone(&pixels)));
                pixels
            }
        };
        let at = self.lexer.clone().next();
        let map = self.word("Map", &MapKind::NAMES, MapKind::from_name)?;
        if let (MapKind::Uv, Some(at)) = (map, at) {
            if self.place.record != "mesh" {
                let msg = format!(
                    "the uv map takes a mesh's own texture coordinates: a {} has none (use planar, spherical or cylindrical)",
                    self.place.record
                );
                return Err(self.error(&at, msg, "Map"));
            }
        }
        let interp = self.word("Interp", &Interp::NAMES, Interp::from_name)?;
        let size = self.positive("Size")?;
        Ok(Texture::Image(Arc::new(ImageTexture {
            file: written,
            map,
            interp,
            size,
            pixels,
        })))
    }

    /// One of the keywords `names`, as `from` reads it; an unknown one is refused with
    /// the nearest suggested.
    fn word<T>(
        &mut self,
        field: &str,
        names: &[&'static str],
        from: fn(&str) -> Option<T>,
    ) -> Result<T> {
        let list = names.join(", ");
        let tok = self.token(field, &format!("one of {list}"))?;
        if let Some(v) = from(tok.text) {
            return Ok(v);
        }
        let mut msg = format!("unknown {field} '{}'", quote(tok.text));
        match keywords::nearest(tok.text, names.iter().copied()) {
            Some(k) => msg += &format!(" (did you mean '{k}'?)"),
            None => msg += &format!(" (expected one of {list})"),
        }
        Err(self.error(&tok, msg, field))
    }
}
