//! Point 9: a tev that accepts the connection and never reads stalled a run once per
//! trickle of bytes the kernel let through (three 5-second write timeouts, 15.7 s for six
//! 640×480 frames); now one packet may take `SEND_LIMIT` (5 s) in all, then the viewer
//! is given up for the run.

use super::run;
use std::net::TcpListener;
use std::time::{Duration, Instant};

#[test]
fn a_viewer_that_never_reads_costs_one_timeout_in_all() {
    let listener = TcpListener::bind("127.0.0.1:0").unwrap();
    let port = listener.local_addr().unwrap().port();
    // Accept and hold every connection, reading nothing, until the test ends.
    std::thread::spawn(move || {
        let mut held = Vec::new();
        for s in listener.incoming().flatten() {
            held.push(s);
        }
    });
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("scene.txt"),
        crate::support::scene_with_eye([0.0, 2.0, 8.0]),
    )
    .unwrap();
    let m = dir.path().join("m.toml");
    let manifest = "scene = \"scene.txt\"\nframes = 6\n[render]\nwidth = 640\nheight = 480\n\
                    [output]\ndir = \"f\"\n";
    std::fs::write(&m, manifest).unwrap();
    let display = format!("tev=127.0.0.1:{port}");
    let start = Instant::now();
    let (code, _, err) = run(&[&m, &"--display", &display]);
    let took = start.elapsed();
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(err.matches("went away").count(), 1, "{err}");
    // One 5 s limit plus six small frames; the stall was three limits or more.
    assert!(took < Duration::from_secs(12), "{took:?}: {err}");
}
