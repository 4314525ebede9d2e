//! Messages a newcomer meets: an output folder that is a file or cannot be created, and
//! a manifest given to `raytrace`.

use crate::support;

use support::*;

/// Standard error of a run that must refuse its input with exit status 2.
fn refused(cmd: &mut assert_cmd::Command) -> String {
    let out = cmd.output().unwrap();
    assert_eq!(out.status.code(), Some(2), "{out:?}");
    String::from_utf8(out.stderr).unwrap()
}

#[test]
fn an_output_folder_that_is_a_file_or_cannot_be_made_is_explained() {
    let (dir, manifest) = project(&circle_manifest(""));
    let file = dir.path().join("taken");
    std::fs::write(&file, b"x").unwrap();
    let err = refused(animate().arg(&manifest).arg("-o").arg(&file));
    // Before: "File exists (os error 17)" alone.
    assert!(err.contains("a file of that name is in the way"), "{err}");
    let err = refused(animate().arg(&manifest).args(["-o", "/proc/whitted-x"]));
    // Before: "No such file or directory (os error 2)" alone.
    assert!(err.contains("/proc does not take new folders"), "{err}");
}

#[test]
fn raytrace_on_a_manifest_says_to_use_animate() {
    let (_dir, manifest) = project(&circle_manifest(""));
    let err = refused(raytrace().arg(&manifest));
    // Before: "expected an integer … for ResX, found 'scene'".
    assert!(err.contains("looks like an animation manifest"), "{err}");
    assert!(err.contains("render it with `animate "), "{err}");
}

