//! Random manifests: TOML documents from a structure of every section, and mutated
//! seeds.

use super::*;
#[allow(unused_imports)]
use super::{findings::*, manifests::*, properties::*, seeds::*, tracks::*};

/// A TOML string literal of any text (basic string, escaped).
pub(super) fn toml_string(s: &str) -> String {
    let mut out = String::from("\"");
    for c in s.chars() {
        match c {
            '"' => out += "\\\"",
            '\\' => out += "\\\\",
            c if c.is_control() => out += &format!("\\u{:04X}", c as u32),
            c => out.push(c),
        }
    }
    out + "\""
}

/// A TOML value of any type, nested a little; sometimes not valid TOML at all.
pub(super) fn toml_value() -> impl Strategy<Value = String> {
    let leaf = prop_oneof![
        3 => (0i64..300).prop_map(|n| n.to_string()),
        1 => any::<i64>().prop_map(|n| n.to_string()),
        3 => (-1e3f64..1e3).prop_map(|x| format!("{x:?}")),
        1 => any::<f64>().prop_filter("finite", |x| x.is_finite()).prop_map(|x| format!("{x:?}")),
        2 => prop::sample::select(NASTY_VALUES).prop_map(str::to_string),
        2 => prop::sample::select(&[
            "circle", "spline", "png", "jpeg", "ppm", "raw", "bmp", "frame_####", "s.txt", "",
        ][..])
        .prop_map(toml_string),
        1 => "\\PC{0,6}".prop_map(|s| toml_string(&s)),
        1 => any::<bool>().prop_map(|b| b.to_string()),
        1 => "[a-z0-9.\\[\\]{}=,\"' -]{1,6}",
    ];
    leaf.prop_recursive(3, 24, 4, |inner| {
        prop_oneof![
            prop::collection::vec(inner.clone(), 0..4).prop_map(|v| format!("[{}]", v.join(", "))),
            prop::collection::vec((prop::sample::select(KEYS), inner), 0..4).prop_map(|kv| {
                let body: Vec<String> = kv.iter().map(|(k, v)| format!("{k} = {v}")).collect();
                format!("{{ {} }}", body.join(", "))
            }),
        ]
    })
}

/// Random TOML: table headers and key = value lines from the manifest's vocabulary.
pub(super) fn toml_document() -> impl Strategy<Value = String> {
    let line = prop_oneof![
        5 => (prop::sample::select(KEYS), toml_value()).prop_map(|(k, v)| format!("{k} = {v}")),
        1 => ("[a-z_]{1,8}", toml_value()).prop_map(|(k, v)| format!("{k} = {v}")),
        2 => prop::sample::select(TABLES).prop_map(str::to_string),
        1 => "#[^\n]{0,10}",
        1 => Just(String::new()),
    ];
    let end = prop_oneof![8 => Just("\n"), 1 => Just("\r\n"), 1 => Just(" # c\n"), 1 => Just("")];
    prop::collection::vec((line, end), 0..16)
        .prop_map(|v| v.into_iter().map(|(l, e)| l + e).collect())
}

/// A value for a manifest field: usually of the right type, sometimes anything.
pub(super) fn field(good: BoxedStrategy<String>) -> impl Strategy<Value = Option<String>> {
    prop_oneof![
        14 => good.prop_map(Some),
        1 => toml_value().prop_map(Some),
        1 => Just(None),
    ]
}

pub(super) fn float() -> BoxedStrategy<String> {
    prop_oneof![
        4 => (-20.0f64..20.0).prop_map(|x| format!("{x:?}")),
        1 => prop::sample::select(&["0.0", "1e9", "-1e9", "1e10", "1e-300", "nan", "inf"][..])
            .prop_map(str::to_string),
    ]
    .boxed()
}

pub(super) fn int(range: std::ops::Range<i64>) -> BoxedStrategy<String> {
    range.prop_map(|n| n.to_string()).boxed()
}

