//! `animate view MANIFEST [--port P] [--bind ADDR]` (SPEC §13): a page that shows the
//! animation while it is made. The fifth idea of `anim/` beside manifest, timeline,
//! frames and check: it reads the project with the same `Project::load` and draws with
//! the same `Animation` as every command.
//!
//! - `live`: the project, reloaded when the manifest or scene changes on disk (`notify`);
//! - `frames`: frames at 1/scale, one render per client at a time, newer requests
//!   superseding older ones, a bounded cache;
//! - `context`: what the routes share (the `Context`, the `Reply`, reading a query and
//!   the live project), below `routes`, `strip` and `direct`;
//! - `routes`: the HTTP routes, the Host check and the 400 reasons;
//! - `strip`: the output folder's state of every frame (`/api/status`);
//! - `direct`: the directing aids' routes: `paths` (the camera's and tracks' paths over
//!   the picture) and `camera_key` (a frame's camera as a manifest key);
//! - `assets`: the page, its scripts and style, compiled into the binary (no network).
//!
//! The server is `tiny_http` (small, synchronous, no async runtime to carry for a
//! loopback page), in a copy whose connection pool is patched (`vendor/README.md`: a
//! burst of connections left some unread until another closed). `tiny_http` reads each
//! open connection on a thread of its own; this loop hands their requests to `WORKERS`
//! threads through a queue of `QUEUE` places, and a full queue is answered 503 at once;
//! long polls have their own threads, at most `WAITERS`. The work and memory spent on
//! requests are so bounded whatever their number. The loop ends when `stop` holds a
//! signal number.

pub mod assets;
pub mod camera_key;
pub mod context;
pub mod direct;
pub mod frames;
pub mod live;
pub mod paths;
pub mod routes;
pub mod strip;

use context::{Context, Reply};
use routes::answer;
use std::io::Write;
use std::net::{IpAddr, SocketAddr};
use std::path::PathBuf;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{mpsc, Arc};
use std::time::Duration;

/// The default port.
pub const DEFAULT_PORT: u16 = 8417;
/// Threads answering requests other than long polls.
pub const WORKERS: usize = 4;
/// Requests waiting for a worker; past this, 503.
pub const QUEUE: usize = 64;
/// Long polls held at once; past this they are answered at once.
pub const WAITERS: usize = 32;

/// What `animate view` is asked.
#[derive(Clone, Debug)]
pub struct ViewOptions {
    /// The manifest.
    pub manifest: PathBuf,
    /// The address to bind (loopback unless told otherwise).
    pub bind: IpAddr,
    /// The port (0: any free one).
    pub port: u16,
    /// The threads that draw frames (`None`: one a core).
    pub threads: Option<u32>,
    /// A draft's overrides of the manifest (none by default), as `status` takes them.
    pub draft: crate::project::draft::Draft,
}

