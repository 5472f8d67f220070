//! The golden scenes' run directories (walls-sim's `tests/golden`), which pkdgrav ran, read by the build each names
//! in its `params.par` header: no error, and only the start-up warnings pkdgrav prints
//! for them (`iOutcomes` in every DEM build, B37; the particles' rolling and twisting
//! friction zeroed with aggregates, B31).

use std::path::Path;
use walls_diagnostics::Severity;
use walls_par::{Build, check, options::OPTIONS};

/// The build a golden `params.par` names in its first comment lines (`# pkdgrav build:
/// ssdem -- compile options: COLLISIONS WALLS DEM …`, continued on the next line).
fn build_of(text: &str) -> Build {
    let header: Vec<&str> = text.lines().take_while(|l| l.starts_with('#')).collect();
    let at = header
        .iter()
        .position(|l| l.contains("compile options:"))
        .expect("a build line");
    let mut words = String::new();
    for line in &header[at..(at + 2).min(header.len())] {
        let line = line.split("compile options:").last().unwrap();
        let line = line.split('(').next().unwrap();
        for w in line.split_whitespace() {
            if OPTIONS.contains(&w) {
                words.push(' ');
                words.push_str(w);
            }
        }
    }
    Build::parse(&words).unwrap()
}

#[test]
fn golden_run_directories_have_no_error_in_their_build() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../walls-sim/tests/golden");
    let mut seen = 0;
    let mut found = Vec::new();
    for dir in std::fs::read_dir(&root).unwrap() {
        let par = dir.unwrap().path().join("params.par");
        let Ok(text) = std::fs::read_to_string(&par) else {
            continue;
        };
        seen += 1;
        let build = build_of(&text);
        for d in check(&text, &build) {
            assert_ne!(d.severity, Severity::Error, "{}: {d:#?}", par.display());
            let row = d
                .message
                .split(" [")
                .nth(1)
                .and_then(|r| r.split(']').next());
            found.push((d.code.id, row.unwrap_or("").to_string(), build.has("DEM")));
        }
    }
    assert_eq!(seen, 30);
    let dem_runs = 24;
    let b37 = found
        .iter()
        .filter(|f| *f == &("P009", "B37".to_string(), true))
        .count();
    let b31 = found
        .iter()
        .filter(|f| *f == &("P009", "B31".to_string(), true))
        .count();
    assert_eq!(
        (b37, b31, found.len()),
        (dem_runs, 1, dem_runs + 1),
        "{found:#?}"
    );
}
