//! `animate MANIFEST.toml`: renders the frames of an animation manifest into a folder,
//! or streams them to standard output or ffmpeg; `status`, `stats`, `preview`, `check`,
//! `bless`, `job`, `estimate`, `encode`, `clean` and `view` are subcommands. `main` turns
//! the command line (`cli`) into library calls (`commands`, `render` for the render
//! itself) and their outcome into an exit status (`whitted::exit`); `report` shows
//! progress and results.

pub mod cli;
mod commands;
mod render;
pub mod report;

use clap::Parser;
use cli::{Cli, Command};
use commands::{bless, check, encode, job, pool, preview, stdout, view};
use std::process::ExitCode;
use whitted::exit::Outcome;
use whitted_anim::commands as library;
use whitted_anim::AnimError;

fn run(cli: Cli) -> anyhow::Result<Outcome> {
    Ok(match cli.command {
        None => render::render(cli.render)?,
        Some(Command::Bless(args)) => bless(args)?,
        Some(Command::Check(args)) => check(args)?,
        Some(Command::Status(a)) => {
            let (project, pool) = (a.common.load_draft(&a.draft)?, pool(a.common.threads)?);
            pool.install(|| library::status::status(&project, &a.request(), &mut stdout()))?
        }
        Some(Command::Stats(a)) => {
            let (project, pool) = (a.common.load_draft(&a.draft)?, pool(a.common.threads)?);
            pool.install(|| library::stats::stats(&project, &a.request(), &mut stdout()))?
        }
        Some(Command::Preview(args)) => preview(args)?,
        Some(Command::Job(args)) => job(args)?,
        Some(Command::Estimate(a)) => {
            let (project, pool) = (a.common.load()?, pool(a.common.threads)?);
            let list = a.common.frames.as_deref();
            pool.install(|| library::farm::estimate(&project, list, a.shards, &mut stdout()))?
        }
        Some(Command::Encode(args)) => encode(args)?,
        Some(Command::Clean(a)) => {
            let project = whitted_anim::Project::load(&a.manifest)?;
            library::folder::clean(&project, &a.request(), &mut stdout())?
        }
        Some(Command::View(args)) => view(args)?,
    })
}

/// Says why a command failed, with the hint that helps.
fn say(e: &anyhow::Error) {
    eprintln!("animate: {}", report::message(e));
    if let Some(hint) = e.downcast_ref::<AnimError>().and_then(report::hint) {
        eprintln!("animate: hint: {hint}");
    }
}

/// `animate`'s whole run: the exit status of the command line the process was given.
pub fn main() -> ExitCode {
    if let Err(e) = whitted_cmd::process::check_cpu() {
        eprintln!("animate: {e}");
        return ExitCode::from(Outcome::BadInput.code());
    }
    match run(Cli::parse()) {
        Ok(outcome) => ExitCode::from(outcome.code()),
        Err(e) => {
            say(&e);
            ExitCode::from(report::outcome(&e).code())
        }
    }
}
