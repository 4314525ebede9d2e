//! An animation shown on a live display while it renders (`animate --display tev`):
//! every finished frame, whatever its format (an EXR frame as its picture), is sent to
//! tev as image `PROGRAM: MANIFEST`, replacing the last one, as the floats an EXR frame
//! holds: the display values decoded to linear light, or as they are for an EXR manifest
//! with `colour = "linear"` (`whitted::display::packet`).
//!
//! ```text
//! Animation::new(&project)?.displayed(&Display::Tev("127.0.0.1:14158".into()), "animate")
//! ```

use super::{Animation, FrameObserver};
use std::sync::Arc;
use whitted::base::Transfer;
use whitted::display::{Display, Tev};
use whitted::output::ImageFormat;

impl<'p> Animation<'p> {
    /// This animation, showing each frame it draws on `display` (a missing or vanished
    /// viewer: one warning on standard error, `PROGRAM: warning: …`).
    pub fn displayed(self, display: &Display, program: &'static str) -> Animation<'p> {
        let observer = match display {
            Display::Tev(addr) => tev_observer(addr, &self, program),
        };
        self.observed(observer)
    }
}

/// Sends every finished frame to tev, replaced frame after frame (`Tev::send` does
/// nothing once the viewer is gone).
fn tev_observer(addr: &str, anim: &Animation, program: &'static str) -> FrameObserver {
    let colour = match anim.format() {
        ImageFormat::Exr(options) => options.colour,
        _ => Transfer::Srgb,
    };
    let tev = Tev::connect_stderr(addr, program).with_colour(colour);
    let name = format!("{program}: {}", anim.manifest.path.display());
    tev.create(&name, anim.width, anim.height);
    Arc::new(move |_, frame| tev.rows(&name, frame.width, 0, &frame.pixels))
}
