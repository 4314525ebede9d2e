//! What every route of the view shares, below them all: the `Context` the server hands
//! each request (the live project, the frame service, the drawing pool, the bound
//! address), the `Reply` a route gives back, and the helpers that read a query
//! (`param`, `number`) and the live project (`project`). `routes`, `direct` and `strip`
//! import from here; nothing here imports a route, so the routes form no circle.

use super::frames::Frames;
use super::live::{Live, Loaded};
use serde_json::{json, Value};
use std::net::SocketAddr;
use std::sync::Arc;

/// An answer.
pub struct Reply {
    /// HTTP status.
    pub status: u16,
    /// Its `Content-Type`.
    pub content_type: &'static str,
    /// Its body.
    pub body: Arc<Vec<u8>>,
    /// Extra headers.
    pub headers: Vec<(&'static str, String)>,
}

impl Reply {
    /// `body` with `status` and `content_type`, no extra header.
    pub fn bytes(status: u16, content_type: &'static str, body: Vec<u8>) -> Reply {
        Reply {
            status,
            content_type,
            body: Arc::new(body),
            headers: Vec::new(),
        }
    }
    /// `v` as JSON with `status`.
    pub fn json(status: u16, v: Value) -> Reply {
        Reply::bytes(status, "application/json", v.to_string().into_bytes())
    }
    /// `{"error": why}` with `status`.
    pub fn error(status: u16, why: impl Into<String>) -> Reply {
        Reply::json(status, json!({ "error": why.into() }))
    }
}

/// An `/api/status` body, with the generation and folder fingerprint it was made from.
pub type CachedStatus = ((u64, u64), Vec<u8>);

/// What the routes share.
pub struct Context {
    /// The project, reloaded as it changes.
    pub live: Arc<Live>,
    /// The frame service.
    pub frames: Frames,
    /// The threads that draw (`--threads`).
    pub pool: Arc<rayon::ThreadPool>,
    /// The address the server is bound to.
    pub bound: SocketAddr,
    /// The last `/api/status` body and what it was computed from.
    pub status: std::sync::Mutex<Option<CachedStatus>>,
}

/// The query's value of `key` (the last one given).
pub fn param<'q>(query: &'q str, key: &str) -> Option<&'q str> {
    query
        .split('&')
        .filter_map(|kv| kv.split_once('=').or(Some((kv, ""))))
        .filter(|(k, _)| *k == key)
        .map(|(_, v)| v)
        .next_back()
}

/// An integer parameter in `lo..=hi`, or the 400 reason.
pub fn number(
    query: &str,
    key: &str,
    lo: u32,
    hi: u32,
    default: Option<u32>,
) -> Result<u32, Reply> {
    let Some(text) = param(query, key) else {
        return default.ok_or_else(|| Reply::error(400, format!("missing parameter `{key}`")));
    };
    let digits = !text.is_empty() && text.bytes().all(|b| b.is_ascii_digit());
    match text.parse::<u32>() {
        Ok(v) if (lo..=hi).contains(&v) => Ok(v),
        Ok(v) => Err(Reply::error(
            400,
            format!("`{key}` = {v} is out of range: expected {lo} to {hi}"),
        )),
        // A whole number too large for any range: say so, not "not a whole number".
        Err(_) if digits => Err(Reply::error(
            400,
            format!("`{key}` = {text} is out of range: expected {lo} to {hi}"),
        )),
        Err(_) => Err(Reply::error(
            400,
            format!("`{key}` = {text:?} is not a whole number"),
        )),
    }
}

/// The live project, or 503 when none ever loaded.
pub fn project(ctx: &Context) -> Result<(Loaded, Arc<crate::Project>), Reply> {
    let l = ctx.live.current();
    match l.project.clone() {
        Some(p) => Ok((l, p)),
        None => Err(Reply::json(
            503,
            json!({"error": "the manifest has not loaded yet", "detail": l.error}),
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parameters() {
        assert_eq!(param("n=3&scale=4", "scale"), Some("4"));
        assert_eq!(param("n=3&n=5", "n"), Some("5"));
        assert_eq!(param("flag", "flag"), Some(""));
        assert_eq!(param("n=3", "x"), None);
        assert!(number("n=3", "n", 0, 9, None).is_ok());
        let r = number("n=10", "n", 0, 9, None).unwrap_err();
        assert_eq!(r.status, 400);
        let body: Value = serde_json::from_slice(&r.body).unwrap();
        assert_eq!(body["error"], "`n` = 10 is out of range: expected 0 to 9");
        let r = number("n=ten", "n", 0, 9, None).unwrap_err();
        let body: Value = serde_json::from_slice(&r.body).unwrap();
        assert_eq!(body["error"], "`n` = \"ten\" is not a whole number");
        assert_eq!(number("", "scale", 1, 64, Some(1)).ok(), Some(1));
        assert_eq!(number("", "n", 0, 9, None).unwrap_err().status, 400);
    }
}
