//! Every table and key a manifest may hold, checked before any value is read: a walk of
//! the parsed TOML document that collects, in file order, each key or table the schema
//! does not know, located at its name, with the nearest known name suggested ("did you
//! mean `camera`?") and the names that place takes listed. `[camera]`'s keys depend on
//! its `path` (circle, spline, or none); a key of another kind of path says which.
//!
//! ```toml
//! [camra]            # unknown table `[camra]` (did you mean `[camera]`?); the top level takes ...
//! path = "circle"
//! [output]
//! fromat = "png"     # output: unknown key `fromat` (did you mean `format`?); [output] takes ...
//! ```
//!
//! Values of the wrong type (`camera = 5`) are left to serde, which says what it expected.

use crate::typo::nearest;
use std::ops::Range;
use toml::de::{DeTable, DeValue};
use toml::Spanned;

/// What a name holds: a value, a table of known keys, or an array of such tables (a
/// `[[track]]` array, or an inline array of `{ frame = .., .. }` keys).
#[derive(Clone, Copy)]
enum Shape {
    Value,
    Table(Place),
    Tables(Place),
    /// `[camera]`, whose keys depend on its `path`.
    Camera,
}

/// A table of the schema: how messages name it, and its keys, in groups so that a group
/// two tables share (a circle's keys: the camera's and a track's) is written once.
#[derive(Clone, Copy)]
struct Place {
    name: &'static str,
    groups: &'static [Keys],
}

/// A group of keys, in the order messages list them.
type Keys = &'static [(&'static str, Shape)];

impl Place {
    /// Every key of the table, group after group.
    fn keys(self) -> impl Iterator<Item = (&'static str, Shape)> + Clone {
        self.groups.iter().flat_map(|g| g.iter().copied())
    }
}

use Shape::{Camera, Table, Tables, Value};

const TOP: Place = Place {
    name: "the top level",
    groups: &[&[
        ("scene", Value),
        ("frames", Value),
        ("fps", Value),
        ("loop", Value),
        ("camera", Camera),
        ("animation", Table(ANIMATION)),
        ("output", Table(OUTPUT)),
        ("render", Table(RENDER)),
        ("check", Table(CHECK)),
        ("track", Tables(TRACK)),
    ]],
};

const PATH: Keys = &[("path", Value)];
/// A glTF scene's camera, by name.
const NAME: Keys = &[("name", Value)];
/// `[animation]`: which of a glTF file's animations play.
const ANIMATION: Place = Place {
    name: "[animation]",
    groups: &[NAME],
};
const LOOK_AT: Keys = &[("look_at", Value)];
/// Every camera's framing: a vertical field of view and a roll.
const LENS: Keys = &[("fov", Value), ("roll", Value)];
/// A circle: the camera's orbit (`path = "circle"`) and a track that follows one.
const CIRCLE_KEYS: Keys = &[
    ("center", Value),
    ("radius", Value),
    ("height", Value),
    ("start_angle", Value),
    ("turns", Value),
];
/// A camera spline's options, then its keys.
const SPLINE_OPTIONS: Keys = &[("closed", Value), ("constant_speed", Value)];
const SPLINE_KEYS: Keys = &[("keys", Tables(SPLINE_KEY))];

const STILL: Place = Place {
    name: "[camera] without a path",
    groups: &[PATH, NAME, LOOK_AT, LENS],
};

const CIRCLE: Place = Place {
    name: "[camera] with path = \"circle\"",
    groups: &[PATH, NAME, CIRCLE_KEYS, LOOK_AT, LENS],
};

const SPLINE: Place = Place {
    name: "[camera] with path = \"spline\"",
    groups: &[PATH, NAME, SPLINE_OPTIONS, LOOK_AT, LENS, SPLINE_KEYS],
};

/// An unknown path: every key of some path is accepted (the path itself is refused later).
const ANY_CAMERA: Place = Place {
    name: "[camera]",
    groups: &[
        PATH,
        NAME,
        CIRCLE_KEYS,
        SPLINE_OPTIONS,
        LOOK_AT,
        LENS,
        SPLINE_KEYS,
    ],
};

const SPLINE_KEY: Place = Place {
    name: "a spline key",
    groups: &[
        &[
            ("frame", Value),
            ("time", Value),
            ("position", Value),
            ("ease", Value),
        ],
        LOOK_AT,
    ],
};

