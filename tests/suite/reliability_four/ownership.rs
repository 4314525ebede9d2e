//! Point 1: `clean` removed a text file under a frame's name past the end without
//! `--force` (a file that cannot be read as a frame was taken for a damaged frame of the
//! tool's), and a folder under a frame's name stopped it half way, its claim files left.
//! A run replaced such a file within the sequence as silently.

use super::{edit, run};
use crate::support::*;

#[test]
fn clean_leaves_a_users_file_under_a_frame_name_unless_forced() {
    let (dir, m) = project(&circle_manifest(""));
    let frames = dir.path().join("frames");
    let (code, _, err) = run(&[&m, &"-q"]);
    assert_eq!(code, Some(0), "{err}");
    edit(&m, "frames = 12", "frames = 6");
    let notes = frames.join("frame_0020.png");
    std::fs::write(&notes, "my notes, not a picture\n").unwrap();
    // --dry-run says it is not the manifest's.
    let (code, out, err) = run(&[&"clean", &m, &"--dry-run"]);
    assert_eq!(code, Some(0), "{err}");
    assert!(
        out.contains("would remove 7 frame(s) past the end (6-11,20)")
            && out.contains("(1 of them not this manifest's: removed only when forced)"),
        "{out}"
    );
    let (code, out, err) = run(&[&"clean", &m]);
    assert_eq!(code, Some(2), "{out}{err}");
    assert!(
        err.contains("frame_0020.png: not written by animate")
            && err.contains("and would be removed")
            && err.contains("`--force`"),
        "{err}"
    );
    assert_eq!(
        std::fs::read_to_string(&notes).unwrap(),
        "my notes, not a picture\n"
    );
    assert_eq!(files(&frames).len(), 13, "nothing removed");
    let (code, out, err) = run(&[&"clean", &m, &"--force"]);
    assert_eq!(code, Some(0), "{err}");
    assert!(
        out.contains("removed 7 frame(s) past the end (6-11,20)"),
        "{out}"
    );
    assert!(!notes.exists());
}

#[test]
fn a_cut_short_frame_of_the_tools_is_still_its_own_to_clean() {
    let (dir, m) = project(&circle_manifest(""));
    let frames = dir.path().join("frames");
    let (code, _, err) = run(&[&m, &"-q"]);
    assert_eq!(code, Some(0), "{err}");
    // A frame of the tool's cut short (a full disk, a copy stopped half way).
    let f9 = frames.join("frame_0009.png");
    let bytes = std::fs::read(&f9).unwrap();
    std::fs::write(&f9, &bytes[..bytes.len() / 2]).unwrap();
    edit(&m, "frames = 12", "frames = 8");
    let (code, out, err) = run(&[&"clean", &m]);
    assert_eq!(code, Some(0), "{err}");
    assert!(
        out.contains("removed 4 frame(s) past the end (8-11)"),
        "{out}"
    );
}

#[test]
fn a_folder_under_a_frame_name_does_not_stop_clean_half_way() {
    let (dir, m) = project(&circle_manifest(""));
    let frames = dir.path().join("frames");
    let (code, _, err) = run(&[&m, &"-q"]);
    assert_eq!(code, Some(0), "{err}");
    let folder = frames.join("frame_0030.png");
    std::fs::create_dir(&folder).unwrap();
    std::fs::write(folder.join("inside.txt"), "kept").unwrap();
    edit(&m, "frames = 12", "frames = 4");
    let (code, out, err) = run(&[&"clean", &m, &"--dry-run"]);
    assert_eq!(code, Some(0), "{err}");
    assert!(
        out.contains("would remove 8 frame(s) past the end (4-11)"),
        "{out}"
    );
    let (code, out, err) = run(&[&"clean", &m]);
    assert_eq!(code, Some(0), "{err}");
    assert!(
        out.contains(
            "removed 8 frame(s) past the end (4-11), 0 temporary file(s) and 12 claim file(s)"
        ),
        "{out}"
    );
    // Every frame past the end went, the claims too, and the folder is as it was.
    let names: Vec<String> = entries(&frames)
        .into_iter()
        .filter(|n| n.starts_with("frame_"))
        .collect();
    let kept = ["0000", "0001", "0002", "0003", "0030"].map(|k| format!("frame_{k}.png"));
    assert_eq!(names, kept);
    assert!(!frames.join(".whitted-claims").exists());
    assert_eq!(
        std::fs::read_to_string(folder.join("inside.txt")).unwrap(),
        "kept"
    );
    // Forced, it is still not a frame to remove.
    let (code, _, err) = run(&[&"clean", &m, &"--force"]);
    assert_eq!(code, Some(0), "{err}");
    assert!(folder.join("inside.txt").is_file());
}

#[test]
fn a_run_does_not_replace_a_users_text_file_under_a_frame_name() {
    let (dir, m) = project(&circle_manifest(""));
    let frames = dir.path().join("frames");
    std::fs::create_dir(&frames).unwrap();
    let notes = frames.join("frame_0003.png");
    std::fs::write(&notes, "my notes\n").unwrap();
    let (code, _, err) = run(&[&m, &"-q"]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("frame_0003.png: not written by animate")
            && err.contains("and would be replaced"),
        "{err}"
    );
    assert_eq!(std::fs::read_to_string(&notes).unwrap(), "my notes\n");
    let (code, _, err) = run(&[&m, &"-q", &"--force"]);
    assert_eq!(code, Some(0), "{err}");
    assert!(image::open(&notes).is_ok());
}
