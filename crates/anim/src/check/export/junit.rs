//! The check report as JUnit XML (`--junit FILE`), written with the `quick-junit` crate:
//! one report holding one test suite `animate check`, one test case per checked frame
//! named `frame N (MANIFEST)` with its time; a failing frame carries a `<failure>` whose
//! `type` names the broken limits and whose message gives the figures (max difference and
//! where, failing %, mean error, PSNR, and the mean FLIP error when the tolerance has a
//! FLIP limit). Every case also has the figures as properties.

use super::{write_file, ExportError, Exporter};
use crate::check::report::{CheckReport, FrameReport};
use quick_junit::{NonSuccessKind, Property, Report, TestCase, TestCaseStatus, TestSuite};
use std::path::PathBuf;
use std::time::Duration;

/// The JUnit exporter, writing to a file.
pub struct Junit(pub PathBuf);

impl Junit {
    /// The report as JUnit XML.
    pub fn text(report: &CheckReport) -> Result<String, ExportError> {
        let manifest = report.manifest.display().to_string();
        let mut suite = TestSuite::new("animate check");
        suite.add_test_cases(report.frames.iter().map(|f| case(f, &manifest)));
        let total: f64 = report.frames.iter().map(|f| f.seconds).sum();
        suite.set_time(duration(total));
        let mut xml = Report::new("whitted");
        xml.add_test_suite(suite);
        xml.to_string()
            .map_err(|e| ExportError::Junit(e.to_string()))
    }
}

fn duration(seconds: f64) -> Duration {
    Duration::try_from_secs_f64(seconds).unwrap_or_default()
}

fn case(f: &FrameReport, manifest: &str) -> TestCase {
    let status = if f.pass {
        TestCaseStatus::success()
    } else {
        let mut s = TestCaseStatus::non_success(NonSuccessKind::Failure);
        s.set_type(f.failed_names());
        s.set_message(format!(
            "frame {} broke {}: {}",
            f.frame,
            f.failed_names(),
            f.figures()
        ));
        let images = [&f.rendered_image, &f.diff_image, &f.flip_image];
        let listed: Vec<String> = images
            .iter()
            .filter_map(|p| p.as_ref().map(|p| p.display().to_string()))
            .collect();
        s.set_description(format!(
            "reference: {}\nimages: {}",
            f.reference_image.display(),
            listed.join(", ")
        ));
        s
    };
    let mut case = TestCase::new(format!("frame {} ({manifest})", f.frame), status);
    case.set_classname(format!("animate check {manifest}"));
    case.set_time(duration(f.seconds));
    let c = &f.comparison;
    let mut props = vec![
        Property::new("max_diff", c.max_diff.to_string()),
        Property::new("max_at", f.max_at()),
        Property::new("failing_percent", format!("{:.3}", c.failing_percent)),
        Property::new("mean_error", format!("{:.4}", c.mean_error)),
        Property::new("psnr_db", f.psnr()),
    ];
    if let Some(flip) = f.flip {
        props.push(Property::new("flip", format!("{flip:.4}")));
    }
    case.add_properties(props);
    case
}

impl Exporter for Junit {
    fn export(&self, report: &CheckReport) -> Result<(), ExportError> {
        write_file(&self.0, Self::text(report)?.as_bytes())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::report::tests::sample;

    #[test]
    fn parsed_back_one_case_per_frame_and_the_failure_with_figures() {
        let xml = Junit::text(&sample(true)).unwrap();
        let parsed = Report::deserialize_from_str(&xml).unwrap();
        assert_eq!(parsed.test_suites.len(), 1);
        let suite = &parsed.test_suites[0];
        assert_eq!((suite.tests, suite.failures), (2, 1));
        let [pass, fail] = &suite.test_cases[..] else {
            panic!("{xml}")
        };
        assert_eq!(pass.name.as_str(), "frame 0 (anim.toml)");
        assert!(matches!(pass.status, TestCaseStatus::Success { .. }));
        assert_eq!(fail.name.as_str(), "frame 5 (anim.toml)");
        assert_eq!(fail.time, Some(Duration::from_millis(250)));
        let TestCaseStatus::NonSuccess {
            kind, message, ty, ..
        } = &fail.status
        else {
            panic!("{xml}")
        };
        assert_eq!(*kind, NonSuccessKind::Failure);
        assert_eq!(
            ty.as_ref().unwrap().as_str(),
            "fail_percent, hard_fail, flip"
        );
        let message = message.as_ref().unwrap().as_str();
        for figure in ["255 at (10, 12) G", "3.255 %", "PSNR 21.46", "FLIP 0.0712"] {
            assert!(message.contains(figure), "{figure} not in {message}");
        }
    }
}
