//! `--display tev`: a test server written from tev's IPC protocol (`include/tev/Ipc.h`,
//! `src/Ipc.cpp`: u32 size, u8 type, payload) decodes what `raytrace` and `animate`
//! stream and reassembles the frame, which must equal the `.raw` file byte for byte
//! (floats back to bytes as tev's sRGB view shows them: the sent floats are linear light,
//! what an EXR frame holds); an EXR manifest's frames arrive as its files hold them, as
//! they are under `colour = "linear"`; the packets
//! PyPI's `tevclient` (the official client) sends for the same image decode to the same
//! bytes; a missing viewer is one warning and the render goes on.

use crate::common;
use crate::skip;
use crate::support;

use std::collections::HashMap;
use std::io::Read;
use std::net::TcpListener;
use std::path::Path;
use std::process::Command;
use support::*;

/// One image as the server sees it.
#[derive(Clone, Debug, Default)]
struct Image {
    width: usize,
    height: usize,
    channels: Vec<String>,
    /// channel-major floats, width·height each.
    data: Vec<Vec<f32>>,
}

/// What a connection sent.
#[derive(Debug, Default)]
struct Seen {
    images: HashMap<String, Image>,
    /// (packet type, image name), in order.
    packets: Vec<(u8, String)>,
    /// A copy of an image's R, G, B as bytes after every UpdateImage that covers it whole.
    whole: Vec<Vec<u8>>,
}

struct Reader<'a>(&'a [u8]);

impl Reader<'_> {
    fn take(&mut self, n: usize) -> &[u8] {
        assert!(self.0.len() >= n, "packet cut short");
        let (a, b) = self.0.split_at(n);
        self.0 = b;
        a
    }
    fn u8(&mut self) -> u8 {
        self.take(1)[0]
    }
    fn bool(&mut self) -> bool {
        self.u8() == 1
    }
    fn i32(&mut self) -> i32 {
        i32::from_le_bytes(self.take(4).try_into().unwrap())
    }
    fn i64(&mut self) -> i64 {
        i64::from_le_bytes(self.take(8).try_into().unwrap())
    }
    fn string(&mut self) -> String {
        let end = self.0.iter().position(|&b| b == 0).expect("a NUL");
        let s = String::from_utf8(self.0[..end].to_vec()).unwrap();
        self.0 = &self.0[end + 1..];
        s
    }
}

fn to_byte(f: f32) -> u8 {
    support::srgb_byte(f)
}

impl Image {
    /// The floats of channel `name`.
    fn floats(&self, name: &str) -> &[f32] {
        &self.data[self.channels.iter().position(|c| c == name).unwrap()]
    }

    fn rgb(&self) -> Vec<u8> {
        let at = |name: &str| self.channels.iter().position(|c| c == name).unwrap();
        let (r, g, b) = (at("R"), at("G"), at("B"));
        (0..self.width * self.height)
            .flat_map(|k| [r, g, b].map(|c| to_byte(self.data[c][k])))
            .collect()
    }
}

/// Decodes a whole stream of packets.
fn decode(mut stream: &[u8]) -> Seen {
    let mut seen = Seen::default();
    while !stream.is_empty() {
        let size = u32::from_le_bytes(stream[..4].try_into().unwrap()) as usize;
        assert!(size >= 5 && size <= stream.len(), "bad packet size {size}");
        let mut p = Reader(&stream[4..size]);
        stream = &stream[size..];
        let kind = p.u8();
        match kind {
            // CloseImage: name.
            2 => {
                let name = p.string();
                seen.images.remove(&name);
                seen.packets.push((kind, name));
            }
            // CreateImage: grabFocus, name, width, height, nChannels, names.
            4 => {
                let _focus = p.bool();
                let name = p.string();
                let (w, h) = (p.i32() as usize, p.i32() as usize);
                let n = p.i32() as usize;
                let channels: Vec<String> = (0..n).map(|_| p.string()).collect();
                let data = vec![vec![0.0; w * h]; n];
                seen.images.insert(
                    name.clone(),
                    Image {
                        width: w,
                        height: h,
                        channels,
                        data,
                    },
                );
                seen.packets.push((kind, name));
            }
            // UpdateImage (v1 one channel, v2 several, v3 with offsets and strides).
            3 | 5 | 6 => {
                let _focus = p.bool();
                let name = p.string();
                let n = if kind >= 5 { p.i32() as usize } else { 1 };
                let names: Vec<String> = (0..n).map(|_| p.string()).collect();
                let (x, y, w, h) = (
                    p.i32() as usize,
                    p.i32() as usize,
                    p.i32() as usize,
                    p.i32() as usize,
                );
                let pixels = w * h;
                let (offsets, strides): (Vec<usize>, Vec<usize>) = if kind == 6 {
                    let o = (0..n).map(|_| p.i64() as usize).collect();
                    let s = (0..n).map(|_| p.i64() as usize).collect();
                    (o, s)
                } else {
                    ((0..n).map(|c| c * pixels).collect(), vec![1; n])
                };
                let floats: Vec<f32> =
                    p.0.chunks_exact(4)
                        .map(|b| f32::from_le_bytes(b.try_into().unwrap()))
                        .collect();
                let img = seen
                    .images
                    .get_mut(&name)
                    .expect("UpdateImage of an image never created");
                for (c, cname) in names.iter().enumerate() {
                    let ci = img
                        .channels
                        .iter()
                        .position(|k| k == cname)
                        .expect("a known channel");
                    for k in 0..pixels {
                        let (i, j) = (x + k % w, y + k / w);
                        img.data[ci][j * img.width + i] = floats[offsets[c] + k * strides[c]];
                    }
                }
                if (x, y, w, h) == (0, 0, img.width, img.height) {
                    let rgb = img.rgb();
                    seen.whole.push(rgb);
                }
                seen.packets.push((kind, name));
            }
            other => panic!("a packet type tev does not know: {other}"),
        }
    }
    seen
}

