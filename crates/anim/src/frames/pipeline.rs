//! Producing frames: rendered in parallel with rayon, then either written into a folder
//! or streamed in frame order, every step reported as an `Event`.
//!
//! - Folder: the run holds the folder's lock (`lock`) and, alone in it, clears the
//!   temporaries killed runs left (`folder::take`); frames render in windows of four per thread; each is encoded
//!   with its provenance (`provenance`), written to a temporary name in the folder, then
//!   renamed, so a file under a final name is always complete. Each frame is claimed
//!   first (`claim`): runs of the same manifest in one folder render each frame once, a
//!   frame another run holds is left, then waited for at the end and taken over if that
//!   run died. With `resume`, frames
//!   whose file records the digest the manifest now gives them are left untouched
//!   (`status`); frames recorded by another manifest, files the tool did not write and,
//!   for a draft, the manifest's finals are not overwritten unless forced.
//! - Stream (`--stdout`, `--video`): frames render in windows of twice the thread count
//!   and are written in order.
//!
//! A window never holds more than `FRAME_MEMORY` of frames, so memory stays bounded
//! whatever the frame count, the frame size or the thread count. Both stop between frames
//! when `stop` holds a signal number, and after the first failure; the frames already
//! finished stay finished.

use super::claim::Claims;
use super::cost::{self, Meter};
use super::events::{Event, Reporter};
use super::folder;
use super::found::{found, refuse_foreign, Found};
use super::owner::{self, Owner};
use super::policy::Policy;
use super::provenance::{self, raw_record_path};
use super::status;
use crate::error::AnimError;
use crate::project::{Animation, FramePlan};
use rayon::prelude::*;
use std::io::Write;
use std::path::Path;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;
use std::time::Instant;
use whitted::output::{encode, temp_beside, write_atomic, ImageFormat, OutputError};
use whitted::trace::RayCount;
use whitted_cmd::process::stopped;

pub use crate::project::FRAME_MEMORY;

/// What a run did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Summary {
    /// Frames rendered and delivered by this run.
    pub rendered: usize,
    /// Frames left as they were because they were up to date (`--resume`).
    pub skipped: usize,
    /// Frames rendered by another run sharing the folder (`claim`).
    pub elsewhere: usize,
    /// All rays cast by the rendered frames, by kind.
    pub rays: RayCount,
}

/// A write error with the frame's path in it: the encoder's own errors (a full disk
/// while encoding) name no file.
fn with_path(path: &Path, e: OutputError) -> OutputError {
    match e {
        OutputError::Stream(source) | OutputError::Encode(image::ImageError::IoError(source)) => {
            OutputError::Io {
                path: path.to_path_buf(),
                source,
            }
        }
        other => other,
    }
}

/// Renders the plan's frame (a recorded plan: drawing it makes its digest) and writes it
/// with its provenance under its final name (the plan's path); a RAW frame's record,
/// written after it, carries the SHA-256 of its pixels.
fn write_frame(plan: &FramePlan, meter: &Meter) -> Result<RayCount, AnimError> {
    let measuring = meter.start();
    let (anim, frame, path) = (plan.anim(), plan.frame(), plan.path());
    let write = |source| AnimError::Write { frame, source };
    let format = anim.format();
    let rays = if format.is_layered() {
        // EXR: the beauty unclamped and the passes, provenance in the header.
        let (layers, rays) = anim.render_layers(plan, format.passes())?;
        let stamp = provenance::stamp(plan);
        write_atomic(path, layers, format, &stamp).map_err(|e| write(with_path(path, e)))?;
        rays
    } else {
        let (image, rays) = anim.render(plan)?;
        let mut stamp = provenance::stamp(plan);
        write_atomic(path, &image, format, &stamp).map_err(|e| write(with_path(path, e)))?;
        if format == ImageFormat::Raw {
            stamp.push(provenance::pixels_line(&image.pixels));
            write_raw_record(path, &stamp).map_err(|source| {
                write(OutputError::Io {
                    path: raw_record_path(path),
                    source,
                })
            })?;
        }
        rays
    };
    let digest = plan.digest().to_string();
    let spent = meter.finish(measuring, frame, digest, &rays);
    cost::write(path, &spent).map_err(|source| {
        write(OutputError::Io {
            path: cost::cost_path(path),
            source,
        })
    })?;
    Ok(rays)
}