/// Why the view could not start.
#[derive(Debug, thiserror::Error)]
pub enum ViewError {
    /// The manifest does not exist or cannot be read (`ManifestError::Io`, as every
    /// command says it).
    #[error(transparent)]
    Manifest(#[from] crate::error::AnimError),
    /// The address cannot be bound.
    #[error("cannot listen on {addr}: {why}")]
    Bind {
        /// The address.
        addr: SocketAddr,
        /// The reason.
        why: String,
    },
    /// The system refused a file watcher.
    #[error("cannot watch the manifest's folder: {0}")]
    Watch(#[from] notify::Error),
    /// The system refused the drawing threads.
    #[error("cannot start the worker threads: {0}")]
    Threads(#[from] rayon::ThreadPoolBuildError),
}

impl ViewError {
    /// The exit-status row: bad input (status 2).
    pub fn outcome(&self) -> whitted::exit::Outcome {
        whitted::exit::Outcome::BadInput
    }
}

/// A reply's body as tiny_http reads it: the shared bytes themselves (a cached frame is
/// not copied for each reply).
struct Body(Arc<Vec<u8>>);

impl AsRef<[u8]> for Body {
    fn as_ref(&self) -> &[u8] {
        self.0.as_slice()
    }
}

fn respond(request: tiny_http::Request, reply: Reply) {
    let length = reply.body.len();
    let mut response = tiny_http::Response::new(
        tiny_http::StatusCode(reply.status),
        Vec::new(),
        std::io::Cursor::new(Body(reply.body)),
        Some(length),
        None,
    );
    let mut headers = vec![
        ("Content-Type", reply.content_type.to_string()),
        ("Cache-Control", "no-store".to_string()),
        ("X-Content-Type-Options", "nosniff".to_string()),
    ];
    headers.extend(reply.headers.iter().map(|(k, v)| (*k, v.clone())));
    for (k, v) in headers {
        if let Ok(h) = tiny_http::Header::from_bytes(k.as_bytes(), v.as_bytes()) {
            response.add_header(h);
        }
    }
    let _ = request.respond(response);
}

/// Answers `request`; `instead` replaces its target (a long poll answered at once).
fn handle(ctx: &Context, request: tiny_http::Request, instead: Option<&str>) {
    let method = request.method().as_str().to_string();
    let target = instead.unwrap_or(request.url()).to_string();
    let header = |name: &'static str| {
        (request.headers().iter())
            .find(|h| h.field.equiv(name))
            .map(|h| h.value.as_str().to_string())
    };
    let (host, origin, site) = (header("Host"), header("Origin"), header("Sec-Fetch-Site"));
    let reply = match routes::cross_site(origin.as_deref(), site.as_deref(), ctx.bound) {
        Some(refused) => refused,
        None => answer(ctx, &method, &target, host.as_deref()),
    };
    respond(request, reply);
}

/// Serves the view until `stop` holds a signal number; returns that number. `ready` is
/// told the page's URL once the server listens.
pub fn serve(
    options: &ViewOptions,
    stop: &AtomicUsize,
    ready: &dyn Fn(&str),
) -> Result<i32, ViewError> {
    let live = Arc::new(live::Live::with_draft(&options.manifest, options.draft)?);
    let addr = SocketAddr::new(options.bind, options.port);
    let server = tiny_http::Server::http(addr).map_err(|e| ViewError::Bind {
        addr,
        why: e.to_string(),
    })?;
    let bound = server
        .server_addr()
        .to_ip()
        .ok_or_else(|| ViewError::Bind {
            addr,
            why: "not an IP socket".into(),
        })?;
    // Requests are answered on threads of their own; their drawing runs on this pool
    // (`--threads`), not on rayon's global one.
    let pool = Arc::new(crate::process::pool(options.threads)?);
    live::watch(Arc::clone(&live))?;
    let ctx = Arc::new(Context {
        live,
        frames: frames::Frames::new(Arc::clone(&pool)),
        pool,
        bound,
        status: std::sync::Mutex::new(None),
    });
    let (tx, rx) = mpsc::sync_channel::<tiny_http::Request>(QUEUE);
    let rx = Arc::new(std::sync::Mutex::new(rx));
    for k in 0..WORKERS {
        let (ctx, rx) = (Arc::clone(&ctx), Arc::clone(&rx));
        let _ = std::thread::Builder::new()
            .name(format!("view-{k}"))
            .spawn(move || loop {
                let next = rx.lock().map(|r| r.recv());
                match next {
                    Ok(Ok(request)) => handle(&ctx, request, None),
                    _ => return,
                }
            });
    }
    let waiters = Arc::new(AtomicUsize::new(0));
    let host = match bound.ip() {
        IpAddr::V6(ip) => format!("[{ip}]"),
        IpAddr::V4(ip) => ip.to_string(),
    };
    ready(&format!("http://{host}:{}/", bound.port()));
    loop {
        let sig = stop.load(Ordering::SeqCst);
        if sig != 0 {
            return Ok(sig as i32);
        }
        let request = match server.recv_timeout(Duration::from_millis(100)) {
            Ok(Some(r)) => r,
            Ok(None) => continue,
            Err(_) => continue,
        };
        let wait = request.url().starts_with("/api/wait");
        if wait && waiters.load(Ordering::SeqCst) >= WAITERS {
            // Answering with the state at once would send the page straight back: a
            // client loop at full speed. 503 with a delay instead.
            let mut busy = Reply::error(503, "too many long polls held at once: retry in a second");
            busy.headers.push(("Retry-After", "1".into()));
            respond(request, busy);
            continue;
        }
        if wait {
            waiters.fetch_add(1, Ordering::SeqCst);
            let (ctx, held) = (Arc::clone(&ctx), Arc::clone(&waiters));
            let spawned = std::thread::Builder::new()
                .name("view-wait".into())
                .spawn(move || {
                    handle(&ctx, request, None);
                    held.fetch_sub(1, Ordering::SeqCst);
                });
            if spawned.is_err() {
                waiters.fetch_sub(1, Ordering::SeqCst);
            }
            continue;
        }
        if let Err(mpsc::TrySendError::Full(request)) = tx.try_send(request) {
            respond(
                request,
                Reply::error(503, "busy: too many requests at once, retry"),
            );
        }
    }
}

/// Writes the URL line on standard output and flushes it (scripts read it).
pub fn print_url(url: &str) {
    let mut out = std::io::stdout().lock();
    let _ = writeln!(out, "{url}");
    let _ = out.flush();
}
