//! The paths the view draws over a frame (`/api/paths`): where the camera goes over the
//! animation and where every tracked position goes (a sphere's centre, a light, a mesh's
//! translation, `camera look_at`…), each point projected with frame F's own camera
//! (`whitted::camera::Camera::project`, the inverse of the rays that draw the pixels).
//!
//! A path is taken at every frame (and at frame `frames`, frame 0 again, when the
//! sequence loops, so that it closes), the frame's own time. A point behind frame F's
//! camera has no place on the picture: it ends a segment, and the next visible point
//! starts another. Points are `[x, y, frame]`, x and y in whole-frame pixel units
//! ((i + 0.5, j + 0.5) the centre of pixel (i, j)), possibly outside the picture.

use crate::error::AnimError;
use crate::timeline::{Field, Timeline};
use crate::Animation;
use glam::DVec3;
use serde::Serialize;
use whitted::camera::Camera;

/// One path on the picture.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Path {
    /// `camera`, or the track's target as the manifest writes it (`sphere 1 center`).
    pub name: String,
    /// Runs of points in front of the camera, each `[x, y, frame]`.
    pub segments: Vec<Vec<[f64; 3]>>,
    /// Where the path is at frame F itself, when in front of the camera (never for the
    /// camera's own path: that point is the eye).
    pub at: Option<[f64; 2]>,
}

/// Every path of frame F's picture.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Paths {
    /// F.
    pub frame: u32,
    /// The whole frame's width and height in pixels (the points' frame of reference).
    pub width: u32,
    /// See `width`.
    pub height: u32,
    /// The camera's path first, then the tracks' in manifest order.
    pub paths: Vec<Path>,
}

/// The eye at time `t`: what `Timeline::at(t).eye` gives, without copying the scene for
/// each time (a path, else a `camera position` track, else the scene file's eye).
pub fn eye_at(timeline: &Timeline, t: f64) -> DVec3 {
    let base = &timeline.base;
    if let Some(path) = &timeline.camera {
        return path
            .at_about(t, timeline.frames, base.look_at, base.lens.up)
            .0;
    }
    let tracked = (timeline.tracks.iter()).find(|t| t.target.field == Field::CameraPosition);
    match tracked {
        Some(track) => timeline.value(track, t),
        None => base.eye,
    }
}

/// `points` (the i-th at frame i) on `camera`'s picture, split where they go behind it.
fn project(camera: &Camera, points: &[DVec3], frame: u32, name: String, own: bool) -> Path {
    let mut segments: Vec<Vec<[f64; 3]>> = Vec::new();
    let mut run = Vec::new();
    for (f, p) in points.iter().enumerate() {
        match camera.project(*p) {
            Some((x, y)) => run.push([x, y, f as f64]),
            None if run.is_empty() => {}
            None => segments.push(std::mem::take(&mut run)),
        }
    }
    if !run.is_empty() {
        segments.push(run);
    }
    let at = match own {
        true => None,
        false => (points.get(frame as usize))
            .and_then(|p| camera.project(*p))
            .map(|(x, y)| [x, y]),
    };
    Path { name, segments, at }
}

