//! Random scenes: token streams, headers with random records, mutated seeds, grammar
//! scenes with degenerate values, random bytes through a file.

use super::*;
#[allow(unused_imports)]
use super::{findings::*, manifest_properties::*, manifests::*, seeds::*, tracks::*};

/// One token of any kind, leaning towards the small integers the header needs.
pub(super) fn token() -> impl Strategy<Value = String> {
    prop_oneof![
        4 => (0u32..5).prop_map(|n| n.to_string()),
        2 => (0u32..70_000).prop_map(|n| n.to_string()),
        2 => any::<i64>().prop_map(|n| n.to_string()),
        3 => (-100.0f64..100.0).prop_map(|x| format!("{x}")),
        2 => any::<f64>().prop_map(|x| format!("{x:e}")),
        1 => any::<f64>().prop_map(|x| format!("{x}")),
        2 => prop::sample::select(NASTY).prop_map(str::to_string),
        1 => "[a-zA-Z_]{1,8}",
        1 => "[0-9.eE+-]{1,6}",
        1 => "\\PC{1,3}",
        1 => "[0-9]{1,3}#[a-z]{0,3}",
    ]
}

/// What goes between tokens: blanks of every kind, comments, nothing at all.
pub(super) fn separator() -> impl Strategy<Value = String> {
    prop_oneof![
        8 => Just(" ".to_string()),
        2 => Just("\n".to_string()),
        1 => Just("\t".to_string()),
        1 => Just("\r\n".to_string()),
        1 => Just("  \t \n\n".to_string()),
        1 => Just("\u{a0}".to_string()),
        1 => Just("\u{2028}".to_string()),
        1 => Just("\u{3000}".to_string()),
        1 => Just("\x0b\x0c".to_string()),
        1 => "#[^\n]{0,12}\n",
        1 => "#[^\n]{0,12}",
        1 => Just(String::new()),
    ]
}

pub(super) fn stream(len: std::ops::Range<usize>) -> impl Strategy<Value = String> {
    prop::collection::vec((token(), separator()), len)
        .prop_map(|parts| parts.into_iter().map(|(t, s)| t + &s).collect::<String>())
}

/// A header that parses (tiny image, camera, fog, counts), so that random tokens after it
/// reach the records.
pub(super) fn header() -> impl Strategy<Value = String> {
    (
        1u32..5,
        1u32..5,
        0u32..4,
        0u32..3,
        0u32..3,
        0u32..3,
        0u32..3,
    )
        .prop_map(|(w, h, fog, ns, np, nc, nl)| {
            format!("{w} {h}\n0 1 5\n0 0 0\n{fog} 7\n{ns} {np} {nc} {nl}\n")
        })
}

/// A number for a field of a generated scene: usually ordinary, sometimes degenerate.
pub(super) fn value() -> impl Strategy<Value = f64> {
    prop_oneof![
        6 => (-3i32..=3).prop_map(f64::from),
        6 => -10.0f64..10.0,
        2 => 0.0f64..1.0,
        1 => prop::sample::select(&[
            0.0, -0.0, 1e-300, 1e-9, 1e-4, 1e4, 1e6, -1e6, 1e9, 1e150, 1e300, -1e300, 1.7e308,
            5e-324,
        ][..]),
        1 => any::<f64>(),
    ]
}

/// A number for a field that must be > 0 (radius, Ior, fog distance): usually valid.
pub(super) fn positive() -> impl Strategy<Value = f64> {
    prop_oneof![
        10 => 0.01f64..10.0,
        2 => prop::sample::select(&[
            1e-300, 1e-9, 1e-4, 1e4, 1e6, 1e9, 1e150, 1e300, 1.7e308, 5e-324,
        ][..]),
        1 => value(),
    ]
}

pub(super) fn vec3() -> impl Strategy<Value = String> {
    (value(), value(), value()).prop_map(|(x, y, z)| format!("{x:?} {y:?} {z:?}"))
}

pub(super) fn texture() -> impl Strategy<Value = String> {
    prop_oneof![
        vec3().prop_map(|c| format!("1 {c}")),
        (1u32..=4, vec3(), vec3(), vec3()).prop_map(|(t, a, b, c)| format!("2 {t} {a} {b} {c}")),
    ]
}

pub(super) fn material() -> impl Strategy<Value = String> {
    (value(), value(), value(), positive(), 0u32..=2, value())
        .prop_map(|(kd, kr, kt, ior, bt, bv)| format!("{kd:?} {kr:?} {kt:?} {ior:?} {bt} {bv:?}"))
}

/// A scene following the grammar, with random and often degenerate values: it parses
/// unless a value breaks a rule (radius ≤ 0, zero normal, Ior ≤ 0, eye on look-at...).
pub(super) fn grammar_scene() -> impl Strategy<Value = String> {
    let sphere = (positive(), vec3(), texture(), material())
        .prop_map(|(r, c, t, m)| format!("{r:?} {c} {t} {m}\n"));
    let plane = (vec3(), vec3(), texture(), material())
        .prop_map(|(p, n, t, m)| format!("{p} {n} {t} {m}\n"));
    let cylinder = (vec3(), vec3(), positive(), texture(), material())
        .prop_map(|(a, p, r, t, m)| format!("{a} {p} {r:?} {t} {m}\n"));
    let light = (vec3(), vec3(), value()).prop_map(|(p, c, i)| format!("{p} {c} {i:?}\n"));
    (
        (1u32..6, 1u32..6, vec3(), vec3(), 0u32..4, positive()),
        prop::collection::vec(sphere, 0..4),
        prop::collection::vec(plane, 0..3),
        prop::collection::vec(cylinder, 0..3),
        prop::collection::vec(light, 0..4),
    )
        .prop_map(|((w, h, eye, look, fog, fd), s, p, c, l)| {
            let mut out = format!(
                "{w} {h}\n{eye}\n{look}\n{fog} {fd:?}\n{} {} {} {}\n",
                s.len(),
                p.len(),
                c.len(),
                l.len()
            );
            for rec in s.iter().chain(&p).chain(&c).chain(&l) {
                out += rec;
            }
            out
        })
}

