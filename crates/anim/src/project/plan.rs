//! A frame's plan, built once and passed on: where its file goes (`OutputSpec::path`),
//! its scene and camera at each time it samples, the state at its own time (the stamp's
//! camera, an EXR header's) and its digest (`digest`). Each part is made at its first
//! ask and kept, so a run that checks a frame's file, draws it and records it builds the
//! frame's scene (a copy, when tracks change it) once; a check that never asks for the
//! digest never hashes.
//!
//! A frame without motion blur keeps its one state. A blurred frame's sub-frame states
//! are made one at a time and let go after their sub-frame is drawn (a frame of 64
//! sub-frames of a large scene never holds 64 copies of it); a plan whose frame is
//! written with its provenance (`recorded`) hashes each into the digest as it is handed
//! out, so drawing the frame makes its digest too.
//!
//! ```text
//! let plan = anim.plan_in(dir, frame).recorded(); // its path now; nothing built yet
//! anim.render(&plan)?                             // its states, drawn (and hashed)
//! provenance::stamp(&plan)                        // the digest, the camera at its time
//! ```

use super::digest::Hashing;
use super::Animation;
use crate::timeline::Snapshot;
use std::borrow::Cow;
use std::cell::OnceCell;
use std::path::{Path, PathBuf};

/// What a frame is made from, and where it goes.
pub struct FramePlan<'a> {
    anim: &'a Animation<'a>,
    frame: u32,
    path: PathBuf,
    times: Vec<f64>,
    /// The one state of a frame without motion blur.
    kept: OnceCell<Snapshot<'a>>,
    /// A blurred frame's state at its own time.
    own: OnceCell<Snapshot<'a>>,
    digest: OnceCell<String>,
    recorded: bool,
}

impl<'a> FramePlan<'a> {
    /// This plan, for a frame written with its provenance: going through its samples to
    /// draw it makes its digest on the way.
    pub fn recorded(self) -> FramePlan<'a> {
        FramePlan {
            recorded: true,
            ..self
        }
    }

    /// The animation the plan is of (its settings are part of the digest).
    pub fn anim(&self) -> &'a Animation<'a> {
        self.anim
    }

    /// The frame's number.
    pub fn frame(&self) -> u32 {
        self.frame
    }

    /// Where the frame's file goes: in the manifest's `[output] dir`, or in the folder the
    /// plan was made for (`Animation::plan_in`).
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// The times the frame samples: its own, or its motion-blur sub-frames'.
    pub fn times(&self) -> &[f64] {
        &self.times
    }

    /// Whether the frame has one time, its own (no motion blur).
    fn single(&self) -> bool {
        self.times[..] == [f64::from(self.frame)]
    }

    /// The scene and camera at each of `times`, in order: the kept state of a frame
    /// without motion blur, or each sub-frame's made as it is reached. Going through all
    /// of a recorded plan's makes its digest, if nothing has yet.
    pub fn samples(&self) -> Samples<'_, 'a> {
        self.samples_hashed(self.recorded)
    }

    /// `samples`, hashing a blurred frame's states into its digest when `hash` says so
    /// and the digest is not made yet.
    fn samples_hashed(&self, hash: bool) -> Samples<'_, 'a> {
        let hashing = match self.digest.get() {
            None if hash && !self.single() => Some(Hashing::new(self.anim)),
            _ => None,
        };
        Samples {
            plan: self,
            next: 0,
            hashing,
        }
    }

    /// The scene and camera at the frame's own time (its one sample without motion blur).
    pub fn own(&self) -> &Snapshot<'a> {
        let t = f64::from(self.frame);
        match self.single() {
            true => self.kept.get_or_init(|| self.anim.timeline.at(t)),
            false => self.own.get_or_init(|| self.anim.timeline.at(t)),
        }
    }

    /// The frame's digest, lower-case hex (`digest`): made at the first ask, from the
    /// states of its times (or by the pass over them that drew it), and kept.
    pub fn digest(&self) -> &str {
        if self.digest.get().is_none() && self.single() {
            let mut hashing = Hashing::new(self.anim);
            hashing.add(self.own());
            let _ = self.digest.set(hashing.finish());
        }
        if self.digest.get().is_none() {
            self.samples_hashed(true).for_each(drop); // going through them all makes it
        }
        self.digest.get().map_or("", String::as_str)
    }
}

