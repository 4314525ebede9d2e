//! `[render] antialias`: adaptive anti-aliasing instead of the `samples` grid (SPEC §15).
//!
//! ```toml
//! [render]
//! antialias = { mode = "adaptive", threshold = 0.4, depth = 2 }  # mode required; threshold
//!                                                                 # 0..=3, depth 0..=6
//! ```
//!
//! `samples` above 1 beside it is refused: a frame is anti-aliased one way. EXR frames are
//! refused too: the layered render (beauty and passes) samples the grid only.

use super::raw::RawAntialias;
use super::{ManifestError, Source};
use toml::Spanned;
use whitted::output::ImageFormat;
use whitted::render::adaptive::{Adaptive, AntialiasError};

impl Source<'_> {
    /// The adaptive settings of `antialias`, each value checked at its own place.
    pub(super) fn antialias(
        &self,
        raw: &Spanned<RawAntialias>,
        samples: &Option<Spanned<i64>>,
        format: ImageFormat,
    ) -> Result<Adaptive, ManifestError> {
        let a = raw.get_ref();
        if format.is_layered() {
            let message = "`antialias` draws 8-bit frames only: EXR frames (and their passes) \
                           take `samples = n`";
            return Err(self.error(raw.span(), message));
        }
        if a.mode.get_ref() != "adaptive" {
            let message = format!(
                "unknown antialias mode `{}`, expected `adaptive` (the grid is `samples = n`)",
                a.mode.get_ref()
            );
            return Err(self.error(a.mode.span(), message));
        }
        if let Some(s) = samples.as_ref().filter(|s| *s.get_ref() > 1) {
            let message =
                "`samples` above 1 and `antialias` cannot both be set: choose the grid or adaptive";
            return Err(self.error(s.span(), message));
        }
        let threshold = a.threshold.as_ref().map(|t| *t.get_ref());
        let depth = a.depth.as_ref().map(|d| *d.get_ref());
        Adaptive::with(threshold, depth).map_err(|e| {
            let span = match e {
                AntialiasError::Depth(_) => a.depth.as_ref().map(Spanned::span),
                _ => a.threshold.as_ref().map(Spanned::span),
            };
            self.error(span.unwrap_or_else(|| raw.span()), e.to_string())
        })
    }
}

#[cfg(test)]
mod tests {
    use crate::manifest::Manifest;
    use whitted::render::adaptive::{Adaptive, Measure};

    fn load(render: &str) -> Result<Manifest, String> {
        let dir = tempfile::tempdir().unwrap();
        std::fs::write(dir.path().join("s.txt"), "").unwrap();
        let path = dir.path().join("m.toml");
        let text = format!("scene = \"s.txt\"\nframes = 2\n[render]\n{render}\n");
        std::fs::write(&path, text).unwrap();
        Manifest::load(&path).map_err(|e| e.to_string())
    }

    #[test]
    fn adaptive_settings_are_read_with_defaults() {
        let m = load("antialias = { mode = \"adaptive\", threshold = 0.25, depth = 2 }").unwrap();
        assert_eq!(
            m.render.antialias,
            Some(Adaptive {
                threshold: 0.25,
                depth: 2,
                measure: Measure::Edge
            })
        );
        let m = load("antialias = { mode = \"adaptive\" }").unwrap();
        assert_eq!(m.render.antialias, Some(Adaptive::DEFAULT));
        assert_eq!(load("samples = 1").unwrap().render.antialias, None);
    }

    #[test]
    fn bad_settings_are_located() {
        let bad = |r: &str| load(r).unwrap_err();
        let e = bad("antialias = { mode = \"grid\" }");
        assert!(
            e.contains("4:22") && e.contains("unknown antialias mode `grid`"),
            "{e}"
        );
        let e = bad("antialias = { mode = \"adaptive\", threshold = 4.0 }");
        assert!(e.contains("4:46") && e.contains("threshold must be"), "{e}");
        let e = bad("antialias = { mode = \"adaptive\", depth = 9 }");
        assert!(e.contains("4:42") && e.contains("depth must be"), "{e}");
        let e = bad("samples = 2\nantialias = { mode = \"adaptive\" }");
        let dir = tempfile::tempdir().unwrap();
        std::fs::write(dir.path().join("s.txt"), "").unwrap();
        let path = dir.path().join("m.toml");
        let text = "scene = \"s.txt\"\nframes = 2\n[output]\nformat = \"exr\"\n\
                    [render]\nantialias = { mode = \"adaptive\" }\n";
        std::fs::write(&path, text).unwrap();
        let exr = Manifest::load(&path).unwrap_err().to_string();
        assert!(
            exr.contains("m.toml:6:13") && exr.contains("8-bit frames only"),
            "{exr}"
        );
        assert!(
            e.contains("4:11") && e.contains("cannot both be set"),
            "{e}"
        );
        let e = bad("antialias = { mode = \"adaptive\", treshold = 0.1 }");
        assert!(e.contains("did you mean `threshold`"), "{e}");
    }
}
