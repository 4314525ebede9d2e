//! The directing aids' routes: `/api/camera?n=F` (frame F's camera as a manifest key,
//! `camera_key`) and `/api/paths?n=F` (the camera's and tracked positions' paths
//! projected with frame F's camera, `paths`). Both are computed from the live project,
//! with the same `Animation` that draws the frames; a bad parameter is a 400 as on every
//! route, a camera on the point it looks at a 422 with the command line's message.

use super::context::{number, project, Context, Reply};
use crate::project::Animation;
use serde_json::json;

/// The live project's animation and the frame `n` the query asks for.
fn frame_of(ctx: &Context, query: &str) -> Result<(u32, std::sync::Arc<crate::Project>), Reply> {
    let (_, p) = project(ctx)?;
    let n = number(query, "n", 0, p.manifest.frames - 1, None)?;
    Ok((n, p))
}

fn failed(e: crate::AnimError) -> Reply {
    Reply::error(422, format!("animate: {e}"))
}

/// `GET /api/camera?n=F`: `{frame, position, look_at, fov, fov_tracked, text}`.
pub fn camera(ctx: &Context, query: &str) -> Result<Reply, Reply> {
    let (n, p) = frame_of(ctx, query)?;
    let anim = Animation::new(&p).map_err(failed)?;
    let name = (p.manifest.path.file_name()).map_or_else(
        || "the manifest".into(),
        |n| n.to_string_lossy().to_string(),
    );
    let key = super::camera_key::camera_key(&anim, n, &name).map_err(failed)?;
    Ok(Reply::json(200, json!(key)))
}

/// `GET /api/paths?n=F`: `{frame, width, height, paths: [{name, segments, at}]}`.
pub fn paths(ctx: &Context, query: &str) -> Result<Reply, Reply> {
    let (n, p) = frame_of(ctx, query)?;
    let anim = Animation::new(&p).map_err(failed)?;
    let paths = super::paths::paths(&anim, n).map_err(failed)?;
    Ok(Reply::json(200, json!(paths)))
}
