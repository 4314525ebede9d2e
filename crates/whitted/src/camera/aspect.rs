//! Whether a picture's pixels are square. The report's view plane is 0.5 × 0.35 (10:7);
//! a scene file whose resolution has another shape stretches every pixel, and a sphere
//! draws as an oval. The report's own 640 × 480 is 7 % off, which is the report's look
//! and stays silent; past `TOLERANCE` `NonSquare` is the warning both commands print,
//! naming the fixes: the view width that would make the pixels square, and the field of
//! view (`--fov`, a manifest's `[camera] fov`) that gives square pixels at the report's
//! height.
//!
//! ```text
//! NonSquare::check(&lens, (1920, 1080), (1920, 1080)) → Some(aspect 0.804)
//! NonSquare::check(&lens, (640, 480), (640, 480))     → None (1.071, the report's)
//! ```

use super::{Lens, VIEW_DISTANCE, VIEW_HEIGHT};

/// How far a pixel's width over its height may be from 1 before the warning: 10 %.
pub const TOLERANCE: f64 = 0.10;

/// A picture whose pixels are not square.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NonSquare {
    /// A pixel's width over its height.
    pub aspect: f64,
    /// The picture's size in pixels.
    pub size: (u32, u32),
    /// The view plane's height.
    pub plane_height: f64,
}

impl Lens {
    /// A pixel's width over its height in an image of `size` of a scene whose own size is
    /// `native` (1 for square pixels).
    pub fn pixel_aspect(&self, native: (u32, u32), size: (u32, u32)) -> f64 {
        let (pw, ph) = self.plane(native, size);
        let (w, h) = (f64::from(size.0.max(1)), f64::from(size.1.max(1)));
        (pw / w) / (ph / h)
    }
}

impl NonSquare {
    /// The warning for an image of `size` of a scene whose own size is `native`, or
    /// `None` when its pixels are square within `TOLERANCE`.
    pub fn check(lens: &Lens, native: (u32, u32), size: (u32, u32)) -> Option<NonSquare> {
        let aspect = lens.pixel_aspect(native, size);
        let plane_height = lens.plane(native, size).1;
        ((aspect - 1.0).abs() > TOLERANCE).then_some(NonSquare {
            aspect,
            size,
            plane_height,
        })
    }

    /// The view plane's width that would make the pixels square at its height.
    pub fn square_width(&self) -> f64 {
        self.plane_height * f64::from(self.size.0) / f64::from(self.size.1.max(1))
    }

    /// The vertical field of view, in degrees, of the view plane's height: square pixels
    /// at any size, with the same vertical framing.
    pub fn fov(&self) -> f64 {
        2.0 * (self.plane_height / 2.0 / VIEW_DISTANCE)
            .atan()
            .to_degrees()
    }
}

impl std::fmt::Display for NonSquare {
    fn fmt(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        let (w, h) = self.size;
        let fov = self.fov();
        write!(
            f,
            "the pixels are not square: the view plane ({VIEW_HEIGHT} high) at {w}×{h} makes \
             each pixel {:.3} times as wide as it is high, so spheres draw as ovals; square \
             pixels need a view {:.4} wide, which `--fov {fov:.2}` (raytrace) or \
             `[camera] fov = {fov:.2}` (a manifest) gives at the same height",
            self.aspect,
            self.square_width()
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sixteen_by_nine_on_the_report_plane_is_refused_by_hand() {
        let lens = Lens::default();
        let w = NonSquare::check(&lens, (1920, 1080), (1920, 1080)).unwrap();
        // (0.5/1920) / (0.35/1080) = 540/672.
        assert!((w.aspect - 540.0 / 672.0).abs() < 1e-12, "{}", w.aspect);
        // 0.35 · 1920/1080 = 0.6222…
        assert!((w.square_width() - 0.35 * 16.0 / 9.0).abs() < 1e-12);
        // 2·atan(0.175) = 2 × 9.9262° = 19.8525°
        assert!((w.fov() - 19.852_5).abs() < 1e-4, "{}", w.fov());
        let text = w.to_string();
        assert!(text.contains("0.804") && text.contains("0.6222"), "{text}");
        assert!(
            text.contains("--fov 19.85") && text.contains("fov = 19.85"),
            "{text}"
        );
    }

    #[test]
    fn the_reports_own_shape_and_square_framings_are_silent() {
        let lens = Lens::default();
        // 640×480: 240/224 = 1.0714, the report's own look.
        assert!((lens.pixel_aspect((640, 480), (640, 480)) - 240.0 / 224.0).abs() < 1e-12);
        assert_eq!(NonSquare::check(&lens, (640, 480), (640, 480)), None);
        // Another size than the file's: the plane follows the picture, square pixels.
        assert_eq!(NonSquare::check(&lens, (640, 480), (1920, 1080)), None);
        // A field of view: square at any size.
        let fov = Lens {
            fov: Some(30.0),
            ..Lens::default()
        };
        assert_eq!(NonSquare::check(&fov, (1920, 1080), (1920, 1080)), None);
        // 10:7, the plane's own shape: exactly square.
        assert!((lens.pixel_aspect((700, 490), (700, 490)) - 1.0).abs() < 1e-12);
    }
}
