//! Shared by the `animate view` tests: starting the server on a free port, and a plain
//! HTTP/1.1 GET written by hand (the routes are tested byte by byte, with any `Host`).

#![allow(dead_code)]

pub mod cdp;

use std::io::{BufRead, BufReader, Read, Write};
use std::net::TcpStream;
use std::path::Path;
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

/// What an edit on disk to the reloaded state (or the page's new picture) aims at
/// (SPEC §13); measured by view_browser's ignored measurement test.
pub const RELOAD_TARGET: Duration = Duration::from_secs(2);
/// When a reload fails a test: generous for inotify, a render and Chromium on a loaded
/// two-core machine, still far below "never".
pub const RELOAD_BOUND: Duration = Duration::from_secs(30);

/// A running `animate view`, killed when dropped.
pub struct Viewer {
    pub child: Child,
    pub url: String,
    pub port: u16,
}

impl Viewer {
    /// `animate view MANIFEST --port 0 ARGS`, once it prints its URL.
    pub fn start(manifest: &Path, args: &[&str]) -> Viewer {
        Viewer::start_with_env(manifest, args, &[])
    }

    /// `start`, with `env` added to the server's environment.
    pub fn start_with_env(manifest: &Path, args: &[&str], env: &[(&str, &str)]) -> Viewer {
        let mut child = Command::new(assert_cmd::cargo::cargo_bin("animate"))
            .arg("view")
            .arg(manifest)
            .args(["--port", "0"])
            .args(args)
            .envs(env.iter().copied())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .expect("animate runs");
        let mut line = String::new();
        BufReader::new(child.stdout.take().unwrap())
            .read_line(&mut line)
            .unwrap();
        let url = line.trim().to_string();
        assert!(
            url.starts_with("http://127.0.0.1:"),
            "no URL printed: {url:?}"
        );
        let port = url
            .trim_end_matches('/')
            .rsplit(':')
            .next()
            .unwrap()
            .parse()
            .unwrap();
        Viewer { child, url, port }
    }

    /// GET `target` with the right Host.
    pub fn get(&self, target: &str) -> Reply {
        get(self.port, target, Some(&format!("127.0.0.1:{}", self.port)))
    }

    /// GET `target` and parse the JSON body.
    pub fn json(&self, target: &str) -> (u16, serde_json::Value) {
        let r = self.get(target);
        let v = serde_json::from_slice(&r.body)
            .unwrap_or_else(|e| panic!("{target}: not JSON ({e}): {:?}", r.text()));
        (r.status, v)
    }

    /// Waits (up to `limit`) until `/api/state` satisfies `ok`; the state then.
    pub fn wait_state(
        &self,
        limit: Duration,
        ok: impl Fn(&serde_json::Value) -> bool,
    ) -> serde_json::Value {
        let start = Instant::now();
        loop {
            let (_, s) = self.json("/api/state");
            if ok(&s) {
                return s;
            }
            assert!(start.elapsed() < limit, "state never came: {s}");
            std::thread::sleep(Duration::from_millis(20));
        }
    }

    /// Waits for a reload: until `/api/state` satisfies `ok`, failing only past
    /// `RELOAD_BOUND`; the time it took is printed beside the 2 s target (`timed`).
    pub fn wait_reload(
        &self,
        what: &str,
        ok: impl Fn(&serde_json::Value) -> bool,
    ) -> serde_json::Value {
        let start = Instant::now();
        let s = self.wait_state(RELOAD_BOUND, ok);
        crate::support::timed(what, start.elapsed(), RELOAD_TARGET, RELOAD_BOUND);
        s
    }

    /// The server's resident memory in KiB (Linux).
    pub fn rss_kib(&self) -> u64 {
        self.proc_status("VmRSS:")
    }

    /// The server's peak resident memory so far in KiB (Linux).
    pub fn peak_rss_kib(&self) -> u64 {
        self.proc_status("VmHWM:")
    }

    /// The server's threads (Linux).
    pub fn threads(&self) -> u64 {
        self.proc_status("Threads:")
    }

