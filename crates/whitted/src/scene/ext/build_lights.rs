//! The extension's light records built for shading (SPEC §16, and glTF's lights): each
//! `ExtLight` becomes one `lights::SceneLight`, in file order, its kind's built form
//! (`lights::Kind`: a spot's axis and cosines, a directional light's unit direction, an
//! area light's grid) with its fade. The records are already checked
//! (`scene::ext::check::light`): the reader and the tracks refuse what §16's bounds
//! refuse. The tracer calls this for every frame's scene, so tracks on the records'
//! fields just work.

use crate::lights::{Area, Directional, Fade, Kind, PointLight, Punctual, SceneLight, Spot};
use crate::scene::ext::{ExtLight, Extension, LightKind};
use glam::DVec3;

/// The lights of `ext.lights`, built, in file order.
pub fn lights(ext: &Extension) -> Vec<SceneLight> {
    ext.lights.iter().map(ExtLight::build).collect()
}

impl ExtLight {
    /// The light the tracer shades with.
    pub fn build(&self) -> SceneLight {
        let (c, i) = (self.color, self.intensity);
        let kind = match self.kind {
            LightKind::Point { position } => Kind::Point(PointLight {
                position,
                color: c,
                intensity: i,
            }),
            LightKind::Directional { direction } => {
                Kind::Directional(Directional::new(direction, c, i))
            }
            LightKind::Spot {
                position,
                target,
                radius,
                falloff,
                tightness,
            } => Kind::Spot(Spot::new(
                position, target, radius, falloff, tightness, c, i,
            )),
            LightKind::Area {
                position,
                a1,
                a2,
                n1,
                n2,
            } => Kind::Area(Area::new(position, a1, a2, n1, n2, c, i)),
            LightKind::Punctual(shape, range) => Kind::Punctual(Punctual {
                shape,
                color: c,
                intensity: i,
                range,
            }),
        };
        SceneLight {
            kind,
            fade: self
                .mods
                .fade
                .map(|(distance, power)| Fade { distance, power }),
        }
    }
}

impl LightKind {
    /// Where the light is (what a camera told to look at it looks at); `None` for a
    /// directional light, which is infinitely far.
    pub fn position(&self) -> Option<DVec3> {
        use crate::lights::punctual::Shape;
        match *self {
            LightKind::Point { position }
            | LightKind::Spot { position, .. }
            | LightKind::Area { position, .. }
            | LightKind::Punctual(Shape::Point { position } | Shape::Spot { position, .. }, _) => {
                Some(position)
            }
            LightKind::Directional { .. } | LightKind::Punctual(Shape::Directional { .. }, _) => {
                None
            }
        }
    }

    /// The direction a directional light travels in, as its record holds it; `None` for
    /// the lights that have a position.
    pub fn direction(&self) -> Option<DVec3> {
        use crate::lights::punctual::Shape;
        match *self {
            LightKind::Directional { direction }
            | LightKind::Punctual(Shape::Directional { direction }, _) => Some(direction),
            _ => None,
        }
    }
}
