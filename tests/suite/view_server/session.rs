//! A session's life: live reload, a watched scene file that may vanish, Ctrl-C, bad
//! input, the rendering threads, picking, an EXR manifest's pictures.

use super::*;

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
    let picture = anim.render_picture(&anim.plan(4)).unwrap().0.pixels;
    assert_ne!(
        picture,
        anim.render(&anim.plan(4)).unwrap().0.pixels,
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
