//! The golden scenes' run directories (walls-sim's `tests/golden`), which pkdgrav ran, read by the build each names
//! in its `params.par` header: no error, and only the start-up warnings pkdgrav prints
//! for them (`iOutcomes` in every DEM build, B37; the particles' rolling and twisting
//! friction zeroed with aggregates, B31; the merge parameters in every hard-sphere build,
//! B19); and the rows of the hard-sphere, aggregate and springs builds.

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
    // B19 fires on every hard-sphere run that leaves `dMergeLimit` at its default 1
    // (startup_checks.md, reproduced with pkdgrav).
    let b19 = found
        .iter()
        .filter(|f| *f == &("P009", "B19".to_string(), false))
        .count();
    assert_eq!(
        (b37, b31, b19, found.len()),
        (dem_runs, 1, seen - dem_runs, seen + 1),
        "{found:#?}"
    );
}

/// The rows of hard-sphere, aggregate and springs builds hold as startup_checks.md says,
/// each with its severity: the option codes of `iOutcomes` (1 merge, 2 bounce, 4
/// fragment) and `iOverlapOption` (1 backstep, 2 adjust positions, 3 repel, 4 merge).
#[test]
fn hard_sphere_aggregate_and_springs_rows() {
    let rows = |text: &str, build: &str| -> Vec<(Severity, String)> {
        let build = Build::parse(build).unwrap();
        check(text, &build)
            .into_iter()
            .filter_map(|d| {
                let row = d.message.split(" [").nth(1)?.split(']').next()?.to_string();
                Some((d.severity, row))
            })
            .collect()
    };
    let holds = |text: &str, build: &str, row: &str, severity: Severity| {
        let found = rows(text, build);
        assert!(
            found.contains(&(severity, row.to_string())),
            "{row} in {build} on {text:?}: {found:?}"
        );
    };
    let quiet = |text: &str, build: &str, row: &str| {
        let found = rows(text, build);
        assert!(
            found.iter().all(|(_, r)| r != row),
            "{row} in {build} on {text:?}: {found:?}"
        );
    };
    use Severity::{Error, Warning};
    let hs = "NUMREC";
    // The defaults: bounce, dMergeLimit 1 (B19), nothing that stops.
    holds("dMergeLimit = 1\n", hs, "B19", Warning);
    quiet("dMergeLimit = 0\n", hs, "B19");
    holds("iOutcomes = 0\n", hs, "A43", Error);
    holds("iOutcomes = 3\nbDoSelfGravity = 0\n", hs, "A44", Error);
    quiet("iOutcomes = 1\nbDoSelfGravity = 0\n", hs, "A44");
    holds("dEpsN = 0\n", hs, "A48", Error);
    holds("iEpsNOption = 5\n", hs, "A51", Error);
    holds("iOutcomes = 6\n", hs, "A58", Error);
    quiet("iOutcomes = 6\n", "NUMREC AGGS", "A58");
    holds("iOverlapOption = 7\n", hs, "A59", Error);
    // Adjusting positions with the default dAdjPosLimit of 0 stops.
    holds("iOverlapOption = 2\n", hs, "A63", Error);
    quiet("iOverlapOption = 2\ndAdjPosLimit = 0.5\n", hs, "A63");
    holds("dRepelFac = 1e-3\n", hs, "B25", Warning);
    quiet(
        "dRepelFac = 1e-3\niOverlapOption = 3\nbDoSelfGravity = 1\n",
        hs,
        "B25",
    );
    holds(
        "iOverlapOption = 1\nbStrictOverlap = 1\n",
        hs,
        "B24",
        Warning,
    );
    holds("iOverlapOption = 3\nnSmooth = 0\n", hs, "A65", Error);
    // The hard-sphere block is not compiled in a DEM build.
    quiet("iOutcomes = 0\n", "DEM", "A43");
    holds("iOutcomes = 4\n", "NUMREC AGGS", "A67", Error);
    holds(
        "iOutcomes = 7\ndFragLimit = 1\ndMergeLimit = 2\nbDoSelfGravity = 1\n",
        "NUMREC AGGS",
        "A68",
        Error,
    );
    holds(
        "iOutcomes = 7\ndFragLimit = -3\ndMergeLimit = 2\nbDoSelfGravity = 1\n",
        "NUMREC AGGS",
        "B27",
        Warning,
    );
    // Springs: the default nSmooth of 64 stops every run.
    holds("dDelta = 1\n", "SPRINGS", "A86", Error);
    holds("dPorosityFactor = 0\n", "SPRINGS", "A85", Error);
    holds("bFindRejects = 1\n", hs, "A126", Error);
    holds("iCollLogOption = 3\n", hs, "A42", Error);
    holds("bVariableSoft = 1\n", hs, "A13", Error);
    holds("bCannonical = 0\n", hs, "B7", Warning);
}
