//! Point 5 of reliability round three: a closed standard output ends a command quietly.

use super::{run, PROMPT};
use crate::support::*;

// 5. A closed standard output ends a command quietly.

/// `animate ARGS` with standard output a pipe whose reader has already gone away:
/// (status, stderr).
fn into_closed_pipe(args: &[&dyn AsRef<std::ffi::OsStr>]) -> (Option<i32>, String) {
    let (reader, writer) = std::io::pipe().unwrap();
    drop(reader);
    let mut cmd = std::process::Command::new(assert_cmd::cargo::cargo_bin("animate"));
    for a in args {
        cmd.arg(a);
    }
    let mut child = cmd
        .stdout(writer)
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let (code, _) = wait_within(&mut child, PROMPT);
    let mut err = String::new();
    std::io::Read::read_to_string(&mut child.stderr.take().unwrap(), &mut err).unwrap();
    (code, err)
}

#[test]
fn a_closed_stdout_ends_quietly_with_the_verdict() {
    let check = "\n[check]\nframes = [0]\nreferences = \"refs\"\n";
    let (dir, m) = project(&circle_manifest(check));
    let (code, _, err) = run(&[&"bless", &m, &"-q"]);
    assert_eq!(code, Some(0), "{err}");
    std::fs::create_dir(dir.path().join("frames")).unwrap();
    let cases: [(&[&dyn AsRef<std::ffi::OsStr>], i32); 7] = [
        // The frames are missing: status's verdict is 1, text or no text.
        (&[&"status", &m], 1),
        (&[&"status", &m, &"--json"], 1),
        (&[&"check", &m], 0),
        (&[&"check", &m, &"--json"], 0),
        (&[&"clean", &m], 0),
        // Their text is their product: cut short.
        (&[&"estimate", &m, &"--shards", &"3"], 141),
        (&[&"job", &m, &"--openjd"], 141),
    ];
    for (args, expected) in cases {
        let (code, err) = into_closed_pipe(args);
        let shown: Vec<String> = args
            .iter()
            .map(|a| a.as_ref().to_string_lossy().into())
            .collect();
        assert_eq!(code, Some(expected), "{shown:?}: {err}");
        assert_eq!(err, "", "{shown:?}");
    }
    // A check that fails keeps its 1.
    edit_reference(dir.path(), 0, magenta_block);
    let (code, err) = into_closed_pipe(&[&"check", &m]);
    assert_eq!((code, err.as_str()), (Some(1), ""));
}