    /// A number of /proc/PID/status (its `key:` line, a unit such as kB dropped).
    fn proc_status(&self, key: &str) -> u64 {
        let status = std::fs::read_to_string(format!("/proc/{}/status", self.child.id())).unwrap();
        status
            .lines()
            .find_map(|l| l.strip_prefix(key))
            .and_then(|v| v.trim().trim_end_matches("kB").trim().parse().ok())
            .unwrap()
    }
}

impl Drop for Viewer {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// An HTTP answer.
pub struct Reply {
    pub status: u16,
    pub headers: Vec<(String, String)>,
    pub body: Vec<u8>,
}

impl Reply {
    pub fn text(&self) -> String {
        String::from_utf8_lossy(&self.body).into_owned()
    }
    pub fn header(&self, name: &str) -> Option<&str> {
        self.headers
            .iter()
            .find(|(k, _)| k.eq_ignore_ascii_case(name))
            .map(|(_, v)| v.as_str())
    }
}

/// A raw request: `request` is written as is.
pub fn raw(port: u16, request: &str) -> Reply {
    let mut s = TcpStream::connect(("127.0.0.1", port)).unwrap();
    s.set_read_timeout(Some(Duration::from_secs(60))).unwrap();
    s.write_all(request.as_bytes()).unwrap();
    // Read the head, then the body by its length when it has one (a keep-alive server
    // such as Chromium's does not close), else to the end.
    let mut all = Vec::new();
    let mut buf = [0u8; 65536];
    let split = loop {
        if let Some(p) = all.windows(4).position(|w| w == b"\r\n\r\n") {
            break p;
        }
        let n = s.read(&mut buf).unwrap();
        assert!(n > 0, "no header end: {:?}", String::from_utf8_lossy(&all));
        all.extend_from_slice(&buf[..n]);
    };
    let length = String::from_utf8_lossy(&all[..split])
        .lines()
        .filter_map(|l| l.split_once(':'))
        .find(|(k, _)| k.trim().eq_ignore_ascii_case("content-length"))
        .and_then(|(_, v)| v.trim().parse::<usize>().ok());
    match length {
        Some(n) => {
            while all.len() < split + 4 + n {
                let k = s.read(&mut buf).unwrap();
                assert!(k > 0, "the body ended early");
                all.extend_from_slice(&buf[..k]);
            }
        }
        None => {
            s.read_to_end(&mut all).unwrap();
        }
    }
    let head = String::from_utf8_lossy(&all[..split]).into_owned();
    let mut lines = head.lines();
    let status = lines
        .next()
        .unwrap()
        .split(' ')
        .nth(1)
        .unwrap()
        .parse()
        .unwrap();
    let headers: Vec<(String, String)> = lines
        .filter_map(|l| l.split_once(':'))
        .map(|(k, v)| (k.trim().to_string(), v.trim().to_string()))
        .collect();
    let mut body = all[split + 4..].to_vec();
    let chunked = headers
        .iter()
        .any(|(k, v)| k.eq_ignore_ascii_case("transfer-encoding") && v.contains("chunked"));
    if chunked {
        body = dechunk(&body);
    }
    Reply {
        status,
        headers,
        body,
    }
}

fn dechunk(mut b: &[u8]) -> Vec<u8> {
    let mut out = Vec::new();
    loop {
        let end = b.windows(2).position(|w| w == b"\r\n").unwrap();
        let n = usize::from_str_radix(std::str::from_utf8(&b[..end]).unwrap().trim(), 16).unwrap();
        if n == 0 {
            return out;
        }
        out.extend_from_slice(&b[end + 2..end + 2 + n]);
        b = &b[end + 2 + n + 2..];
    }
}

/// GET `target` with `host` as the Host header (none when `None`).
pub fn get(port: u16, target: &str, host: Option<&str>) -> Reply {
    let host = host.map(|h| format!("Host: {h}\r\n")).unwrap_or_default();
    raw(
        port,
        &format!("GET {target} HTTP/1.1\r\n{host}Connection: close\r\n\r\n"),
    )
}
