//! The files the project ships in `scenes/` and `animations/`, by name: the tests render
//! and parse these, never whatever else is in those folders (they are where a user's own
//! scenes and manifests go, and a work in progress there must not fail `cargo test`).
//! A file added to the repository is added here; `tests/shipped_files.rs` checks that
//! every name here exists and that git tracks no other file in those folders.

#![allow(dead_code)]

use std::path::{Path, PathBuf};

/// The shipped scenes, in `scenes/`.
pub const SCENES: &[&str] = &[
    "01-ambient.txt",
    "02-diffuse.txt",
    "03-specular.txt",
    "04-reflection.txt",
    "05-refraction.txt",
    "06-refraction-indices.txt",
    "07-transparency.txt",
    "08-procedural-textures.txt",
    "09-bump-mapping.txt",
    "10-water-bump.txt",
    "11-no-fog.txt",
    "12-linear-fog.txt",
    "13-exp-fog.txt",
    "14-exp2-fog.txt",
    "bounce.txt",
    "bunny.txt",
    "csg-piece.txt",
    "glass-cluster.txt",
    "meshes.txt",
    "new-shapes.txt",
    "orbit.txt",
    "showcase.txt",
    "torus-chain.txt",
];

/// The mesh files the shipped scenes read, in `scenes/` (written by
/// `benches/gen_meshes.py`).
pub const MESH_FILES: &[&str] = &["meshes/gem.obj", "meshes/trefoil.ply"];

/// The models, in `scenes/` (each written by the script beside it), their scripts and
/// the page that credits them: `walk.toml` plays the walker (glTF); `bunny.txt` reads the
/// Stanford bunny (a PLY converted from an OBJ by `obj_to_ply.py`).
pub const MODEL_FILES: &[&str] = &[
    "models/README.md",
    "models/bunny.ply",
    "models/make_walker.py",
    "models/obj_to_ply.py",
    "models/walker.glb",
];

/// The shipped manifests, in `animations/`.
pub const ANIMATIONS: &[&str] = &[
    "bounce.toml",
    "bunny-turntable.toml",
    "flythrough.toml",
    "fog.toml",
    "orbit-passes.toml",
    "orbit.toml",
    "showcase.toml",
    "turn-to-glass.toml",
];

/// The shipped manifests that render a Standard Procedural Database from the copy
/// beside the repository (`../shared/spd`, not in it): listed apart, since they load only
/// where that copy is (`tests/suite/nff.rs` loads them there, and skips elsewhere).
pub const SPD_ANIMATIONS: &[&str] = &["sphereflake.toml"];

/// The shipped manifests that play a glTF file's animation without `frames`: listed
/// apart, since they count their frames from the file, which must be beside them (the
/// parsers' seeds are parsed from text alone).
pub const GLTF_ANIMATIONS: &[&str] = &["walk.toml"];

/// The repository's root.
pub fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// The paths of the shipped scenes.
pub fn scenes() -> Vec<PathBuf> {
    SCENES
        .iter()
        .map(|n| root().join("scenes").join(n))
        .collect()
}

/// The paths of the shipped manifests.
pub fn animations() -> Vec<PathBuf> {
    ANIMATIONS
        .iter()
        .map(|n| root().join("animations").join(n))
        .collect()
}