pub(super) fn point() -> BoxedStrategy<String> {
    (float(), float(), float())
        .prop_map(|(x, y, z)| format!("[{x}, {y}, {z}]"))
        .boxed()
}

pub(super) fn key_entry() -> BoxedStrategy<String> {
    (int(-2..40), point(), prop::option::of(point()))
        .prop_map(|(f, p, l)| match l {
            Some(l) => format!("{{ frame = {f}, position = {p}, look_at = {l} }}"),
            None => format!("{{ frame = {f}, position = {p} }}"),
        })
        .boxed()
}

/// A manifest shaped like SPEC §5 with random, often out-of-range, values.
pub(super) fn structured_manifest() -> impl Strategy<Value = String> {
    let top = (
        field(Just("\"s.txt\"".to_string()).boxed()),
        field(int(-2..50)),
        field(float()),
    );
    let circle = (
        field(point()),
        field(float()),
        field(float()),
        field(float()),
        field(float()),
        field(point()),
    )
        .prop_map(|(c, r, h, a, t, l)| {
            let mut s = "path = \"circle\"\n".to_string();
            for (k, v) in [
                ("center", c),
                ("radius", r),
                ("height", h),
                ("start_angle", a),
                ("turns", t),
                ("look_at", l),
            ] {
                if let Some(v) = v {
                    s += &format!("{k} = {v}\n");
                }
            }
            s
        });
    let spline = (
        field(any::<bool>().prop_map(|b| b.to_string()).boxed()),
        field(any::<bool>().prop_map(|b| b.to_string()).boxed()),
        prop::option::of(point()),
        prop::collection::vec(key_entry(), 0..6),
    )
        .prop_map(|(closed, speed, look, keys)| {
            let mut s = "path = \"spline\"\n".to_string();
            for (k, v) in [
                ("closed", closed),
                ("constant_speed", speed),
                ("look_at", look),
            ] {
                if let Some(v) = v {
                    s += &format!("{k} = {v}\n");
                }
            }
            s + &format!("keys = [\n  {}\n]\n", keys.join(",\n  "))
        });
    let output = (
        field(Just("\"out\"".to_string()).boxed()),
        field(
            prop::sample::select(
                &[
                    "\"f_####\"",
                    "\"#\"",
                    "\"a#b##\"",
                    "\"x\"",
                    "\"##########\"",
                ][..],
            )
            .prop_map(str::to_string)
            .boxed(),
        ),
        field(
            prop::sample::select(&["\"png\"", "\"jpeg\"", "\"ppm\"", "\"raw\"", "\"gif\""][..])
                .prop_map(str::to_string)
                .boxed(),
        ),
        field(int(-1..120)),
    );
    let render = (
        field(int(0..20000)),
        field(int(0..20000)),
        field(int(-1..20)),
    );
    let check = (
        field(
            prop::collection::vec(-2i64..50, 0..5)
                .prop_map(|v| format!("{v:?}"))
                .boxed(),
        ),
        field(Just("\"golden\"".to_string()).boxed()),
        field(int(-1..300)),
        field(float()),
        field(int(-1..300)),
    );
    (
        top,
        prop_oneof![circle, spline],
        prop::option::of(output),
        prop::option::of(render),
        prop::option::of(check),
    )
        .prop_map(|((scene, frames, fps), camera, output, render, check)| {
            let mut s = String::new();
            for (k, v) in [("scene", scene), ("frames", frames), ("fps", fps)] {
                if let Some(v) = v {
                    s += &format!("{k} = {v}\n");
                }
            }
            s += "[camera]\n";
            s += &camera;
            let mut table = |name: &str, kv: Vec<(&str, Option<String>)>| {
                s += &format!("[{name}]\n");
                for (k, v) in kv {
                    if let Some(v) = v {
                        s += &format!("{k} = {v}\n");
                    }
                }
            };
            if let Some((d, n, f, q)) = output {
                table(
                    "output",
                    vec![("dir", d), ("name", n), ("format", f), ("jpeg_quality", q)],
                );
            }
            if let Some((w, h, n)) = render {
                table("render", vec![("width", w), ("height", h), ("samples", n)]);
            }
            if let Some((fr, r, f, p, h)) = check {
                table(
                    "check",
                    vec![
                        ("frames", fr),
                        ("references", r),
                        ("fail", f),
                        ("fail_percent", p),
                        ("hard_fail", h),
                    ],
                );
            }
            s
        })
}

