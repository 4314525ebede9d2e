//! Where the view's requests are answered: `WORKERS` threads take requests from a queue
//! of `QUEUE` places, and a full queue is answered 503 at once; long polls
//! (`/api/wait`) have threads of their own (`view-wait`), at most `WAITERS`, past which
//! they are answered 503 with `Retry-After: 1`. The routes block (a frame is drawn, a
//! long poll waits 20 s), so they never run on the server's own thread: `answer` hands a
//! request over and waits, without blocking that thread, for its reply. The work and
//! memory spent on requests are so bounded whatever their number.

use super::context::{Context, Reply};
use super::routes::{answer, cross_site};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{mpsc, Arc, Mutex};
use tokio::sync::oneshot;

/// Threads answering requests other than long polls.
pub const WORKERS: usize = 4;
/// Requests waiting for a worker; past this, 503.
pub const QUEUE: usize = 64;
/// Long polls held at once; past this they are answered 503 with a delay.
pub const WAITERS: usize = 32;

/// What a route needs of a request.
#[derive(Clone, Debug)]
pub struct Asked {
    /// `GET`, `HEAD`…
    pub method: String,
    /// The path and query.
    pub target: String,
    /// The `Host` header.
    pub host: Option<String>,
    /// The `Origin` header.
    pub origin: Option<String>,
    /// The `Sec-Fetch-Site` header.
    pub site: Option<String>,
}

/// The answer to `asked`: another site's request is refused before any route runs.
pub fn reply(ctx: &Context, asked: &Asked) -> Reply {
    match cross_site(asked.origin.as_deref(), asked.site.as_deref(), ctx.bound) {
        Some(refused) => refused,
        None => answer(ctx, &asked.method, &asked.target, asked.host.as_deref()),
    }
}

/// A request handed to a worker, and where its reply goes.
type Job = (Asked, oneshot::Sender<Reply>);

/// The workers, their queue and the long polls' count.
pub struct Dispatch {
    ctx: Arc<Context>,
    queue: mpsc::SyncSender<Job>,
    waiters: Arc<AtomicUsize>,
}

impl Dispatch {
    /// Starts the `WORKERS` threads (named `view-K`) on `ctx`.
    pub fn start(ctx: Arc<Context>) -> Dispatch {
        let (queue, rx) = mpsc::sync_channel::<Job>(QUEUE);
        let rx = Arc::new(Mutex::new(rx));
        for k in 0..WORKERS {
            let (ctx, rx) = (Arc::clone(&ctx), Arc::clone(&rx));
            let _ = std::thread::Builder::new()
                .name(format!("view-{k}"))
                .spawn(move || loop {
                    let next = rx.lock().map(|r| r.recv());
                    match next {
                        Ok(Ok((asked, to))) => {
                            let _ = to.send(reply(&ctx, &asked));
                        }
                        _ => return,
                    }
                });
        }
        Dispatch {
            ctx,
            queue,
            waiters: Arc::new(AtomicUsize::new(0)),
        }
    }

    /// The reply to `asked`, from a worker, a long poll's thread, or at once when all
    /// are taken.
    pub async fn answer(&self, asked: Asked) -> Reply {
        let (to, from) = oneshot::channel();
        let handed = if asked.target.starts_with("/api/wait") {
            self.hold(asked, to)
        } else {
            match self.queue.try_send((asked, to)) {
                Ok(()) => Ok(()),
                Err(_) => Err(Reply::error(503, "busy: too many requests at once, retry")),
            }
        };
        match handed {
            Ok(()) => from
                .await
                .unwrap_or_else(|_| Reply::error(500, "the request's thread ended")),
            Err(refused) => refused,
        }
    }

    /// A long poll on a thread of its own, or 503 when `WAITERS` are held.
    fn hold(&self, asked: Asked, to: oneshot::Sender<Reply>) -> Result<(), Reply> {
        if self.waiters.fetch_add(1, Ordering::SeqCst) >= WAITERS {
            self.waiters.fetch_sub(1, Ordering::SeqCst);
            // Answering with the state at once would send the page straight back: a
            // client loop at full speed. 503 with a delay instead.
            let mut busy = Reply::error(503, "too many long polls held at once: retry in a second");
            busy.headers.push(("Retry-After", "1".into()));
            return Err(busy);
        }
        let (ctx, held) = (Arc::clone(&self.ctx), Arc::clone(&self.waiters));
        let spawned = std::thread::Builder::new()
            .name("view-wait".into())
            .spawn(move || {
                let _ = to.send(reply(&ctx, &asked));
                held.fetch_sub(1, Ordering::SeqCst);
            });
        match spawned {
            Ok(_) => Ok(()),
            Err(_) => {
                self.waiters.fetch_sub(1, Ordering::SeqCst);
                Err(Reply::error(503, "cannot start a thread: retry"))
            }
        }
    }
}
