//! EXR frames read by outside tools (SPEC §12): OpenEXR's `exrheader`, OpenImageIO's
//! `oiiotool --info -v` and `idiff`, the PyPI `OpenEXR` reader with `numpy`, and a
//! Cryptomatte decoder written here from the 1.1 specification with PyPI `mmh3`. A missing
//! tool skips its test with a message outside CI and fails it under CI (`CI` set).

use crate::skip;
use crate::support;

use std::path::{Path, PathBuf};
use std::process::Command;
use support::*;

use skip::have;

/// A 48×36 render of the test scene with every pass, as float EXR, and its PNG.
fn render_all(dir: &Path, samples: &str) -> (PathBuf, PathBuf) {
    let scene = scene_txt(dir, [1.0, 3.0, 8.0]);
    let (exr, png) = (dir.join("f.exr"), dir.join("f.png"));
    for (out, extra) in [
        (&exr, vec!["--passes", "all", "--exr-depth", "float"]),
        (&png, vec![]),
    ] {
        raytrace()
            .arg(&scene)
            .arg("-o")
            .arg(out)
            .args(["--size", "48x36", "--samples", samples, "-q"])
            .args(extra)
            .assert()
            .success();
    }
    (exr, png)
}

fn run(program: &str, args: &[&str]) -> String {
    let out = Command::new(program).args(args).output().unwrap();
    let text = String::from_utf8_lossy(&out.stdout).into_owned();
    assert!(
        out.status.success(),
        "{program}: {}{text}",
        String::from_utf8_lossy(&out.stderr)
    );
    text
}

#[test]
fn exrheader_and_oiiotool_list_the_layers_and_attributes() {
    if !have("exrheader", &[]) {
        return;
    }
    if !have("oiiotool", &["--version"]) {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let (exr, _) = render_all(dir.path(), "1");
    let path = exr.to_str().unwrap();
    let header = run("exrheader", &[path]);
    let info = run("oiiotool", &["--info", "-v", path]);
    for text in [&header, &info] {
        for name in [
            "Z",
            "P.X",
            "N.Z",
            "albedo.R",
            "diffuse.G",
            "fog.B",
            "crypto_object00.R",
            "crypto_material02.A",
            "chromaticities",
            "worldToCamera",
            "worldToNDC",
            "/name",
            "/manifest",
            "MurmurHash3_32",
            "uint32_to_float32",
            "crypto_object",
        ] {
            assert!(text.contains(name), "{name} missing from:\n{text}");
        }
    }
    assert!(header.contains("zip, multi-scanline blocks"), "{header}");
    // oiiotool names the Cryptomatte key the way Nuke's decoder looks it up.
    assert!(info.contains("cryptomatte/f834d0a/name"), "{info}");
}

const PYTHON: &str = r#"
import sys, json, struct, OpenEXR, numpy as np, mmh3
exr, raw, w, h, samples = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4]), int(sys.argv[5])
f = OpenEXR.File(exr)
ch = {}
for name, c in f.channels().items():
    p = c.pixels
    if p.ndim == 3:
        comps = {3: "RGB", 4: "RGBA"}[p.shape[2]]
        for k, comp in enumerate(comps):
            ch[comp if name in ("RGB", "RGBA") else f"{name}.{comp}"] = p[:, :, k].astype(np.float64)
    else:
        ch[name] = p.astype(np.float64)
rgb = np.stack([ch[c] for c in "RGB"], -1)
png = np.fromfile(raw, np.uint8).reshape(h, w, 3)
# The beauty is linear light: its sRGB encoding (IEC 61966-2-1) shows the PNG's bytes.
c = np.clip(rgb, 0, 1)
shown = np.where(c <= 0.0031308, 12.92 * c, 1.055 * c ** (1 / 2.4) - 0.055)
if samples == 1:
    off = np.abs(np.floor(shown * 255 + 0.5) - png)
    assert off.max() <= 1, f"beauty != png by {off.max()}"
    assert (np.floor(c * 255 + 0.5) != png).any(), "the beauty is not decoded"
# Alpha: coverage; every camera ray of this view meets the floor or an object.
assert (ch["A"] == 1.0).all(), "alpha is not the coverage"
parts = sum(np.stack([ch[f"{p}.{c}"] for c in "RGB"], -1)
            for p in ["ambient", "diffuse", "specular", "reflection", "transmission", "fog"])
rel = np.abs(parts - rgb) / np.maximum(np.abs(rgb), 1e-6)
assert rel.max() < 1e-5, f"light split off by {rel.max()}"
# Cryptomatte 1.1, from the spec: find the layer by name, read the manifest, hash a name
# with mmh3 and flip the exponent off 0/255, sum the coverage of every rank holding it.
hdr = f.header()
def attr(key):
    v = hdr[key]
    return v.decode() if isinstance(v, bytes) else v
