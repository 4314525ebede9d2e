//! Points 3 and 4 of reliability round three: runs, `clean` and `bless` touch only their
//! manifest's files; reports and templates do not overwrite inputs or others' files.

use super::{run, PROMPT};
use crate::support::*;
use std::path::Path;
use std::time::Duration;

// 3. Files that are not the tool's are neither removed nor overwritten.

/// A photo: a sound PNG with no record.
fn photo(path: &Path) {
    image::RgbImage::from_pixel(8, 8, image::Rgb([200, 100, 50]))
        .save(path)
        .unwrap();
}

/// A circle manifest of `frames` frames named `IMG_####` into `shared/`.
fn img_manifest(dir: &Path, name: &str, frames: u32) -> std::path::PathBuf {
    let text = circle_manifest("")
        .replace("frames = 12", &format!("frames = {frames}"))
        .replace("dir = \"frames\"", "dir = \"shared\"")
        .replace("frame_####", "IMG_####");
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path
}

#[test]
fn a_run_does_not_replace_a_file_with_no_record() {
    let (dir, _) = project("");
    let m = img_manifest(dir.path(), "a.toml", 2);
    let shared = dir.path().join("shared");
    std::fs::create_dir(&shared).unwrap();
    photo(&shared.join("IMG_0000.png"));
    let before = std::fs::read(shared.join("IMG_0000.png")).unwrap();
    let (code, _, err) = run(&[&m, &"-q"]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("IMG_0000.png: not written by animate (no record), and would be replaced")
            && err.contains("hint: `--force`"),
        "{err}"
    );
    assert_eq!(std::fs::read(shared.join("IMG_0000.png")).unwrap(), before);
    assert!(!shared.join("IMG_0001.png").exists(), "nothing rendered");
    let (code, _, err) = run(&[&m, &"-q", &"--force"]);
    assert_eq!(code, Some(0), "{err}");
    assert_ne!(std::fs::read(shared.join("IMG_0000.png")).unwrap(), before);
    // The run's own frames are its to replace.
    let (code, _, err) = run(&[&m, &"-q"]);
    assert_eq!(code, Some(0), "{err}");
}

#[test]
fn clean_removes_only_its_own_frames_unless_forced() {
    let (dir, _) = project("");
    let a = img_manifest(dir.path(), "a.toml", 6);
    let b = img_manifest(dir.path(), "b.toml", 12);
    let shared = dir.path().join("shared");
    let (code, _, err) = run(&[&a, &"-q"]);
    assert_eq!(code, Some(0), "{err}");
    // Another manifest's frames past a's end, and a photo under the pattern.
    let (code, _, err) = run(&[&b, &"-q", &"--frames", &"8-9"]);
    assert_eq!(code, Some(0), "{err}");
    photo(&shared.join("IMG_0042.png"));
    // a is shortened: its frames 4 and 5 are past the end, and its own.
    std::fs::write(
        &a,
        std::fs::read_to_string(&a)
            .unwrap()
            .replace("frames = 6", "frames = 4"),
    )
    .unwrap();
    let (code, out, err) = run(&[&"clean", &a]);
    assert_eq!(code, Some(2), "{out}{err}");
    assert!(err.contains("and would be removed"), "{err}");
    assert_eq!(files(&shared).len(), 9, "nothing removed");
    let (code, out, err) = run(&[&"clean", &a, &"--force"]);
    assert_eq!(code, Some(0), "{err}");
    assert!(out.contains("removed 5 frame(s) past the end"), "{out}");
    let names: Vec<String> = files(&shared).into_iter().map(|f| f.0).collect();
    assert_eq!(
        names,
        [
            "IMG_0000.png",
            "IMG_0001.png",
            "IMG_0002.png",
            "IMG_0003.png"
        ]
    );
    // With only its own frames past the end, clean needs no --force.
    std::fs::write(
        &a,
        std::fs::read_to_string(&a)
            .unwrap()
            .replace("frames = 4", "frames = 2"),
    )
    .unwrap();
    let (code, out, err) = run(&[&"clean", &a]);
    assert_eq!(code, Some(0), "{err}");
    assert!(
        out.contains("removed 2 frame(s) past the end (2-3)"),
        "{out}"
    );
}

