//! Points 6 and 9 of reliability round three: `view` and other sites' pages, the status
//! cache, long polls, the debounce, Ctrl-C and every interface.

use super::PROMPT;
use crate::support::*;
use std::time::Duration;

// 6. `view` and other sites' pages; 9. its smaller faults.

use crate::view_common::{raw, Viewer};

/// A running view of the circle manifest (its folder kept alive with it).
fn viewer() -> (tempfile::TempDir, std::path::PathBuf, Viewer) {
    let (dir, m) = project(&circle_manifest(""));
    let v = Viewer::start(&m, &[]);
    (dir, m, v)
}

/// The status of a HEAD of a frame with `extra` headers (a HEAD's reply has no body).
fn head(port: u16, host: &str, extra: &str) -> u16 {
    use std::io::{Read, Write};
    let mut s = std::net::TcpStream::connect(("127.0.0.1", port)).unwrap();
    let req = format!(
        "HEAD /api/frame?n=0&scale=4&client=x HTTP/1.1\r\nHost: {host}\r\n{extra}Connection: close\r\n\r\n"
    );
    s.write_all(req.as_bytes()).unwrap();
    let mut first = [0u8; 12];
    s.read_exact(&mut first).unwrap();
    String::from_utf8_lossy(&first[9..12]).parse().unwrap()
}

#[test]
fn view_refuses_other_sites_whatever_the_method() {
    let (_dir, _m, v) = viewer();
    let host = format!("127.0.0.1:{}", v.port);
    let request = |method: &str, extra: &str| {
        raw(
            v.port,
            &format!(
                "{method} /api/frame?n=0&scale=4&client=x HTTP/1.1\r\nHost: {host}\r\n{extra}Connection: close\r\n\r\n"
            ),
        )
    };
    for method in ["GET", "HEAD"] {
        let request = |method: &str, extra: &str| match method {
            "HEAD" => head(v.port, &host, extra),
            _ => request(method, extra).status,
        };
        for extra in [
            "Sec-Fetch-Site: cross-site\r\n",
            "Sec-Fetch-Site: same-site\r\n",
            "Origin: http://evil.example\r\n",
            "Origin: null\r\n",
            "Origin: http://127.0.0.1:1\r\n",
        ] {
            assert_eq!(request(method, extra), 403, "{method} {extra}");
        }
    }
    // The page's own requests, and a browser's address bar.
    for extra in [
        format!("Origin: http://{host}\r\nSec-Fetch-Site: same-origin\r\n"),
        "Sec-Fetch-Site: none\r\n".to_string(),
        String::new(),
    ] {
        assert_eq!(request("GET", &extra).status, 200, "{extra}");
    }
}

#[test]
fn a_since_past_u64_says_why() {
    let (_dir, _m, v) = viewer();
    let r = v.get("/api/wait?since=18446744073709551616");
    assert_eq!(r.status, 400);
    assert!(
        r.text().contains("is out of range: expected 0 to"),
        "{}",
        r.text()
    );
}

#[test]
fn long_polls_past_the_limit_wait_instead_of_spinning() {
    use std::io::Write;
    let (_dir, _m, v) = viewer();
    let host = format!("127.0.0.1:{}", v.port);
    let waiting = || {
        let tasks = std::fs::read_dir(format!("/proc/{}/task", v.child.id())).unwrap();
        let comm = |t: &std::fs::DirEntry| std::fs::read_to_string(t.path().join("comm"));
        tasks
            .flatten()
            .filter(|t| comm(t).is_ok_and(|c| c.trim() == "view-wait"))
            .count()
    };
    // 32 held long polls (the server holds them 20 s), each on a `view-wait` thread. A
    // late reload of the freshly written project answers them at once: then again.
    let mut tries = 0;
    let (held, since) = loop {
        let (_, state) = v.json("/api/state");
        let since = state["generation"].as_u64().unwrap();
        let held: Vec<std::net::TcpStream> = (0..32)
            .map(|_| {
                let mut s = std::net::TcpStream::connect(("127.0.0.1", v.port)).unwrap();
                let req = format!("GET /api/wait?since={since} HTTP/1.1\r\nHost: {host}\r\n\r\n");
                s.write_all(req.as_bytes()).unwrap();
                s
            })
            .collect();
        if poll_until(Duration::from_secs(10), || waiting() == 32).is_some() {
            break (held, since);
        }
        tries += 1;
        assert!(tries < 5, "{} waiting", waiting());
    };
    // Answered at once with the state, the page came straight back: a loop at full speed.
    let r = v.get(&format!("/api/wait?since={since}"));
    assert_eq!(r.status, 503, "{}", r.text());
    assert_eq!(r.header("Retry-After"), Some("1"));
    drop(held);
}

