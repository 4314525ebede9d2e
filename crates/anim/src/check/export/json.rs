//! The check report as JSON (`animate check --json`): the report value as serde writes
//! it: `manifest`, `references`, `report`, `tolerance`, `pass`, and `frames`, each with
//! its figures (max_diff, max_at, failing_pixels, failing_percent, mean_error, psnr, flip),
//! `failed` (limit names), `pass`, `seconds` and image paths (null when not written).

use super::{ExportError, Exporter, Sink};
use crate::check::report::CheckReport;

/// The JSON exporter.
pub struct Json(pub Sink);

impl Json {
    /// The report as pretty-printed JSON with a final newline.
    pub fn text(report: &CheckReport) -> String {
        // A report holds only strings, numbers, options and lists: it always serializes.
        let mut text = serde_json::to_string_pretty(report).unwrap_or_default();
        text.push('\n');
        text
    }
}

impl Exporter for Json {
    fn export(&self, report: &CheckReport) -> Result<(), ExportError> {
        self.0.write(Self::text(report).as_bytes())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::report::tests::sample;

    #[test]
    fn fields_of_a_failing_frame() {
        let doc: serde_json::Value = serde_json::from_str(&Json::text(&sample(true))).unwrap();
        assert_eq!(doc["pass"], false);
        assert_eq!(doc["tolerance"]["flip"], 0.05);
        let f = &doc["frames"][1];
        assert_eq!(f["frame"], 5);
        assert_eq!(f["max_diff"], 255);
        assert_eq!(f["max_at"], serde_json::json!([10, 12, 1]));
        assert_eq!(f["flip"], 0.0712);
        assert_eq!(
            f["failed"],
            serde_json::json!(["fail_percent", "hard_fail", "flip"])
        );
        assert_eq!(doc["frames"][0]["psnr"], serde_json::Value::Null);
    }
}