/// One edit of a text: on tokens or on bytes.
#[derive(Clone, Debug)]
pub(super) enum Edit {
    DeleteToken(Index),
    DuplicateToken(Index),
    ReplaceToken(Index, String),
    InsertToken(Index, String),
    SwapTokens(Index, Index),
    Truncate(Index),
    FlipByte(Index, u8),
    InsertBytes(Index, Vec<u8>),
}

pub(super) fn edit() -> impl Strategy<Value = Edit> {
    prop_oneof![
        3 => any::<Index>().prop_map(Edit::DeleteToken),
        2 => any::<Index>().prop_map(Edit::DuplicateToken),
        4 => (any::<Index>(), token()).prop_map(|(i, t)| Edit::ReplaceToken(i, t)),
        2 => (any::<Index>(), token()).prop_map(|(i, t)| Edit::InsertToken(i, t)),
        1 => (any::<Index>(), any::<Index>()).prop_map(|(a, b)| Edit::SwapTokens(a, b)),
        1 => any::<Index>().prop_map(Edit::Truncate),
        2 => (any::<Index>(), 1u8..=255).prop_map(|(i, m)| Edit::FlipByte(i, m)),
        1 => (any::<Index>(), prop::collection::vec(any::<u8>(), 1..4))
            .prop_map(|(i, b)| Edit::InsertBytes(i, b)),
    ]
}

/// Applies `edits` to `text`; the result may no longer be UTF-8.
pub(super) fn apply(text: &str, edits: &[Edit]) -> Vec<u8> {
    let mut bytes = text.as_bytes().to_vec();
    for e in edits {
        // Token edits work on the text as it is now (lossy if a byte edit broke it).
        let now = String::from_utf8_lossy(&bytes).into_owned();
        let spans = token_spans(&now);
        let pick = |i: &Index| (!spans.is_empty()).then(|| spans[i.index(spans.len())]);
        let splice = |(s, e): (usize, usize), with: &str| {
            format!("{}{}{}", &now[..s], with, &now[e..]).into_bytes()
        };
        bytes = match e {
            Edit::DeleteToken(i) => pick(i).map_or(bytes, |sp| splice(sp, "")),
            Edit::DuplicateToken(i) => pick(i).map_or(bytes, |(s, e)| {
                splice((s, e), &format!("{0} {0}", &now[s..e]))
            }),
            Edit::ReplaceToken(i, t) => pick(i).map_or(bytes, |sp| splice(sp, t)),
            Edit::InsertToken(i, t) => match pick(i) {
                Some((s, _)) => splice((s, s), &format!("{t} ")),
                None => t.clone().into_bytes(),
            },
            Edit::SwapTokens(a, b) => match (pick(a), pick(b)) {
                (Some(x), Some(y)) if x.0 < y.0 => format!(
                    "{}{}{}{}{}",
                    &now[..x.0],
                    &now[y.0..y.1],
                    &now[x.1..y.0],
                    &now[x.0..x.1],
                    &now[y.1..]
                )
                .into_bytes(),
                _ => bytes,
            },
            Edit::Truncate(i) => {
                let cut = i.index(bytes.len() + 1);
                bytes.truncate(cut);
                bytes
            }
            Edit::FlipByte(i, m) => {
                if !bytes.is_empty() {
                    let k = i.index(bytes.len());
                    bytes[k] ^= m;
                }
                bytes
            }
            Edit::InsertBytes(i, b) => {
                let k = i.index(bytes.len() + 1);
                bytes.splice(k..k, b.iter().copied());
                bytes
            }
        };
    }
    bytes
}

// ---------------------------------------------------------------------------------------
// Properties
// ---------------------------------------------------------------------------------------

proptest! {
    #![proptest_config(config(1500))]

    #[test]
    fn random_token_streams(src in stream(0..40)) {
        parse_ok_or_located(src, "random.txt").map_err(TestCaseError::fail)?;
    }

    #[test]
    fn random_records_after_a_valid_header(head in header(), tail in stream(0..80)) {
        parse_ok_or_located(head + &tail, "records.txt").map_err(TestCaseError::fail)?;
    }

    #[test]
    fn mutated_seed_scenes(seed in any::<Index>(), edits in prop::collection::vec(edit(), 1..5)) {
        let seeds = seeds();
        let (_, text) = &seeds[seed.index(seeds.len())];
        let bytes = apply(text, &edits);
        match String::from_utf8(bytes) {
            Ok(src) => parse_ok_or_located(src, "mutant.txt").map(|_| ()),
            Err(e) => load_ok_or_located(e.into_bytes()).map(|_| ()),
        }
        .map_err(TestCaseError::fail)?;
    }
}

proptest! {
    #![proptest_config(config(400))]

    #[test]
    fn grammar_scenes_with_degenerate_values(src in grammar_scene()) {
        parse_ok_or_located(src, "grammar.txt").map_err(TestCaseError::fail)?;
    }

    #[test]
    fn random_bytes_through_a_file(bytes in prop::collection::vec(any::<u8>(), 0..200)) {
        load_ok_or_located(bytes).map_err(TestCaseError::fail)?;
    }
}
