//! Who a target or a `look_at` names: `KIND N`, N counted from 1 in file order among the
//! records of that kind (the extension's records continue the report's numbering: with
//! four report spheres, the first `sphere` record is `sphere 5`; `point` records are
//! `light N` after the report's lights), or the `name` an extension record gives.
//!
//! ```toml
//! target = "box 2 max"          # KIND N FIELD
//! target = "teapot rotate"      # NAME FIELD
//! look_at = "spot 1"            # KIND N, or NAME
//! ```

use crate::typo::did_you_mean;
use glam::DVec3;
use whitted::scene::ext::ExtItem;
use whitted::scene::{ObjectSpec, Scene};

/// A record of the scene a track or the camera can follow.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Subject {
    /// `scene.objects[i]` (a report record or an extension shape or CSG block).
    Object(usize),
    /// The report's `scene.lights[i]`.
    Light(usize),
    /// The extension's `scene.ext.lights[i]`.
    ExtLight(usize),
    /// The fog (`fog distance`).
    Fog,
    /// The `focus` record (`focus distance`).
    Focus,
}

/// The kinds a subject may name, for the nearest-kind hint.
pub const KINDS: [&str; 16] = [
    "sphere",
    "plane",
    "cylinder",
    "box",
    "cone",
    "disc",
    "torus",
    "triangle",
    "mesh",
    "csg",
    "light",
    "directional",
    "spot",
    "area",
    "fog",
    "focus",
];

/// `unknown kind …` with the nearest kind.
pub fn unknown_kind(kind: &str) -> String {
    let hint = did_you_mean(kind, KINDS.into_iter().filter(|&k| k != kind));
    format!(
        "unknown kind `{kind}`{hint}: expected {}, or a record's name",
        KINDS.join(", ")
    )
}

/// The object indices of `kind` in `scene`, in file order.
pub fn objects_of(scene: &Scene, kind: &str) -> Vec<usize> {
    (0..scene.specs.len())
        .filter(|&i| scene.specs[i].kind() == kind)
        .collect()
}

/// `KIND N` in `scene`.
pub fn numbered(kind: &str, n: &str, scene: &Scene) -> Result<Subject, String> {
    let ext_lights = |keyword: &str| -> Vec<Subject> {
        let lights = scene.ext.lights.iter().enumerate();
        lights
            .filter(|(_, l)| l.kind.keyword() == keyword)
            .map(|(i, _)| Subject::ExtLight(i))
            .collect()
    };
    let candidates: Vec<Subject> = match kind {
        "light" => (0..scene.lights.len())
            .map(Subject::Light)
            .chain(ext_lights("point"))
            .collect(),
        "directional" | "spot" | "area" => ext_lights(kind),
        "fog" | "focus" => return Err(format!("`{kind}` takes no number: write `{kind} FIELD`")),
        _ if KINDS.contains(&kind) || scene.specs.iter().any(|s| s.kind() == kind) => {
            objects_of(scene, kind)
                .into_iter()
                .map(Subject::Object)
                .collect()
        }
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

/// The record an extension `name` names, if any.
pub fn named(name: &str, scene: &Scene) -> Option<Subject> {
    let object = scene.specs.iter().position(|spec| {
        let mods = match spec.item().and_then(|item| scene.ext.objects.get(item)) {
            Some(ExtItem::Shape(o)) => &o.mods,
            Some(ExtItem::Csg(c)) => &c.mods,
            None => return false,
        };
        mods.name.as_deref() == Some(name)
    });
    if let Some(i) = object {
        return Some(Subject::Object(i));
    }
    (scene.ext.lights.iter())
        .position(|l| l.mods.name.as_deref() == Some(name))
        .map(Subject::ExtLight)
}

/// `KIND N` or a name, for `look_at`: a record that has a point to look at.
pub fn parse_subject(text: &str, scene: &Scene) -> Result<Subject, String> {
    let words: Vec<&str> = text.split_whitespace().collect();
    let subject = match words[..] {
        [kind, n] => numbered(kind, n, scene)?,
        [name] => named(name, scene).ok_or_else(|| {
            format!("no record is named `{name}`: expected `KIND N` (e.g. \"sphere 2\") or a record's name")
        })?,
        _ => {
            return Err(format!(
                "expected `KIND N` (e.g. \"sphere 2\" or \"light 1\") or a name, found {text:?}"
            ))
        }
    };
    match point(subject, scene) {
        Some(_) => Ok(subject),
        None => Err(format!(
            "{text:?} has no position to look at (a directional light is infinitely far)"
        )),
    }
}

/// The point a subject stands for: an object's anchor or a light's position; `None` for
/// a directional light, the fog and the focus.
pub fn point(subject: Subject, scene: &Scene) -> Option<DVec3> {
    match subject {
        Subject::Object(i) => scene.specs.get(i).map(ObjectSpec::anchor),
        Subject::Light(i) => scene.lights.get(i).map(|l| l.position),
        Subject::ExtLight(i) => scene.ext.lights.get(i)?.kind.position(),
        Subject::Fog | Subject::Focus => None,
    }
}
