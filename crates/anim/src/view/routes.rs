//! The view's routes, as a function from a request (method, target, Host) to a reply;
//! `server` carries them over HTTP. Nothing here opens a file by a name from a request:
//! the page's three assets are inside the binary, and every other answer is computed.
//!
//! | route | answer |
//! |---|---|
//! | `GET /`, `/app.js`, `/direct.js`, `/ab.js`, `/app.css` | the page (`assets`) |
//! | `GET /api/state` | `{generation, error, frames, fps, width, height, manifest}` |
//! | `GET /api/wait?since=G` | the same, once the generation is not G (or after 20 s) |
//! | `GET /api/frame?n=F&scale=S&client=C[&format=raw]` | frame F at 1/S (S 1..=64), PNG or RGB bytes; 409 when a newer request of client C superseded it |
//! | `GET /api/pick?n=F&x=X&y=Y` | `{hit}`: what the camera ray through pixel (X, Y) of the whole frame F hits (`pick`) |
//! | `GET /api/camera?n=F` | frame F's camera as a manifest key (`camera_key`) |
//! | `GET /api/paths?n=F` | the camera's and tracked positions' paths on frame F's picture (`paths`) |
//! | `GET /api/status` | `{generation, folder, states}`: every frame up-to-date, stale or missing in the output folder |
//!
//! A request whose `Host` is not this server's bound name is refused (403); a bad
//! parameter gets 400 and `{"error": reason}`; an unknown route 404, a method other than
//! GET or HEAD 405, all with a JSON reason.

use super::context::{number, param, project, Context, Reply};
use super::frames::{Drawn, Encoding};
use super::live::{Live, Loaded};
use crate::project::Animation;
use serde_json::{json, Value};
use std::net::SocketAddr;
use std::time::Duration;

/// How long `/api/wait` holds a request when nothing changes.
pub const WAIT: Duration = Duration::from_secs(20);
/// The largest divisor of the frame's size a request may ask for.
pub const MAX_SCALE: u32 = 64;

/// Whether `host` (a `Host` header) names this server: `IP:PORT` of the bound address,
/// or `localhost:PORT` when it is a loopback one. Bound to every interface (0.0.0.0,
/// ::), any IP literal with the port is this server; a DNS name never is (DNS
/// rebinding).
pub fn host_ok(host: &str, bound: SocketAddr) -> bool {
    let port = bound.port();
    let Some((name, p)) = host.rsplit_once(':') else {
        return false;
    };
    if p.parse::<u16>() != Ok(port) {
        return false;
    }
    let name = name.trim_start_matches('[').trim_end_matches(']');
    if name.eq_ignore_ascii_case("localhost") {
        return bound.ip().is_loopback() || bound.ip().is_unspecified();
    }
    match name.parse::<std::net::IpAddr>() {
        Ok(ip) => ip == bound.ip() || bound.ip().is_unspecified(),
        Err(_) => false,
    }
}

/// The refusal of a request another site's page made (an `<img>`, a `fetch`, a form):
/// `Sec-Fetch-Site` other than `same-origin` or `none` (a browser's own navigation), or
/// an `Origin` that is not this server's. Such a request is answered 403 before anything
/// is rendered, whatever its method.
pub fn cross_site(
    origin: Option<&str>,
    fetch_site: Option<&str>,
    bound: SocketAddr,
) -> Option<Reply> {
    if let Some(site) = fetch_site {
        if !matches!(site.trim(), "same-origin" | "none") {
            return Some(Reply::error(
                403,
                format!("a request from another site (Sec-Fetch-Site: {site}): refused"),
            ));
        }
    }
    let origin = origin?.trim();
    let host = origin.strip_prefix("http://");
    match host.filter(|h| !h.contains('/') && host_ok(h, bound)) {
        Some(_) => None,
        None => Some(Reply::error(
            403,
            format!("a request from another origin ({origin}): refused"),
        )),
    }
}

fn state(l: &Loaded, live: &Live) -> Value {
    let manifest = live.manifest().display().to_string();
    match &l.project {
        Some(p) => {
            let (width, height) = p.size();
            json!({
                "generation": l.generation, "error": l.error, "manifest": manifest,
                "frames": p.manifest.frames, "fps": p.manifest.fps,
                "width": width, "height": height,
            })
        }
        None => json!({"generation": l.generation, "error": l.error, "manifest": manifest,
                       "frames": null}),
    }
}

