//! A read-only output folder, existing or new, is refused before anything renders (status
//! 2, the folder named), where a run used to render frame 0 and then fail with status 1.
//! Root ignores permission bits, so the folder is on a tmpfs remounted read-only; where
//! mounting is not allowed the test says it skipped, and under CI (root) it must run.

use crate::skip;
use crate::support;

use std::path::Path;
use std::process::{Command, Stdio};
use support::*;

fn mount(args: &[&str], at: &Path) -> bool {
    Command::new("mount")
        .args(args)
        .arg(at)
        .stderr(Stdio::null())
        .status()
        .is_ok_and(|s| s.success())
}

#[test]
fn a_read_only_folder_is_refused_before_rendering_whether_it_exists_or_not() {
    let (dir, manifest) = project(&circle_manifest(""));
    let mnt = dir.path().join("ro");
    std::fs::create_dir(&mnt).unwrap();
    if !mount(&["-t", "tmpfs", "-o", "size=1m", "tmpfs"], &mnt) {
        skip::skip("cannot mount a tmpfs here (not root?); CI runs as root");
        return;
    }
    std::fs::create_dir(mnt.join("existing")).unwrap();
    let read_only = mount(&["-o", "remount,ro"], &mnt);
    let mut results = Vec::new();
    for folder in ["existing", "new"] {
        let out = animate()
            .arg(&manifest)
            .arg("-o")
            .arg(mnt.join(folder))
            .args(["-q", "--threads", "1"])
            .output()
            .unwrap();
        results.push((folder, out));
    }
    let left = entries(&mnt.join("existing"));
    let _ = Command::new("umount").arg(&mnt).status();
    assert!(read_only, "remounting the tmpfs read-only failed");
    for (folder, out) in results {
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{folder}: {err}");
        assert!(
            err.contains(&format!("ro/{folder}")) && err.contains("Read-only file system"),
            "{folder}: {err}"
        );
    }
    assert!(left.is_empty(), "nothing was written: {left:?}");
}
