//! The HTTP side of `animate view`: hyper 1 (HTTP/1.1 only) over one tokio thread, which
//! accepts connections, reads request heads and writes replies; the routes themselves run
//! on threads of their own (`dispatch`), never on that thread.
//!
//! What a client may make the server hold is bounded here, before any route runs:
//!
//! - a request head (request line and headers) of at most `MAX_HEAD` bytes: past it,
//!   431 and the connection is closed (hyper's `max_header_size` and `max_buf_size`, so
//!   the bytes past the limit are never read); at most `MAX_HEADERS` header lines;
//! - a head whole within `HEAD_TIMEOUT` of the connection waiting for it (a slow sender,
//!   or a keep-alive connection left idle, is closed);
//! - at most `MAX_CONNECTIONS` connections open: one more is closed at once, so the heads
//!   held in all are at most `MAX_CONNECTIONS` × `MAX_HEAD` bytes.
//!
//! The loop ends when `stop` holds a signal number (looked at every 100 ms).

use super::context::{Context, Reply};
use super::dispatch::{Asked, Dispatch};
use bytes::Bytes;
use http_body_util::Full;
use hyper::body::Incoming;
use hyper::header::{HeaderName, HeaderValue};
use hyper::{Request, Response, StatusCode};
use hyper_util::rt::{TokioIo, TokioTimer};
use std::convert::Infallible;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Arc;
use std::time::Duration;

/// The largest request head read, in bytes (nginx's default is 32 KiB in all too).
pub const MAX_HEAD: usize = 32 << 10;
/// The most header lines a request may have (hyper's default).
pub const MAX_HEADERS: usize = 100;
/// How long a connection may take to send a whole request head, idle time included.
pub const HEAD_TIMEOUT: Duration = Duration::from_secs(10);
/// Connections open at once; one more is closed as soon as it is accepted.
pub const MAX_CONNECTIONS: usize = 2048;

/// A reply's body as hyper sends it: the shared bytes themselves (a cached frame is not
/// copied for each reply).
struct Body(Arc<Vec<u8>>);

impl AsRef<[u8]> for Body {
    fn as_ref(&self) -> &[u8] {
        self.0.as_slice()
    }
}

/// `reply` as hyper's response, with the headers every reply carries.
fn response(reply: Reply) -> Response<Full<Bytes>> {
    let mut response = Response::new(Full::new(Bytes::from_owner(Body(reply.body))));
    *response.status_mut() =
        StatusCode::from_u16(reply.status).unwrap_or(StatusCode::INTERNAL_SERVER_ERROR);
    let mut headers = vec![
        ("Content-Type", reply.content_type.to_string()),
        ("Cache-Control", "no-store".to_string()),
        ("X-Content-Type-Options", "nosniff".to_string()),
    ];
    headers.extend(reply.headers);
    for (k, v) in headers {
        let name = HeaderName::from_bytes(k.as_bytes());
        if let (Ok(name), Ok(value)) = (name, HeaderValue::from_str(&v)) {
            response.headers_mut().insert(name, value);
        }
    }
    response
}

/// What a route needs of `request`: its method, target and three headers.
fn asked(request: &Request<Incoming>) -> Asked {
    let header = |name: &str| {
        (request.headers().get(name)).map(|v| String::from_utf8_lossy(v.as_bytes()).into_owned())
    };
    let target = request.uri().path_and_query().map_or("/", |p| p.as_str());
    Asked {
        method: request.method().as_str().to_string(),
        target: target.to_string(),
        host: header("host"),
        origin: header("origin"),
        site: header("sec-fetch-site"),
    }
}

/// Serves `listener` until `stop` holds a signal number; returns that number.
pub fn run(
    listener: std::net::TcpListener,
    ctx: Arc<Context>,
    stop: &AtomicUsize,
) -> std::io::Result<i32> {
    let runtime = tokio::runtime::Builder::new_current_thread()
        .enable_all()
        .build()?;
    let dispatch = Arc::new(Dispatch::start(ctx));
    runtime.block_on(accept(listener, dispatch, stop))
}

async fn accept(
    listener: std::net::TcpListener,
    dispatch: Arc<Dispatch>,
    stop: &AtomicUsize,
) -> std::io::Result<i32> {
    listener.set_nonblocking(true)?;
    let listener = tokio::net::TcpListener::from_std(listener)?;
    let mut http = hyper::server::conn::http1::Builder::new();
    http.timer(TokioTimer::new())
        .header_read_timeout(HEAD_TIMEOUT)
        .max_header_size(MAX_HEAD)
        .max_buf_size(MAX_HEAD)
        .max_headers(MAX_HEADERS);
    let open = Arc::new(AtomicUsize::new(0));
    loop {
        let sig = stop.load(Ordering::SeqCst);
        if sig != 0 {
            return Ok(sig as i32);
        }
        let stream = match tokio::time::timeout(Duration::from_millis(100), listener.accept()).await
        {
            Ok(Ok((stream, _))) => stream,
            Ok(Err(_)) => {
                // Out of descriptors, or a connection gone before it was accepted: not a
                // reason to stop, nor to spin.
                tokio::time::sleep(Duration::from_millis(20)).await;
                continue;
            }
            Err(_) => continue,
        };
        if open.fetch_add(1, Ordering::SeqCst) >= MAX_CONNECTIONS {
            open.fetch_sub(1, Ordering::SeqCst);
            drop(stream);
            continue;
        }
        let (dispatch, open, http) = (Arc::clone(&dispatch), Arc::clone(&open), http.clone());
        tokio::spawn(async move {
            let service = hyper::service::service_fn(move |request: Request<Incoming>| {
                let dispatch = Arc::clone(&dispatch);
                async move {
                    let reply = dispatch.answer(asked(&request)).await;
                    Ok::<_, Infallible>(response(reply))
                }
            });
            let _ = http.serve_connection(TokioIo::new(stream), service).await;
            open.fetch_sub(1, Ordering::SeqCst);
        });
    }
}
