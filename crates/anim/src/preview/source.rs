//! The preview's only contact with the animation pipeline: loading a manifest and its
//! scene, shrinking the frames by the preview's scale, drawing one frame, and sampling the
//! timeline (the camera, and the paths of tracked positions) as plain data for the plot. Everything else in `preview` works on what
//! these functions return, so a change of the pipeline's API is a change of this file.

use super::plot::{CameraSample, Track};
use crate::{AnimError, Animation, Project};
use std::path::Path;
use whitted::base::Frame;

/// The most camera samples the plot takes (evenly spread over the frames).
pub const MAX_SAMPLES: u32 = 4096;

/// A loaded project whose frames are drawn at 1/scale of their size.
pub struct Source {
    project: Project,
    /// The preview size.
    width: u32,
    height: u32,
}

/// `side / scale` rounded to the nearest pixel (halves up), at least 1.
pub fn scaled(side: u32, scale: u32) -> u32 {
    let scale = scale.max(1);
    ((side + scale / 2) / scale).max(1)
}

impl Source {
    /// Loads `manifest` and its scene; frames will be drawn at 1/`scale` of the size the
    /// manifest (or its scene) gives.
    pub fn load(manifest: &Path, scale: u32) -> Result<Source, AnimError> {
        let project = Project::load(manifest)?;
        // The full size is checked as the render would check it.
        let full = Animation::new(&project)?;
        let (width, height) = (scaled(full.width, scale), scaled(full.height, scale));
        Ok(Source {
            project,
            width,
            height,
        })
    }

    /// The frame count, fps and the frame folder of the manifest.
    pub fn frames(&self) -> u32 {
        self.project.manifest.frames
    }

    pub fn fps(&self) -> f64 {
        self.project.manifest.fps
    }

    pub fn frame_dir(&self) -> &Path {
        &self.project.manifest.output.dir
    }

    pub fn manifest_path(&self) -> &Path {
        &self.project.manifest.path
    }

    /// The scene the manifest names (before tracks).
    pub fn scene(&self) -> &whitted::Scene {
        &self.project.timeline.base
    }

    /// The preview-sized animation; every frame's camera is checked first.
    pub fn animation(&self) -> Result<Animation<'_>, AnimError> {
        let anim = Animation::with_size(&self.project, self.width, self.height)?;
        let frames: Vec<u32> = (0..self.frames()).collect();
        anim.check_cameras(&frames)?;
        Ok(anim)
    }

    /// The camera at (up to `MAX_SAMPLES`) frames spread evenly from the first to the last
    /// (to frame `frames`, which is frame 0, when the sequence loops: the drawn path closes).
    pub fn camera_samples(&self) -> Vec<CameraSample> {
        let timeline = &self.project.timeline;
        sample_frames(self.project.timeline.plotted_frames(), MAX_SAMPLES)
            .into_iter()
            .map(|frame| {
                let state = timeline.at(f64::from(frame));
                CameraSample {
                    frame,
                    eye: state.eye,
                    look_at: state.look_at,
                }
            })
            .collect()
    }

    /// The path of every tracked position (sphere centre, plane or cylinder point, light
    /// position), at the same frames as the camera samples.
    pub fn tracks(&self) -> Vec<Track> {
        let frames = sample_frames(self.project.timeline.plotted_frames(), MAX_SAMPLES);
        self.project
            .timeline
            .tracked_positions()
            .into_iter()
            .map(|(name, points)| Track {
                name,
                points: frames.iter().map(|&f| (f, points[f as usize])).collect(),
            })
            .collect()
    }
}

/// Draws frame `frame` of the preview-sized animation.
pub fn draw(anim: &Animation, frame: u32) -> Result<Frame, AnimError> {
    anim.render_picture(&anim.plan(frame))
        .map(|(image, _)| image)
}

/// `frames` frame numbers when there are at most `max`, otherwise `max` of them spread
/// evenly, the first and the last included.
pub fn sample_frames(frames: u32, max: u32) -> Vec<u32> {
    let max = max.max(2);
    if frames <= max {
        return (0..frames).collect();
    }
    let last = u64::from(frames - 1);
    (0..u64::from(max))
        .map(|i| ((i * last + u64::from(max - 1) / 2) / u64::from(max - 1)) as u32)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scaled_rounds_to_nearest_and_never_reaches_zero() {
        assert_eq!(scaled(640, 4), 160);
        assert_eq!(scaled(480, 4), 120);
        // 642/4 = 160.5 rounds up, 641/4 = 160.25 down.
        assert_eq!(scaled(642, 4), 161);
        assert_eq!(scaled(641, 4), 160);
        assert_eq!(scaled(3, 8), 1);
        assert_eq!(scaled(7, 1), 7);
    }

    #[test]
    fn sample_frames_keeps_all_when_few_and_spreads_when_many() {
        assert_eq!(sample_frames(4, 10), vec![0, 1, 2, 3]);
        // 11 frames into 5 samples: 0, 2.5, 5, 7.5, 10 rounded half up.
        assert_eq!(sample_frames(11, 5), vec![0, 3, 5, 8, 10]);
        let many = sample_frames(1_000_000, 4096);
        assert_eq!(many.len(), 4096);
        assert_eq!((many[0], many[4095]), (0, 999_999));
    }
}
