//! What a run may keep or replace (`Policy`) and how its video is encoded (`Encoding`):
//! the options the render command (`run`), the pipeline and ffmpeg's side (`video`,
//! `encode`) all read. Their own home, so that none of those imports another for them.

/// How ffmpeg encodes a video (`--codec`, `--crf`, `--pix-fmt`); `None`s leave ffmpeg's
/// choice for the container (libx264 for `.mp4`) and yuv420p.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Encoding {
    /// ffmpeg's `-c:v`, e.g. `libx264`, `libx265`, `libvpx-vp9`.
    pub codec: Option<String>,
    /// ffmpeg's `-crf` (quality: lower is better; 0 to 63).
    pub crf: Option<u8>,
    /// ffmpeg's output `-pix_fmt`; yuv420p when not given.
    pub pix_fmt: Option<String>,
}

/// What a run may keep or replace.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Policy {
    /// Leave a folder's up-to-date frames as they are.
    pub resume: bool,
    /// With `resume`, decode each kept frame too (`status --verify`).
    pub verify: bool,
    /// Write over frames recorded by another manifest, and over an existing video.
    pub force: bool,
    /// How a video is encoded.
    pub encoding: Encoding,
    /// `encode`: take frames that are sound but not up to date (drafts among finals,
    /// another renderer or other settings) instead of refusing the folder.
    pub allow_mixed: bool,
}
