//! A frame's camera written as a key of the manifest (`/api/camera`), for the view's
//! "copy camera" button: the director stops on a frame they like and pastes its camera
//! into the manifest.
//!
//! The key is a spline camera's key, in the manifest's own spelling, its numbers the
//! shortest text that reads back to the same `f64` (so the pasted key gives the very same
//! camera):
//!
//! ```toml
//! # the camera of frame 7 of anim.toml, a key of [camera] path = "spline"
//! { frame = 7, position = [5.656854249492381, 3.0, -5.65685424949238], look_at = [0.0, 1.0, 0.0] },
//! ```
//!
//! The field of view is the whole camera's (`[camera] fov`), not a key's: when the
//! manifest sets one it is named in a comment line (`# fov = 30.0: [camera]'s, every
//! frame`); when a `camera fov` track drives it, the track's key for this frame follows
//! (`{ frame = 7, value = 32.5 },`). Without either the picture keeps the scene's own
//! framing and nothing is said. The roll is the whole camera's and cannot be keyed.

use crate::error::AnimError;
use crate::timeline::Field;
use crate::Animation;
use serde::Serialize;

/// Frame `frame`'s camera as the manifest writes it.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct CameraKey {
    /// The frame.
    pub frame: u32,
    /// The eye.
    pub position: [f64; 3],
    /// The point looked at.
    pub look_at: [f64; 3],
    /// The vertical field of view the manifest gives this frame (its `fov`, or a `camera
    /// fov` track's value); `None`: the scene's own framing.
    pub fov: Option<f64>,
    /// Whether `fov` comes from a `camera fov` track.
    pub fov_tracked: bool,
    /// The snippet: comment lines and the key, as the page copies it.
    pub text: String,
}

/// A number as TOML reads it back to the same `f64`: Rust's shortest round-trip text,
/// which always has a `.` or an exponent (`3.0`, `1e-7`), so TOML takes it as a float.
fn number(v: f64) -> String {
    format!("{v:?}")
}

fn point(p: [f64; 3]) -> String {
    format!("[{}, {}, {}]", number(p[0]), number(p[1]), number(p[2]))
}

