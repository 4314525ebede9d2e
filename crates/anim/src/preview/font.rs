//! The one typeface of the preview's pictures, embedded so that nothing needs to be
//! installed: Hack Regular (MIT/Bitstream Vera licence), as the `epaint_default_fonts`
//! crate ships it, registered with plotters' `ab_glyph` text back end under the family
//! name plotters uses by default, `sans-serif`.

use std::sync::OnceLock;

/// The family every label of the preview is drawn in.
pub const FAMILY: &str = "sans-serif";

/// The embedded font could not be read (it is part of the binary, so this means a broken
/// build, but it is an error, not a panic).
#[derive(Debug, Clone, thiserror::Error)]
#[error("the embedded font cannot be read by the text renderer")]
pub struct FontError;

/// Registers the font once per process; later calls return the first outcome.
pub fn ensure() -> Result<(), FontError> {
    static DONE: OnceLock<Result<(), FontError>> = OnceLock::new();
    DONE.get_or_init(|| {
        plotters::style::register_font(
            FAMILY,
            plotters::style::FontStyle::Normal,
            epaint_default_fonts::HACK_REGULAR,
        )
        .map_err(|_| FontError)
    })
    .clone()
}

#[cfg(test)]
mod tests {
    use super::*;
    use plotters::prelude::*;

    #[test]
    fn text_draws_ink_with_the_embedded_font() {
        ensure().unwrap();
        let (w, h) = (40u32, 20u32);
        let mut buf = vec![0u8; (w * h * 3) as usize];
        {
            let area = BitMapBackend::with_buffer(&mut buf, (w, h)).into_drawing_area();
            let style = (FAMILY, 16).into_font().color(&WHITE);
            area.draw(&Text::new("42", (2, 2), style)).unwrap();
            area.present().unwrap();
        }
        let lit = buf.iter().filter(|&&b| b > 128).count();
        assert!(lit > 20, "only {lit} bright bytes: no text was drawn");
    }
}
