//! The frame-list grammar of `fileseq` (the VFX pipelines' de-facto standard, also read by
//! OpenCue, Deadline and Open Job Description), parsed into items that keep their columns:
//!
//! ```text
//! spec   = item { "," item }            empty items are skipped: "1,,2" is 1, 2
//! item   = frame [ "-" frame [ step ] ]
//! step   = ( "x" | "y" | ":" ) number   x5: every 5th; y5: the ones x5 leaves out;
//!                                       :5: x5, then x4, … x1, without repeats
//! frame  = [ "-" ] digits               negative frames parse (and are refused later
//!                                       by a sequence that starts at 0)
//! ```
//!
//! Whitespace and the padding characters `#` and `@` are ignored anywhere, as `fileseq`
//! does. A range may run backwards (`10-1`); a step is never 0, and never negative on a
//! forward range. The frames come out in the order the spec gives them, each once (the
//! first time it appears): `1-9:4` is 1 5 9 (x4), 4 7 (what x3 adds), 3 (x2), 2 6 8 (x1)
//! — coarse to fine, so a run stopped early has frames spread over the whole shot. Decimal
//! sub-frames (`1.5`) are not frames of a sequence and are refused.

/// The most frames a spec may name before bounds are known (`fileseq`'s MAX_FRAME_SIZE).
pub const MAX_SPEC_FRAMES: u64 = 10_000_000;

/// How an item steps through its range.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Step {
    /// Every frame (`A-B`, or a single frame).
    One,
    /// Every N-th (`A-BxN`).
    Every(u64),
    /// The frames `xN` leaves out (`A-ByN`).
    Fill(u64),
    /// `xN`, `x(N−1)`, … `x1`, each frame once (`A-B:N`).
    Stagger(u64),
}

/// One comma-separated item of a spec, with the 1-based columns (in characters of the
/// text as given) of its first and last frame numbers.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Item {
    /// The first frame.
    pub start: i64,
    /// The last frame (the first, for a single frame).
    pub end: i64,
    /// How the range is walked.
    pub step: Step,
    /// Column of `start`.
    pub start_column: usize,
    /// Column of `end`.
    pub end_column: usize,
}

/// What is wrong with a frame list; the column says where.
#[derive(Debug, thiserror::Error, PartialEq, Eq, Clone)]
pub enum ListProblem {
    /// A frame number was expected where something else (or nothing) is.
    #[error("expected a frame number, found {0}")]
    NotANumber(String),
    /// A character that cannot follow what came before.
    #[error("unexpected {found} after {after}")]
    Unexpected {
        /// What was found, quoted.
        found: String,
        /// What it follows.
        after: &'static str,
    },
    /// `AxN` with no range: a step needs an end frame.
    #[error("a step needs a range: write A-B{0}N")]
    StepWithoutRange(char),
    /// A step of 0.
    #[error("the step must not be 0")]
    ZeroStep,
    /// A negative step on a forward range (`1-20x-5`).
    #[error("a forward range cannot have a negative step")]
    NegativeStep,
    /// A decimal sub-frame such as `1.5`.
    #[error("sub-frames such as 1.5 are not frames of a sequence")]
    Subframe,
    /// A number too large for a frame.
    #[error("{0} is too large for a frame number")]
    TooLarge(String),
    /// More frames than [`MAX_SPEC_FRAMES`].
    #[error("more than {MAX_SPEC_FRAMES} frames")]
    TooMany,
    /// A frame below 0.
    #[error("frame {0} is before the first frame, 0")]
    BeforeTheStart(i64),
    /// A frame at or past the sequence's frame count.
    #[error("frame {frame} is past the last frame, {last}")]
    PastTheEnd {
        /// The frame asked for.
        frame: i64,
        /// The sequence's last frame (count − 1).
        last: u32,
    },
    /// A spec that names no frame at all (empty, or only commas).
    #[error("it names no frame")]
    NoFrames,
}