/// A one-connection tev: the port, and a thread that returns everything it received.
fn server() -> (u16, std::thread::JoinHandle<Vec<u8>>) {
    let listener = TcpListener::bind("127.0.0.1:0").unwrap();
    let port = listener.local_addr().unwrap().port();
    let t = std::thread::spawn(move || {
        let (mut s, _) = listener.accept().unwrap();
        let mut all = Vec::new();
        s.read_to_end(&mut all).unwrap();
        all
    });
    (port, t)
}

fn scene_file(dir: &Path) -> std::path::PathBuf {
    let path = dir.join("s.txt");
    std::fs::write(&path, common::rich_scene(97, 61)).unwrap();
    path
}

#[test]
fn raytrace_streams_rows_that_reassemble_to_the_raw_file() {
    let dir = tempfile::tempdir().unwrap();
    let scene = scene_file(dir.path());
    let (port, got) = server();
    let out = raytrace()
        .arg(&scene)
        .args(["-o", "x.raw", "--display", &format!("tev=127.0.0.1:{port}")])
        .current_dir(dir.path())
        .output()
        .unwrap();
    stdout_ok(out);
    let raw = std::fs::read(dir.path().join("x.raw")).unwrap();
    let seen = decode(&got.join().unwrap());
    let img = seen.images.values().next().expect("an image");
    assert_eq!((img.width, img.height, seen.images.len()), (97, 61, 1));
    assert!(
        img.rgb() == raw,
        "the reassembled frame differs from the .raw"
    );
    // Streamed as it renders: several bands of rows, after one CreateImage.
    let kinds: Vec<u8> = seen.packets.iter().map(|p| p.0).collect();
    assert_eq!(&kinds[..2], &[2, 4]);
    assert!(
        kinds[2..].iter().all(|&k| k == 6) && kinds.len() - 2 == 4,
        "{kinds:?}"
    );
}

#[test]
fn animate_sends_every_frame() {
    let (_dir, manifest) = project(&circle_manifest(""));
    let (port, got) = server();
    let out = animate()
        .arg(&manifest)
        .args(["--frames", "0-3", "-q", "--stdout", "raw", "--force"])
        .args(["--display", &format!("tev=127.0.0.1:{port}")])
        .output()
        .unwrap();
    let stdout = stdout_ok(out);
    let seen = decode(&got.join().unwrap());
    let frames: Vec<&[u8]> = stdout.chunks(64 * 48 * 3).collect();
    assert_eq!(frames.len(), 4);
    let mut sent = seen.whole.clone();
    assert_eq!(sent.len(), 4, "one whole picture a frame");
    sent.sort();
    let mut want: Vec<Vec<u8>> = frames.iter().map(|f| f.to_vec()).collect();
    want.sort();
    assert!(
        sent == want,
        "the frames tev received are not animate's frames"
    );
}

/// What tev is sent while `animate` renders `frames` of an EXR manifest into `out`.
fn exr_frames_to_tev(manifest: &Path, out: &Path, frames: &str) -> Seen {
    let (port, got) = server();
    let run = animate()
        .arg(manifest)
        .args(["--frames", frames, "-q", "-o"])
        .arg(out)
        .args(["--display", &format!("tev=127.0.0.1:{port}")])
        .output()
        .unwrap();
    stdout_ok(run);
    decode(&got.join().unwrap())
}

