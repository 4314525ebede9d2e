//! The user's reference pages are true of the code: every example of docs/manifest.md and
//! docs/scene-format.md is read by the library, and every error shown after a refused
//! example is the error the library gives, byte for byte.
//!
//! A fenced block's info string says what it is:
//! - `toml complete`: a whole manifest, which `Manifest::parse` must accept;
//! - `toml`: a fragment, accepted after `scene = "scene.txt"` and `frames = 250`;
//! - `toml refused` / `text refused` (a scene): refused, with exactly the message of the
//!   ```` ```text ```` block that follows it;
//! - `text complete`: a whole Scene.txt, which `Scene::parse` must accept.

use std::path::Path;
use whitted::Scene;
use whitted_anim::Manifest;

/// The fenced blocks of a Markdown page: (info string, text, line of the opening fence).
fn blocks(page: &str) -> Vec<(String, String, usize)> {
    let mut out = Vec::new();
    let mut open: Option<(String, String, usize)> = None;
    for (n, line) in page.lines().enumerate() {
        match (&mut open, line.strip_prefix("```")) {
            (None, Some(info)) => open = Some((info.trim().to_string(), String::new(), n + 1)),
            (Some(_), Some("")) => out.push(open.take().unwrap()),
            (Some((_, text, _)), _) => {
                text.push_str(line);
                text.push('\n');
            }
            (None, None) => {}
        }
    }
    assert!(open.is_none(), "an unclosed code block");
    out
}

fn page(name: &str) -> String {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("docs")
        .join(name);
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// Where the manifest examples are read from: `../scenes/orbit.txt` is the repository's.
fn doc_manifest_path() -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("animations/doc.toml")
}

#[test]
fn the_block_reader_finds_info_strings_and_text() {
    let page = "a\n```toml complete\nx = 1\n```\nb\n```text\nerr\n```\n";
    assert_eq!(
        blocks(page),
        vec![
            ("toml complete".to_string(), "x = 1\n".to_string(), 2),
            ("text".to_string(), "err\n".to_string(), 6),
        ]
    );
}

#[test]
fn every_manifest_example_parses() {
    let page = page("manifest.md");
    let path = doc_manifest_path();
    let (mut complete, mut fragments) = (0, 0);
    for (info, text, line) in blocks(&page) {
        let src = match info.as_str() {
            "toml complete" => {
                complete += 1;
                text.clone()
            }
            "toml" => {
                fragments += 1;
                format!("scene = \"scene.txt\"\nframes = 250\n{text}")
            }
            _ => continue,
        };
        let m = Manifest::parse(&src, &path).unwrap_or_else(|e| {
            panic!("docs/manifest.md:{line}: the example is refused:\n{e}\n---\n{src}")
        });
        // A complete example over a scene of the repository: the scene is readable too.
        if info == "toml complete" && m.scene.exists() {
            Scene::load(&m.scene).unwrap_or_else(|e| panic!("docs/manifest.md:{line}: {e}"));
        }
    }
    assert!(
        complete >= 3 && fragments >= 8,
        "{complete} complete, {fragments} fragments"
    );
}

#[test]
fn every_scene_example_parses() {
    let page = page("scene-format.md");
    let complete: Vec<_> = blocks(&page)
        .into_iter()
        .filter(|(info, _, _)| info == "text complete")
        .collect();
    assert!(complete.len() >= 2);
    for (_, text, line) in complete {
        Scene::parse(&text, "scene.txt").unwrap_or_else(|e| {
            panic!("docs/scene-format.md:{line}: the example is refused:\n{e}")
        });
    }
}

/// Each refused example and the error shown after it: (example, shown, line).
fn refusals(page: &str, info: &str) -> Vec<(String, String, usize)> {
    let all = blocks(page);
    let found: Vec<_> = all
        .iter()
        .enumerate()
        .filter(|(_, (i, _, _))| i == info)
        .map(|(k, (_, text, line))| {
            let (next, shown, _) = all.get(k + 1).expect("an error block after the example");
            assert_eq!(next, "text", "line {line}: a ```text block must follow");
            (text.clone(), shown.trim_end().to_string(), *line)
        })
        .collect();
    assert!(!found.is_empty(), "no `{info}` example");
    found
}

#[test]
fn the_manifest_errors_shown_are_the_real_ones() {
    let page = page("manifest.md");
    for (src, shown, line) in refusals(&page, "toml refused") {
        let err = Manifest::parse(&src, Path::new("anim.toml")).unwrap_err();
        assert_eq!(err.to_string(), shown, "docs/manifest.md:{line}");
    }
}

#[test]
fn the_scene_errors_shown_are_the_real_ones() {
    let page = page("scene-format.md");
    for (src, shown, line) in refusals(&page, "text refused") {
        let err = Scene::parse(&src, "scene.txt").unwrap_err();
        assert_eq!(err.to_string(), shown, "docs/scene-format.md:{line}");
    }
}

#[test]
fn every_nff_example_parses_and_its_errors_are_the_real_ones() {
    let page = page("scene-format.md");
    let complete: Vec<_> = blocks(&page)
        .into_iter()
        .filter(|(info, _, _)| info == "nff complete")
        .collect();
    assert!(!complete.is_empty());
    for (_, text, line) in complete {
        whitted::scene::nff::parse(&text, "scene.nff").unwrap_or_else(|e| {
            panic!("docs/scene-format.md:{line}: the example is refused:\n{e}")
        });
    }
    for (src, shown, line) in refusals(&page, "nff refused") {
        let err = whitted::scene::nff::parse(&src, "scene.nff").unwrap_err();
        assert_eq!(err.to_string(), shown, "docs/scene-format.md:{line}");
    }
}

#[test]
fn the_pages_point_nowhere_outside_the_repository() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    for name in [
        "README.md",
        "docs/manifest.md",
        "docs/scene-format.md",
        "docs/decisions.md",
    ] {
        let text = std::fs::read_to_string(root.join(name)).unwrap();
        assert!(!text.contains("SPEC.md"), "{name} points at the SPEC");
        // Every relative Markdown link names a file of the repository.
        let folder = root.join(name).parent().unwrap().to_path_buf();
        for target in text.split("](").skip(1).filter_map(|s| s.split(')').next()) {
            if target.contains("://") || target.starts_with('#') {
                continue;
            }
            let file = target.split('#').next().unwrap();
            assert!(
                folder.join(file).exists(),
                "{name} links to missing {target}"
            );
        }
    }
    let readme = std::fs::read_to_string(root.join("README.md")).unwrap();
    for page in ["docs/manifest.md", "docs/scene-format.md"] {
        assert!(
            readme.contains(&format!("]({page})")),
            "README links {page}"
        );
    }
}