/// A problem and its 1-based column in the text as given.
#[derive(Debug, thiserror::Error, PartialEq, Eq, Clone)]
#[error("{problem} (column {column})")]
pub struct SpecError {
    /// Where, in characters from 1.
    pub column: usize,
    /// What.
    pub problem: ListProblem,
}

/// A parsed spec: its items in order.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FrameSpec {
    /// The items, as written.
    pub items: Vec<Item>,
}

/// The characters that count, each with its 1-based column.
type Chars = Vec<(char, usize)>;

impl FrameSpec {
    /// Parses `text`; the frames are not bounded yet (see [`FrameSpec::frames`]).
    pub fn parse(text: &str) -> Result<FrameSpec, SpecError> {
        let chars: Chars = text
            .chars()
            .zip(1..)
            .filter(|(c, _)| !c.is_whitespace() && *c != '#' && *c != '@')
            .collect();
        let end_column = text.chars().count() + 1;
        let mut items = Vec::new();
        for part in chars.split(|(c, _)| *c == ',') {
            if part.is_empty() {
                continue;
            }
            let stop = part.last().map_or(end_column, |&(_, col)| col + 1);
            items.push(
                Cursor {
                    chars: part,
                    at: 0,
                    stop,
                }
                .item()?,
            );
        }
        Ok(FrameSpec { items })
    }

    /// The frames in spec order, each once. With `count`, every frame must lie in
    /// `0..count` (checked before anything is expanded, so `0-999999999` fails fast).
    pub fn frames(&self, count: Option<u32>) -> Result<Vec<i64>, SpecError> {
        let mut total = 0u64;
        for item in &self.items {
            if let Some(count) = count {
                item.check_bounds(count)?;
            }
            total += item.len_bound();
            if total > MAX_SPEC_FRAMES {
                let column = item.start_column;
                return Err(SpecError {
                    column,
                    problem: ListProblem::TooMany,
                });
            }
        }
        let mut seen = std::collections::HashSet::new();
        let mut out = Vec::new();
        for item in &self.items {
            item.walk(&mut |f| {
                if seen.insert(f) {
                    out.push(f);
                }
            });
        }
        Ok(out)
    }
}

impl Item {
    fn dir(&self) -> i64 {
        if self.start <= self.end {
            1
        } else {
            -1
        }
    }

    fn span(&self) -> u64 {
        self.start.abs_diff(self.end)
    }

    /// At most this many frames (before removing repeats).
    fn len_bound(&self) -> u64 {
        match self.step {
            Step::Every(k) => self.span() / k + 1,
            _ => self.span() + 1,
        }
    }

    /// `start`, `start ± k`, … up to `end`, inclusive when reached.
    fn stride(&self, k: u64, f: &mut dyn FnMut(i64)) {
        for i in 0..=self.span() / k {
            f(self.start + self.dir() * (i * k) as i64);
        }
    }

    fn walk(&self, f: &mut dyn FnMut(i64)) {
        match self.step {
            Step::One => self.stride(1, f),
            Step::Every(k) => self.stride(k, f),
            Step::Fill(k) => self.stride(1, &mut |x| {
                if !(x - self.start).unsigned_abs().is_multiple_of(k) {
                    f(x)
                }
            }),
            // Steps past the span add nothing but the first frame, which the step of the
            // span itself gives: walk from there, never over the number as typed.
            Step::Stagger(k) => (1..=k.min(self.span().max(1)))
                .rev()
                .for_each(|s| self.stride(s, f)),
        }
    }

    /// The first and last frames the item produces (`None` when it produces none), with
    /// the columns to blame.
    fn hull(&self) -> Option<((i64, usize), (i64, usize))> {
        let (s, e, d) = (self.start, self.end, self.dir());
        let first = (s, self.start_column);
        match self.step {
            Step::One | Step::Stagger(_) => Some((first, (e, self.end_column))),
            Step::Every(k) => {
                let last = s + d * ((self.span() / k * k) as i64);
                Some((first, (last, self.end_column)))
            }
            Step::Fill(k) => {
                if k == 1 || self.span() == 0 {
                    return None;
                }
                let last = if self.span().is_multiple_of(k) {
                    e - d
                } else {
                    e
                };
                Some(((s + d, self.start_column), (last, self.end_column)))
            }
        }
    }