/// The states of a plan's times, in order (`FramePlan::samples`).
pub struct Samples<'s, 'a> {
    plan: &'s FramePlan<'a>,
    next: usize,
    hashing: Option<Hashing>,
}

impl<'s, 'a> Iterator for Samples<'s, 'a> {
    type Item = Cow<'s, Snapshot<'a>>;

    fn next(&mut self) -> Option<Self::Item> {
        let plan = self.plan;
        let Some(&t) = plan.times.get(self.next) else {
            if let Some(hashing) = self.hashing.take() {
                let _ = plan.digest.set(hashing.finish());
            }
            return None;
        };
        self.next += 1;
        if plan.single() {
            return Some(Cow::Borrowed(plan.own()));
        }
        let state = plan.anim.timeline.at(t);
        if let Some(hashing) = &mut self.hashing {
            hashing.add(&state);
        }
        Some(Cow::Owned(state))
    }
}

impl<'p> Animation<'p> {
    /// The plan of frame `frame`, its file in the manifest's `[output] dir`.
    pub fn plan<'a>(&'a self, frame: u32) -> FramePlan<'a> {
        self.plan_in(&self.manifest.output.dir, frame)
    }

    /// The plan of frame `frame`, its file in `dir` (`--out`, a draft's folder).
    pub fn plan_in<'a>(&'a self, dir: &Path, frame: u32) -> FramePlan<'a> {
        FramePlan {
            anim: self,
            frame,
            path: self.frame_path(dir, frame),
            times: self.timeline.times(frame),
            kept: OnceCell::new(),
            own: OnceCell::new(),
            digest: OnceCell::new(),
            recorded: false,
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::project::{Animation, Project};

    const SCENE: &str = "8 6  0 1 6  0 1 0  0 0  1 0 0 1
1.0  0 1 0   1 0.9 0.2 0.1   0.7 0.3 0 1 0 0
5 10 5  1 1 1  0.9";

    fn project(dir: &std::path::Path, render: &str) -> Project {
        std::fs::write(dir.join("s.txt"), SCENE).unwrap();
        let track = "[[track]]\ntarget = \"sphere 1 center\"\nkeys = [{ frame = 0, value = [-1.0, 1.0, 0.0] }, { frame = 3, value = [1.0, 1.0, 0.0] }]\n";
        let path = dir.join("m.toml");
        let text = format!("scene = \"s.txt\"\nframes = 4\n{render}{track}");
        std::fs::write(&path, text).unwrap();
        Project::load(&path).unwrap()
    }

    #[test]
    fn drawing_a_recorded_plan_makes_the_digest_a_plan_alone_makes() {
        let dir = tempfile::tempdir().unwrap();
        for render in [
            "",
            "[render]\nmotion_blur = { shutter = 1.0, samples = 4 }\n",
        ] {
            let p = project(dir.path(), render);
            let anim = Animation::new(&p).unwrap();
            let recorded = anim.plan(2).recorded();
            let (drawn, _) = anim.render(&recorded).unwrap();
            let blurred = !render.is_empty();
            // A blurred frame's states were hashed as they were drawn; one state is kept.
            assert_eq!(recorded.digest.get().is_some(), blurred, "{render}");
            assert_eq!(recorded.digest(), anim.plan(2).digest(), "{render}");
            assert_ne!(recorded.digest(), anim.plan(1).digest(), "{render}");
            // Drawn from a plain plan (no hashing on the way): the same picture.
            let plain = anim.plan(2);
            assert_eq!(anim.render(&plain).unwrap().0, drawn);
            assert!(plain.digest.get().is_none());
            assert_eq!(plain.times().len(), if blurred { 4 } else { 1 });
        }
    }
}