/// Frame `frame`'s camera of `anim` as a key; `name` names the manifest in the comment.
pub fn camera_key(anim: &Animation, frame: u32, name: &str) -> Result<CameraKey, AnimError> {
    let state = anim.timeline.at(f64::from(frame));
    anim.camera(&state)
        .ok_or_else(|| anim.camera_error(frame))?;
    let fov_tracked = (anim.timeline.tracks.iter()).any(|t| t.target.field == Field::CameraFov);
    let fov = match fov_tracked || anim.manifest.lens.fov.is_some() {
        true => anim.lens_of(&state.scene).fov,
        false => None,
    };
    let (position, look_at) = (state.eye.to_array(), state.look_at.to_array());
    let mut text = format!(
        "# the camera of frame {frame} of {name}, a key of [camera] path = \"spline\"\n\
         {{ frame = {frame}, position = {}, look_at = {} }},\n",
        point(position),
        point(look_at)
    );
    match fov {
        Some(v) if fov_tracked => text.push_str(&format!(
            "# its fov, a key of the \"camera fov\" track\n{{ frame = {frame}, value = {} }},\n",
            number(v)
        )),
        Some(v) => text.push_str(&format!("# fov = {}: [camera]'s, every frame\n", number(v))),
        None => {}
    }
    Ok(CameraKey {
        frame,
        position,
        look_at,
        fov,
        fov_tracked,
        text,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Project;

    const SCENE: &str = "16 12  0 1 6  0 1 0  0 0  1 1 0 1
1.0  0 1 0   1 0.9 0.2 0.1   0.7 0.3 0 1 0 0
0 0 0  0 1 0   2 1 1 1 1 0 0 0 0 0 0   0.9 0 0 1 0 0
5 10 5  1 1 1  0.9";

    fn load(dir: &std::path::Path, name: &str, manifest: &str) -> Project {
        std::fs::write(dir.join("s.txt"), SCENE).unwrap();
        let path = dir.join(name);
        std::fs::write(&path, format!("scene = \"s.txt\"\nframes = 12\n{manifest}")).unwrap();
        Project::load(&path).unwrap()
    }

    /// The snippet's lines that are not comments.
    fn keys(text: &str) -> Vec<&str> {
        text.lines().filter(|l| !l.starts_with('#')).collect()
    }

    #[test]
    fn numbers_read_back_as_the_same_floats() {
        for v in [
            3.0,
            -0.0,
            0.1 + 0.2,
            1e-7,
            5.656854249492381,
            1e21,
            -123.456,
        ] {
            let doc: toml::Value = toml::from_str(&format!("x = {}", number(v))).unwrap();
            assert_eq!(doc["x"].as_float(), Some(v), "{}", number(v));
        }
    }

    #[test]
    fn two_keys_pasted_into_a_spline_give_the_same_cameras() {
        // A circle with a fov: the keys of frames 3 and 8 pasted into a spline (with the
        // same fov) give the very same camera on those frames.
        let dir = tempfile::tempdir().unwrap();
        let circle = "[camera]\npath = \"circle\"\ncenter = [0.0, 1.0, 0.0]\nradius = 8.0\n\
                      height = 3.0\nstart_angle = 10.0\nfov = 35.5\n";
        let p = load(dir.path(), "circle.toml", circle);
        let anim = Animation::new(&p).unwrap();
        let (k3, k8) = (
            camera_key(&anim, 3, "circle.toml").unwrap(),
            camera_key(&anim, 8, "circle.toml").unwrap(),
        );
        assert_eq!((k3.fov, k3.fov_tracked), (Some(35.5), false));
        assert!(k3
            .text
            .starts_with("# the camera of frame 3 of circle.toml"));
        assert!(
            k3.text.ends_with("# fov = 35.5: [camera]'s, every frame\n"),
            "{}",
            k3.text
        );
        let (l3, l8) = (keys(&k3.text), keys(&k8.text));
        assert_eq!((l3.len(), l8.len()), (1, 1), "{}", k3.text);
        let spline = format!(
            "[camera]\npath = \"spline\"\nfov = 35.5\nkeys = [\n{}\n{}\n]\n",
            l3[0], l8[0]
        );
        let q = load(dir.path(), "spline.toml", &spline);
        let again = Animation::new(&q).unwrap();
        for f in [3, 8] {
            let (a, b) = (p.timeline.at(f64::from(f)), q.timeline.at(f64::from(f)));
            assert_eq!((a.eye, a.look_at), (b.eye, b.look_at), "frame {f}");
            assert_eq!(anim.camera(&a), again.camera(&b), "frame {f}");
            assert!(anim.camera(&a).is_some());
        }
    }

    #[test]
    fn a_tracked_fov_is_the_track_key_of_the_frame() {
        // fov from 20 at frame 0 to 40 at frame 10, linear: 26 at frame 3.
        let dir = tempfile::tempdir().unwrap();
        let m = "[[track]]\ntarget = \"camera fov\"\n\
                 keys = [{ frame = 0, value = 20.0 }, { frame = 10, value = 40.0 }]\n";
        let p = load(dir.path(), "m.toml", m);
        let anim = Animation::new(&p).unwrap();
        let k = camera_key(&anim, 3, "m.toml").unwrap();
        assert_eq!((k.fov, k.fov_tracked), (Some(26.0), true));
        assert_eq!(keys(&k.text)[1], "{ frame = 3, value = 26.0 },");
        // A still camera: the scene file's eye and point, no fov said without one.
        let p = load(dir.path(), "still.toml", "");
        let k = camera_key(&Animation::new(&p).unwrap(), 0, "still.toml").unwrap();
        assert_eq!(
            (k.position, k.look_at, k.fov),
            ([0.0, 1.0, 6.0], [0.0, 1.0, 0.0], None)
        );
        assert_eq!(
            keys(&k.text),
            ["{ frame = 0, position = [0.0, 1.0, 6.0], look_at = [0.0, 1.0, 0.0] },"]
        );
    }
}
