//! Point 6: a draft written into the finals' folder (`--size 32x24 -o frames`) replaced
//! all twelve finals and exited 0. Writing a draft over finals now needs `--force`, as
//! writing over another manifest's frames does; finals still replace drafts freely.

use super::run;
use crate::support::*;

#[test]
fn a_draft_into_the_finals_folder_needs_force() {
    let (dir, m) = project(&circle_manifest(""));
    let frames = dir.path().join("frames");
    let (code, _, err) = run(&[&m, &"-q"]);
    assert_eq!(code, Some(0), "{err}");
    let finals = files(&frames);
    let (code, _, err) = run(&[&m, &"--size", &"32x24", &"-o", &frames, &"-q"]);
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("holds 12 final frame(s) of this manifest (frames 0-11); this draft (32x24) would replace them")
            && err.contains("`--force` writes over them"),
        "{err}"
    );
    assert_eq!(files(&frames), finals, "the finals are untouched");
    // --resume refuses too (the finals are not the draft's to skip or replace).
    let (code, _, err) = run(&[&m, &"--size", &"32x24", &"-o", &frames, &"--resume", &"-q"]);
    assert_eq!(code, Some(2), "{err}");
    assert_eq!(files(&frames), finals);
    // Forced, the draft replaces them; a draft over drafts and the finals over the
    // drafts need nothing.
    let (code, _, err) = run(&[&m, &"--size", &"32x24", &"-o", &frames, &"--force", &"-q"]);
    assert_eq!(code, Some(0), "{err}");
    let first = image::open(frames.join("frame_0000.png")).unwrap();
    assert_eq!((first.width(), first.height()), (32, 24));
    let (code, _, err) = run(&[&m, &"--size", &"16x12", &"-o", &frames, &"-q"]);
    assert_eq!(code, Some(0), "{err}");
    let (code, _, err) = run(&[&m, &"-q"]);
    assert_eq!(code, Some(0), "{err}");
    assert_eq!(files(&frames), finals, "the same finals again");
}
