//! `animate` prints the warnings of a scene's mesh files before it draws, as `raytrace`
//! does (`--quiet` silences them), and still draws the frames.

use crate::support::animate;

#[test]
fn animate_names_what_a_mesh_file_holds_unused() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let obj = "mtllib gone.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    std::fs::write(d.join("w.obj"), obj).unwrap();
    let scene = "32 24  0 0.5 3  0.3 0.3 0  0 0  0 0 0 1
0 5 5  1 1 1  1
mesh \"w.obj\" 1 1 1 1  0.7 0 0 1 0 0
";
    std::fs::write(d.join("scene.txt"), scene).unwrap();
    let manifest = "scene = \"scene.txt\"\nframes = 1\nfps = 1\n\n[output]\ndir = \"frames\"\nname = \"f_####\"\nformat = \"png\"\n";
    std::fs::write(d.join("anim.toml"), manifest).unwrap();
    let out = animate().arg(d.join("anim.toml")).output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "{err}");
    assert!(
        err.contains("animate: warning: ")
            && err.contains("w.obj: mtllib 'gone.mtl' cannot be read"),
        "{err}"
    );
    assert!(d.join("frames/f_0000.png").exists());
    let out = animate()
        .arg(d.join("anim.toml"))
        .arg("--quiet")
        .arg("--force")
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success() && !err.contains("warning"), "{err}");
}
