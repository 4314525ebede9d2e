//! The check report as a page (`--html DIR`): `DIR/index.html` with the verdict, the
//! tolerance and one row per checked frame (its figures and the limits it broke). A
//! failing frame's row shows its reference, rendered image, diff heat map (and FLIP map)
//! side by side, and a flip image that switches between reference and render on a click.
//! The images are copied beside the page (`NAME.reference.png`, `NAME.rendered.png`,
//! `NAME.diff.png`, `NAME.flip.png`) with the legends (`heat-legend.png`,
//! `flip-legend.png`), so the folder opens from disk with no server and no network: no
//! file outside DIR and no address is named. The page is written last; then the images
//! the page it replaced named (an earlier run's failing frames) and this one does not are
//! removed, so the folder holds one run's report.

use super::{copy_file, write_file, ExportError, Exporter};
use crate::check::diff::heat_legend;
use crate::check::flip;
use crate::check::report::{CheckReport, FrameReport};
use std::path::{Path, PathBuf};
use whitted::base::Frame;
use whitted::output::{write_atomic, ImageFormat};

/// The HTML exporter, writing into a folder.
pub struct Html(pub PathBuf);

const STYLE: &str = "body{font-family:sans-serif;margin:1.5em;background:#fff;color:#222}\
table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:.3em .6em;text-align:right}\
tr.fail td.verdict{color:#b00;font-weight:bold}tr.pass td.verdict{color:#070}\
.pictures{display:flex;flex-wrap:wrap;gap:1em;margin:.5em 0 1.5em}\
figure{margin:0}figcaption{font-size:.9em;text-align:center}\
img.frame{image-rendering:pixelated;max-width:45vw}.flip img{cursor:pointer}\
.legend{position:relative;width:256px;height:2.6em;margin:.2em 0 1em}\
.legend img{width:256px;height:14px;display:block;image-rendering:pixelated}\
.legend span{position:absolute;top:16px;font-size:.75em;transform:translateX(-50%)}";

const SCRIPT: &str = "for(const i of document.querySelectorAll('.flip img')){\
const c=i.parentNode.querySelector('figcaption');i.addEventListener('click',()=>{\
const r=i.dataset.showing!=='render';i.src=r?i.dataset.render:i.dataset.reference;\
i.dataset.showing=r?'render':'reference';c.textContent=(r?'render':'reference')+\
' (click to flip)';});}";

/// `&`, `<`, `>`, `"` and `'` as entities.
fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for ch in text.chars() {
        match ch {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            c => out.push(c),
        }
    }
    out
}

impl Html {
    /// The page; `NAME.*.png` of failing frames are expected beside it.
    pub fn page(report: &CheckReport) -> String {
        let t = &report.tolerance;
        let flip = t.flip.is_some();
        let scale = (320 / report.width.max(1)).max(1);
        let width = report.width * scale;
        let verdict = escape(&report.verdict());
        let mut limits = format!(
            "fail = {}, fail_percent = {}, hard_fail = {}",
            t.fail, t.fail_percent, t.hard_fail
        );
        if let Some(f) = t.flip {
            limits += &format!(", flip = {f}");
        }
        let mut html = format!(
            "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\
             <title>animate check: {verdict}</title><style>{STYLE}</style></head><body>\n\
             <h1>animate check</h1>\n<p class=\"verdict\"><strong>{verdict}</strong></p>\n\
             <p>Manifest {}, references {}, tolerance {limits}.</p>\n",
            escape(&report.manifest.display().to_string()),
            escape(&report.references.display().to_string()),
        );
        html += "<table><tr><th>frame</th><th>max diff</th><th>at (x, y) ch</th>\
                 <th>fail %</th><th>mean err</th><th>PSNR dB</th>";
        if flip {
            html += "<th>FLIP</th>";
        }
        html += "<th>failed limits</th><th>result</th></tr>\n";
        for f in &report.frames {
            html += &row(f, flip);
        }
        html += "</table>\n";
        if !report.pass {
            html += &legends(flip);
        }
        for f in report.failures() {
            html += &pictures(f, width);
        }
        html += &format!("<script>{SCRIPT}</script>\n</body></html>\n");
        html
    }
}