#[test]
fn a_shard_summary_names_the_shard() {
    let (dir, manifest) = project(&circle_manifest(""));
    let out = animate()
        .arg(&manifest)
        .args(["--shard", "2/4", "-o"])
        .arg(dir.path().join("f"))
        .output()
        .unwrap();
    assert!(out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    // Before: the summary ended with the folder alone.
    assert!(err.contains("(shard 2/4)"), "{err}");
}

#[test]
fn a_misspelt_track_target_gets_a_did_you_mean() {
    let keys = "keys = [{ frame = 0, value = [0.0, 1.0, 0.0] }]\n";
    let track = format!("\n[[track]]\ntarget = \"sphere 1 centre\"\n{keys}");
    let (_dir, manifest) = project(&circle_manifest(&track));
    let err = refused(animate().arg("status").arg(&manifest));
    // Before: "sphere has no field `centre`: expected one of …" alone.
    assert!(err.contains("anim.toml:19:10: "), "{err}");
    assert!(
        err.contains("sphere has no field `centre` (did you mean `center`?)"),
        "{err}"
    );
    let track = format!("\n[[track]]\ntarget = \"shpere 1 center\"\n{keys}");
    let (_dir, manifest) = project(&circle_manifest(&track));
    let err = refused(animate().arg("status").arg(&manifest));
    assert!(
        err.contains("unknown kind `shpere` (did you mean `sphere`?)"),
        "{err}"
    );
}

#[test]
fn a_missing_reference_gives_its_hint_once() {
    let check = "\n[check]\nframes = [0]\nreferences = \"refs\"\n";
    let (_dir, manifest) = project(&circle_manifest(check));
    let err = refused(animate().arg("check").arg(&manifest));
    assert!(err.contains("frame 0: the reference "), "{err}");
    // Before: "(run `animate bless` first)" in the message and the hint after it.
    assert_eq!(err.matches("animate bless").count(), 1, "{err}");
}

#[test]
fn a_camera_on_the_point_it_looks_at_is_located() {
    // The scene's eye is (0, 3, 8): a still camera told to look at it has no direction.
    let text = "scene = \"scene.txt\"\nframes = 2\n\n[camera]\nlook_at = [0.0, 3.0, 8.0]\n";
    let (dir, manifest) = project(text);
    let err = refused(animate().arg(&manifest).arg("-o").arg(dir.path().join("f")));
    // Before: "frame 0: the camera is placed on the point it looks at", no place; now
    // the `[camera]` table's.
    assert!(
        err.contains("anim.toml:4:1: frame 0: the camera is placed on the point it looks at"),
        "{err}"
    );
}

#[test]
fn the_first_error_in_the_file_is_the_one_reported() {
    // `samples = 0` on line 4, a negative radius on line 8.
    let text = "scene = \"scene.txt\"\nframes = 3\n[render]\nsamples = 0\n[camera]\n\
                path = \"circle\"\ncenter = [0.0, 1.0, 0.0]\nradius = -1.0\nheight = 2.0\n";
    let (_dir, manifest) = project(text);
    let err = refused(animate().arg("status").arg(&manifest));
    // Before: line 8's radius, though line 4 comes first.
    assert!(err.contains("anim.toml:4:11: "), "{err}");
    // A track on line 4 the scene does not have, a look_at on line 7 it does not have
    // either: the track is reported.
    let text = "scene = \"scene.txt\"\nframes = 3\n[[track]]\ntarget = \"sphere 9 radius\"\n\
                keys = [{ frame = 0, value = 1.0 }]\n[camera]\nlook_at = \"sphere 7\"\n";
    let (_dir, manifest) = project(text);
    let err = refused(animate().arg("status").arg(&manifest));
    assert!(
        err.contains("anim.toml:4:10: sphere 9 does not exist"),
        "{err}"
    );
}

#[test]
fn bless_counts_what_it_replaced() {
    let check = "\n[check]\nframes = [0, 5, 9]\nreferences = \"refs\"\n";
    let (dir, manifest) = project(&circle_manifest(check));
    let bless = || {
        let out = animate().arg("bless").arg(&manifest).output().unwrap();
        assert!(out.status.success(), "{out:?}");
        String::from_utf8(out.stderr).unwrap()
    };
    let err = bless();
    assert!(err.contains("blessed 3 reference(s) in "), "{err}");
    assert!(err.trim_end().ends_with(": 3 new"), "{err}");
    // One reference edited, one removed: blessing again replaces two, one of them with
    // other pixels, and writes one anew.
    edit_reference(dir.path(), 5, magenta_block);
    std::fs::remove_file(dir.path().join("refs/frame_0009.png")).unwrap();
    let err = bless();
    // Before: "blessed 3 reference(s) in …" alone.
    assert!(
        err.trim_end().ends_with(": 2 replaced (1 changed), 1 new"),
        "{err}"
    );
}

#[test]
fn paths_are_shown_without_dot_dot() {
    let (dir, _) = project("");
    std::fs::create_dir(dir.path().join("sub")).unwrap();
    let manifest = dir.path().join("sub/m.toml");
    let text = "scene = \"../scene.txt\"\nframes = 2\n[output]\ndir = \"../out\"\n\
                [render]\nwidth = 16\nheight = 12\n";
    std::fs::write(&manifest, text).unwrap();
    let out = animate().arg(&manifest).output().unwrap();
    assert!(out.status.success(), "{out:?}");
    let err = String::from_utf8_lossy(&out.stderr);
    let folder = dir.path().join("out").display().to_string();
    // Before: "-> …/sub/../out".
    assert!(err.trim_end().ends_with(&format!("-> {folder}")), "{err}");
    let out = animate().arg("status").arg(&manifest).output().unwrap();
    let table = String::from_utf8_lossy(&out.stdout);
    assert!(
        table.starts_with(&format!("{folder}: 2 frame(s)\n")),
        "{table}"
    );
    // The frames are where the manifest said: the folder itself was not renamed.
    assert!(dir.path().join("out/frame_0000.png").is_file());
}

#[test]
fn status_says_why_a_frame_is_stale() {
    let (dir, manifest) = project(&circle_manifest(""));
    let out = dir.path().join("f");
    render_into(&manifest, &out, &["--frames", "0-2"]);
    let status = || {
        let run = animate()
            .arg("status")
            .arg(&manifest)
            .args(["--frames", "0-2", "--out"])
            .arg(&out)
            .output()
            .unwrap();
        String::from_utf8(run.stdout).unwrap()
    };
    // Twice the samples: the render settings the frames record are not the manifest's.
    let text = circle_manifest("\n[render]\nsamples = 2\n");
    std::fs::write(&manifest, text).unwrap();
    let table = status();
    // Before: "stale: 3  0-2" and no reason.
    assert!(
        table.contains(
            "0-2: the render settings were 64x48, 1x1 sample(s) per pixel, \
             now 64x48, 2x2 sample(s) per pixel"
        ),
        "{table}"
    );
    // Back to one sample, a sphere of another colour in the scene file: nothing the
    // stamp shows changed, so the record says only that the values did.
    std::fs::write(&manifest, circle_manifest("")).unwrap();
    let scene = dir.path().join("scene.txt");
    let text = std::fs::read_to_string(&scene).unwrap();
    std::fs::write(&scene, text.replace("1 0.9 0.9 0.9", "1 0.8 0.9 0.9")).unwrap();
    // Frame 1 cut short.
    let one = out.join("frame_0001.png");
    let bytes = std::fs::read(&one).unwrap();
    std::fs::write(&one, &bytes[..bytes.len() / 2]).unwrap();
    let table = status();
    assert!(table.contains("0,2: the scene's values changed"), "{table}");
    assert!(table.contains("1: damaged: "), "{table}");
}
