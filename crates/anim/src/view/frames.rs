//! Frames for the page: frame n of the live project at 1/scale of its size, drawn by
//! `Animation::render_picture` (the picture its frame files hold: `render`, the very call
//! `animate` writes 8-bit frames with, or an EXR's beauty clamped and rounded, so the
//! whole frame's pixels are the written frame's pixels) and encoded as PNG (`output::encode`,
//! without the provenance chunks a frame file carries) or as the raw RGB bytes.
//!
//! - At most one render per client at a time: each client (the page's random id) has a
//!   slot; a request takes a ticket, waits for the slot, and renders only if no newer
//!   request of that client came meanwhile (else it answers "superseded"), so scrubbing
//!   never queues stale work.
//! - Recent frames are kept, up to `CACHE_BYTES`, for the current project only (a failed
//!   reload keeps it; a frame of an older one, finished after a reload, is not kept):
//!   playing a loop again, or sharpening a frame already drawn, costs nothing.

use super::live::Loaded;
use crate::error::AnimError;
use crate::preview::scaled;
use crate::project::{Animation, Project};
use std::collections::{HashMap, VecDeque};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Arc, Mutex};
use whitted::output::{encode, ImageFormat};

/// The bytes of encoded frames kept.
pub const CACHE_BYTES: usize = 48 << 20;
/// Clients remembered (each a few bytes); past this the idle ones are forgotten.
pub const MAX_CLIENTS: usize = 256;

/// How a frame is sent.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Encoding {
    /// A PNG of the pixels.
    Png,
    /// width·height·3 bytes, RGB, rows top to bottom (`.raw`).
    Raw,
}

/// What a frame request gives.
pub enum Drawn {
    /// The encoded frame, its size, and the seconds its drawing and encoding took (when it
    /// was drawn: a frame from the cache keeps its own).
    Frame(Arc<Vec<u8>>, u32, u32, f64),
    /// A newer request of the same client came first.
    Superseded,
}

#[derive(Default)]
struct Slot {
    latest: AtomicU64,
    busy: Mutex<()>,
}

type Key = (u64, u32, u32, Encoding);
/// A cached frame: its key, bytes, size and drawing seconds.
type Entry = (Key, Arc<Vec<u8>>, u32, u32, f64);

/// The frame service: client slots, the cache, and the threads that draw.
pub struct Frames {
    clients: Mutex<HashMap<String, Arc<Slot>>>,
    cache: Mutex<VecDeque<Entry>>,
    pool: Arc<rayon::ThreadPool>,
}

/// The size of a project's frames at 1/scale, by the preview's rule (`preview::scaled`:
/// to the nearest pixel, at least one a side).
pub fn scaled_size(project: &Project, scale: u32) -> (u32, u32) {
    let (w, h) = project.size();
    (scaled(w, scale), scaled(h, scale))
}

/// Draws frame `frame` of `project` at 1/scale, encoded.
pub fn draw(
    project: &Project,
    frame: u32,
    scale: u32,
    encoding: Encoding,
) -> Result<(Vec<u8>, u32, u32), AnimError> {
    let (w, h) = scaled_size(project, scale);
    let anim = Animation::with_size(project, w, h)?;
    let (image, _) = anim.render_picture(&anim.plan(frame))?;
    let bytes = match encoding {
        Encoding::Raw => image.pixels,
        Encoding::Png => {
            let mut out = Vec::new();
            encode(&image, ImageFormat::Png, &[], &mut out)
                .map_err(|e| AnimError::Write { frame, source: e })?;
            out
        }
    };
    Ok((bytes, anim.width, anim.height))
}

impl Frames {
    /// A frame service drawing on `pool`.
    pub fn new(pool: Arc<rayon::ThreadPool>) -> Frames {
        Frames {
            clients: Mutex::default(),
            cache: Mutex::default(),
            pool,
        }
    }

    fn slot(&self, client: &str) -> Arc<Slot> {
        let mut clients = self.clients.lock().unwrap_or_else(|e| e.into_inner());
        if clients.len() >= MAX_CLIENTS && !clients.contains_key(client) {
            // Forget the clients nobody is rendering for.
            clients.retain(|_, s| Arc::strong_count(s) > 1);
        }
        Arc::clone(clients.entry(client.to_string()).or_default())
    }

    fn cached(&self, key: &Key) -> Option<Drawn> {
        let cache = self.cache.lock().unwrap_or_else(|e| e.into_inner());
        cache
            .iter()
            .find(|(k, ..)| k == key)
            .map(|(_, b, w, h, s)| Drawn::Frame(Arc::clone(b), *w, *h, *s))
    }

