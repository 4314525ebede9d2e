//! Drafts beside finals: `--size WxH`, `--scale K` (1/K of the manifest's size, as
//! `preview --scale K`), `--samples N` and `--aa adaptive[:T[:D[:MEASURE]]]` (as `raytrace`
//! takes them) override the manifest for one run. They change the manifest as loaded
//! (`Project::load_draft`): its `[render]` size and anti-aliasing, its `[output] dir` (a
//! draft's own folder, `DIR-draft-WxH`, with `-sN` or `-aa` when those are overridden;
//! `[check] references` likewise),
//! and `Manifest::draft`, a label every frame records (`whitted:draft`) and its digest
//! covers, so that `--resume`, `status` and `encode` tell a draft from a final even in
//! one folder. An empty `Draft` is the manifest as written, byte for byte.

use super::Project;
use crate::error::AnimError;
use std::path::{Path, PathBuf};
use whitted::render::Adaptive;

/// The overrides of a draft.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Draft {
    /// The frames' size.
    pub size: Option<(u32, u32)>,
    /// 1/K of the manifest's size (each side, at least one pixel).
    pub scale: Option<u32>,
    /// An N×N grid per pixel (drops the manifest's adaptive anti-aliasing).
    pub samples: Option<u32>,
    /// Adaptive anti-aliasing (drops the manifest's grid).
    pub aa: Option<Adaptive>,
}

impl Draft {
    /// Whether nothing is overridden.
    pub fn is_empty(&self) -> bool {
        *self == Draft::default()
    }

    /// The size of a draft of a manifest whose frames are `base`.
    pub fn size_of(&self, base: (u32, u32)) -> (u32, u32) {
        match (self.size, self.scale) {
            (Some(size), _) => size,
            (None, Some(k)) => ((base.0 / k.max(1)).max(1), (base.1 / k.max(1)).max(1)),
            (None, None) => base,
        }
    }

    /// The label frames record: what the draft overrides, e.g. `160x120, samples 1`.
    pub fn label(&self, base: (u32, u32)) -> String {
        let (w, h) = self.size_of(base);
        let mut parts = vec![format!("{w}x{h}")];
        if let Some(n) = self.samples {
            parts.push(format!("samples {n}"));
        }
        if let Some(a) = self.aa {
            let m = a.measure.name();
            parts.push(format!("aa adaptive:{}:{}:{m}", a.threshold, a.depth));
        }
        parts.join(", ")
    }

    /// A draft's own folder beside the final one `dir` of the manifest at `manifest`:
    /// `DIR-draft-WxH`, then `-sN` and `-aa`, DIR read without its `.` and `..` steps
    /// (`frames/.` is `frames`). When `dir` is the manifest's own folder or one above it
    /// (`.`, `..`), whose name says nothing of the animation and whose side is outside the
    /// manifest's folder, the draft's folder is `STEM-draft-WxH` inside the manifest's
    /// folder, STEM the manifest's file name without `.toml`.
    pub fn folder(&self, dir: &Path, manifest: &Path, base: (u32, u32)) -> PathBuf {
        let (w, h) = self.size_of(base);
        let mut suffix = format!("-draft-{w}x{h}");
        if let Some(n) = self.samples {
            suffix.push_str(&format!("-s{n}"));
        }
        if self.aa.is_some() {
            suffix.push_str("-aa");
        }
        let home = manifest.parent().unwrap_or(Path::new(""));
        let dir = lexical(dir);
        match dir.file_name() {
            Some(name) if !lexical(home).starts_with(&dir) => {
                let mut name = name.to_os_string();
                name.push(suffix);
                dir.with_file_name(name)
            }
            _ => {
                let mut name = manifest.file_stem().unwrap_or_default().to_os_string();
                name.push(suffix);
                home.join(name)
            }
        }
    }
}