/// The paths over frame `frame` of `anim`.
pub fn paths(anim: &Animation, frame: u32) -> Result<Paths, AnimError> {
    let timeline = anim.timeline;
    let camera = anim
        .camera(&timeline.at(f64::from(frame)))
        .ok_or_else(|| anim.camera_error(frame))?;
    let eyes: Vec<DVec3> = (0..timeline.plotted_frames())
        .map(|f| eye_at(timeline, f64::from(f)))
        .collect();
    let mut paths = vec![project(&camera, &eyes, frame, "camera".into(), true)];
    for (name, points) in timeline.tracked_positions() {
        paths.push(project(&camera, &points, frame, name, false));
    }
    Ok(Paths {
        frame,
        width: anim.width,
        height: anim.height,
        paths,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Project;

    const SCENE: &str = "200 100  0 1 6  0 1 0  0 0  1 1 0 1
1.0  0 1 0   1 0.9 0.2 0.1   0.7 0.3 0 1 0 0
0 0 0  0 1 0   2 1 1 1 1 0 0 0 0 0 0   0.9 0 0 1 0 0
5 10 5  1 1 1  0.9";

    fn load(dir: &std::path::Path, manifest: &str) -> Project {
        std::fs::write(dir.join("s.txt"), SCENE).unwrap();
        let path = dir.join("m.toml");
        std::fs::write(&path, format!("scene = \"s.txt\"\n{manifest}")).unwrap();
        Project::load(&path).unwrap()
    }

    fn close(a: &[f64], b: &[f64]) -> bool {
        a.len() == b.len() && a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-9)
    }

    #[test]
    fn a_circle_and_a_track_by_hand() {
        // Four frames of a circle of radius 10 about the origin at height 0, fov 90 at
        // 200×100 (the plane 4 × 2 at distance 1): frame 0's eye is (0, 0, 10), looking
        // at the origin. Frames 1-3 are at (10, 0, 0), (0, 0, −10), (−10, 0, 0), on the
        // plane at (1, 0), (0, 0), (−1, 0): x = (X + 2)/4·200, y = (1 − Y)/2·100.
        // The eye itself (frame 0) has no place.
        let dir = tempfile::tempdir().unwrap();
        let m = "frames = 4\n[camera]\npath = \"circle\"\ncenter = [0.0, 0.0, 0.0]\n\
                 radius = 10.0\nheight = 0.0\nfov = 90.0\n[[track]]\n\
                 target = \"sphere 1 center\"\n\
                 keys = [{ frame = 0, value = [0.0, 2.0, 0.0] }, { frame = 3, value = [3.0, 2.0, -3.0] }]\n";
        let p = load(dir.path(), m);
        let got = paths(&Animation::new(&p).unwrap(), 0).unwrap();
        assert_eq!((got.width, got.height, got.paths.len()), (200, 100, 2));
        let cam = &got.paths[0];
        assert_eq!((cam.name.as_str(), cam.at), ("camera", None));
        assert_eq!(cam.segments.len(), 1, "{cam:?}");
        let want = [[150.0, 50.0, 1.0], [100.0, 50.0, 2.0], [50.0, 50.0, 3.0]];
        assert!(
            close(cam.segments[0].concat().as_slice(), &want.concat()),
            "{cam:?}"
        );
        // The sphere at frame f: (f, 2, −f), depth 10 + f, on the plane at
        // (f, 2)/(10 + f).
        let sphere = &got.paths[1];
        assert_eq!(sphere.name, "sphere 1 center");
        let want: Vec<f64> = (0..4)
            .flat_map(|f| {
                let d = 10.0 + f64::from(f);
                [
                    (f64::from(f) / d + 2.0) * 50.0,
                    (1.0 - 2.0 / d) * 50.0,
                    f64::from(f),
                ]
            })
            .collect();
        assert!(
            close(&sphere.segments.concat().concat(), &want),
            "{sphere:?}"
        );
        assert!(close(&sphere.at.unwrap(), &[100.0, 40.0]), "{sphere:?}");
    }

    #[test]
    fn points_behind_split_the_path_and_the_eye_is_the_timeline_s() {
        // Seen from frame 1's eye (10, 0, 0), the other frames of the circle lie in front
        // of it: one segment 0, 2, 3 would cross the eye; frame 1 is out, so 0 | 2, 3.
        let dir = tempfile::tempdir().unwrap();
        let m = "frames = 4\n[camera]\npath = \"circle\"\ncenter = [0.0, 0.0, 0.0]\n\
                 radius = 10.0\nheight = 0.0\n";
        let p = load(dir.path(), m);
        let got = paths(&Animation::new(&p).unwrap(), 1).unwrap();
        let frames: Vec<Vec<f64>> = (got.paths[0].segments.iter())
            .map(|s| s.iter().map(|p| p[2]).collect())
            .collect();
        assert_eq!(frames, [vec![0.0], vec![2.0, 3.0]]);
        // eye_at is Timeline::at's eye, for a path, a tracked still eye and a still one.
        let still = "frames = 5\n[[track]]\ntarget = \"camera position\"\n\
                     keys = [{ frame = 0, value = [0.0, 1.0, 6.0] }, { frame = 4, value = [2.0, 3.0, 9.0] }]\n";
        for m in [m, still, "frames = 3\n"] {
            let p = load(dir.path(), m);
            for f in 0..3 {
                let t = f64::from(f) + 0.25;
                assert_eq!(eye_at(&p.timeline, t), p.timeline.at(t).eye, "{m}");
            }
        }
    }
}