/// The record of a RAW frame, written atomically after the frame itself.
fn write_raw_record(frame_path: &Path, stamp: &[(String, String)]) -> std::io::Result<()> {
    let path = raw_record_path(frame_path);
    if let Some(dir) = path.parent() {
        std::fs::create_dir_all(dir)?;
    }
    let mut tmp = temp_beside(&path)?;
    for (k, v) in stamp {
        writeln!(tmp, "{k}: {v}")?;
    }
    tmp.persist(path).map_err(|e| e.error)?;
    Ok(())
}

/// Renders `frames` into `dir` (created if missing), in parallel, holding the folder's
/// lock; temporaries that killed runs left are removed first. With `policy.resume`,
/// frames that are up to date are skipped (and reported so); frames recorded by another
/// manifest are refused unless `policy.force`.
pub(crate) fn render_to_folder(
    anim: &Animation,
    frames: &[u32],
    dir: &Path,
    policy: &Policy,
    reporter: &dyn Reporter,
    stop: &AtomicUsize,
) -> Result<Summary, AnimError> {
    std::fs::create_dir_all(dir).map_err(|source| AnimError::Folder {
        dir: dir.to_path_buf(),
        source,
    })?;
    let lock = folder::take(anim, dir)?;
    // Each file is inspected once, in parallel, for both answers.
    let ours = anim.manifest.path.file_name().map(|n| n.to_string_lossy());
    let seen: Vec<Found> = frames
        .par_iter()
        .map(|&f| found(anim, dir, f, policy, ours.as_deref()))
        .collect();
    let (mut todo, mut done, mut foreign, mut unrecorded, mut finals) =
        (Vec::new(), Vec::new(), Vec::new(), Vec::new(), Vec::new());
    for (&f, seen) in frames.iter().zip(seen) {
        match seen {
            Found::UpToDate => done.push(f),
            Found::Foreign(m) => foreign.push((f, m)),
            Found::Unrecorded(path) => unrecorded.push((path, Owner::Nobody)),
            Found::Final => finals.push(f),
            Found::Render => todo.push(f),
        }
    }
    refuse_foreign(dir, &foreign)?;
    if let Some(refusal) = owner::refusal("replaced", &unrecorded) {
        return Err(refusal);
    }
    if !finals.is_empty() {
        return Err(AnimError::Finals {
            dir: dir.to_path_buf(),
            frames: status::ranges(&finals),
            count: finals.len(),
            draft: anim.manifest.draft.clone().unwrap_or_default(),
        });
    }
    if let Some(pid) = lock.shared_with() {
        reporter.event(Event::Sharing { pid });
    }
    let claims = Claims::new(dir, lock.since())?;
    reporter.event(Event::Started {
        total: frames.len(),
        skipped: done.len(),
    });
    for &frame in &done {
        reporter.event(Event::Skipped { frame });
    }

    let failure: Mutex<Option<AnimError>> = Mutex::new(None);
    let fail = |e: AnimError| {
        if let Ok(mut slot) = failure.lock() {
            slot.get_or_insert(e);
        }
    };
    let failed = || failure.lock().map(|f| f.is_some()).unwrap_or(true);
    let meter = Meter::default();
    let (busy, elsewhere, rendered) = (
        Mutex::new(Vec::new()),
        AtomicUsize::new(0),
        AtomicUsize::new(0),
    );
    // One frame: claimed (now, or with `wait` once its holder lets go), then rendered,
    // encoded and written on its worker unless another run wrote it meanwhile; the first
    // failure is kept.
    let work = |frame: u32, wait: bool| -> RayCount {
        if stopped(stop).is_some() || failed() {
            return RayCount::default();
        }
        // The frame's plan: its path now, its states and digest at their first ask.
        let plan = anim.plan_in(dir, frame).recorded();
        let path = plan.path();
        let claimed = match wait {
            true => claims.claim(path).map(Some),
            false => claims.try_claim(path),
        };
        let _claim = match claimed {
            Ok(Some(claim)) => claim,
            Ok(None) => {
                busy.lock().map(|mut b| b.push(frame)).unwrap_or(());
                return RayCount::default();
            }
            Err(source) => {
                reporter.event(Event::Failed { frame });
                fail(AnimError::Folder {
                    dir: dir.join(super::claim::CLAIMS),
                    source,
                });
                return RayCount::default();
            }
        };
        if claims.done_elsewhere(&plan) {
            elsewhere.fetch_add(1, Ordering::Relaxed);
            reporter.event(Event::Elsewhere { frame });
            return RayCount::default();
        }
        let start = Instant::now();
        match write_frame(&plan, &meter) {
            Ok(rays) => {
                let seconds = start.elapsed().as_secs_f64();
                rendered.fetch_add(1, Ordering::Relaxed);
                reporter.event(Event::Finished {
                    frame,
                    seconds,
                    rays,
                });
                rays
            }
            Err(AnimError::Interrupted(_)) => RayCount::default(), // stopped mid-frame
            Err(e) => {
                reporter.event(Event::Failed { frame });
                fail(e);
                RayCount::default()
            }
        }
    };
    let pass = |frames: &[u32], wait: bool| {
        frames
            .chunks(anim.window(4))
            .map(|chunk| {
                let sum = |a, b| a + b;
                chunk
                    .par_iter()
                    .map(|&f| work(f, wait))
                    .reduce(RayCount::default, sum)
            })
            .fold(RayCount::default(), |a, b| a + b)
    };
    let mut rays = pass(&todo, false);
    // Frames another live run held: each waited for, then written by it or taken over.
    let mut held = busy
        .lock()
        .map(|mut b| std::mem::take(&mut *b))
        .unwrap_or_default();
    let order: std::collections::HashMap<u32, usize> =
        todo.iter().enumerate().map(|(i, &f)| (f, i)).collect();
    held.sort_by_key(|f| order.get(f).copied());
    rays = rays + pass(&held, true);

    drop(lock);
    if let Some(e) = failure.into_inner().unwrap_or(None) {
        return Err(e);
    }
    if let Some(sig) = stopped(stop) {
        return Err(AnimError::Interrupted(sig));
    }
    Ok(Summary {
        rendered: rendered.into_inner(),
        skipped: done.len(),
        elsewhere: elsewhere.into_inner(),
        rays,
    })
}