key = "cryptomatte/" + format(mmh3.hash("crypto_object", signed=False), "08x")[:7]
assert attr(key + "/name") == "crypto_object"
manifest = json.loads(attr(key + "/manifest"))
def id_of(name):
    h32 = mmh3.hash(name, signed=False)
    e = (h32 >> 23) & 255
    if e == 0 or e == 255:
        h32 ^= 1 << 23
    return struct.unpack("<f", struct.pack("<I", h32))[0]
ranks = []
for layer in range(3):
    for (i, c) in [("R", "G"), ("B", "A")]:
        ranks.append((ch[f"crypto_object{layer:02}.{i}"].astype(np.float32), ch[f"crypto_object{layer:02}.{c}"]))
total = np.zeros((h, w))
for name, hexid in manifest.items():
    fid = id_of(name)
    assert format(struct.unpack("<I", struct.pack("<f", fid))[0], "08x") == hexid, name
    mask = sum(np.where(ids == np.float32(fid), cov, 0.0) for ids, cov in ranks)
    total += mask
hit = np.isfinite(ch["Z"])
# Every pixel whose samples all hit (finite depth) is fully covered; pixels hit by no
# sample have no coverage at all.
assert np.allclose(total[hit], 1.0, atol=1e-6), total[hit].min()
none = (total == 0)
assert (none <= ~hit).all()
if samples == 1:
    # At one sample, each object's mask is exactly the pixels whose depth is its hit.
    sphere = manifest["sphere 1"]
    m = sum(np.where(ids == np.float32(id_of("sphere 1")), cov, 0.0) for ids, cov in ranks)
    assert set(np.unique(m)) <= {0.0, 1.0}
    assert (m > 0).sum() > 0 and ((m > 0) <= hit).all()
print("ok", len(manifest))
"#;

#[test]
fn python_openexr_reads_the_beauty_split_and_cryptomatte() {
    if !have("python3", &["-c", "import OpenEXR, numpy, mmh3"]) {
        return;
    }
    for samples in ["1", "3"] {
        let dir = tempfile::tempdir().unwrap();
        let (exr, _) = render_all(dir.path(), samples);
        let raw = dir.path().join("f.raw");
        raytrace()
            .arg(dir.path().join("scene.txt"))
            .arg("-o")
            .arg(&raw)
            .args(["--size", "48x36", "--samples", samples, "-q"])
            .assert()
            .success();
        let out = run(
            "python3",
            &[
                "-c",
                PYTHON,
                exr.to_str().unwrap(),
                raw.to_str().unwrap(),
                "48",
                "36",
                samples,
            ],
        );
        assert!(out.starts_with("ok 5"), "{out}");
    }
}

#[test]
fn idiff_passes_the_beauty_in_srgb_against_the_one_sample_png() {
    if !have("oiiotool", &["--version"]) || !have("idiff", &["--help"]) {
        return;
    }
    // At one sample the PNG's byte is the beauty's sRGB encoding, clamped and rounded
    // (SPEC §12): the beauty converted by oiiotool from linear to sRGB (OpenImageIO's own
    // curve, to 8 bits) must match the PNG that raytrace wrote through its own 8-bit path
    // to within one level (0.00392; oiiotool's rounding differs from ours on a level's
    // edge), where the unconverted beauty is tens of levels off.
    let dir = tempfile::tempdir().unwrap();
    let (exr, png) = render_all(dir.path(), "1");
    let beauty = dir.path().join("beauty.exr");
    let (a, b) = (exr.to_str().unwrap(), beauty.to_str().unwrap());
    let converted = dir.path().join("beauty.png");
    let c = converted.to_str().unwrap();
    run(
        "oiiotool",
        &[a, "--ch", "R,G,B", "--clamp:min=0:max=1", "-o", b],
    );
    run(
        "oiiotool",
        &[
            b,
            "--colorconvert",
            "linear",
            "sRGB",
            "-d",
            "uint8",
            "-o",
            c,
        ],
    );
    let idiff = |x: &Path, y: &Path| {
        let out = Command::new("idiff")
            .args(["-fail", "0.0045", "-warn", "0.0045"])
            .args([x, y])
            .output()
            .unwrap();
        let text = String::from_utf8_lossy(&out.stdout).into_owned();
        (out.status.success() && text.contains("PASS"), text)
    };
    let (pass, text) = idiff(&converted, &png);
    assert!(pass, "{text}");
    // And it can fail: the beauty as it is (not converted) does not pass, nor does a
    // brightened one.
    let (pass, text) = idiff(&beauty, &png);
    assert!(!pass, "{text}");
    let bright = dir.path().join("bright.png");
    run(
        "oiiotool",
        &[c, "--mulc", "1.5", "-o", bright.to_str().unwrap()],
    );
    let (pass, text) = idiff(&bright, &png);
    assert!(!pass, "{text}");
}
