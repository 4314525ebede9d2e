//! What a track animates: `KIND N FIELD` (SPEC §7), N counted from 1 in file order among
//! objects of that kind, resolved against the base scene, and how a value is put into a
//! scene and checked against the bounds of SPEC §1.
//!
//! ```toml
//! target = "sphere 1 center"    # sphere N center|radius
//! target = "plane 1 normal"     # plane N point|normal
//! target = "cylinder 2 radius"  # cylinder N axis|point|radius
//! target = "sphere 3 color"     # any object: color (texture 1), color1..3 (texture 2),
//!                               #   kd kr kt ior bump texture_scale
//! target = "light 1 position"   # light N position|color|intensity
//! target = "fog distance"       # no N
//! target = "camera position"    # camera position|look_at|fov (`camera`)
//! target = "box 2 max"          # the extension's records and names: `ext`, `subject`
//! ```

use crate::typo::did_you_mean;
pub use ext::{ExtField, Record};
use glam::DVec3;
pub use subject::{parse_subject, Subject};
use whitted::bump::Bump;
use whitted::fog::Fog;
use whitted::limits::MAX_INTENSITY;
use whitted::scene::ext::ExtItem;
use whitted::scene::{direction, ObjectSpec, Scene};
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
    /// The scale of a procedural texture's pattern, > 0 (`sphere 1 texture_scale`).
    TextureScale,
    /// A light's position.
    Position,
    /// A light's colour, RGB in 0..1 (`light N color`).
    LightColor,
    /// A light's intensity, 0 to `MAX_INTENSITY`.
    Intensity,
    /// The fog's distance, > 0 (`fog distance`).
    FogDistance,
    /// A field of an extension record (`box 1 max`, `spot 1 falloff`, `focus distance`).
    Ext(ExtField),
    /// The camera's eye (`camera position`).
    CameraPosition,
    /// The point the camera looks at (`camera look_at`).
    CameraLookAt,
    /// The vertical field of view in degrees, 0 < fov < 180 (`camera fov`).
    CameraFov,
}

/// A resolved target: the field and, for objects and lights, the index into
/// `Scene::objects` or `Scene::lights` (for an extension light, `Scene::ext.lights`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Target {
    /// The value animated.
    pub field: Field,
    /// The index into `Scene::objects` or `Scene::lights` (0-based); 0 for the fog.
    pub index: usize,
}

