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
//! - `assets`: the page, its scripts and style, compiled into the binary (no network);
//! - `server`: HTTP/1.1 over hyper, with the request head bounded (size, header count,
//!   time) and the connections counted, before any route runs;
//! - `dispatch`: the threads that answer (`WORKERS` from a queue of `QUEUE`, and at most
//!   `WAITERS` long polls), each answered 503 at once when all are taken.
//!
//! The routes are synchronous and block (a frame is drawn, a long poll waits): the
//! server's one tokio thread only reads heads and writes replies, so a slow route never
//! holds up another connection. The loop ends when `stop` holds a signal number.

pub mod assets;
pub mod camera_key;
pub mod context;
pub mod direct;
pub mod dispatch;
pub mod frames;
pub mod live;
pub mod paths;
pub mod routes;
pub mod server;
pub mod strip;

use context::Context;
use std::io::Write;
use std::net::{IpAddr, SocketAddr};
use std::path::PathBuf;
use std::sync::atomic::AtomicUsize;
use std::sync::Arc;

pub use dispatch::{QUEUE, WAITERS, WORKERS};
pub use server::{HEAD_TIMEOUT, MAX_CONNECTIONS, MAX_HEAD};

/// The default port.
pub const DEFAULT_PORT: u16 = 8417;

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

/// Serves the view until `stop` holds a signal number; returns that number. `ready` is
/// told the page's URL once the server listens.
pub fn serve(
    options: &ViewOptions,
    stop: &AtomicUsize,
    ready: &dyn Fn(&str),
) -> Result<i32, ViewError> {
    let live = Arc::new(live::Live::with_draft(&options.manifest, options.draft)?);
    let addr = SocketAddr::new(options.bind, options.port);
    let bind_error = |e: std::io::Error| ViewError::Bind {
        addr,
        why: e.to_string(),
    };
    let listener = std::net::TcpListener::bind(addr).map_err(bind_error)?;
    let bound = listener.local_addr().map_err(bind_error)?;
    // Requests are answered on threads of their own; their drawing runs on this pool
    // (`--threads`), not on rayon's global one.
    let pool = Arc::new(whitted_cmd::process::pool(options.threads)?);
    live::watch(Arc::clone(&live))?;
    let ctx = Arc::new(Context {
        live,
        frames: frames::Frames::new(Arc::clone(&pool)),
        pool,
        bound,
        status: std::sync::Mutex::new(None),
    });
    let host = match bound.ip() {
        IpAddr::V6(ip) => format!("[{ip}]"),
        IpAddr::V4(ip) => ip.to_string(),
    };
    ready(&format!("http://{host}:{}/", bound.port()));
    server::run(listener, ctx, stop).map_err(|e| ViewError::Bind {
        addr: bound,
        why: e.to_string(),
    })
}

/// Writes the URL line on standard output and flushes it (scripts read it).
pub fn print_url(url: &str) {
    let mut out = std::io::stdout().lock();
    let _ = writeln!(out, "{url}");
    let _ = out.flush();
}
