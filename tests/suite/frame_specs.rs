//! The frame-list grammar against `fileseq`: the cases of fileseq's own test suite
//! (`tests/data/fileseq_cases.txt`, copied from its test/test_fuzz.py), the PyPI `fileseq`
//! itself on hand-written and random specs (run through python3; the test says "skipped:"
//! when python3 or fileseq is missing, and fails under CI), and a property: every frame of
//! any spec is rendered exactly once whatever the shard count and order.

use crate::skip;

use proptest::prelude::*;
use proptest::strategy::ValueTree;
use std::collections::BTreeMap;
use std::io::Write;
use std::process::{Command, Stdio};
use whitted_anim::select::{self, FrameSpec};

/// Our reading of `spec`: the frames in order, or `None` when refused.
fn ours(spec: &str) -> Option<Vec<i64>> {
    FrameSpec::parse(spec).and_then(|s| s.frames(None)).ok()
}

#[test]
fn fileseqs_own_cases() {
    let text = include_str!("../data/fileseq_cases.txt");
    let (mut ok, mut fail) = (0, 0);
    for line in text.lines().filter(|l| !l.starts_with('#')) {
        let fields: Vec<&str> = line.split('\t').collect();
        match fields[..] {
            ["ok", name, spec, frames] => {
                let want: Vec<i64> = frames
                    .split(',')
                    .filter(|f| !f.is_empty())
                    .map(|f| f.parse().unwrap())
                    .collect();
                assert_eq!(ours(spec).as_ref(), Some(&want), "{name}: {spec:?}");
                ok += 1;
            }
            ["fail", name, spec] => {
                assert_eq!(ours(spec), None, "{name}: {spec:?} must be refused");
                fail += 1;
            }
            _ => panic!("bad case line {line:?}"),
        }
    }
    // The file has 1,110 accepted and 17 refused string cases.
    assert!(ok > 1000 && fail > 10, "{ok} {fail}");
}

/// fileseq's answers for `specs`, one line each: the frames in order, or `None` when
/// fileseq refuses the spec; `Err` when python3 or fileseq is missing.
fn fileseq(specs: &[String]) -> Result<Vec<Option<Vec<i64>>>, String> {
    let script = r#"
import sys, json
try:
    from fileseq import FrameSet
except ImportError as e:
    print("missing:", e); sys.exit(3)
for line in sys.stdin.read().split("\n")[:-1]:
    spec = json.loads(line)
    try:
        fs = FrameSet(spec)
        # Sub-frames (2.5) are no frames of a sequence: we refuse them.
        print("null" if fs.hasSubFrames() else json.dumps([int(f) for f in fs]))
    except Exception:
        print("null")
"#;
    let mut child = Command::new("python3")
        .args(["-c", script])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .spawn()
        .map_err(|e| format!("python3: {e}"))?;
    let mut input = String::new();
    for s in specs {
        input.push_str(&serde_json::to_string(s).unwrap());
        input.push('\n');
    }
    child
        .stdin
        .take()
        .unwrap()
        .write_all(input.as_bytes())
        .unwrap();
    let out = child.wait_with_output().unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    if out.status.code() == Some(3) {
        return Err(text.trim().to_string());
    }
    assert!(out.status.success(), "python3 failed: {text}");
    Ok(text
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect())
}

/// fileseq's answers, or `None` after saying the test is skipped (outside CI).
fn oracle(specs: &[String]) -> Option<Vec<Option<Vec<i64>>>> {
    match fileseq(specs) {
        Ok(answers) => Some(answers),
        Err(why) => {
            skip::skip(&format!("fileseq does not answer: {why}"));
            None
        }
    }
}