#[test]
fn animate_sends_every_frame_of_an_exr_manifest() {
    // EXR frames are drawn as layers: tev is shown their pictures, one a frame.
    let (dir, manifest) = project(&circle_manifest("").replace("\"png\"", "\"exr\""));
    let seen = exr_frames_to_tev(&manifest, &dir.path().join("exr"), "0-2");
    let mut sent = seen.whole.clone();
    assert_eq!(sent.len(), 3, "one whole picture a frame");
    sent.sort();
    let project = whitted_anim::Project::load(&manifest).unwrap();
    let anim = whitted_anim::Animation::new(&project).unwrap();
    let mut want: Vec<Vec<u8>> = (0..3)
        .map(|f| anim.render_picture(&anim.plan(f)).unwrap().0.pixels)
        .collect();
    want.sort();
    assert!(sent == want, "tev did not receive the EXR frames' pictures");
}

#[test]
fn tev_receives_what_the_exr_frame_holds_in_either_colour() {
    // The default EXR holds linear light: tev's floats show the file's bytes in an sRGB
    // view and sit within a level of the file's values. `colour = "linear"` stores and
    // sends the values as they are: b/255 for the file's clamp-and-round b.
    for colour in ["", "colour = \"linear\"\n"] {
        let extra = colour;
        let (dir, manifest) = project(&circle_manifest(extra).replace("\"png\"", "\"exr\""));
        let seen = exr_frames_to_tev(&manifest, &dir.path().join("exr"), "0");
        let img = seen.images.values().next().expect("an image");
        let file = exr_channels(&dir.path().join("exr/frame_0000.exr"));
        let mut compared = 0;
        for c in ["R", "G", "B"] {
            for (k, (&sent, &held)) in img.floats(c).iter().zip(&file[c]).enumerate() {
                let held = held.clamp(0.0, 1.0);
                if colour.is_empty() {
                    assert_eq!(srgb_byte(sent), srgb_byte(held), "{c} {k}");
                    assert!((sent - held).abs() < 0.01, "{c} {k}: {sent} vs {held}");
                } else {
                    let byte = (held * 255.0).round();
                    assert!(
                        (sent - byte / 255.0).abs() < 1e-7,
                        "{c} {k}: {sent} vs {held}"
                    );
                }
                compared += 1;
            }
        }
        assert_eq!(compared, 64 * 48 * 3);
    }
}

#[test]
fn tevclient_packets_decode_the_same() {
    if !skip::have("python3", &["-c", "import tevclient, numpy"]) {
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let scene = scene_file(dir.path());
    raytrace()
        .arg(&scene)
        .args(["-o", "x.raw", "-q"])
        .current_dir(dir.path())
        .assert()
        .success();
    let raw = std::fs::read(dir.path().join("x.raw")).unwrap();
    let (port, got) = server();
    let script = format!(
        "import numpy as np, tevclient\n\
         b = np.fromfile('x.raw', dtype=np.uint8).reshape(61, 97, 3)\n\
         v = b / 255.0\n\
         lin = np.where(v <= 0.04045, v / 12.92, ((v + 0.055) / 1.055) ** 2.4)\n\
         with tevclient.Ipc('127.0.0.1', {port}) as tev:\n\
         \x20   tev.create_image('x', 97, 61, ['R', 'G', 'B'])\n\
         \x20   tev.update_image('x', lin.astype(np.float32), ['R', 'G', 'B'])\n"
    );
    let ran = Command::new("python3")
        .args(["-c", &script])
        .current_dir(dir.path())
        .output()
        .unwrap();
    assert!(
        ran.status.success(),
        "{}",
        String::from_utf8_lossy(&ran.stderr)
    );
    let seen = decode(&got.join().unwrap());
    assert!(
        seen.images["x"].rgb() == raw,
        "tevclient's image decodes to other bytes"
    );
    // tevclient tiles by 128×128: this 97×61 image is one UpdateImage v3, as ours are.
    assert_eq!(
        seen.packets.iter().map(|p| p.0).collect::<Vec<_>>(),
        vec![4, 6]
    );
}

#[test]
fn a_missing_viewer_is_one_warning() {
    let dir = tempfile::tempdir().unwrap();
    let scene = scene_file(dir.path());
    let port = TcpListener::bind("127.0.0.1:0")
        .unwrap()
        .local_addr()
        .unwrap()
        .port();
    let out = raytrace()
        .arg(&scene)
        .args([
            "-o",
            "x.png",
            "-q",
            "--display",
            &format!("tev=127.0.0.1:{port}"),
        ])
        .current_dir(dir.path())
        .output()
        .unwrap();
    assert!(out.status.success());
    assert!(dir.path().join("x.png").exists());
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.starts_with(&format!(
            "raytrace: warning: no tev viewer at 127.0.0.1:{port}"
        )),
        "{err}"
    );
    let bad = raytrace()
        .arg(&scene)
        .args(["--display", "x11"])
        .output()
        .unwrap();
    assert_eq!(bad.status.code(), Some(2));
}