const TRACK: Place = Place {
    name: "[[track]]",
    groups: &[
        &[
            ("target", Value),
            ("interpolation", Value),
            ("ease", Value),
            ("keys", Tables(TRACK_KEY)),
        ],
        PATH,
        CIRCLE_KEYS,
    ],
};

const TRACK_KEY: Place = Place {
    name: "a track key",
    groups: &[&[
        ("frame", Value),
        ("time", Value),
        ("value", Value),
        ("ease", Value),
    ]],
};

const OUTPUT: Place = Place {
    name: "[output]",
    groups: &[&[
        ("dir", Value),
        ("name", Value),
        ("format", Value),
        ("jpeg_quality", Value),
        ("exr_depth", Value),
        ("exr_compression", Value),
        ("passes", Value),
        ("colour", Value),
    ]],
};

const RENDER: Place = Place {
    name: "[render]",
    groups: &[&[
        ("width", Value),
        ("height", Value),
        ("samples", Value),
        ("motion_blur", Table(BLUR)),
        ("antialias", Table(ANTIALIAS)),
    ]],
};

const ANTIALIAS: Place = Place {
    name: "antialias",
    groups: &[&[("mode", Value), ("threshold", Value), ("depth", Value)]],
};

const BLUR: Place = Place {
    name: "motion_blur",
    groups: &[&[("shutter", Value), ("samples", Value)]],
};

const CHECK: Place = Place {
    name: "[check]",
    groups: &[&[
        ("frames", Value),
        ("references", Value),
        ("fail", Value),
        ("fail_percent", Value),
        ("hard_fail", Value),
        ("flip", Value),
    ]],
};

/// The camera tables by path, for "belongs to path = ..." hints.
const CAMERAS: [(&str, Place); 3] = [("", STILL), ("circle", CIRCLE), ("spline", SPLINE)];

/// Every unknown key or table of `text`, in file order: the span of its name and the
/// message. Empty when all are known, or when the text is not TOML (serde says why).
pub(super) fn unknown_keys(text: &str) -> Vec<(Range<usize>, String)> {
    let Ok(root) = DeTable::parse(text) else {
        return Vec::new();
    };
    let mut found = Vec::new();
    walk(root.get_ref(), TOP, "", &mut found);
    found.sort_by_key(|(span, _)| span.start);
    found
}

/// Checks `table` against `place`; `path` is the key path of `table` (empty at the top).
fn walk(table: &DeTable<'_>, place: Place, path: &str, found: &mut Vec<(Range<usize>, String)>) {
    for (key, value) in table.iter() {
        let name = key.get_ref().as_ref();
        let Some((_, shape)) = place.keys().find(|(k, _)| *k == name) else {
            found.push((key.span(), unknown(place, path, name, value)));
            continue;
        };
        let inner = join(path, name);
        match (shape, value.get_ref()) {
            (Table(p), DeValue::Table(t)) => walk(t, p, &inner, found),
            (Camera, DeValue::Table(t)) => walk(t, camera_place(t), &inner, found),
            (Tables(p), DeValue::Array(items)) => {
                for (i, item) in items.iter().enumerate() {
                    if let DeValue::Table(t) = item.get_ref() {
                        walk(t, p, &format!("{inner}[{i}]"), found);
                    }
                }
            }
            _ => {} // a value, or the wrong type: serde says what it expected
        }
    }
}

/// The `[camera]` schema for the table's `path`.
fn camera_place(t: &DeTable<'_>) -> Place {
    let path = t.iter().find(|(k, _)| k.get_ref() == "path");
    match path.map(|(_, v)| v.get_ref()) {
        None => STILL,
        Some(DeValue::String(s)) => CAMERAS
            .iter()
            .find(|(kind, _)| !kind.is_empty() && kind == s)
            .map_or(ANY_CAMERA, |&(_, p)| p),
        Some(_) => ANY_CAMERA,
    }
}

/// `a.b` from `a` and `b`.
fn join(path: &str, name: &str) -> String {
    if path.is_empty() {
        name.to_string()
    } else {
        format!("{path}.{name}")
    }
}

