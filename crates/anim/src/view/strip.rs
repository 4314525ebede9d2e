//! `/api/status`: the state of every frame of the output folder (up to date, stale,
//! missing), as the page's strip shows it. The states hash every RAW frame, so an answer
//! is kept and given again while neither the project nor the folder changed.

use super::context::{project, Context, Reply};
use crate::frames::status::states;
use crate::project::Animation;
use serde_json::json;

/// `GET /api/status`: `{generation, folder, states}`.
pub fn strip(ctx: &Context) -> Reply {
    let (loaded, p) = match project(ctx) {
        Ok(v) => v,
        Err(r) => return r,
    };
    let anim = match Animation::new(&p) {
        Ok(a) => a,
        Err(e) => return Reply::error(422, format!("animate: {e}")),
    };
    let dir = &p.manifest.output.dir;
    // The states hash every RAW frame: computed again only when the project or a file of
    // the folder (its name, size or time) changed since the last answer.
    let key = (loaded.generation, folder_fingerprint(dir));
    if let Ok(cached) = ctx.status.lock() {
        if let Some((_, body)) = cached.as_ref().filter(|(k, _)| *k == key) {
            return Reply::bytes(200, "application/json", body.to_vec());
        }
    }
    let frames: Vec<u32> = (0..p.manifest.frames).collect();
    let states = ctx.pool.install(|| states(&anim, dir, &frames, false));
    let reply = Reply::json(
        200,
        json!({"generation": loaded.generation, "folder": dir.display().to_string(),
               "states": states}),
    );
    if let Ok(mut cached) = ctx.status.lock() {
        *cached = Some((key, reply.body.to_vec()));
    }
    reply
}

/// A hash of the names, sizes and modification times of the files of `dir` and of its
/// RAW records: it changes whenever a frame is written, replaced or removed.
fn folder_fingerprint(dir: &std::path::Path) -> u64 {
    use std::hash::{Hash, Hasher};
    let mut h = std::collections::hash_map::DefaultHasher::new();
    for d in [
        dir.to_path_buf(),
        dir.join(crate::frames::provenance::RAW_RECORDS),
    ] {
        let mut entries: Vec<(std::ffi::OsString, u64, Option<std::time::SystemTime>)> =
            std::fs::read_dir(&d)
                .into_iter()
                .flatten()
                .flatten()
                .map(|e| {
                    let meta = e.metadata().ok();
                    let len = meta.as_ref().map_or(0, |m| m.len());
                    (e.file_name(), len, meta.and_then(|m| m.modified().ok()))
                })
                .collect();
        entries.sort();
        entries.hash(&mut h);
    }
    h.finish()
}