#[test]
fn bless_keeps_to_its_references_and_the_folder_lock() {
    let check = "\n[check]\nframes = [0, 1]\nreferences = \"refs\"\n";
    let (dir, a) = project(&circle_manifest(check));
    let b = dir.path().join("b.toml");
    std::fs::write(
        &b,
        circle_manifest(check).replace("radius = 8.0", "radius = 7.0"),
    )
    .unwrap();
    let refs = dir.path().join("refs");
    let (code, _, err) = run(&[&"bless", &a, &"-q"]);
    assert_eq!(code, Some(0), "{err}");
    let before = files(&refs);
    let (code, _, err) = run(&[&"bless", &b, &"-q"]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("rendered by another manifest (anim.toml)"),
        "{err}"
    );
    assert_eq!(files(&refs), before);
    let (code, _, err) = run(&[&"bless", &b, &"-q", &"--force"]);
    assert_eq!(code, Some(0), "{err}");
    assert_ne!(files(&refs), before);
    // A run of another manifest writing into the folder holds it: bless waits its turn.
    let slow = dir.path().join("slow.toml");
    let text = circle_manifest("\n[render]\nwidth = 640\nheight = 480\nsamples = 4\n")
        .replace("frames = 12", "frames = 200")
        .replace("frame_####", "slow_####");
    std::fs::write(&slow, text).unwrap();
    let mut child = spawn_animate(&slow, &["-q", "-o", refs.to_str().unwrap()]);
    // Its lock file is the third manifest's (anim.toml's and b.toml's are there).
    let locks = || {
        let names = std::fs::read_dir(&refs).unwrap().flatten();
        names
            .filter(|e| {
                e.file_name()
                    .to_string_lossy()
                    .starts_with(".whitted-lock-")
            })
            .count()
    };
    let locked = poll_until(PROMPT, || {
        locks() == 3 && child.try_wait().unwrap().is_none()
    });
    assert!(locked.is_some(), "the slow run never took the lock");
    std::thread::sleep(Duration::from_millis(300));
    let (code, _, err) = run(&[&"bless", &a, &"-q", &"--force"]);
    let _ = child.kill();
    let _ = child.wait();
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("a run of another manifest is writing into"),
        "{err}"
    );
}

// 4. Outputs do not overwrite inputs or others' files.

#[test]
fn reports_and_templates_do_not_overwrite_inputs_or_others_files() {
    let check = "\n[check]\nframes = [0]\nreferences = \"refs\"\n";
    let (dir, m) = project(&circle_manifest(check));
    let manifest = std::fs::read(&m).unwrap();
    let (code, _, err) = run(&[&"bless", &m, &"-q"]);
    assert_eq!(code, Some(0), "{err}");
    for args in [
        vec!["job", "--openjd", "-o"],
        vec!["job", "--openjd", "--force", "-o"],
        vec!["check", "--junit"],
        vec!["check", "--force", "--junit"],
    ] {
        let mut all: Vec<&dyn AsRef<std::ffi::OsStr>> = vec![&args[0], &m];
        all.extend(args[1..].iter().map(|a| a as &dyn AsRef<std::ffi::OsStr>));
        all.push(&m);
        let (code, _, err) = run(&all);
        assert_eq!(code, Some(2), "{args:?}: {err}");
        assert!(
            err.contains("it is an input of this run"),
            "{args:?}: {err}"
        );
        assert_eq!(std::fs::read(&m).unwrap(), manifest, "{args:?}");
    }
    // A page that is not the tool's, then a file that is not a template.
    let site = dir.path().join("site");
    std::fs::create_dir(&site).unwrap();
    std::fs::write(site.join("index.html"), "<h1>my site</h1>").unwrap();
    let (code, _, err) = run(&[&"check", &m, &"--html", &site]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("it exists and was not written by animate"),
        "{err}"
    );
    assert_eq!(
        std::fs::read_to_string(site.join("index.html")).unwrap(),
        "<h1>my site</h1>"
    );
    let (code, _, err) = run(&[&"check", &m, &"--html", &site, &"--force"]);
    assert_eq!(code, Some(0), "{err}");
    // Its own page is its to replace.
    let (code, _, err) = run(&[&"check", &m, &"--html", &site]);
    assert_eq!(code, Some(0), "{err}");
    let notes = dir.path().join("notes.json");
    std::fs::write(&notes, "{}").unwrap();
    let (code, _, err) = run(&[&"job", &m, &"--openjd", &"-o", &notes]);
    assert_eq!(code, Some(2), "{err}");
    let (code, _, err) = run(&[&"job", &m, &"--openjd", &"-o", &notes, &"--force"]);
    assert_eq!(code, Some(0), "{err}");
    let (code, _, err) = run(&[&"job", &m, &"--openjd", &"-o", &notes]);
    assert_eq!(code, Some(0), "its own template: {err}");
    // 9. `job -o folder/` was exit 1.
    let (code, _, err) = run(&[&"job", &m, &"--openjd", &"-o", &site]);
    assert_eq!(code, Some(2), "{err}");
    assert!(err.contains("it is a folder"), "{err}");
}
