//! Points 7 and 8 of reliability round three: damaged EXR offset tables, and OpenJD names.

use super::{run, text};
use crate::support::*;

// 7. Damage to an EXR's offset table.

/// Where the offset table of a single-part EXR of `count` blocks starts: the place whose
/// first entry points just past the table.
fn offset_table(bytes: &[u8], count: usize) -> usize {
    let at = |p: usize| u64::from_le_bytes(bytes[p..p + 8].try_into().unwrap()) as usize;
    (8..bytes.len() - 8 * count)
        .find(|&p| at(p) == p + 8 * count)
        .expect("an offset table")
}

#[test]
fn damage_to_exr_offset_tables_is_stale() {
    let manifest = circle_manifest("").replace("format = \"png\"", "format = \"exr\"");
    let (dir, m) = project(&manifest.replace("frames = 12", "frames = 4"));
    let (code, _, err) = run(&[&m, &"-q"]);
    assert_eq!(code, Some(0), "{err}");
    let frame = |k: u32| dir.path().join(format!("frames/frame_{k:04}.exr"));
    // 48 lines in blocks of 16 (ZIP): three offsets.
    let edit = |k: u32, change: &dyn Fn(&mut Vec<u8>, usize)| {
        let mut bytes = std::fs::read(frame(k)).unwrap();
        let table = offset_table(&bytes, 3);
        change(&mut bytes, table);
        std::fs::write(frame(k), bytes).unwrap();
    };
    let entry = |b: &mut Vec<u8>, p: usize, f: &dyn Fn(u64) -> u64| {
        let v = u64::from_le_bytes(b[p..p + 8].try_into().unwrap());
        b[p..p + 8].copy_from_slice(&f(v).to_le_bytes());
    };
    // Frame 0: the second offset off by 4.
    edit(0, &|b, t| entry(b, t + 8, &|v| v + 4));
    // Frame 1: the first two swapped.
    edit(1, &|b, t| {
        let (x, y) = (b[t..t + 8].to_vec(), b[t + 8..t + 16].to_vec());
        b[t..t + 8].copy_from_slice(&y);
        b[t + 8..t + 16].copy_from_slice(&x);
    });
    // Frame 2: the last one past the end.
    edit(2, &|b, t| {
        let len = b.len() as u64;
        entry(b, t + 16, &|_| len + 100)
    });
    for verify in [false, true] {
        let mut args: Vec<&dyn AsRef<std::ffi::OsStr>> = vec![&"status", &m, &"--json"];
        if verify {
            args.push(&"--verify");
        }
        let (code, json, err) = run(&args);
        assert_eq!(code, Some(1), "{err}");
        let doc: serde_json::Value = serde_json::from_str(&json).unwrap();
        assert_eq!(doc["stale"], "0-2", "verify {verify}: {json}");
        assert_eq!(doc["up_to_date"], "3", "verify {verify}: {json}");
    }
    let (code, _, err) = run(&[&m, &"--resume"]);
    assert_eq!(code, Some(0), "{err}");
    assert!(err.contains("3 frames rendered, 1 up to date"), "{err}");
    let (code, _, err) = run(&[&"status", &m]);
    assert_eq!(code, Some(0), "{err}");
}

// 8. OpenJD templates of manifests with braces and control characters in their names.

#[test]
fn openjd_names_are_escaped_or_left_to_the_job() {
    let (dir, m) = project(&circle_manifest(""));
    let odd = dir.path().join("x{{Param.Animate}}\u{7}.toml");
    std::fs::copy(&m, &odd).unwrap();
    let template = dir.path().join("job.json");
    let (code, _, err) = run(&[&"job", &odd, &"--openjd", &"-q", &"-o", &template]);
    assert_eq!(code, Some(0), "{err}");
    let t: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&template).unwrap()).unwrap();
    assert_eq!(t["name"], "animate x__Param.Animate___");
    let description = t["description"].as_str().unwrap();
    assert!(
        !description.contains("{{") && !description.contains('\u{7}'),
        "{description}"
    );
    // The manifest's path cannot be a default: the job is given it (`-p Manifest=…`).
    let manifest = &t["parameterDefinitions"][1];
    assert_eq!(manifest["name"], "Manifest");
    assert!(manifest.get("default").is_none(), "{manifest}");
    if crate::skip::have("openjd", &["--version"]) {
        let out = std::process::Command::new("openjd")
            .arg("check")
            .arg(&template)
            .output()
            .unwrap();
        assert!(out.status.success(), "{}", text(&out.stderr));
    }
}
