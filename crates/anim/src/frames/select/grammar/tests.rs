use super::*;

fn frames(spec: &str) -> Vec<i64> {
    FrameSpec::parse(spec)
        .and_then(|s| s.frames(None))
        .unwrap_or_else(|e| panic!("{spec}: {e}"))
}

fn error(spec: &str) -> (usize, ListProblem) {
    match FrameSpec::parse(spec).and_then(|s| s.frames(None)) {
        Err(e) => (e.column, e.problem),
        Ok(f) => panic!("{spec} gave {f:?}"),
    }
}

#[test]
fn ranges_steps_fills_and_staggers_by_hand() {
    assert_eq!(frames("1-5"), [1, 2, 3, 4, 5]);
    assert_eq!(frames("5-1"), [5, 4, 3, 2, 1]);
    // x3 from 1: 1 4 7 10; 11 is not reached.
    assert_eq!(frames("1-11x3"), [1, 4, 7, 10]);
    // y3 is what x3 leaves out.
    assert_eq!(frames("1-11y3"), [2, 3, 5, 6, 8, 9, 11]);
    // :3 is x3 (1 4 7 10), then x2 adds 3 5 9 11, then x1 adds 2 6 8.
    assert_eq!(frames("1-11:3"), [1, 4, 7, 10, 3, 5, 9, 11, 2, 6, 8]);
    // Backwards with a step: from 10 down by 4.
    assert_eq!(frames("10-1x4"), [10, 6, 2]);
    assert_eq!(frames("10-1x-4"), [10, 6, 2]);
    // Negative frames and ranges across zero.
    assert_eq!(frames("-2-1"), [-2, -1, 0, 1]);
    assert_eq!(frames("-1--3"), [-1, -2, -3]);
    // A list keeps each frame's first place; spaces and padding marks are ignored.
    assert_eq!(frames(" 4, 1-5 ,#2@"), [4, 1, 2, 3, 5]);
    assert_eq!(frames(",,"), Vec::<i64>::new());
    assert_eq!(frames("1-1y1"), Vec::<i64>::new());
    assert_eq!(frames("7-7x2"), [7]);
}

#[test]
fn malformed_specs_are_located() {
    use ListProblem::*;
    assert_eq!(error("1-20x0"), (6, ZeroStep));
    assert_eq!(error("1-20:-5"), (6, NegativeStep));
    assert_eq!(error("1x5"), (2, StepWithoutRange('x')));
    assert_eq!(error("0,1-"), (5, NotANumber("the end of the item".into())));
    let after = "a range (a step is x, y or : and a number)";
    assert_eq!(
        error("1-20X5"),
        (
            5,
            Unexpected {
                found: "'X'".into(),
                after
            }
        )
    );
    assert_eq!(error("1-20x:y5"), (6, NotANumber("':'".into())));
    assert_eq!(error("1.5"), (2, Subframe));
    // Columns count the text as given, spaces included.
    assert_eq!(error("1, 2-b"), (6, NotANumber("'b'".into())));
    assert_eq!(
        error("3-4x2z"),
        (
            6,
            Unexpected {
                found: "'z'".into(),
                after: "the step"
            }
        )
    );
    assert_eq!(
        error("99999999999999999999"),
        (1, TooLarge("99999999999999999999".into()))
    );
    assert_eq!(error("0-99999999"), (1, TooMany));
}

#[test]
fn bounds_are_checked_on_the_frames_produced() {
    let bounded = |spec: &str, n| FrameSpec::parse(spec).unwrap().frames(Some(n));
    // 0-10x3 stops at 9, inside ten frames; 0-10 does not.
    assert_eq!(bounded("0-10x3", 10).unwrap(), [0, 3, 6, 9]);
    let e = bounded("0-10", 10).unwrap_err();
    assert_eq!(
        (e.column, e.problem),
        (3, ListProblem::PastTheEnd { frame: 10, last: 9 })
    );
    // 0-10y5 leaves out 10 (on the x5 grid), so it fits too.
    assert_eq!(bounded("0-10y5", 10).unwrap(), [1, 2, 3, 4, 6, 7, 8, 9]);
    let e = bounded("2,-1-3", 10).unwrap_err();
    assert_eq!((e.column, e.problem), (3, ListProblem::BeforeTheStart(-1)));
    // A huge range fails on its bound, before anything is expanded.
    let e = bounded("0-4000000000", 250).unwrap_err();
    assert_eq!(e.column, 3);
}

#[test]
fn the_error_message_names_the_column() {
    let e = FrameSpec::parse("1-20x0").unwrap_err();
    assert_eq!(e.to_string(), "the step must not be 0 (column 6)");
}

#[test]
fn a_step_past_the_range_is_not_walked() {
    // Reliability round three: `:N` walked N strides, so a huge N never returned. Steps past the span add
    // only the first frame: `:N` is every frame, coarse to fine; `xN` the first frame.
    assert_eq!(frames("0-11:9999999999"), frames("0-11:11"));
    assert_eq!(frames("0-3:9999999999"), [0, 3, 2, 1]);
    assert_eq!(frames("0-11x9999999999"), [0]);
    assert_eq!(frames("0-11y9999999999"), (1..=11).collect::<Vec<_>>());
    assert_eq!(frames("5-5:9223372036854775807"), [5]);
}
