//! Every `animate` and `raytrace` command line that the README, farm/README.md and docs/
//! quote (in code blocks and inline code) parses with the binaries' own clap definitions,
//! from the package's library (src/lib.rs). Synopses (`[-o DIR]`, `…`) are grammar, not commands,
//! and are left out; shell variables and xargs' `{}` are given a sample value.

use whitted_cli::animate::cli;
use whitted_cli::raytrace::cli as raytrace_cli;

use clap::Parser;
use std::path::{Path, PathBuf};

/// The documents whose command lines are checked.
fn documents() -> Vec<PathBuf> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut docs = vec![root.join("README.md"), root.join("farm/README.md")];
    let mut pages: Vec<PathBuf> = std::fs::read_dir(root.join("docs"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "md"))
        .collect();
    pages.sort();
    docs.extend(pages);
    docs
}

/// The shell text quoted by a Markdown page, with the line each piece starts on: code
/// blocks (comment lines dropped, `\` continuations joined) and inline code spans.
fn quoted(text: &str) -> Vec<(usize, String)> {
    let mut out = Vec::new();
    let (mut in_block, mut pending): (bool, Option<(usize, String)>) = (false, None);
    for (i, line) in text.lines().enumerate() {
        let n = i + 1;
        if line.trim_start().starts_with("```") {
            in_block = !in_block;
            continue;
        }
        if in_block {
            let t = line.trim();
            if t.starts_with('#') && pending.is_none() {
                continue;
            }
            let t = t.split(" # ").next().unwrap_or(t);
            let (start, mut acc) = pending.take().unwrap_or((n, String::new()));
            match t.strip_suffix('\\') {
                Some(head) => {
                    acc.push_str(head);
                    acc.push(' ');
                    pending = Some((start, acc));
                }
                None => {
                    acc.push_str(t);
                    out.push((start, acc));
                }
            }
        } else {
            // Inline code names flags and subcommands too (`animate status`, `--video`):
            // only a span that names a scene or manifest file is a whole command line.
            for (k, span) in line.split('`').enumerate() {
                if k % 2 == 1 && (span.contains(".toml") || span.contains(".txt")) {
                    out.push((n, span.to_string()));
                }
            }
        }
    }
    out
}

/// Splits shell words (single and double quotes; no expansion).
fn words(s: &str) -> Vec<String> {
    let (mut out, mut cur, mut quote, mut any) = (Vec::new(), String::new(), None, false);
    for c in s.chars() {
        match (quote, c) {
            (None, '\'' | '"') => (quote, any) = (Some(c), true),
            (Some(q), c) if c == q => quote = None,
            (None, c) if c.is_whitespace() => {
                if any {
                    out.push(std::mem::take(&mut cur));
                }
                any = false;
            }
            (_, c) => {
                cur.push(c);
                any = true;
            }
        }
    }
    if any {
        out.push(cur);
    }
    out
}

/// The `animate`/`raytrace` invocations in a piece of shell: (binary, its arguments).
fn invocations(shell: &str) -> Vec<(&'static str, Vec<String>)> {
    let mut found = Vec::new();
    for part in shell
        .split(['|', ';', '(', ')'])
        .flat_map(|p| p.split("&&"))
    {
        let w = words(&part.replace("{}", "0"));
        let Some(at) = w.iter().position(|t| {
            let base = t.rsplit('/').next().unwrap_or(t);
            (base == "animate" || base == "raytrace") && !t.contains('=')
        }) else {
            continue;
        };
        let bin = if w[at].ends_with("raytrace") {
            "raytrace"
        } else {
            "animate"
        };
        // `cargo run --bin animate -- ARGS`: the arguments follow the `--`.
        let args: Vec<String> = if at > 0 && w[at - 1] == "--bin" {
            match w.iter().position(|t| t == "--") {
                Some(dd) => w[dd + 1..].to_vec(),
                None => Vec::new(),
            }
        } else {
            w[at + 1..].to_vec()
        };
        let args: Vec<String> = args
            .into_iter()
            .map(|a| if a.contains('$') { sample(&a) } else { a })
            .collect();
        found.push((bin, args));
    }
    found
}

