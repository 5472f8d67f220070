//! Tests as data. Under `tests/data/check`, each `.walls` file is checked (syntax and
//! model) and its diagnostics, with exact spans, the text after its safe fixes and what
//! that text still reports are compared with the `.snap` file beside it. A first-line
//! comment `# options: …` sets the checker's options (`--mode hsdem`, `--max-walls N`,
//! `--min-radius R`, `--dt DT`). (The resolved scene as JSON is tested in
//! walls-geometry.)
//! Update with `INSTA_UPDATE=always cargo test -p walls-model` and review the diff.

use std::fmt::Write as _;
use walls_diagnostics::{Applicability, Diagnostic, apply_fixes};
use walls_model::{ContactModel, Options, analyze};
use walls_test_support::{render, snapshot_beside};

fn options(text: &str) -> Options {
    let mut options = Options::default();
    let Some(line) = text
        .lines()
        .next()
        .and_then(|l| l.strip_prefix("# options:"))
    else {
        return options;
    };
    let words: Vec<&str> = line.split_whitespace().collect();
    for pair in words.windows(2) {
        match pair[0] {
            "--mode" => {
                options.mode = if pair[1] == "hsdem" {
                    ContactModel::Hsdem
                } else {
                    ContactModel::Ssdem
                }
            }
            "--max-walls" => options.max_walls = pair[1].parse().unwrap(),
            "--min-radius" => options.min_radius = Some(pair[1].parse().unwrap()),
            "--dt" => options.dt = Some(pair[1].parse().unwrap()),
            _ => {}
        }
    }
    options
}

fn lint(text: &str, options: &Options) -> Vec<Diagnostic> {
    let parsed = walls_syntax::parse(text);
    let mut all = parsed.diagnostics;
    all.extend(analyze(&parsed.tree, options).diagnostics);
    all.sort_by_key(|d| (d.span.start, d.span.end));
    all
}

#[test]
fn check_cases() {
    insta::glob!("data/check/*.walls", |path| {
        let text = std::fs::read_to_string(path).unwrap();
        let options = options(&text);
        let diagnostics = lint(&text, &options);
        assert!(
            !diagnostics.is_empty(),
            "{} reports nothing",
            path.display()
        );
        let mut out = render(&text, &diagnostics);
        let fixed = apply_fixes(&text, &diagnostics, Applicability::Safe);
        if fixed != text {
            writeln!(out, "--- after safe fixes ---\n{fixed}--- leaves ---").unwrap();
            out.push_str(&render(&fixed, &lint(&fixed, &options)));
        }
        snapshot_beside(path, &out);
    });
}