/// `path` without its `.` steps and with each `..` taking the step before it away, where
/// there is one to take (no look at the file system: `a/./b/..` is `a`, `../x` stays).
fn lexical(path: &Path) -> PathBuf {
    use std::path::Component;
    let mut out = PathBuf::new();
    for c in path.components() {
        match c {
            Component::CurDir => {}
            Component::ParentDir
                if matches!(out.components().next_back(), Some(Component::Normal(_))) =>
            {
                out.pop();
            }
            c => out.push(c),
        }
    }
    out
}

impl Project {
    /// `Project::load` with a draft's overrides applied (none: the same project).
    pub fn load_draft(path: &Path, draft: &Draft) -> Result<Project, AnimError> {
        let mut project = Project::load(path)?;
        if draft.is_empty() {
            return Ok(project);
        }
        let base = project.size();
        let (w, h) = draft.size_of(base);
        let m = &mut project.manifest;
        m.render.width = Some(w);
        m.render.height = Some(h);
        if let Some(n) = draft.samples {
            m.render.samples = n;
            m.render.antialias = None;
        }
        if let Some(a) = draft.aa {
            if m.output.format.is_layered() {
                return Err(AnimError::Draft(format!(
                    "{}: --aa draws 8-bit frames only: EXR frames take --samples N",
                    whitted::fileloc::shown(&m.path)
                )));
            }
            m.render.samples = 1;
            m.render.antialias = Some(a);
        }
        m.output.dir = draft.folder(&m.output.dir, &m.path, base);
        if let Some(check) = &mut m.check {
            // A draft is checked against references of its own.
            check.references = draft.folder(&check.references, &m.path, base);
        }
        m.draft = Some(draft.label(base));
        Ok(project)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_labels_and_folders_by_hand() {
        let scale = Draft {
            scale: Some(4),
            ..Draft::default()
        };
        assert_eq!(scale.size_of((640, 480)), (160, 120));
        assert_eq!(scale.size_of((3, 2)), (1, 1));
        assert_eq!(scale.label((640, 480)), "160x120");
        let out = scale.folder(Path::new("/a/frames"), Path::new("/a/m.toml"), (640, 480));
        assert_eq!(out, Path::new("/a/frames-draft-160x120"));
        let both = Draft {
            size: Some((64, 36)),
            scale: Some(4),
            samples: Some(2),
            aa: None,
        };
        assert_eq!(both.size_of((640, 480)), (64, 36));
        assert_eq!(both.label((640, 480)), "64x36, samples 2");
        let out = both.folder(Path::new("frames"), Path::new("m.toml"), (640, 480));
        assert_eq!(out, Path::new("frames-draft-64x36-s2"));
        // Read without `.` and `..`; the manifest's folder or one above it: inside it.
        let half = Draft {
            size: Some((16, 12)),
            ..Draft::default()
        };
        let folder = |dir: &str, m: &str| half.folder(Path::new(dir), Path::new(m), (32, 24));
        assert_eq!(
            folder("/a/frames/.", "/a/m.toml"),
            Path::new("/a/frames-draft-16x12")
        );
        assert_eq!(
            folder("/a/b/../f", "/a/m.toml"),
            Path::new("/a/f-draft-16x12")
        );
        assert_eq!(folder("/a/.", "/a/m.toml"), Path::new("/a/m-draft-16x12"));
        assert_eq!(
            folder("/a/b/..", "/a/b/m.toml"),
            Path::new("/a/b/m-draft-16x12")
        );
        assert_eq!(folder(".", "m.toml"), Path::new("m-draft-16x12"));
        assert_eq!(folder("./..", "m.toml"), Path::new("m-draft-16x12"));
        assert_eq!(
            folder("sub/.", "sub/m.toml"),
            Path::new("sub/m-draft-16x12")
        );
        assert_eq!(folder("../out", "m.toml"), Path::new("../out-draft-16x12"));
        assert_eq!(folder("/", "/m.toml"), Path::new("/m-draft-16x12"));
        let aa = Draft {
            aa: Some("adaptive:0.5:1".parse().unwrap()),
            ..Draft::default()
        };
        assert_eq!(aa.label((8, 6)), "8x6, aa adaptive:0.5:1:edge");
        assert!(Draft::default().is_empty() && !aa.is_empty());
    }
}