/// A sample value for a word with a shell variable in it.
fn sample(word: &str) -> String {
    if word.contains("SLURM_ARRAY_TASK_ID") {
        "0/16".into()
    } else {
        "x".into()
    }
}

/// A synopsis or a fragment rather than a command: optional parts, ellipses, or words
/// that are only a name (`animate` alone, `animate status`).
fn is_synopsis(args: &[String]) -> bool {
    args.iter()
        .any(|a| a.starts_with('[') || a.contains('…') || a == "..." || a.ends_with(']'))
}

#[test]
fn every_quoted_command_line_parses() {
    let mut checked = 0;
    let mut bad = Vec::new();
    for doc in documents() {
        let text = std::fs::read_to_string(&doc).unwrap();
        for (line, shell) in quoted(&text) {
            for (bin, args) in invocations(&shell) {
                if is_synopsis(&args) || args.is_empty() {
                    continue;
                }
                let argv = std::iter::once(bin.to_string()).chain(args.iter().cloned());
                let parsed = match bin {
                    "raytrace" => raytrace_cli::Args::try_parse_from(argv).map(|_| ()),
                    _ => cli::Cli::try_parse_from(argv).map(|_| ()),
                };
                checked += 1;
                let help = |e: &clap::Error| {
                    use clap::error::ErrorKind::*;
                    matches!(e.kind(), DisplayHelp | DisplayVersion)
                };
                if let Err(e) = parsed.or_else(|e| if help(&e) { Ok(()) } else { Err(e) }) {
                    let first = e.to_string().lines().next().unwrap_or("").to_string();
                    bad.push(format!(
                        "{}:{line}: {bin} {}: {first}",
                        doc.display(),
                        args.join(" ")
                    ));
                }
            }
        }
    }
    assert!(
        bad.is_empty(),
        "command lines that do not parse:\n{}",
        bad.join("\n")
    );
    assert!(checked > 20, "only {checked} command lines found");
}

#[test]
fn a_wrong_flag_is_caught() {
    // The checker itself: a quoted line with a flag the tool lacks is reported.
    let found = invocations("animate animations/orbit.toml --no-such-flag | ffmpeg -i -");
    assert_eq!(found.len(), 1);
    let argv = std::iter::once("animate".to_string()).chain(found[0].1.iter().cloned());
    assert!(cli::Cli::try_parse_from(argv).is_err());
    let found = invocations("cargo run --release --bin raytrace -- scenes/orbit.txt --size 10");
    assert_eq!(found[0].0, "raytrace");
    let argv = std::iter::once("raytrace".to_string()).chain(found[0].1.iter().cloned());
    assert!(raytrace_cli::Args::try_parse_from(argv).is_err());
}

#[test]
fn docs_speak_of_the_repository_alone() {
    // No section numbers of a specification, issue numbers or the report's file name,
    // none of which are in the repository (the README's opening names the report once).
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files = documents();
    for dir in ["farm/slurm", "farm/k8s"] {
        files.extend(
            std::fs::read_dir(root.join(dir))
                .unwrap()
                .map(|e| e.unwrap().path()),
        );
    }
    let mut bad = Vec::new();
    for file in files {
        let text = std::fs::read_to_string(&file).unwrap();
        let readme = file.ends_with("README.md") && file.parent() == Some(root);
        for (i, line) in text.lines().enumerate() {
            let lower = line.to_lowercase();
            let issue = lower
                .match_indices("issue ")
                .any(|(k, m)| lower[k + m.len()..].starts_with(|c: char| c.is_ascii_digit()));
            let report_name = line.contains("rapport-raytracing") && !(readme && i < 5);
            if line.contains("SPEC §") || issue || report_name {
                bad.push(format!("{}:{}: {line}", file.display(), i + 1));
            }
        }
    }
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}