/// Connections that arrive together, each asking one quick question and then left open
/// (keep-alive, as a page's are): every one is answered. Before, the server's connection
/// pool promised one idle thread to several connections of a burst; the others were
/// never read until another connection closed (4 to 10 of 32 answered; the same hang
/// made the 33rd long poll above wait forever in 4 runs of 10).
#[test]
fn a_burst_of_keep_alive_connections_is_all_answered() {
    use std::io::{Read, Write};
    const BURST: usize = 48;
    let (_dir, _m, v) = viewer();
    let request = format!(
        "GET /api/state HTTP/1.1\r\nHost: 127.0.0.1:{}\r\n\r\n",
        v.port
    );
    let mut open: Vec<std::net::TcpStream> = (0..BURST)
        .map(|_| {
            let mut s = std::net::TcpStream::connect(("127.0.0.1", v.port)).unwrap();
            s.write_all(request.as_bytes()).unwrap();
            s
        })
        .collect();
    // One deadline for all: far beyond an answer's time, far below "never".
    let deadline = std::time::Instant::now() + Duration::from_secs(60);
    let mut unanswered = Vec::new();
    for (k, s) in open.iter_mut().enumerate() {
        let left = deadline.saturating_duration_since(std::time::Instant::now());
        s.set_read_timeout(Some(left.max(Duration::from_millis(1))))
            .unwrap();
        let mut first = [0u8; 12];
        if s.read_exact(&mut first).is_err() || &first != b"HTTP/1.1 200" {
            unanswered.push(k);
        }
    }
    assert!(
        unanswered.is_empty(),
        "{} of {BURST} connections got no answer within 60 s: {unanswered:?}",
        unanswered.len()
    );
}

#[test]
fn constant_writes_beside_the_manifest_do_not_starve_the_reload() {
    let (dir, m, v) = viewer();
    let stop = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false));
    let writer = {
        let (stop, busy) = (stop.clone(), dir.path().join("busy.log"));
        std::thread::spawn(move || {
            let mut n = 0u64;
            while !stop.load(std::sync::atomic::Ordering::SeqCst) {
                std::fs::write(&busy, n.to_string()).unwrap();
                n += 1;
                std::thread::sleep(Duration::from_millis(5));
            }
        })
    };
    std::thread::sleep(Duration::from_millis(200));
    std::fs::write(&m, circle_manifest("").replace("frames = 12", "frames = 7")).unwrap();
    // Before: every event restarted the 20 ms debounce, so the reload never came.
    let s = v.wait_state(Duration::from_secs(20), |s| s["frames"] == 7);
    stop.store(true, std::sync::atomic::Ordering::SeqCst);
    writer.join().unwrap();
    assert_eq!(s["frames"], 7);
}

#[test]
fn view_says_nothing_of_frames_on_ctrl_c_and_warns_on_every_interface() {
    let (_dir, m) = project(&circle_manifest(""));
    let mut child = std::process::Command::new(assert_cmd::cargo::cargo_bin("animate"))
        .arg("view")
        .arg(&m)
        .args(["--port", "0", "--bind", "0.0.0.0"])
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let mut line = String::new();
    std::io::BufRead::read_line(
        &mut std::io::BufReader::new(child.stdout.take().unwrap()),
        &mut line,
    )
    .unwrap();
    assert!(line.starts_with("http://0.0.0.0:"), "{line}");
    signal(&child, "INT");
    let (code, _) = wait_within(&mut child, PROMPT);
    assert_eq!(code, Some(130));
    let err = stderr_of(&mut child);
    assert!(
        err.contains("warning: listening on every interface"),
        "{err}"
    );
    assert!(!err.contains("in progress"), "{err}");
}

#[test]
fn the_folder_status_is_hashed_once_until_the_folder_changes() {
    // 24 RAW frames of 640×480: 22 MB that every call of /api/status used to hash.
    let manifest = circle_manifest("\n[render]\nwidth = 640\nheight = 480\n")
        .replace("frames = 12", "frames = 24")
        .replace("format = \"png\"", "format = \"raw\"");
    let (dir, m) = project(&manifest);
    let (code, _, err) = super::run(&[&m, &"-q"]);
    assert_eq!(code, Some(0), "{err}");
    let v = Viewer::start(&m, &[]);
    let strip = |v: &Viewer| {
        let (status, doc) = v.json("/api/status");
        assert_eq!(status, 200, "{doc}");
        doc["states"].clone()
    };
    let first = strip(&v);
    let before = cpu_time(v.child.id());
    for _ in 0..40 {
        assert_eq!(strip(&v), first);
    }
    let spent = cpu_time(v.child.id()) - before;
    // Hashing 40 × 22 MB takes seconds of CPU (SHA-256 at about 0.5-2 GB/s).
    assert!(
        spent < Duration::from_millis(300),
        "{spent:?} of CPU for 40 calls"
    );
    // A frame removed is seen at once.
    std::fs::remove_file(dir.path().join("frames/frame_0005.raw")).unwrap();
    assert_ne!(strip(&v), first);
}
