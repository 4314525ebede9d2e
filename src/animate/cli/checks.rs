//! `animate check` and `animate bless`: the references, the limits, and where the results
//! go (a table or JSON on standard output, JUnit, an HTML page).

use super::{Common, DraftArgs};
use clap::Args;
use std::path::PathBuf;
use whitted_anim::check::export::{Exporter, Html, Json, Junit, Sink, Table};
use whitted_anim::check::Overrides;
use whitted_anim::guard::{self, Mark};

#[derive(Args, Debug)]
pub struct BlessArgs {
    #[command(flatten)]
    pub common: Common,
    /// The references folder, instead of the manifest's `[check] references`.
    #[arg(long, value_name = "DIR")]
    pub references: Option<PathBuf>,
    /// bless: replace references that another manifest recorded; check: write --junit and
    /// --html over files that animate did not write.
    #[arg(long)]
    pub force: bool,
    #[command(flatten)]
    pub draft: DraftArgs,
}

#[derive(Args, Debug)]
pub struct CheckArgs {
    #[command(flatten)]
    pub bless: BlessArgs,
    /// Where images of failing frames go (default: the frame folder's name + `-check`).
    #[arg(long, value_name = "DIR")]
    pub report: Option<PathBuf>,
    /// A pixel fails when a channel differs by more than this (0..255).
    #[arg(long)]
    pub fail: Option<u8>,
    /// A frame fails when more than this percentage of its pixels fail.
    #[arg(long, value_name = "PERCENT")]
    pub fail_percent: Option<f64>,
    /// A frame fails when any channel differs by more than this (0..255).
    #[arg(long)]
    pub hard_fail: Option<u8>,
    /// A frame fails when its mean FLIP error (NVIDIA's perceptual metric, 0..1) is
    /// above this.
    #[arg(long, value_name = "X")]
    pub flip: Option<f64>,
    /// Print the results as JSON on standard output instead of a table.
    #[arg(long)]
    pub json: bool,
    /// Also write the results as JUnit XML into this file.
    #[arg(long, value_name = "FILE")]
    pub junit: Option<PathBuf>,
    /// Also write a report page, DIR/index.html, with the images of failing frames.
    #[arg(long, value_name = "DIR")]
    pub html: Option<PathBuf>,
}

impl CheckArgs {
    /// The command line's share of the check's options.
    pub fn overrides(&self) -> Overrides<'_> {
        Overrides {
            frames: self.bless.common.frames.as_deref(),
            references: self.bless.references.as_deref(),
            report: self.report.as_deref(),
            fail: self.fail,
            fail_percent: self.fail_percent,
            hard_fail: self.hard_fail,
            flip: self.flip,
        }
    }

    /// The exporters asked for: the table or JSON on standard output, JUnit, HTML.
    pub fn exporters(&self) -> Vec<Box<dyn Exporter + Send + Sync>> {
        let mut out: Vec<Box<dyn Exporter + Send + Sync>> = match self.json {
            true => vec![Box::new(Json(Sink::Stdout))],
            false => vec![Box::new(Table(Sink::Stdout))],
        };
        if let Some(file) = &self.junit {
            out.push(Box::new(Junit(file.clone())));
        }
        if let Some(dir) = &self.html {
            out.push(Box::new(Html(dir.clone())));
        }
        out
    }

    /// The files the exporters write, each with its kind's mark.
    pub fn outputs(&self) -> Vec<(PathBuf, Mark)> {
        let junit = self.junit.iter().map(|f| (f.clone(), guard::JUNIT));
        let html = (self.html.iter()).map(|d| (d.join("index.html"), guard::HTML));
        junit.chain(html).collect()
    }
}
