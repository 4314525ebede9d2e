//! The text table `animate check` prints: one row per frame with its figures, the limits
//! it broke and PASS/FAIL, then the verdict line and, when frames failed, the heat map's
//! legend.

use super::{ExportError, Exporter, Sink};
use crate::check::report::CheckReport;

/// The table exporter.
pub struct Table(pub Sink);

/// How to read the diff images, printed under a failing table.
pub const LEGEND: &str = "diff images: largest channel difference of each pixel on a fixed \
                          log scale: black 0, dim red 1, red 3, orange 15, yellow 63, white 255";

impl Table {
    /// The table, the verdict and (on failure) the legend, as text.
    pub fn text(report: &CheckReport) -> String {
        let flip = report.tolerance.flip.is_some();
        let mut out = format!(
            "{:>6}  {:>8}  {:>16}  {:>8}  {:>9}  {:>8}",
            "frame", "max diff", "at (x, y) ch", "fail %", "mean err", "PSNR dB"
        );
        if flip {
            out += &format!("  {:>7}", "FLIP");
        }
        out += &format!("  {:<24}  result\n", "failed limits");
        for r in &report.frames {
            let c = &r.comparison;
            out += &format!(
                "{:>6}  {:>8}  {:>16}  {:>8.3}  {:>9.4}  {:>8}",
                r.frame,
                c.max_diff,
                r.max_at(),
                c.failing_percent,
                c.mean_error,
                r.psnr()
            );
            if let Some(f) = r.flip {
                out += &format!("  {f:>7.4}");
            }
            let verdict = if r.pass { "PASS" } else { "FAIL" };
            out += &format!("  {:<24}  {verdict}\n", r.failed_names());
        }
        out += &report.verdict();
        out.push('\n');
        if !report.pass {
            out += LEGEND;
            out.push('\n');
        }
        out
    }
}

impl Exporter for Table {
    fn export(&self, report: &CheckReport) -> Result<(), ExportError> {
        self.0.write(Self::text(report).as_bytes())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::report::tests::sample;

    #[test]
    fn rows_name_the_broken_limits_and_the_legend_follows_a_failure() {
        let text = Table::text(&sample(false));
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines.len(), 5, "{text}");
        assert!(lines[0].contains("failed limits") && !lines[0].contains("FLIP"));
        let row0: Vec<&str> = lines[1].split_whitespace().collect();
        assert_eq!(
            (row0[0], &row0[row0.len() - 2..]),
            ("0", &["-", "PASS"][..])
        );
        assert!(lines[2].contains("(10, 12) G") && lines[2].contains("21.46"));
        assert!(lines[2].contains("fail_percent, hard_fail") && lines[2].ends_with("FAIL"));
        assert!(lines[3].starts_with("FAIL: 1 of 2"));
        assert_eq!(lines[4], LEGEND);
    }

    #[test]
    fn flip_column_when_the_tolerance_has_a_flip_limit() {
        let text = Table::text(&sample(true));
        assert!(text.lines().next().unwrap().contains("FLIP"));
        let row5 = text.lines().nth(2).unwrap();
        assert!(
            row5.contains(" 0.0712 ") && row5.contains("hard_fail, flip"),
            "{row5}"
        );
    }
}
