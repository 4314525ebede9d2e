//! What a client may make `animate view` hold (issue 57, point 7): a request head past
//! the limit is refused after its first `MAX_HEAD` bytes, not read whole (a 192 MiB
//! header grew the server by 384 MB and got 200), and a head that never ends is cut off
//! after `HEAD_TIMEOUT`; the server answers others all along. Loopback only, every wait
//! bounded.

use crate::support::*;
use crate::view_common::Viewer;
use std::io::{Read, Write};
use std::net::TcpStream;
use std::time::{Duration, Instant};

/// A running view of the circle manifest (its folder kept alive with it).
fn viewer() -> (tempfile::TempDir, Viewer) {
    let (dir, m) = project(&circle_manifest(""));
    let v = Viewer::start(&m, &[]);
    (dir, v)
}

/// The status of the first line of `answer`, if it has one.
fn status_of(answer: &[u8]) -> Option<u16> {
    let line = String::from_utf8_lossy(answer);
    line.strip_prefix("HTTP/1.1 ")
        .or_else(|| line.strip_prefix("HTTP/1.0 "))
        .and_then(|rest| rest.get(..3))
        .and_then(|code| code.parse().ok())
}

#[test]
fn a_192_mib_request_header_is_refused_early_with_bounded_memory() {
    const MIB: usize = 1 << 20;
    let (_dir, v) = viewer();
    assert_eq!(v.get("/api/state").status, 200);
    let before = v.peak_rss_kib();
    let mut s = TcpStream::connect(("127.0.0.1", v.port)).unwrap();
    s.set_write_timeout(Some(Duration::from_secs(30))).unwrap();
    s.set_read_timeout(Some(Duration::from_secs(30))).unwrap();
    let head = format!(
        "GET /api/state HTTP/1.1\r\nHost: 127.0.0.1:{}\r\nConnection: close\r\nX-Big: ",
        v.port
    );
    // 192 writes of 1 MiB at most; the server may close the connection at any of them.
    let chunk = vec![b'a'; MIB];
    let mut sent = 0;
    let mut open = s.write_all(head.as_bytes()).is_ok();
    while open && sent < 192 {
        open = s.write_all(&chunk).is_ok();
        sent += usize::from(open);
    }
    if open {
        open = s.write_all(b"\r\n\r\n").is_ok();
    }
    // The answer: 431, or nothing (the connection reset before it could be read).
    let mut answer = Vec::new();
    let _ = s.take(64 * 1024).read_to_end(&mut answer);
    let status = status_of(&answer);
    assert_ne!(
        status,
        Some(200),
        "a 192 MiB header was read whole and answered 200"
    );
    assert!(
        status.is_none() || status == Some(431),
        "{:?}",
        String::from_utf8_lossy(&answer)
    );
    // Refused after its first bytes: the socket buffers take a few MiB, never 192.
    assert!(
        !open && sent < 64,
        "the server went on reading: {sent} MiB sent"
    );
    let grew = v.peak_rss_kib().saturating_sub(before);
    assert!(
        grew < 32 * 1024,
        "the server's peak memory grew by {grew} KiB"
    );
    // And it still answers.
    assert_eq!(v.get("/api/state").status, 200);
}

#[test]
fn heads_that_never_end_are_cut_off_and_others_are_answered_meanwhile() {
    const SLOW: usize = 200;
    let (_dir, v) = viewer();
    let start = Instant::now();
    // Each sends the start of a head and then nothing (slowloris).
    let mut held: Vec<TcpStream> = (0..SLOW)
        .map(|_| {
            let mut s = TcpStream::connect(("127.0.0.1", v.port)).unwrap();
            let part = format!(
                "GET /api/state HTTP/1.1\r\nHost: 127.0.0.1:{}\r\nX-",
                v.port
            );
            s.write_all(part.as_bytes()).unwrap();
            s
        })
        .collect();
    // Meanwhile the server answers at once.
    for _ in 0..5 {
        assert_eq!(v.get("/api/state").status, 200);
    }
    let answered = start.elapsed();
    assert!(
        answered < whitted_anim::view::HEAD_TIMEOUT,
        "{answered:?} to answer beside {SLOW} slow heads"
    );
    // Past the head's time the server closes them, without an answer: every read ends
    // (0 bytes, or reset) well before the 60 s given to it.
    let limit = Instant::now() + Duration::from_secs(60);
    for (k, s) in held.iter_mut().enumerate() {
        let left = limit.saturating_duration_since(Instant::now());
        s.set_read_timeout(Some(left.max(Duration::from_millis(1))))
            .unwrap();
        let mut got = Vec::new();
        let ended = match s.read_to_end(&mut got) {
            Ok(_) => true,
            Err(e) => e.kind() == std::io::ErrorKind::ConnectionReset,
        };
        assert!(ended, "slow connection {k} still open after 60 s");
        assert_ne!(status_of(&got), Some(200), "{k}");
    }
    let cut = start.elapsed();
    assert!(
        cut >= whitted_anim::view::HEAD_TIMEOUT,
        "cut off after {cut:?}, before the head's time"
    );
    assert_eq!(v.get("/api/state").status, 200);
}
