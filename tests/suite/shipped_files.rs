//! The tests' list of shipped scenes and manifests (`tests/shipped`) is the repository's:
//! every name exists and parses, and git tracks no file in those folders that the list
//! leaves out. Other files there are the user's and no test reads them.

use crate::shipped;
use crate::skip;

use std::process::Command;
use whitted::Scene;
use whitted_anim::Project;

#[test]
fn every_shipped_file_exists_and_loads() {
    for path in shipped::scenes() {
        Scene::load(&path).unwrap_or_else(|e| panic!("{e}"));
    }
    let gltf = shipped::GLTF_ANIMATIONS.iter();
    let gltf = gltf.map(|n| shipped::root().join("animations").join(n));
    for path in shipped::animations().into_iter().chain(gltf) {
        Project::load(&path).unwrap_or_else(|e| panic!("{e}"));
    }
}

#[test]
fn the_list_is_what_git_tracks() {
    let out = Command::new("git")
        .args(["ls-files", "scenes", "animations"])
        .current_dir(shipped::root())
        .output();
    let Some(out) = out.ok().filter(|o| o.status.success()) else {
        skip::skip("not a git checkout (or no git)");
        return;
    };
    let tracked: Vec<String> = String::from_utf8_lossy(&out.stdout)
        .lines()
        .map(str::to_string)
        .collect();
    let mut listed: Vec<String> = shipped::SCENES
        .iter()
        .chain(shipped::MESH_FILES)
        .chain(shipped::MODEL_FILES)
        .map(|n| format!("scenes/{n}"))
        .chain(
            shipped::ANIMATIONS
                .iter()
                .chain(shipped::SPD_ANIMATIONS)
                .chain(shipped::GLTF_ANIMATIONS)
                .map(|n| format!("animations/{n}")),
        )
        .collect();
    listed.sort();
    let mut tracked_sorted = tracked.clone();
    tracked_sorted.sort();
    assert_eq!(
        listed, tracked_sorted,
        "tests/shipped/mod.rs and git disagree"
    );
}