/// Object fields any kind of object has.
const MATERIAL_FIELDS: [(&str, Field); 10] = [
    ("color", Field::Color),
    ("color1", Field::Color1),
    ("color2", Field::Color2),
    ("color3", Field::Color3),
    ("kd", Field::Kd),
    ("kr", Field::Kr),
    ("kt", Field::Kt),
    ("ior", Field::Ior),
    ("bump", Field::Bump),
    ("texture_scale", Field::TextureScale),
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

/// The point a subject (resolved by `parse_subject`) stands for in `scene`.
pub fn subject_point(subject: Subject, scene: &Scene) -> DVec3 {
    subject::point(subject, scene).unwrap_or(scene.look_at)
}

/// The field named `name` among `fields`, or why not.
fn pick<T: Copy>(what: &str, name: &str, fields: &[(&'static str, T)]) -> Result<T, String> {
    if let Some(&(_, field)) = fields.iter().find(|(n, _)| *n == name) {
        return Ok(field);
    }
    let names: Vec<&str> = fields.iter().map(|(n, _)| *n).collect();
    if names.is_empty() {
        return Err(format!(
            "{what} has no field `{name}` that a track can animate"
        ));
    }
    let hint = did_you_mean(name, names.iter().copied());
    Err(format!(
        "{what} has no field `{name}`{hint}: expected one of {}",
        names.join(", ")
    ))
}

/// The field `name` of `subject` (written `what` in messages).
fn field_of(subject: Subject, what: &str, name: &str, scene: &Scene) -> Result<Target, String> {
    let ext = |record, fields: Vec<(&'static str, Kind)>, index| {
        let (name, kind) = fields
            .iter()
            .find(|(n, _)| *n == name)
            .map(|&(n, k)| (if n == "position" { "p" } else { n }, k))
            .ok_or_else(|| pick(what, name, &fields).unwrap_err())?;
        let field = Field::Ext(ExtField { record, name, kind });
        Ok::<_, String>(Target { field, index })
    };
    match subject {
        Subject::Fog => Ok(Target {
            field: pick(what, name, &fields_of("fog").unwrap_or_default())?,
            index: 0,
        }),
        Subject::Focus => ext(Record::Focus, ext::FOCUS_FIELDS.to_vec(), 0),
        Subject::Light(i) => Ok(Target {
            field: pick(what, name, &fields_of("light").unwrap_or_default())?,
            index: i,
        }),
        Subject::ExtLight(i) => {
            let l = &scene.ext.lights[i];
            ext(Record::Light(i), ext::light_fields(&l.kind, &l.mods), i)
        }
        Subject::Object(i) => match scene.specs[i] {
            ObjectSpec::Ext { item, .. } => {
                let item = item as usize;
                let record = &scene.ext.objects[item];
                let own = ext::object_fields(record);
                if own.iter().any(|(n, _)| *n == name) {
                    return ext(Record::Object(item), own, i);
                }
                let material: &[(&str, Field)] = match record {
                    ExtItem::Csg(_) => &[],
                    ExtItem::Shape(_) => &MATERIAL_FIELDS,
                };
                let mut all: Vec<(&'static str, Field)> = own
                    .iter()
                    .map(|&(n, kind)| {
                        let f = ExtField {
                            record: Record::Object(item),
                            name: n,
                            kind,
                        };
                        (n, Field::Ext(f))
                    })
                    .collect();
                all.extend(material.iter().copied());
                Ok(Target {
                    field: pick(what, name, &all)?,
                    index: i,
                })
            }
            ref spec => Ok(Target {
                field: pick(what, name, &fields_of(spec.kind()).unwrap_or_default())?,
                index: i,
            }),
        },
    }
}

impl Target {
    /// Parses `KIND N FIELD`, `NAME FIELD`, `fog distance` or `focus FIELD` against
    /// `scene`.
    pub fn parse(text: &str, scene: &Scene) -> Result<Target, String> {
        let words: Vec<&str> = text.split_whitespace().collect();
        let usage = || {
            format!(
                "expected `KIND N FIELD` (e.g. \"sphere 1 center\"), `NAME FIELD`, \"fog distance\", \"focus distance\" or \"camera position\", found {text:?}"
            )
        };
        let (subject, what, field) = match words[..] {
            ["camera", field] => return camera::target(field),
            ["fog", field] => (Subject::Fog, "fog".to_string(), field),
            ["focus", field] => {
                if scene.ext.focus.is_none() {
                    return Err("the scene has no `focus` record to animate".into());
                }
                (Subject::Focus, "focus".to_string(), field)
            }
            [kind, n, field] if kind != "fog" && kind != "focus" => {
                (subject::numbered(kind, n, scene)?, kind.to_string(), field)
            }
            [name, field] => match subject::named(name, scene) {
                Some(s) => (s, format!("`{name}`"), field),
                None if subject::KINDS.contains(&name) => return Err(usage()),
                None => return Err(subject::unknown_kind(name)),
            },
            _ => return Err(usage()),
        };
        let target = field_of(subject, &what, field, scene)?;
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
            | Field::TextureScale
            | Field::Intensity
            | Field::FogDistance => Kind::Number,
            Field::Ext(f) => f.kind,
            f if camera::is_camera(f) => camera::kind(f),
            _ => Kind::Vector,
        }
    }

    /// Whether the field changes what rays hit (shapes, or which objects are transparent
    /// to shadow rays): then each frame needs its own acceleration structure.
    pub fn moves_geometry(&self) -> bool {
        matches!(
            self.field,
            Field::Center | Field::Radius | Field::Point | Field::Normal | Field::Axis | Field::Kt
        ) || matches!(self.field, Field::Ext(f) if matches!(f.record, Record::Object(_)))
    }

    /// Whether the field is a position, so that it may follow a circle.
    pub fn is_position(&self) -> bool {
        const POINTS: [&str; 10] = [
            "center",
            "point",
            "a",
            "b",
            "p",
            "target",
            "translate",
            "p1",
            "p2",
            "p3",
        ];
        match self.field {
            Field::Ext(f) => POINTS.contains(&f.name),
            f => matches!(
                f,
                Field::Center
                    | Field::Point
                    | Field::Position
                    | Field::CameraPosition
                    | Field::CameraLookAt
            ),
        }
    }

    /// Refuses fields the object's record does not carry: `color` on a procedural texture,
    /// `color1..3` on a single colour, `color3` where the texture has no third colour,
    /// `bump` without bump mapping, `fog distance` without fog.
    fn applicable(&self, scene: &Scene) -> Result<(), String> {
        let texture = || scene.objects[self.index].texture.pattern();
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
            Field::TextureScale if !texture().is_procedural() => {
                "its texture has no pattern to scale (only a procedural texture, type 2, has)"
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
            f if camera::is_camera(f) => camera::check(f, v),
            Field::Center | Field::Point | Field::Position if !v.is_finite() => {
                Err("coordinates must be finite".into())
            }
            Field::Ext(_) if !v.is_finite() => Err("values must be finite".into()),
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
            Field::TextureScale if !(x.is_finite() && x > 0.0) => {
                Err("a texture's scale must be greater than 0".into())
            }
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

pub(crate) mod camera;
pub(crate) mod ext;
mod subject;
mod value;

#[cfg(test)]
mod tests;

#[cfg(test)]
mod ext_tests;
