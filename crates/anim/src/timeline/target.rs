//! What a track animates: `KIND N FIELD` (SPEC §7), N counted from 1 in file order among
//! objects of that kind, resolved against the base scene, and how a value is put into a
//! scene and checked against the bounds of SPEC §1.
//!
//! ```toml
//! target = "sphere 1 center"    # sphere N center|radius
//! target = "plane 1 normal"     # plane N point|normal
//! target = "cylinder 2 radius"  # cylinder N axis|point|radius
//! target = "sphere 3 color"     # any object: color (texture 1), color1..3 (texture 2),
//!                               #   kd kr kt ior bump
//! target = "light 1 position"   # light N position|color|intensity
//! target = "fog distance"       # no N
//! ```

use crate::typo::did_you_mean;
use glam::DVec3;
use whitted::bump::Bump;
use whitted::fog::Fog;
use whitted::limits::MAX_INTENSITY;
use whitted::scene::{direction, Scene};
use whitted::texture::Texture;

/// A number or an `[x, y, z]`; numbers travel as `(x, 0, 0)` through interpolation.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// One number (radius, coefficient, intensity, fog distance).
    Number,
    /// Three numbers (position, direction, RGB colour).
    Vector,
}

/// One animatable value of a scene.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Field {
    /// A sphere's centre (`sphere N center`).
    Center,
    /// A sphere's or cylinder's radius, > 0.
    Radius,
    /// A plane's point or a point on a cylinder's axis.
    Point,
    /// A plane's normal, non-zero.
    Normal,
    /// A cylinder's axis direction, non-zero.
    Axis,
    /// The colour of a one-colour texture (type 1), RGB in 0..1.
    Color,
    /// The first colour of a procedural texture (type 2), RGB in 0..1.
    Color1,
    /// The second colour of a procedural texture, RGB in 0..1.
    Color2,
    /// The third colour of a Perlin texture, RGB in 0..1.
    Color3,
    /// The diffuse coefficient Kd, 0..1.
    Kd,
    /// The reflection coefficient Kr, 0..1.
    Kr,
    /// The transmission coefficient Kt, 0..1.
    Kt,
    /// The object's refraction index, > 0.
    Ior,
    /// The bump amplitude ε of an object with bump mapping.
    Bump,
    /// A light's position.
    Position,
    /// A light's colour, RGB in 0..1 (`light N color`).
    LightColor,
    /// A light's intensity, 0 to `MAX_INTENSITY`.
    Intensity,
    /// The fog's distance, > 0 (`fog distance`).
    FogDistance,
}

/// A resolved target: the field and, for objects and lights, the index into
/// `Scene::objects` or `Scene::lights`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Target {
    /// The value animated.
    pub field: Field,
    /// The index into `Scene::objects` or `Scene::lights` (0-based); 0 for the fog.
    pub index: usize,
}

/// Object fields any kind of object has.
const MATERIAL_FIELDS: [(&str, Field); 9] = [
    ("color", Field::Color),
    ("color1", Field::Color1),
    ("color2", Field::Color2),
    ("color3", Field::Color3),
    ("kd", Field::Kd),
    ("kr", Field::Kr),
    ("kt", Field::Kt),
    ("ior", Field::Ior),
    ("bump", Field::Bump),
];

fn fields_of(kind: &str) -> Option<Vec<(&'static str, Field)>> {
    let own: &[(&str, Field)] = match kind {
        "sphere" => &[("center", Field::Center), ("radius", Field::Radius)],
        "plane" => &[("point", Field::Point), ("normal", Field::Normal)],
        "cylinder" => &[
            ("axis", Field::Axis),
            ("point", Field::Point),
            ("radius", Field::Radius),
        ],
        "light" => {
            return Some(vec![
                ("position", Field::Position),
                ("color", Field::LightColor),
                ("intensity", Field::Intensity),
            ])
        }
        "fog" => return Some(vec![("distance", Field::FogDistance)]),
        _ => return None,
    };
    Some(own.iter().chain(MATERIAL_FIELDS.iter()).copied().collect())
}

/// The object indices of `kind` in `scene`, in file order.
pub fn objects_of(scene: &Scene, kind: &str) -> Vec<usize> {
    (0..scene.specs.len())
        .filter(|&i| scene.specs[i].kind() == kind)
        .collect()
}

/// Resolves `KIND N` (no field) to a point: the object's anchor or the light's position.
/// Used by `look_at = "sphere 2"`.
pub fn parse_subject(text: &str, scene: &Scene) -> Result<(String, usize), String> {
    let words: Vec<&str> = text.split_whitespace().collect();
    let [kind, n] = words[..] else {
        return Err(format!(
            "expected `KIND N` (e.g. \"sphere 2\" or \"light 1\"), found {text:?}"
        ));
    };
    let index = index_of(kind, n, scene)?;
    Ok((kind.to_string(), index))
}

/// The point `KIND N` stands for in `scene` (resolved by `parse_subject`).
pub fn subject_point(kind: &str, index: usize, scene: &Scene) -> DVec3 {
    if kind == "light" {
        scene.lights[index].position
    } else {
        scene.specs[index].anchor()
    }
}

fn index_of(kind: &str, n: &str, scene: &Scene) -> Result<usize, String> {
    let candidates = match kind {
        "light" => (0..scene.lights.len()).collect(),
        "sphere" | "plane" | "cylinder" => objects_of(scene, kind),
        _ => return Err(unknown_kind(kind)),
    };
    let count = candidates.len();
    match n.parse::<usize>() {
        Ok(k) if (1..=count).contains(&k) => Ok(candidates[k - 1]),
        Ok(k) => Err(format!(
            "{kind} {k} does not exist: the scene has {count} {kind}(s), numbered from 1"
        )),
        Err(_) => Err(format!("expected a {kind} number from 1, found `{n}`")),
    }
}

