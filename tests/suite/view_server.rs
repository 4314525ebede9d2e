//! `animate view` through HTTP: the Host check, no file of the disk served whatever the
//! path, 400 with a JSON reason for bad parameters, the whole frame equal to the frame
//! `animate` writes, a hundred requests at once, a newer request superseding an older
//! one, live reload (a bad edit located exactly as the command line prints it, the last
//! good frame still served, a deleted scene file), and Ctrl-C ending with status 130.

use crate::support;
use crate::view_common;

use std::time::Duration;
use support::*;
use view_common::*;

fn viewer(extra: &str) -> (tempfile::TempDir, std::path::PathBuf, Viewer) {
    let (dir, manifest) = project(&circle_manifest(extra));
    let v = Viewer::start(&manifest, &[]);
    (dir, manifest, v)
}

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

#[test]
fn live_reload_locates_a_bad_edit_exactly_as_the_command_line() {
    let (dir, manifest, v) = viewer("");
    let good = std::fs::read_to_string(&manifest).unwrap();
    let (_, s0) = v.json("/api/state");
    assert_eq!(s0["error"], serde_json::Value::Null);
    let g0 = s0["generation"].as_u64().unwrap();
    // Reading the files (every frame request does) is no change: no reload.
    std::thread::sleep(Duration::from_millis(300));
    assert_eq!(v.json("/api/state").1["generation"].as_u64(), Some(g0));
    let before = v.get("/api/frame?n=3&format=raw&client=r").body;
    // A bad value: what `animate status` says of the same file is what the page shows.
    std::fs::write(&manifest, good.replace("radius = 8.0", "radius = -8.0")).unwrap();
    let s = v.wait_reload("bad manifest edit → error", |s| !s["error"].is_null());
    assert!(s["generation"].as_u64() > Some(g0));
    let cli = animate().arg("status").arg(&manifest).output().unwrap();
    let said = String::from_utf8_lossy(&cli.stderr);
    let said = said.lines().next().unwrap();
    assert!(said.contains("anim.toml:8:"), "{said}");
    assert_eq!(s["error"], said);
    // The last good frame is still served.
    assert_eq!(v.get("/api/frame?n=3&format=raw&client=r").body, before);
    // Fixed by a rename-over save (an editor's way): the error goes and the frame changes.
    let tmp = dir.path().join(".anim.toml.swp");
    std::fs::write(&tmp, good.replace("radius = 8.0", "radius = 9.0")).unwrap();
    std::fs::rename(&tmp, &manifest).unwrap();
    let s = v.wait_reload("rename-over save → fixed", |s| s["error"].is_null());
    assert!(s["generation"].as_u64() > Some(g0 + 1));
    assert_ne!(v.get("/api/frame?n=3&format=raw&client=r").body, before);
}

#[test]
fn the_scene_file_is_watched_and_may_vanish() {
    let (dir, _manifest, v) = viewer("");
    let scene = dir.path().join("scene.txt");
    let text = std::fs::read_to_string(&scene).unwrap();
    let before = v.get("/api/frame?n=0&format=raw&client=d").body;
    std::fs::remove_file(&scene).unwrap();
    let s = v.wait_reload("scene deleted → error", |s| !s["error"].is_null());
    let e = s["error"].as_str().unwrap();
    assert!(
        e.starts_with("animate: ") && e.contains("anim.toml:1:9: scene: cannot read"),
        "{e}"
    );
    let r = v.get("/api/frame?n=0&format=raw&client=d");
    assert_eq!(
        (r.status, &r.body),
        (200, &before),
        "the last good frame stays"
    );
    // Back, with a brighter light: the error clears and the frame follows the file.
    std::fs::write(&scene, text.replace("0.9\n-6", "0.3\n-6")).unwrap();
    v.wait_reload("scene back → fixed", |s| s["error"].is_null());
    assert_ne!(v.get("/api/frame?n=0&format=raw&client=d").body, before);
    // A scene edit that breaks it: located in the scene file.
    std::fs::write(&scene, text.replacen("1.0  -1.3", "-1.0  -1.3", 1)).unwrap();
    let s = v.wait_reload("broken scene → error", |s| !s["error"].is_null());
    assert!(
        s["error"].as_str().unwrap().contains("scene.txt:6:1"),
        "{s}"
    );
}