/// Renders `frames` and writes them, encoded in `format`, one after another in frame order
/// into `out`. Frames render in parallel windows; memory is bounded by the window.
pub(crate) fn render_to_stream(
    anim: &Animation,
    frames: &[u32],
    out: &mut dyn Write,
    format: ImageFormat,
    reporter: &dyn Reporter,
    stop: &AtomicUsize,
) -> Result<Summary, AnimError> {
    reporter.event(Event::Started {
        total: frames.len(),
        skipped: 0,
    });
    let window = anim.window(2);
    let mut rays = RayCount::default();
    for chunk in frames.chunks(window) {
        if let Some(sig) = stopped(stop) {
            return Err(AnimError::Interrupted(sig));
        }
        type Encoded = Result<(Vec<u8>, RayCount, f64), AnimError>;
        let encoded: Vec<Encoded> = chunk
            .par_iter()
            .map(|&frame| {
                let start = Instant::now();
                let (image, rays) = anim.render_picture(&anim.plan(frame))?;
                let mut bytes = Vec::with_capacity(image.pixels.len() + 32);
                encode(&image, format, &[], &mut bytes)
                    .map_err(|source| AnimError::Write { frame, source })?;
                Ok((bytes, rays, start.elapsed().as_secs_f64()))
            })
            .collect();
        for (item, &frame) in encoded.into_iter().zip(chunk) {
            let (bytes, r, seconds) = item?;
            out.write_all(&bytes).map_err(AnimError::Stream)?;
            rays = rays + r;
            reporter.event(Event::Finished {
                frame,
                seconds,
                rays: r,
            });
        }
    }
    out.flush().map_err(AnimError::Stream)?;
    Ok(Summary {
        rendered: frames.len(),
        rays,
        ..Summary::default()
    })
}