/// The kinds a target may name (a subject, `look_at = "KIND N"`, all but the fog).
const KINDS: [&str; 5] = ["sphere", "plane", "cylinder", "light", "fog"];

fn unknown_kind(kind: &str) -> String {
    let hint = did_you_mean(kind, KINDS.into_iter().filter(|&k| k != kind));
    format!("unknown kind `{kind}`{hint}: expected sphere, plane, cylinder, light or fog")
}

impl Target {
    /// Parses `KIND N FIELD` (or `fog distance`) against `scene`.
    pub fn parse(text: &str, scene: &Scene) -> Result<Target, String> {
        let words: Vec<&str> = text.split_whitespace().collect();
        let (kind, n, field) = match words[..] {
            ["fog", field] => ("fog", None, field),
            [kind, n, field] if kind != "fog" => (kind, Some(n), field),
            _ => {
                return Err(format!(
                    "expected `KIND N FIELD` (e.g. \"sphere 1 center\") or \"fog distance\", found {text:?}"
                ))
            }
        };
        let Some(fields) = fields_of(kind) else {
            return Err(unknown_kind(kind));
        };
        let Some(&(_, field)) = fields.iter().find(|(name, _)| *name == field) else {
            let names: Vec<&str> = fields.iter().map(|(name, _)| *name).collect();
            let hint = did_you_mean(field, names.iter().copied());
            return Err(format!(
                "{kind} has no field `{field}`{hint}: expected one of {}",
                names.join(", ")
            ));
        };
        let index = match n {
            Some(n) => index_of(kind, n, scene)?,
            None => 0,
        };
        let target = Target { field, index };
        target.applicable(scene)?;
        Ok(target)
    }

    /// Whether the value is a number or a vector.
    pub fn kind(&self) -> Kind {
        match self.field {
            Field::Radius
            | Field::Kd
            | Field::Kr
            | Field::Kt
            | Field::Ior
            | Field::Bump
            | Field::Intensity
            | Field::FogDistance => Kind::Number,
            _ => Kind::Vector,
        }
    }

    /// Whether the field changes what rays hit (shapes, or which objects are transparent
    /// to shadow rays): then each frame needs its own acceleration structure.
    pub fn moves_geometry(&self) -> bool {
        matches!(
            self.field,
            Field::Center | Field::Radius | Field::Point | Field::Normal | Field::Axis | Field::Kt
        )
    }

    /// Whether the field is a position, so that it may follow a circle.
    pub fn is_position(&self) -> bool {
        matches!(self.field, Field::Center | Field::Point | Field::Position)
    }

    /// Refuses fields the object's record does not carry: `color` on a procedural texture,
    /// `color1..3` on a single colour, `color3` where the texture has no third colour,
    /// `bump` without bump mapping, `fog distance` without fog.
    fn applicable(&self, scene: &Scene) -> Result<(), String> {
        let texture = || &scene.objects[self.index].texture;
        let why = match self.field {
            Field::Color | Field::Color1 | Field::Color2 | Field::Color3
                if matches!(texture(), Texture::Image(_)) =>
            {
                "its texture is an image (3): it has no colour to animate"
            }
            Field::Color if !matches!(texture(), Texture::Uniform(_)) => {
                "its texture is procedural (2): animate color1, color2 or color3"
            }
            Field::Color1 | Field::Color2 if matches!(texture(), Texture::Uniform(_)) => {
                "its texture is one colour (1): animate color"
            }
            Field::Color3 if !matches!(texture(), Texture::Perlin(..)) => {
                "only a Perlin texture (type 2) uses its third colour"
            }
            Field::Bump if scene.objects[self.index].material.bump == Bump::None => {
                "it has no bump mapping (BumpType 0)"
            }
            Field::FogDistance if scene.fog == Fog::None => "the scene has no fog (FogType 0)",
            _ => return Ok(()),
        };
        Err(format!("this target cannot be animated: {why}"))
    }

    /// The bound of SPEC §1 that `v` breaks, if any.
    pub fn check(&self, v: DVec3) -> Result<(), String> {
        let x = v.x;
        let unit = |what: &str, ok: bool| {
            if ok {
                Ok(())
            } else {
                Err(format!("{what} must be from 0 to 1"))
            }
        };
        match self.field {
            Field::Center | Field::Point | Field::Position if !v.is_finite() => {
                Err("coordinates must be finite".into())
            }
            Field::Radius if !(x.is_finite() && x > 0.0) => {
                Err("a radius must be greater than 0".into())
            }
            Field::Normal | Field::Axis if direction(v).is_none() => {
                Err("a normal or an axis must not have zero length".into())
            }
            Field::Color | Field::Color1 | Field::Color2 | Field::Color3 | Field::LightColor => {
                let ok = v.to_array().iter().all(|c| (0.0..=1.0).contains(c));
                unit("each colour channel", ok)
            }
            Field::Kd | Field::Kr | Field::Kt => unit("Kd, Kr and Kt", (0.0..=1.0).contains(&x)),
            Field::Ior if !(x.is_finite() && x > 0.0) => {
                Err("a refraction index must be greater than 0".into())
            }
            Field::Bump if !x.is_finite() => Err("the bump ε must be finite".into()),
            Field::Intensity if !(0.0..=MAX_INTENSITY).contains(&x) => Err(format!(
                "a light's intensity must be from 0 to {MAX_INTENSITY}"
            )),
            Field::FogDistance if !(x.is_finite() && x > 0.0) => {
                Err("the fog distance must be greater than 0".into())
            }
            _ => Ok(()),
        }
    }
}

mod value;

#[cfg(test)]
mod tests;