    /// Keeps a frame of project `key.0`, dropping those of older projects; a frame of an
    /// older project than one cached (a render begun before a reload) is not kept.
    fn keep(&self, key: Key, bytes: Arc<Vec<u8>>, w: u32, h: u32, secs: f64) {
        let mut cache = self.cache.lock().unwrap_or_else(|e| e.into_inner());
        if cache.iter().any(|(k, ..)| k.0 > key.0) {
            return;
        }
        cache.retain(|(k, ..)| k.0 == key.0);
        cache.push_back((key, bytes, w, h, secs));
        let mut total: usize = cache.iter().map(|(_, b, ..)| b.len()).sum();
        while total > CACHE_BYTES && cache.len() > 1 {
            if let Some((_, b, ..)) = cache.pop_front() {
                total -= b.len();
            }
        }
    }

    /// Frame `frame` at 1/scale for `client`, from the cache or drawn.
    pub fn get(
        &self,
        loaded: &Loaded,
        project: &Project,
        client: &str,
        frame: u32,
        scale: u32,
        encoding: Encoding,
    ) -> Result<Drawn, AnimError> {
        let key = (loaded.project_id, frame, scale, encoding);
        let slot = self.slot(client);
        let ticket = slot.latest.fetch_add(1, Ordering::SeqCst) + 1;
        if let Some(drawn) = self.cached(&key) {
            return Ok(drawn);
        }
        let _busy = slot.busy.lock().unwrap_or_else(|e| e.into_inner());
        if slot.latest.load(Ordering::SeqCst) != ticket {
            return Ok(Drawn::Superseded);
        }
        if let Some(drawn) = self.cached(&key) {
            return Ok(drawn);
        }
        let start = std::time::Instant::now();
        let (bytes, w, h) = self
            .pool
            .install(|| draw(project, frame, scale, encoding))?;
        let secs = start.elapsed().as_secs_f64();
        let bytes = Arc::new(bytes);
        self.keep(key, Arc::clone(&bytes), w, h, secs);
        Ok(Drawn::Frame(bytes, w, h, secs))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::view::live::Live;

    const SCENE: &str = "16 12  0 1 6  0 1 0  0 0  1 0 0 1
1.0  0 1 0   1 0.9 0.2 0.1   0.7 0.3 0 1 0 0
5 10 5  1 1 1  0.9";

    fn live() -> (tempfile::TempDir, std::path::PathBuf, Live) {
        let dir = tempfile::tempdir().unwrap();
        std::fs::write(dir.path().join("s.txt"), SCENE).unwrap();
        let path = dir.path().join("m.toml");
        std::fs::write(&path, "scene = \"s.txt\"\nframes = 4\n").unwrap();
        let live = Live::new(&path).unwrap();
        (dir, path, live)
    }

    fn service() -> Frames {
        Frames::new(Arc::new(whitted_cmd::process::pool(Some(1)).unwrap()))
    }

    fn frame(frames: &Frames, live: &Live) -> Arc<Vec<u8>> {
        let loaded = live.current();
        let project = loaded.project.clone().unwrap();
        match frames.get(&loaded, &project, "c", 1, 1, Encoding::Raw) {
            Ok(Drawn::Frame(b, ..)) => b,
            _ => panic!("no frame"),
        }
    }

    #[test]
    fn a_stale_frame_neither_wipes_nor_joins_the_cache() {
        let frames = service();
        let bytes = || Arc::new(vec![1u8; 3]);
        frames.keep((2, 0, 1, Encoding::Raw), bytes(), 1, 1, 0.1);
        // A render begun before the reload ends after it.
        frames.keep((1, 0, 1, Encoding::Raw), bytes(), 1, 1, 0.1);
        assert!(frames.cached(&(2, 0, 1, Encoding::Raw)).is_some());
        assert!(frames.cached(&(1, 0, 1, Encoding::Raw)).is_none());
        // A newer generation replaces the older ones.
        frames.keep((3, 0, 1, Encoding::Raw), bytes(), 1, 1, 0.1);
        assert!(frames.cached(&(2, 0, 1, Encoding::Raw)).is_none());
        assert!(frames.cached(&(3, 0, 1, Encoding::Raw)).is_some());
    }

    #[test]
    fn a_failed_reload_keeps_the_cache_and_a_good_one_clears_it() {
        let (_dir, path, live) = live();
        let frames = service();
        let first = frame(&frames, &live);
        assert!(Arc::ptr_eq(&first, &frame(&frames, &live)), "not cached");
        let good = std::fs::read_to_string(&path).unwrap();
        std::fs::write(&path, "scene = \"s.txt\"\nframes = 0\n").unwrap();
        live.reload();
        assert!(live.current().error.is_some());
        assert!(
            Arc::ptr_eq(&first, &frame(&frames, &live)),
            "the same project drawn again after a failed reload"
        );
        std::fs::write(&path, good).unwrap();
        live.reload();
        assert!(
            !Arc::ptr_eq(&first, &frame(&frames, &live)),
            "a reload kept old frames"
        );
    }
}