#[test]
fn ctrl_c_ends_it_with_130() {
    let (_dir, _m, mut v) = viewer("");
    assert_eq!(v.get("/api/state").status, 200);
    signal(&v.child, "INT");
    let status = v.child.wait().unwrap();
    assert_eq!(status.code(), Some(130));
}

#[test]
fn a_missing_manifest_or_a_busy_port_is_bad_input() {
    let dir = tempfile::tempdir().unwrap();
    let out = animate()
        .arg("view")
        .arg(dir.path().join("nope.toml"))
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("nope.toml: cannot read the manifest"));
    let (_dir, manifest, v) = viewer("");
    let out = animate()
        .arg("view")
        .arg(&manifest)
        .args(["--port", &v.port.to_string()])
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(2),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(String::from_utf8_lossy(&out.stderr).contains("cannot listen on 127.0.0.1:"));
}

#[test]
fn view_threads_bounds_the_rendering_threads() {
    // Rayon's global pool would start RAYON_NUM_THREADS threads (kept to the end): with
    // --threads 1, frames and the strip are drawn on the view's own pool of one.
    let (_dir, manifest) = project(&circle_manifest(""));
    let v = Viewer::start_with_env(
        &manifest,
        &["--threads", "1"],
        &[("RAYON_NUM_THREADS", "48")],
    );
    let r = v.get("/api/frame?n=2&client=t");
    assert_eq!(r.status, 200, "{}", r.text());
    assert_eq!(v.get("/api/status").status, 200);
    let threads = v.threads();
    assert!(threads < 40, "{threads} threads with --threads 1");
}

/// A scene of one sphere of radius 1.5 on the point the circle camera looks at.
const ONE_SPHERE: &str = "64 48\n0 3 8\n0 1 0\n0 40\n1 0 0 1\n\
1.5  0 1 0   1 0.8 0.2 0.2   0.9 0 0 1 0 0\n5 10 5  1 1 1  0.9\n";

#[test]
fn picking_uses_the_manifests_camera() {
    // A 5° field of view: the sphere fills the frame, so the corner pixel shows it; the
    // report's wider view (about 20°) would see past it there.
    let (dir, manifest) = project(&circle_manifest(""));
    let text = std::fs::read_to_string(&manifest).unwrap();
    std::fs::write(
        &manifest,
        text.replace("turns = 1.0\n", "turns = 1.0\nfov = 5.0\n"),
    )
    .unwrap();
    std::fs::write(dir.path().join("scene.txt"), ONE_SPHERE).unwrap();
    let v = Viewer::start(&manifest, &[]);
    let (status, p) = v.json("/api/pick?n=0&x=0&y=0");
    assert_eq!(status, 200, "{p}");
    assert_eq!(p["hit"]["object"], "sphere 1", "{p}");
    // And the frame shows the sphere's red there, not the black of a miss.
    let r = v.get("/api/frame?n=0&format=raw&client=p");
    assert_eq!(r.status, 200, "{}", r.text());
    assert!(
        r.body[0] > 20 && r.body[0] > r.body[1],
        "{:?}",
        &r.body[..3]
    );
}

#[test]
fn an_exr_manifest_shows_the_pictures_its_files_hold() {
    // 3×3 samples and a bright light: averaging clamped samples (the PNG way) and
    // clamping the unclamped mean (an EXR's picture) differ at the highlights' edges.
    let extra = "\n[render]\nsamples = 3\n";
    let (dir, manifest) = project(&circle_manifest(extra).replace("\"png\"", "\"exr\""));
    let scene = dir.path().join("scene.txt");
    let text = std::fs::read_to_string(&scene).unwrap();
    std::fs::write(&scene, text.replace("0.9\n-6", "3.0\n-6")).unwrap();
    let project = whitted_anim::Project::load(&manifest).unwrap();
    let anim = whitted_anim::Animation::new(&project).unwrap();
    let picture = anim.render_picture(4).unwrap().0.pixels;
    assert_ne!(
        picture,
        anim.render(4).unwrap().0.pixels,
        "no difference to see"
    );
    let v = Viewer::start(&manifest, &[]);
    let r = v.get("/api/frame?n=4&format=raw&client=x");
    assert_eq!(r.status, 200, "{}", r.text());
    assert!(
        r.body == picture,
        "the page's frame 4 is not the EXR's picture"
    );
}