fn row(f: &FrameReport, flip: bool) -> String {
    let c = &f.comparison;
    let class = if f.pass { "pass" } else { "fail" };
    let mut row = format!(
        "<tr class=\"{class}\"><td><a href=\"#{}\">{}</a></td><td>{}</td><td>{}</td>\
         <td>{:.3}</td><td>{:.4}</td><td>{}</td>",
        escape(&url(&f.name)),
        f.frame,
        c.max_diff,
        f.max_at(),
        c.failing_percent,
        c.mean_error,
        f.psnr()
    );
    if flip {
        row += &format!(
            "<td>{}</td>",
            f.flip.map_or("-".into(), |v| format!("{v:.4}"))
        );
    }
    let verdict = if f.pass { "PASS" } else { "FAIL" };
    row + &format!(
        "<td>{}</td><td class=\"verdict\">{verdict}</td></tr>\n",
        f.failed_names()
    )
}

fn legends(flip: bool) -> String {
    let ticks = |marks: &[(u32, &str)]| -> String {
        marks
            .iter()
            .map(|(x, label)| format!("<span style=\"left:{x}px\">{label}</span>"))
            .collect()
    };
    let mut html = format!(
        "<h2>Legends</h2><p>Diff heat map: the largest channel difference of each pixel, \
         on a fixed logarithmic scale (the same colour means the same difference in every \
         frame).</p><div class=\"legend\"><img src=\"heat-legend.png\" alt=\"heat map \
         legend\">{}</div>\n",
        // Columns of the strip where d = 1, 3, 15, 63 (see diff::heat_legend).
        ticks(&[
            (0, "0"),
            (32, "1"),
            (64, "3"),
            (128, "15"),
            (191, "63"),
            (255, "255")
        ])
    );
    if flip {
        html += &format!(
            "<p>FLIP error map: the perceived difference of each pixel, 0 to 1.</p>\
             <div class=\"legend\"><img src=\"flip-legend.png\" alt=\"FLIP legend\">{}</div>\n",
            ticks(&[
                (0, "0"),
                (64, "0.25"),
                (128, "0.5"),
                (192, "0.75"),
                (255, "1")
            ])
        );
    }
    html
}

/// A file name as it goes into a link: every byte but letters, digits and `-._~`
/// percent-encoded, so that `?`, `#`, `%` and spaces in a frame's name do not break it.
fn url(name: &str) -> String {
    const KEEP: &percent_encoding::AsciiSet = &percent_encoding::NON_ALPHANUMERIC
        .remove(b'-')
        .remove(b'.')
        .remove(b'_')
        .remove(b'~');
    percent_encoding::utf8_percent_encode(name, KEEP).to_string()
}

fn pictures(f: &FrameReport, width: u32) -> String {
    let id = escape(&f.name);
    let name = escape(&url(&f.name));
    let figure = |kind: &str, caption: &str| {
        format!(
            "<figure><img class=\"frame\" src=\"{name}.{kind}.png\" style=\"width:{width}px\" \
             alt=\"{caption}\"><figcaption>{caption}</figcaption></figure>"
        )
    };
    let mut html = format!(
        "<h2 id=\"{id}\">Frame {} failed ({})</h2>\n<p>{}</p>\n<div class=\"pictures\">",
        f.frame,
        f.failed_names(),
        escape(&f.figures())
    );
    html += &figure("reference", "reference");
    html += &figure("rendered", "render");
    html += &figure("diff", "diff heat map");
    if f.flip_image.is_some() {
        html += &figure("flip", "FLIP error map");
    }
    html += &format!(
        "<figure class=\"flip\"><img class=\"frame\" src=\"{name}.reference.png\" \
         data-reference=\"{name}.reference.png\" data-render=\"{name}.rendered.png\" \
         style=\"width:{width}px\" alt=\"reference and render, flipped by a click\">\
         <figcaption>reference (click to flip)</figcaption></figure></div>\n"
    );
    html
}

/// Copies the images of a failing frame beside the page.
fn copy_images(f: &FrameReport, dir: &Path) -> Result<(), ExportError> {
    let dest = |kind: &str| dir.join(format!("{}.{kind}.png", f.name));
    copy_file(&f.reference_image, &dest("reference"))?;
    let others = [
        (&f.rendered_image, "rendered"),
        (&f.diff_image, "diff"),
        (&f.flip_image, "flip"),
    ];
    for (source, kind) in others {
        if let Some(source) = source {
            copy_file(source, &dest(kind))?;
        }
    }
    Ok(())
}

fn write_png(path: &Path, frame: &Frame) -> Result<(), ExportError> {
    write_atomic(path, frame, ImageFormat::Png, &[]).map_err(|e| ExportError::Io {
        path: path.to_path_buf(),
        source: std::io::Error::other(e.to_string()),
    })
}

