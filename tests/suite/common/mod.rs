//! Helpers shared by the integration tests: running the built `raytrace`, writing scene
//! files into temporary folders, listing what a run left behind.

// Each test crate uses its own subset of these helpers.
#![allow(dead_code)]

use assert_cmd::Command;
use std::path::{Path, PathBuf};

/// The built `raytrace` binary, run in `dir`.
pub fn raytrace_in(dir: &Path) -> Command {
    let mut cmd = Command::cargo_bin("raytrace").expect("the raytrace binary is built");
    cmd.current_dir(dir);
    cmd
}

/// Writes `contents` to `dir/name` and returns the path.
pub fn write_file(dir: &Path, name: &str, contents: impl AsRef<[u8]>) -> PathBuf {
    let path = dir.join(name);
    std::fs::write(&path, contents).expect("cannot write a test file");
    path
}

/// The names of the entries of `dir`, sorted (hidden temporaries included).
pub fn entries(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .expect("cannot list a test folder")
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

/// A small valid scene with every record kind, every texture and a refracting,
/// reflecting, bumped set of objects, in fog: what byte-identity tests render.
pub fn rich_scene(width: u32, height: u32) -> String {
    format!(
        "# a test scene with every feature of the format
{width} {height}
0 2.5 10            # eye
0 1 0               # look at
2 60                # exponential fog
3 2 1 2             # spheres, planes, cylinders, lights
# glass sphere, Perlin texture, refraction and reflection
1.2  -1.5 1.2 1   2 2 0.9 0.9 1.0  0.6 0.8 1.0  1 1 1   0.1 0.2 0.7 1.5 0 0
# mirror sphere, marble, uniform bump
1.0   1.6 1.0 0   2 4 0.9 0.9 0.9  0.2 0.2 0.3  0 0 0   0.4 0.5 0 1 1 0.3
# wood sphere behind
0.8   0 0.8 -3    2 3 0.6 0.3 0.1  0.9 0.6 0.3  0 0 0   0.8 0 0 1 0 0
# checker floor, water bump, reflective
0 0 0   0 1 0     2 1 1 1 1  0.1 0.1 0.1  0 0 0      0.7 0.3 0 1 2 0.05
# back wall, one colour
0 0 -12  0 0 1    1 0.4 0.5 0.7                      0.9 0 0 1 0 0
# slanted glass cylinder, uniform colour
1 1 0   4 0 -4  0.5   1 0.9 0.4 0.4                  0.2 0.1 0.6 1.3 0 0
# lights
5 10 8   1 1 1   1
-6 6 4   1 0.8 0.6   0.6
"
    )
}
