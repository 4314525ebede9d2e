//! Requests one at a time and many: the Host check, no file of the disk, bad parameters,
//! the whole frame, a hundred at once, a newer request superseding an older one.

use super::*;

#[test]
fn foreign_hosts_are_refused() {
    let (_dir, _m, v) = viewer("");
    let port = v.port;
    for host in [
        "evil.example:80".to_string(),
        format!("evil.example:{port}"),
        format!("127.0.0.1:{}", port.wrapping_add(1)),
        "127.0.0.1".to_string(),
    ] {
        let r = get(port, "/api/state", Some(&host));
        assert_eq!(r.status, 403, "{host}: {}", r.text());
        let why: serde_json::Value = serde_json::from_slice(&r.body).unwrap();
        assert!(why["error"].as_str().unwrap().contains("refused"), "{why}");
    }
    let r = raw(port, "GET / HTTP/1.0\r\n\r\n");
    assert_eq!(r.status, 403, "no Host: {}", r.text());
    for host in [format!("127.0.0.1:{port}"), format!("localhost:{port}")] {
        let r = get(port, "/", Some(&host));
        assert_eq!(r.status, 200, "{host}");
        assert!(r.text().contains("<script src=\"/app.js\">"));
    }
}

#[test]
fn no_file_of_the_disk_is_served() {
    let (dir, _m, v) = viewer("");
    let secret = "a-secret-only-the-disk-holds";
    std::fs::write(dir.path().join("secret.txt"), secret).unwrap();
    for target in [
        "/secret.txt",
        "/../secret.txt",
        "/%2e%2e/secret.txt",
        "/..%2fsecret.txt",
        "/%2E%2E%2F%2E%2E%2Fetc%2Fpasswd",
        "/api/../secret.txt",
        "/anim.toml",
        "/scene.txt",
        "//etc/passwd",
        "/app.js/../../secret.txt",
        "/frames/frame_0000.png",
    ] {
        let r = v.get(target);
        assert_eq!(r.status, 404, "{target}: {}", r.text());
        assert!(!r.text().contains(secret), "{target}");
        assert!(!r.text().contains("root:"), "{target}");
        assert_eq!(r.header("content-type"), Some("application/json"));
    }
    // The page's assets come from the binary.
    let js = v.get("/app.js");
    assert_eq!(
        (js.status, js.header("content-type")),
        (200, Some("text/javascript; charset=utf-8"))
    );
    assert!(js.text().contains("/api/wait"));
    assert_eq!(v.get("/app.css").status, 200);
    let post = raw(
        v.port,
        &format!("POST /api/state HTTP/1.1\r\nHost: 127.0.0.1:{}\r\nContent-Length: 0\r\nConnection: close\r\n\r\n", v.port),
    );
    assert_eq!(post.status, 405, "{}", post.text());
}

#[test]
fn bad_parameters_get_400_and_a_reason() {
    let (_dir, _m, v) = viewer("");
    for (target, reason) in [
        (
            "/api/frame?n=12",
            "`n` = 12 is out of range: expected 0 to 11",
        ),
        ("/api/frame?n=-1", "`n` = \"-1\" is not a whole number"),
        (
            "/api/frame?n=three",
            "`n` = \"three\" is not a whole number",
        ),
        ("/api/frame", "missing parameter `n`"),
        (
            "/api/frame?n=1&scale=0",
            "`scale` = 0 is out of range: expected 1 to 64",
        ),
        (
            "/api/frame?n=1&scale=65",
            "`scale` = 65 is out of range: expected 1 to 64",
        ),
        (
            "/api/frame?n=1&scale=2.5",
            "`scale` = \"2.5\" is not a whole number",
        ),
        (
            "/api/frame?n=1&format=gif",
            "`format` = \"gif\": expected png or raw",
        ),
        (
            "/api/frame?n=1&client=%3Cx%3E",
            "`client` must be 1 to 64 letters, digits or -",
        ),
        (
            "/api/pick?n=0&x=64&y=0",
            "`x` = 64 is out of range: expected 0 to 63",
        ),
        ("/api/pick?n=0&x=1", "missing parameter `y`"),
        (
            "/api/wait?since=soon",
            "`since` = \"soon\" is not a whole number",
        ),
    ] {
        let (status, body) = v.json(target);
        assert_eq!(status, 400, "{target}: {body}");
        assert_eq!(body["error"], reason, "{target}");
    }
}