/// The message for `name`, unknown in `place`: `path: unknown key `name` (hint); <place>
/// takes <its names>`.
fn unknown(place: Place, path: &str, name: &str, value: &Spanned<DeValue<'_>>) -> String {
    let top = path.is_empty();
    let shown = |n: &str, shape: Shape| match (top, shape) {
        (true, Table(_) | Camera) => format!("`[{n}]`"),
        (true, Tables(_)) => format!("`[[{n}]]`"),
        _ => format!("`{n}`"),
    };
    let (what, this) = match value.get_ref() {
        DeValue::Table(_) => ("table", shown(name, Table(place))),
        _ => ("key", shown(name, Value)),
    };
    let prefix = if top {
        String::new()
    } else {
        format!("{path}: ")
    };
    let other_path = CAMERAS
        .iter()
        .filter(|_| place.name.starts_with("[camera]"))
        .find(|(kind, p)| !kind.is_empty() && has(p, name));
    let hint = match other_path {
        Some((kind, _)) => format!(" (a key of path = \"{kind}\")"),
        None => nearest(name, place.keys().map(|(k, _)| k))
            .and_then(|near| place.keys().find(|(k, _)| *k == near))
            .map_or(String::new(), |(near, shape)| {
                format!(" (did you mean {}?)", shown(near, shape))
            }),
    };
    let names: Vec<String> = place.keys().map(|(k, s)| shown(k, s)).collect();
    format!(
        "{prefix}unknown {what} {this}{hint}; {} takes {}",
        place.name,
        names.join(", ")
    )
}

fn has(place: &Place, name: &str) -> bool {
    place.keys().any(|(k, _)| k == name)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn typos_find_the_nearest_name() {
        let tops = TOP.keys().map(|(k, _)| k);
        assert_eq!(nearest("camra", tops.clone()), Some("camera"));
        assert_eq!(nearest("outptu", tops.clone()), Some("output"));
        assert_eq!(nearest("Frames", tops.clone()), Some("frames"));
        assert_eq!(nearest("tracks", tops.clone()), Some("track"));
        // "zzz" is 3 edits from "fps": no suggestion.
        assert_eq!(nearest("zzz", tops.clone()), None);
        assert_eq!(nearest(&"x".repeat(41), tops.clone()), None);
        let check = CHECK.keys().map(|(k, _)| k);
        // fail_percentage: 3 deletions, within 15 / 3 = 5.
        assert_eq!(nearest("fail_percentage", check), Some("fail_percent"));
    }

    #[test]
    fn unknown_names_are_found_in_file_order() {
        let text = "[render]\nwidht = 4\n[camra]\npath = 1\n[output]\nfromat = 'png'\n";
        let found = unknown_keys(text);
        let starts: Vec<usize> = found.iter().map(|(s, _)| s.start).collect();
        // `widht` at byte 9, `camra` at 20, `fromat` at 45.
        assert_eq!(starts, vec![9, 20, 45]);
        assert_eq!(
            found[1].1,
            "unknown table `[camra]` (did you mean `[camera]`?); the top level takes `scene`, \
             `frames`, `fps`, `loop`, `[camera]`, `[animation]`, `[output]`, `[render]`, `[check]`, `[[track]]`"
        );
        assert_eq!(
            found[2].1,
            "output: unknown key `fromat` (did you mean `format`?); [output] takes `dir`, \
             `name`, `format`, `jpeg_quality`, `exr_depth`, `exr_compression`, `passes`, \
             `colour`"
        );
    }

    #[test]
    fn the_reference_page_names_every_table_and_key() {
        let page = include_str!("../../../../docs/manifest.md");
        let places = [
            TOP, STILL, CIRCLE, SPLINE, ANY_CAMERA, SPLINE_KEY, TRACK, TRACK_KEY, OUTPUT, RENDER,
            BLUR, ANTIALIAS, CHECK,
        ];
        for place in places {
            for (key, _) in place.keys() {
                assert!(
                    page.contains(&format!("`{key}`")) || page.contains(&format!("[{key}]")),
                    "docs/manifest.md does not name `{key}` of {}",
                    place.name
                );
            }
        }
    }

    #[test]
    fn camera_keys_follow_the_path() {
        let found = unknown_keys("[camera]\nradius = 3\n");
        assert_eq!(found.len(), 1);
        assert_eq!(
            found[0].1,
            "camera: unknown key `radius` (a key of path = \"circle\"); \
             [camera] without a path takes `path`, `name`, `look_at`, `fov`, `roll`"
        );
        assert!(unknown_keys("[camera]\npath = 'circle'\nradius = 3\n").is_empty());
        // An unknown path accepts any camera key: the path is what is refused.
        assert!(unknown_keys("[camera]\npath = 'spiral'\nclosed = true\n").is_empty());
    }
}