/// One edit of a manifest, by lines, values or bytes.
#[derive(Clone, Debug)]
pub(super) enum ManifestEdit {
    DeleteLine(Index),
    DuplicateLine(Index),
    SwapLines(Index, Index),
    ReplaceValue(Index, String),
    InsertLine(Index, String),
    Text(Edit),
}

pub(super) fn manifest_edit() -> impl Strategy<Value = ManifestEdit> {
    prop_oneof![
        2 => any::<Index>().prop_map(ManifestEdit::DeleteLine),
        2 => any::<Index>().prop_map(ManifestEdit::DuplicateLine),
        1 => (any::<Index>(), any::<Index>()).prop_map(|(a, b)| ManifestEdit::SwapLines(a, b)),
        4 => (any::<Index>(), toml_value()).prop_map(|(i, v)| ManifestEdit::ReplaceValue(i, v)),
        2 => (any::<Index>(), toml_document()).prop_map(|(i, d)| ManifestEdit::InsertLine(i, d)),
        3 => edit().prop_map(ManifestEdit::Text),
    ]
}

pub(super) fn apply_manifest(text: &str, edits: &[ManifestEdit]) -> Vec<u8> {
    let mut bytes = text.as_bytes().to_vec();
    for e in edits {
        let now = String::from_utf8_lossy(&bytes).into_owned();
        let mut lines: Vec<String> = now.split_inclusive('\n').map(str::to_string).collect();
        if lines.is_empty() {
            lines.push(String::new());
        }
        let n = lines.len();
        match e {
            ManifestEdit::DeleteLine(i) => {
                lines.remove(i.index(n));
            }
            ManifestEdit::DuplicateLine(i) => {
                let k = i.index(n);
                let l = lines[k].clone();
                lines.insert(k, l);
            }
            ManifestEdit::SwapLines(a, b) => lines.swap(a.index(n), b.index(n)),
            ManifestEdit::ReplaceValue(i, v) => {
                let k = i.index(n);
                if let Some(eq) = lines[k].find('=') {
                    lines[k] = format!("{}= {v}\n", &lines[k][..eq]);
                }
            }
            ManifestEdit::InsertLine(i, d) => lines.insert(i.index(n + 1), d.clone() + "\n"),
            ManifestEdit::Text(edit) => {
                bytes = apply(&now, std::slice::from_ref(edit));
                continue;
            }
        }
        bytes = lines.concat().into_bytes();
    }
    bytes
}

proptest! {
    #![proptest_config(config(1000))]

    #[test]
    fn random_toml_documents(src in toml_document()) {
        manifest_ok_or_located(src).map_err(TestCaseError::fail)?;
    }

    #[test]
    fn structured_manifests_with_random_values(src in structured_manifest()) {
        manifest_ok_or_located(src).map_err(TestCaseError::fail)?;
    }

    #[test]
    fn mutated_seed_manifests(
        seed in any::<Index>(),
        edits in prop::collection::vec(manifest_edit(), 1..4),
    ) {
        let seeds = manifest_seeds();
        let text = &seeds[seed.index(seeds.len())];
        let src = String::from_utf8_lossy(&apply_manifest(text, &edits)).into_owned();
        manifest_ok_or_located(src).map_err(TestCaseError::fail)?;
    }
}