const HAND: &[&str] = &[
    "1-100",
    "1-100x5",
    "1-100y5",
    "1-100:5",
    "1,2,3,4,99",
    "100-1x7",
    "0-0",
    "0-1:9",
    "5-5y1",
    "1-10x3,2-9y2",
    "10-20:4,1-30",
    "1-20:5,1-20",
    "3,1-5:2,4",
    "-5-5:3",
    "-10--1y4",
    "1-20x-5",
    "20-1x-5",
    "1-20:0",
    "1x5",
    "1-",
    "a-b",
    "1-20X5",
    "1.5",
    "1-5,,",
    " 1 - 5 x 2 ",
    "#1-4@",
    "0-99999999999999999999",
    "--1",
    "1--",
    "1-2-3",
    "1-10x",
    "1-10:+2",
    "+3",
    "1-5x2x2",
    "7:1",
    "",
    ",",
];

/// Same sets, same order, same refusals, on hand-written specs.
#[test]
fn the_same_frames_as_pypi_fileseq_on_hand_written_specs() {
    let specs: Vec<String> = HAND.iter().map(|s| s.to_string()).collect();
    let Some(answers) = oracle(&specs) else {
        return;
    };
    for (spec, theirs) in specs.iter().zip(answers) {
        assert_eq!(ours(spec), theirs, "{spec:?}");
    }
}

/// A random spec: items of small (possibly negative) frames, ranges and steps, with now
/// and then a malformed piece.
fn spec() -> impl Strategy<Value = String> {
    spec_in(-30..60)
}

/// A random spec of frames in `frames`.
fn spec_in(frames: std::ops::Range<i64>) -> impl Strategy<Value = String> {
    let frame = frames;
    let item = prop_oneof![
        3 => frame.clone().prop_map(|f| f.to_string()),
        4 => (frame.clone(), frame.clone()).prop_map(|(a, b)| format!("{a}-{b}")),
        6 => (frame.clone(), frame, prop::sample::select(vec!["x", "y", ":"]), -3i64..12)
            .prop_map(|(a, b, s, n)| format!("{a}-{b}{s}{n}")),
        1 => prop::sample::select(vec!["", "x", "1-", "a", "2.5", "3-4z", "1x2", " ", "#"])
            .prop_map(str::to_string),
    ];
    prop::collection::vec(item, 0..5).prop_map(|items| items.join(","))
}

#[test]
fn the_same_frames_as_pypi_fileseq_on_random_specs() {
    let mut runner = proptest::test_runner::TestRunner::deterministic();
    let specs: Vec<String> = (0..600)
        .map(|_| spec().new_tree(&mut runner).unwrap().current())
        .collect();
    let Some(answers) = oracle(&specs) else {
        return;
    };
    let mut refused = 0;
    for (spec, theirs) in specs.iter().zip(answers) {
        refused += usize::from(theirs.is_none());
        assert_eq!(ours(spec), theirs, "{spec:?}");
    }
    // The sample has both kinds.
    assert!(refused > 20 && refused < 500, "{refused} of 600 refused");
}

proptest! {
    /// Every frame of a spec is rendered by exactly one of N shards, each shard in the
    /// spec's order, whatever N (and the union is the spec's frames).
    #[test]
    fn every_frame_is_rendered_exactly_once(spec in spec_in(0..60), n in 1u32..12, total in 60u32..80) {
        // Malformed specs are refused (tested above); the others are runs.
        let Ok(all) = select::parse_frames(&spec, total) else { return Ok(()); };
        let mut count: BTreeMap<u32, usize> = BTreeMap::new();
        for k in 0..n {
            let part = select::select(total, Some(&spec), Some((k, n))).unwrap();
            // In the spec's order: a subsequence of `all`.
            let mut rest = all.iter();
            prop_assert!(part.iter().all(|f| rest.any(|g| g == f)), "{part:?} of {all:?}");
            for f in part {
                *count.entry(f).or_default() += 1;
            }
        }
        prop_assert!(count.values().all(|&c| c == 1));
        prop_assert_eq!(count.keys().copied().collect::<Vec<_>>(), select::sorted(&all));
    }
}
