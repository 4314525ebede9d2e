//! `loop = true` through the built `animate`: a loop of N frames is the open animation of
//! N + 1 frames whose last key repeats the first (linear tracks), without its doubled last
//! frame; what
//! cannot loop is refused at its line.

use crate::support;

use support::*;

/// A still camera and a sphere moving through `keys`, over `frames` frames.
fn moving(frames: u32, looped: bool, keys: &str) -> String {
    format!(
        "scene = \"scene.txt\"\nframes = {frames}\nloop = {looped}\n\n[output]\ndir = \"frames\"\n\n\
         [[track]]\ntarget = \"sphere 1 center\"\ninterpolation = \"linear\"\nkeys = [{keys}]\n"
    )
}

#[test]
fn a_loop_is_the_open_animation_without_its_doubled_frame() {
    let (a, b) = ("[-1.3, 1.0, 0.0]", "[0.5, 2.0, 1.0]");
    let c = "[-0.5, 1.5, -1.0]";
    let keys = format!(
        "{{ frame = 0, value = {a} }}, {{ frame = 4, value = {b} }}, {{ frame = 8, value = {c} }}"
    );
    let (dir, looped) = project(&moving(12, true, &keys));
    // The same keys, open, with the first key's value again at frame 12 (the doubled frame).
    let open = dir.path().join("open.toml");
    let back = format!("{keys}, {{ frame = 12, value = {a} }}");
    std::fs::write(&open, moving(13, false, &back)).unwrap();
    let (lf, of) = (dir.path().join("l"), dir.path().join("o"));
    render_into(&looped, &lf, &["-q"]);
    render_into(&open, &of, &["-q"]);
    for f in 0..12 {
        let name = format!("frame_{f:04}.png");
        assert_eq!(pixels(&lf.join(&name)), pixels(&of.join(&name)), "{name}");
    }
    assert_eq!(files(&lf).len(), 12);
    // Frame 12 of the open one, the frame a loop leaves out, is frame 0 again.
    let first = pixels(&of.join("frame_0000.png"));
    assert_eq!(pixels(&of.join("frame_0012.png")), first);
    // Without the loop the last frames hold the last key instead.
    std::fs::write(&looped, moving(12, false, &keys)).unwrap();
    let held = dir.path().join("h");
    render_into(&looped, &held, &["-q"]);
    let name = "frame_0010.png";
    assert_ne!(pixels(&held.join(name)), pixels(&lf.join(name)));
}

#[test]
fn a_circle_of_fractional_turns_cannot_loop() {
    let (_dir, manifest) = project(
        &circle_manifest("")
            .replace("turns = 1.0", "turns = 1.5")
            .replace("fps = 12\n", "fps = 12\nloop = true\n"),
    );
    let out = animate().arg(&manifest).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("anim.toml:4:8: loop = true: the camera's circle must make whole turns to loop, found turns = 1.5"), "{err}");
}
