//! The frame grammar on the command line and in the manifest: a staggered list streams in
//! its coarse-to-fine order; a bad `--frames` shows a caret under its column; a bad
//! `[check] frames` string is located at file:line:column inside the string; the output
//! name spellings `@@@@`, `%04d` and `$F4` name the files as `####` does.

use crate::support;

use support::*;

/// The PPM frames of a `--stdout ppm` stream, split at each `P6` header.
fn ppm_frames(bytes: &[u8], n: usize) -> Vec<Vec<u8>> {
    let one = bytes.len() / n;
    assert_eq!(one * n, bytes.len(), "frames of equal size");
    bytes.chunks(one).map(<[u8]>::to_vec).collect()
}

fn stream(manifest: &std::path::Path, frames: &str) -> Vec<u8> {
    let out = animate()
        .arg(manifest)
        .args(["--stdout", "ppm", "--quiet", "--frames", frames])
        .output()
        .unwrap();
    stdout_ok(out)
}

#[test]
fn a_staggered_list_streams_coarse_to_fine() {
    let (_dir, manifest) = project(&circle_manifest("\n[render]\nwidth = 32\nheight = 24\n"));
    let order = [0, 4, 8, 3, 6, 2, 1, 5, 7];
    let staggered = ppm_frames(&stream(&manifest, "0-8:4"), order.len());
    for (frame, bytes) in order.iter().zip(&staggered) {
        assert_eq!(
            bytes,
            &stream(&manifest, &frame.to_string()),
            "frame {frame}"
        );
    }
    // The frames differ (the camera turns), so the order is what the test sees.
    assert_ne!(staggered[0], staggered[1]);
}

#[test]
fn a_bad_frame_list_shows_its_column() {
    let (_dir, manifest) = project(&circle_manifest(""));
    let out = animate()
        .arg(&manifest)
        .args(["--frames", "0-11x0"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("--frames \"0-11x0\", column 6: the step must not be 0\n  0-11x0\n       ^"),
        "{err}"
    );
    let out = animate()
        .arg(&manifest)
        .args(["--frames", "0-12"])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("column 3: frame 12 is past the last frame, 11"),
        "{err}"
    );
}

#[test]
fn check_frames_take_the_grammar_with_located_errors() {
    let check = |frames: &str| {
        circle_manifest(&format!(
            "\n[check]\nframes = {frames}\nreferences = \"refs\"\n"
        ))
    };
    let (dir, manifest) = project(&check("\"0-11x4\""));
    animate()
        .arg("bless")
        .arg(&manifest)
        .arg("--quiet")
        .assert()
        .success();
    // Besides bless's folder lock (it locks the references as a run locks its frames).
    let refs = leftovers(&dir.path().join("refs"));
    assert_eq!(refs, ["frame_0000.png", "frame_0004.png", "frame_0008.png"]);
    // The error points into the string, at the step's 0.
    let (_dir, manifest) = project(&check("\"0-11x0\""));
    let out = animate().arg("status").arg(&manifest).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    let text = std::fs::read_to_string(&manifest).unwrap();
    let line = text
        .lines()
        .position(|l| l.starts_with("frames = \""))
        .unwrap()
        + 1;
    let column = "frames = \"0-11x".len() + 1;
    let at = format!("anim.toml:{line}:{column}:");
    assert!(
        err.contains(&at) && err.contains("the step must not be 0"),
        "{at}: {err}"
    );
}

#[test]
fn output_names_in_every_spelling() {
    for (name, first) in [
        ("shot_@@@@", "shot_0000.png"),
        ("shot_%04d", "shot_0000.png"),
        ("shot_$F4", "shot_0000.png"),
        ("shot_$F", "shot_00.png"),
        ("shot.@@@.v2", "shot.000.v2.png"),
    ] {
        let text =
            circle_manifest("").replace("name = \"frame_####\"", &format!("name = \"{name}\""));
        let (dir, manifest) = project(&text);
        render_into(&manifest, &dir.path().join("out"), &["--frames", "0"]);
        assert_eq!(leftovers(&dir.path().join("out")), [first], "{name}");
    }
    let text = circle_manifest("").replace("name = \"frame_####\"", "name = \"a@@_$F4\"");
    let (_dir, manifest) = project(&text);
    let out = animate().arg(&manifest).output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("gives the frame number twice"), "{err}");
}