/// Answers one request.
pub fn answer(ctx: &Context, method: &str, target: &str, host: Option<&str>) -> Reply {
    match host {
        Some(h) if host_ok(h, ctx.bound) => {}
        Some(h) => {
            return Reply::error(
                403,
                format!("Host {h:?} is not this server ({}): refused", ctx.bound),
            )
        }
        None => return Reply::error(403, "no Host header: refused"),
    }
    if method != "GET" && method != "HEAD" {
        return Reply::error(405, format!("{method} is not served: GET only"));
    }
    let (path, query) = target.split_once('?').unwrap_or((target, ""));
    if let Some(a) = super::assets::find(path) {
        return Reply::bytes(200, a.content_type, a.text.into());
    }
    match path {
        "/api/state" => Reply::json(200, state(&ctx.live.current(), &ctx.live)),
        "/api/wait" => match number(query, "since", 0, u32::MAX, Some(0)) {
            Ok(since) => Reply::json(
                200,
                state(&ctx.live.wait(u64::from(since), WAIT), &ctx.live),
            ),
            Err(r) => r,
        },
        "/api/frame" => frame(ctx, query).unwrap_or_else(|r| r),
        "/api/pick" => pick(ctx, query).unwrap_or_else(|r| r),
        "/api/status" => super::strip::strip(ctx),
        "/api/camera" => super::direct::camera(ctx, query).unwrap_or_else(|r| r),
        "/api/paths" => super::direct::paths(ctx, query).unwrap_or_else(|r| r),
        _ => Reply::error(404, format!("no route {path:?}")),
    }
}

fn frame(ctx: &Context, query: &str) -> Result<Reply, Reply> {
    let (loaded, p) = project(ctx)?;
    let last = p.manifest.frames - 1;
    let n = number(query, "n", 0, last, None)?;
    let scale = number(query, "scale", 1, MAX_SCALE, Some(1))?;
    let client = param(query, "client").unwrap_or("anonymous");
    if client.is_empty()
        || client.len() > 64
        || !client
            .bytes()
            .all(|b| b.is_ascii_alphanumeric() || b == b'-')
    {
        return Err(Reply::error(
            400,
            "`client` must be 1 to 64 letters, digits or -",
        ));
    }
    let encoding = match param(query, "format").unwrap_or("png") {
        "png" => Encoding::Png,
        "raw" => Encoding::Raw,
        other => {
            return Err(Reply::error(
                400,
                format!("`format` = {other:?}: expected png or raw"),
            ))
        }
    };
    let drawn = ctx.frames.get(&loaded, &p, client, n, scale, encoding);
    match drawn {
        Ok(Drawn::Frame(body, w, h, secs)) => Ok(Reply {
            status: 200,
            content_type: match encoding {
                Encoding::Png => "image/png",
                Encoding::Raw => "application/octet-stream",
            },
            body,
            headers: vec![
                ("X-Frame", n.to_string()),
                ("X-Size", format!("{w}x{h}")),
                ("X-Generation", loaded.generation.to_string()),
                ("X-Render-Seconds", format!("{secs:.4}")),
            ],
        }),
        Ok(Drawn::Superseded) => Err(Reply::error(
            409,
            "superseded by a newer request of this client",
        )),
        Err(e) => Err(Reply::error(422, format!("animate: {e}"))),
    }
}

fn pick(ctx: &Context, query: &str) -> Result<Reply, Reply> {
    let (_, p) = project(ctx)?;
    let (w, h) = p.size();
    let n = number(query, "n", 0, p.manifest.frames - 1, None)?;
    let x = number(query, "x", 0, w - 1, None)?;
    let y = number(query, "y", 0, h - 1, None)?;
    let anim = Animation::new(&p).map_err(|e| Reply::error(422, format!("animate: {e}")))?;
    let hit = anim
        .pick(n, x, y)
        .map_err(|e| Reply::error(422, format!("animate: {e}")))?;
    Ok(Reply::json(
        200,
        json!({ "frame": n, "x": x, "y": y, "hit": hit }),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hosts() {
        let lo: SocketAddr = "127.0.0.1:8417".parse().unwrap();
        assert!(host_ok("127.0.0.1:8417", lo));
        assert!(host_ok("localhost:8417", lo));
        assert!(host_ok("LOCALHOST:8417", lo));
        assert!(!host_ok("127.0.0.1:8418", lo));
        assert!(!host_ok("127.0.0.1", lo));
        assert!(!host_ok("evil.example:8417", lo));
        assert!(!host_ok("10.0.0.1:8417", lo));
        let v6: SocketAddr = "[::1]:9".parse().unwrap();
        assert!(host_ok("[::1]:9", v6));
        let any: SocketAddr = "0.0.0.0:9".parse().unwrap();
        assert!(host_ok("192.168.1.4:9", any));
        assert!(!host_ok("rebind.example:9", any));
    }
}
