//! The GitLab Code Quality report that `walls-lint --format gitlab` writes has every
//! field GitLab needs, over every lint case under `tests/lint/`.
//!
//! GitLab publishes no schema package for this format, so the test checks what its
//! documentation requires of each issue (a string `description`, `check_name`,
//! `fingerprint` and `severity` among `info`, `minor`, `major`, `critical`, `blocker`,
//! `location.path` and an integer `location.lines.begin`) and what its parser relies
//! on: fingerprints unique within a report, since it keeps one issue per fingerprint.
//! The issues are also compared with the `--format json` report of the same files, and
//! the fingerprints must not change when lines are added above the issues.

use serde_json::Value;
use std::collections::HashSet;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn lint(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_walls-lint"))
        .args(args)
        .current_dir(dir)
        .output()
        .unwrap()
}

fn parse(out: &Output) -> Value {
    serde_json::from_slice(&out.stdout).unwrap_or_else(|e| panic!("{e}: {out:?}"))
}

/// Checks one report against the required fields; its issues.
fn check_report(report: &Value, what: &str) -> Vec<Value> {
    let issues = report
        .as_array()
        .unwrap_or_else(|| panic!("{what}: not an array"));
    let mut fingerprints = HashSet::new();
    for issue in issues {
        let text = |key: &str| {
            issue[key]
                .as_str()
                .unwrap_or_else(|| panic!("{what}: `{key}` is not a string in {issue}"))
        };
        assert!(!text("description").is_empty(), "{what}: {issue}");
        let check = text("check_name");
        assert!(
            check == "unreadable-file" || walls_cli::find_code(check).is_some(),
            "{what}: {issue}"
        );
        let fingerprint = text("fingerprint");
        assert!(
            fingerprint.len() == 64
                && fingerprint
                    .bytes()
                    .all(|b| b.is_ascii_digit() || (b'a'..=b'f').contains(&b)),
            "{what}: {issue}"
        );
        assert!(
            fingerprints.insert(fingerprint.to_owned()),
            "{what}: fingerprint repeated: {issue}"
        );
        assert!(
            ["info", "minor", "major", "critical", "blocker"].contains(&text("severity")),
            "{what}: {issue}"
        );
        let location = &issue["location"];
        let path = location["path"].as_str().expect("location.path");
        assert!(
            !path.starts_with("./") && !path.is_empty(),
            "{what}: {issue}"
        );
        let begin = location["lines"]["begin"].as_u64().expect("lines.begin");
        let end = location["lines"]["end"].as_u64().expect("lines.end");
        assert!(1 <= begin && begin <= end, "{what}: {issue}");
    }
    issues.clone()
}

/// The walls files of every lint case, by case.
fn cases() -> Vec<(PathBuf, Vec<String>)> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/lint");
    let mut cases: Vec<_> = std::fs::read_dir(root)
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    cases.sort();
    cases
        .into_iter()
        .filter_map(|case| {
            let mut files: Vec<String> = std::fs::read_dir(&case)
                .unwrap()
                .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
                .filter(|name| name.ends_with(".walls"))
                .collect();
            files.sort();
            (!files.is_empty()).then_some((case, files))
        })
        .collect()
}

#[test]
fn every_case_has_the_required_fields_and_agrees_with_json() {
    let mut issues_seen = 0;
    for (case, files) in cases() {
        for mode in ["ssdem", "hsdem"] {
            let what = format!("{} --mode {mode}", case.display());
            let names: Vec<&str> = files.iter().map(String::as_str).collect();
            // --isolated: the cases' settings files are not what this test is about (one
            // is deliberately broken), as in sarif_schema.rs.
            let run = |format| {
                lint(
                    &case,
                    &[
                        &["--isolated", "--mode", mode, "--format", format],
                        &names[..],
                    ]
                    .concat(),
                )
            };
            let gitlab = run("gitlab");
            let json = run("json");
            assert!(gitlab.status.code().unwrap() <= 1, "{what}: {gitlab:?}");
            assert_eq!(gitlab.status.code(), json.status.code(), "{what}");
            let issues = check_report(&parse(&gitlab), &what);
            issues_seen += issues.len();

            // The same findings as the JSON report, in the same order.
            let expected: Vec<(String, String, u64, u64)> = parse(&json)["files"]
                .as_array()
                .unwrap()
                .iter()
                .flat_map(|f| {
                    f["diagnostics"].as_array().unwrap().iter().map(move |d| {
                        let severity = match d["severity"].as_str().unwrap() {
                            "error" => "critical",
                            "warning" => "major",
                            _ => "info",
                        };
                        (
                            format!("{} {}", f["path"].as_str().unwrap(), d["code"]),
                            severity.to_owned(),
                            d["line"].as_u64().unwrap(),
                            d["end_line"].as_u64().unwrap(),
                        )
                    })
                })
                .collect();
            let got: Vec<(String, String, u64, u64)> = issues
                .iter()
                .map(|i| {
                    (
                        format!(
                            "{} {}",
                            i["location"]["path"].as_str().unwrap(),
                            i["check_name"]
                        ),
                        i["severity"].as_str().unwrap().to_owned(),
                        i["location"]["lines"]["begin"].as_u64().unwrap(),
                        i["location"]["lines"]["end"].as_u64().unwrap(),
                    )
                })
                .collect();
            assert_eq!(got, expected, "{what}");
        }
    }
    assert!(issues_seen >= 50, "too few issues: {issues_seen}");
}

#[test]
fn unreadable_files_are_blockers() {
    let dir = tempfile::tempdir().unwrap();
    let out = lint(dir.path(), &["--format", "gitlab", "./absent.walls"]);
    assert_eq!(out.status.code(), Some(2), "{out:?}");
    let issues = check_report(&parse(&out), "absent.walls");
    assert_eq!(issues.len(), 1);
    assert_eq!(issues[0]["severity"], "blocker");
    assert_eq!(issues[0]["check_name"], "unreadable-file");
    assert_eq!(issues[0]["location"]["path"], "absent.walls");
}

#[test]
fn fingerprints_do_not_change_when_lines_move() {
    let case = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/lint/mistakes-gitlab");
    let text = std::fs::read_to_string(case.join("mistakes.walls")).unwrap();
    let dir = tempfile::tempdir().unwrap();
    let fingerprints = |text: &str| -> Vec<Value> {
        std::fs::write(dir.path().join("mistakes.walls"), text).unwrap();
        let out = lint(dir.path(), &["--format", "gitlab", "mistakes.walls"]);
        check_report(&parse(&out), "mistakes.walls")
            .into_iter()
            .map(|i| i["fingerprint"].clone())
            .collect()
    };
    let before = fingerprints(&text);
    assert!(before.len() >= 5);
    let after = fingerprints(&format!("# a comment\n\n# and a blank line above\n{text}"));
    assert_eq!(before, after);
}
