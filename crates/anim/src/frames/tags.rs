//! The colour of a video (SPEC §12): the frames' bytes are sRGB display values, and a
//! video says BT.709, the HD standard whose primaries and white are sRGB's, in all four
//! of its tags, so that players stop guessing:
//!
//! ```text
//! -vf pad=…,scale=out_color_matrix=bt709:out_range=tv      # Y'CbCr by BT.709's matrix
//! -colorspace bt709 -color_primaries bt709 -color_trc bt709 -color_range tv
//! -movflags +faststart                                      # .mp4, .mov, .m4v
//! ```
//!
//! ffmpeg's RGB→YUV conversion (swscale) uses BT.601's matrix unless told otherwise, and
//! tags nothing; a player assuming BT.709 for HD would then shift the hues. The matrix
//! and range matter only to a Y'CbCr `pix_fmt` (`yuv420p`, the default; `yuvj…` is full
//! range); an RGB one (`rgb24`, `gbrp` for lossless codecs) is tagged with the primaries
//! and transfer and the `rgb` matrix. The transfer is tagged `bt709` as every SDR
//! renderer's video is (the sRGB curve has no tag most players read); `faststart` moves
//! an MP4's index to its front so that it plays while it downloads.

/// The filter that follows the pad filter for `pix_fmt` (`None`: none needed).
pub fn filter(pix_fmt: &str) -> Option<String> {
    yuv(pix_fmt).map(|range| format!("scale=out_color_matrix=bt709:out_range={range}"))
}

/// The output options that tag a video of `pix_fmt` written to a file ending in `ext`.
pub fn options(pix_fmt: &str, ext: &str) -> Vec<&'static str> {
    let mut args = vec!["-color_primaries", "bt709", "-color_trc", "bt709"];
    match yuv(pix_fmt) {
        Some(range) => args.extend(["-colorspace", "bt709", "-color_range", range]),
        None => args.extend(["-colorspace", "rgb", "-color_range", "pc"]),
    }
    if ["mp4", "mov", "m4v"].contains(&ext.to_ascii_lowercase().as_str()) {
        args.extend(["-movflags", "+faststart"]);
    }
    args
}

/// The range of a Y'CbCr `pix_fmt` (`tv`: limited, `pc`: full for `yuvj…`), `None` for
/// another.
fn yuv(pix_fmt: &str) -> Option<&'static str> {
    if pix_fmt.starts_with("yuvj") {
        Some("pc")
    } else if ["yuv", "nv", "p01", "y2"]
        .iter()
        .any(|p| pix_fmt.starts_with(p))
    {
        Some("tv")
    } else {
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn yuv_gets_the_matrix_and_every_format_the_tags() {
        assert_eq!(
            filter("yuv420p").as_deref(),
            Some("scale=out_color_matrix=bt709:out_range=tv")
        );
        assert_eq!(
            options("yuv420p", "MP4").join(" "),
            "-color_primaries bt709 -color_trc bt709 -colorspace bt709 -color_range tv \
             -movflags +faststart"
        );
        assert_eq!(
            options("yuv444p10le", "mkv")[4..],
            ["-colorspace", "bt709", "-color_range", "tv"]
        );
        assert!(options("yuvj420p", "mkv").ends_with(&["-color_range", "pc"]));
        assert_eq!(filter("rgb24"), None);
        assert_eq!(filter("gbrp"), None);
        assert!(options("rgb24", "mkv").ends_with(&["-colorspace", "rgb", "-color_range", "pc"]));
    }
}