impl Exporter for Html {
    fn export(&self, report: &CheckReport) -> Result<(), ExportError> {
        let dir = &self.0;
        std::fs::create_dir_all(dir).map_err(|source| ExportError::Io {
            path: dir.clone(),
            source,
        })?;
        for f in report.failures() {
            copy_images(f, dir)?;
        }
        if !report.pass {
            write_png(&dir.join("heat-legend.png"), &heat_legend(256, 1))?;
            if report.tolerance.flip.is_some() {
                write_png(&dir.join("flip-legend.png"), &flip::legend())?;
            }
        }
        let index = dir.join("index.html");
        let old = std::fs::read_to_string(&index).unwrap_or_default();
        let page = Html::page(report);
        write_file(&index, page.as_bytes())?;
        for name in stale(&old, &page) {
            let path = dir.join(&name);
            match std::fs::remove_file(&path) {
                Err(e) if e.kind() != std::io::ErrorKind::NotFound => {
                    return Err(ExportError::Io { path, source: e })
                }
                _ => {}
            }
        }
        Ok(())
    }
}

/// The image files a page names (`src`, `data-reference`, `data-render`), decoded.
fn images(page: &str) -> std::collections::BTreeSet<String> {
    let mut names = std::collections::BTreeSet::new();
    for attr in ["src=\"", "data-reference=\"", "data-render=\""] {
        for rest in page.split(attr).skip(1) {
            let name = rest.split('"').next().unwrap_or_default();
            let name = percent_encoding::percent_decode_str(name).decode_utf8_lossy();
            names.insert(name.into_owned());
        }
    }
    names
}

/// The images an earlier page of ours (`old`, marked by its title) named that `new` does
/// not: plain PNG names in the page's folder, nothing else.
fn stale(old: &str, new: &str) -> Vec<String> {
    if !old.contains(crate::guard::HTML.0) {
        return Vec::new();
    }
    let keep = images(new);
    let plain = |n: &String| {
        n.ends_with(".png") && !n.contains(['/', '\\']) && !n.starts_with('.') && !keep.contains(n)
    };
    images(old).into_iter().filter(plain).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::report::tests::sample;

    #[test]
    fn names_in_links_are_percent_encoded() {
        assert_eq!(url("frame_0001"), "frame_0001");
        assert_eq!(url("a?b#c d%"), "a%3Fb%23c%20d%25");
        assert_eq!(url("日"), "%E6%97%A5");
    }

    /// Every `src="…"` of the page.
    fn sources(html: &str) -> Vec<&str> {
        html.split("src=\"")
            .skip(1)
            .filter_map(|s| s.split('"').next())
            .collect()
    }

    #[test]
    fn a_failing_frame_shows_its_pictures_and_a_passing_one_none() {
        let html = Html::page(&sample(true));
        let mut names = sources(&html);
        names.sort();
        names.dedup();
        let expected = [
            "flip-legend.png",
            "frame_0005.diff.png",
            "frame_0005.reference.png",
            "frame_0005.rendered.png",
            "heat-legend.png",
        ];
        // The FLIP map is named only when the frame has one (the sample has none).
        assert_eq!(names, expected, "{html}");
        assert!(html.contains("data-render=\"frame_0005.rendered.png\""));
        assert!(html.contains("<td>0.0712</td>") && html.contains("hard_fail, flip"));
        assert!(!html.contains("http"), "the page must not need the network");
    }

    #[test]
    fn a_passing_report_has_no_pictures() {
        let mut report = sample(false);
        report.frames.truncate(1);
        report.pass = true;
        let html = Html::page(&report);
        assert!(sources(&html).is_empty(), "{html}");
        assert!(html.contains("PASS: 1 frame(s)"));
    }

    #[test]
    fn the_images_only_an_earlier_page_of_ours_named_are_stale() {
        let page = |title: &str, name: &str| {
            format!(
                "<title>{title}</title><img src=\"{name}.diff.png\"><img src=\"a%20b.png\">\
                     <img data-reference=\"../up.png\" data-render=\"x.html\">"
            )
        };
        let old = page("animate check: FAIL", "frame_0005");
        let new = page("animate check: FAIL", "frame_0009");
        assert_eq!(stale(&old, &new), ["frame_0005.diff.png"]);
        assert_eq!(
            stale(&old, "<title>animate check: PASS</title>"),
            ["a b.png", "frame_0005.diff.png"]
        );
        assert!(stale(&page("someone's page", "frame_0005"), &new).is_empty());
    }

    #[test]
    fn text_is_escaped() {
        assert_eq!(escape("a<b & \"c\"'"), "a&lt;b &amp; &quot;c&quot;&#39;");
    }
}