#[test]
fn the_whole_frame_is_the_frame_animate_writes() {
    let (dir, manifest, v) = viewer("");
    let out = animate()
        .arg(&manifest)
        .args(["--frames", "5", "--stdout", "raw", "--force", "-q"])
        .output()
        .unwrap();
    assert!(out.status.success());
    assert_eq!(out.stdout.len(), 64 * 48 * 3);
    let r = v.get("/api/frame?n=5&scale=1&format=raw&client=t");
    assert_eq!(r.status, 200, "{}", r.text());
    assert_eq!(r.header("x-size"), Some("64x48"));
    // How long the drawing took, in seconds; the same figure again from the cache.
    let secs = r
        .header("x-render-seconds")
        .map(|s| s.parse::<f64>().unwrap());
    assert!(secs.is_some_and(|s| s > 0.0 && s < 60.0), "{secs:?}");
    let again = v.get("/api/frame?n=5&scale=1&format=raw&client=t");
    let again = again
        .header("x-render-seconds")
        .map(|s| s.parse::<f64>().unwrap());
    assert_eq!(again, secs, "a cached frame keeps its drawing time");
    assert!(
        r.body == out.stdout,
        "the served frame 5 differs from animate's"
    );
    // The PNG the page shows holds the pixels of the PNG file animate writes.
    render_into(&manifest, &dir.path().join("frames"), &["--frames", "5"]);
    let written = image::open(dir.path().join("frames/frame_0005.png"))
        .unwrap()
        .to_rgb8();
    let r = v.get("/api/frame?n=5&client=t");
    assert_eq!(r.header("content-type"), Some("image/png"));
    let shown = image::load_from_memory(&r.body).unwrap().to_rgb8();
    assert_eq!(shown.dimensions(), (64, 48));
    assert!(shown.as_raw() == written.as_raw());
    // A quarter size first: 16×12, and not some other frame's picture.
    let q = v.get("/api/frame?n=5&scale=4&client=t");
    let q = image::load_from_memory(&q.body).unwrap().to_rgb8();
    assert_eq!(q.dimensions(), (16, 12));
    let other = v.get("/api/frame?n=0&scale=4&client=t");
    assert_ne!(other.body, v.get("/api/frame?n=5&scale=4&client=t").body);
    // The folder's state: frame 5 up to date, the others missing.
    let (_, strip) = v.json("/api/status");
    let states = strip["states"].as_array().unwrap();
    assert_eq!(states.len(), 12);
    assert_eq!(states[5], "up-to-date");
    assert_eq!(states[4], "missing");
}

#[test]
fn a_hundred_requests_at_once() {
    let (_dir, _m, v) = viewer("\n[render]\nwidth = 160\nheight = 120\n");
    let wave = |salt: u32| {
        let port = v.port;
        let threads: Vec<_> = (0..100u32)
            .map(|i| {
                std::thread::spawn(move || {
                    let target = match i % 4 {
                        0 => format!("/api/frame?n={}&scale=1&client=c{i}x{salt}", i % 12),
                        1 => format!("/api/frame?n={}&scale=4&client=c{i}", i % 12),
                        2 => "/api/status".to_string(),
                        _ => format!("/api/pick?n={}&x=80&y=60", i % 12),
                    };
                    get(port, &target, Some(&format!("127.0.0.1:{port}"))).status
                })
            })
            .collect();
        threads
            .into_iter()
            .map(|t| t.join().unwrap())
            .collect::<Vec<u16>>()
    };
    let first = wave(0);
    assert!(
        first.iter().all(|s| [200, 409, 503].contains(s)),
        "{first:?}"
    );
    assert!(
        first.iter().filter(|&&s| s == 200).count() >= 50,
        "{first:?}"
    );
    let after_one = v.rss_kib();
    for salt in 1..4 {
        let statuses = wave(salt);
        assert!(
            statuses.iter().all(|s| [200, 409, 503].contains(s)),
            "{statuses:?}"
        );
    }
    let after_four = v.rss_kib();
    assert!(
        after_four < after_one + 64 * 1024,
        "memory grew from {after_one} KiB to {after_four} KiB over three more waves"
    );
    assert_eq!(v.get("/api/state").status, 200, "the server still answers");
}

#[test]
fn a_newer_request_supersedes_an_older_one() {
    // A slow whole frame (1280×960, 4×4 samples: seconds) holds the client's slot; of the
    // two requests that come while it renders, the older is superseded and only the newer
    // renders.
    let (_dir, _m, v) = viewer("\n[render]\nwidth = 1280\nheight = 960\nsamples = 4\n");
    let port = v.port;
    let host = format!("127.0.0.1:{port}");
    let send = |target: String| {
        let host = host.clone();
        std::thread::spawn(move || get(port, &target, Some(&host)).status)
    };
    let pid = v.child.id();
    let idle = cpu_time(pid);
    let slow = send("/api/frame?n=1&client=s".into());
    // The slot is held once the server renders: an idle server spends no CPU.
    let busy = poll_until(Duration::from_secs(60), || {
        cpu_time(pid) > idle + Duration::from_millis(300)
    });
    assert!(busy.is_some(), "the server never started the slow frame");
    let older = send("/api/frame?n=2&scale=2&client=s".into());
    // The older request must have taken its ticket before the newer one comes (nothing
    // tells when it has: a second is far more than a request's parsing takes).
    std::thread::sleep(Duration::from_secs(1));
    assert!(
        !slow.is_finished(),
        "the slow frame ended before the newer request: nothing is tested"
    );
    let newer = send("/api/frame?n=3&scale=2&client=s".into());
    // Another client is not held up by this one's queue.
    let other = send("/api/frame?n=3&scale=8&client=other".into());
    assert_eq!(slow.join().unwrap(), 200);
    assert_eq!(
        older.join().unwrap(),
        409,
        "the older request was rendered anyway"
    );
    assert_eq!(newer.join().unwrap(), 200);
    assert_eq!(other.join().unwrap(), 200);
}