    fn check_bounds(&self, count: u32) -> Result<(), SpecError> {
        let Some((a, b)) = self.hull() else {
            return Ok(());
        };
        for (frame, column) in [a, b] {
            let problem = if frame < 0 {
                ListProblem::BeforeTheStart(frame)
            } else if frame >= i64::from(count) {
                let last = count.saturating_sub(1);
                ListProblem::PastTheEnd { frame, last }
            } else {
                continue;
            };
            return Err(SpecError { column, problem });
        }
        Ok(())
    }
}

/// Reads one item.
struct Cursor<'a> {
    chars: &'a [(char, usize)],
    at: usize,
    /// The column just past the item.
    stop: usize,
}

impl Cursor<'_> {
    fn peek(&self) -> Option<char> {
        self.chars.get(self.at).map(|&(c, _)| c)
    }

    fn column(&self) -> usize {
        self.chars.get(self.at).map_or(self.stop, |&(_, col)| col)
    }

    fn fail<T>(&self, problem: ListProblem) -> Result<T, SpecError> {
        let column = self.column();
        Err(SpecError { column, problem })
    }

    fn found(&self) -> String {
        match self.peek() {
            Some(c) => format!("'{c}'"),
            None => "the end of the item".into(),
        }
    }

    /// `[-]digits`, with its column.
    fn number(&mut self) -> Result<(i64, usize), SpecError> {
        let (begin, column) = (self.at, self.column());
        if self.peek() == Some('-') {
            self.at += 1;
        }
        let digits = self.at;
        while self.peek().is_some_and(|c| c.is_ascii_digit()) {
            self.at += 1;
        }
        if self.at == digits {
            self.at = begin;
            return self.fail(ListProblem::NotANumber(self.found()));
        }
        if self.peek() == Some('.') {
            return self.fail(ListProblem::Subframe);
        }
        let text: String = self.chars[begin..self.at].iter().map(|&(c, _)| c).collect();
        match text.parse() {
            Ok(n) => Ok((n, column)),
            Err(_) => Err(SpecError {
                column,
                problem: ListProblem::TooLarge(text),
            }),
        }
    }

    fn item(mut self) -> Result<Item, SpecError> {
        let (start, start_column) = self.number()?;
        let single = Item {
            start,
            end: start,
            step: Step::One,
            start_column,
            end_column: start_column,
        };
        match self.peek() {
            None => return Ok(single),
            Some('-') => self.at += 1,
            Some(c @ ('x' | 'y' | ':')) => return self.fail(ListProblem::StepWithoutRange(c)),
            Some(_) => {
                let found = self.found();
                return self.fail(ListProblem::Unexpected {
                    found,
                    after: "a frame",
                });
            }
        }
        let (end, end_column) = self.number()?;
        let range = Item {
            end,
            end_column,
            ..single
        };
        let kind = match self.peek() {
            None => return Ok(range),
            Some(c @ ('x' | 'y' | ':')) => c,
            Some(_) => {
                let found = self.found();
                let after = "a range (a step is x, y or : and a number)";
                return self.fail(ListProblem::Unexpected { found, after });
            }
        };
        self.at += 1;
        let step_column = self.column();
        let (n, _) = self.number()?;
        if self.peek().is_some() {
            let found = self.found();
            return self.fail(ListProblem::Unexpected {
                found,
                after: "the step",
            });
        }
        let at_step = |problem| {
            Err(SpecError {
                column: step_column,
                problem,
            })
        };
        if n == 0 {
            return at_step(ListProblem::ZeroStep);
        }
        if end > start && n < 0 {
            return at_step(ListProblem::NegativeStep);
        }
        let k = n.unsigned_abs();
        let step = match kind {
            'x' => Step::Every(k),
            'y' => Step::Fill(k),
            _ => Step::Stagger(k),
        };
        Ok(Item { step, ..range })
    }
}

#[cfg(test)]
mod tests;
