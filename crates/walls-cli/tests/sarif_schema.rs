//! The SARIF that `walls-lint --format sarif` writes is valid against the OASIS SARIF
//! 2.1.0 schema, checked by an independent reader (Python's jsonschema) over every lint
//! case under `tests/lint/`. `scripts/install-test-tools` (run by `scripts/test`)
//! installs the reader and the schema.

use std::path::Path;
use std::process::Command;

#[test]
fn sarif_output_is_valid_against_the_schema() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let schema = root.join("target/test-tools/sarif-2.1.0-rtm.5.json");
    assert!(
        schema.exists(),
        "{} is missing: run scripts/install-test-tools (or scripts/test)",
        schema.display()
    );
    let out_dir = tempfile::tempdir().unwrap();
    let mut logs = Vec::new();
    let mut cases: Vec<_> = std::fs::read_dir(root.join("tests/lint"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    cases.sort();
    for case in cases {
        let mut files: Vec<_> = std::fs::read_dir(&case)
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| p.extension().is_some_and(|x| x == "walls"))
            .collect();
        if files.is_empty() {
            continue;
        }
        files.sort();
        for mode in ["ssdem", "hsdem"] {
            let out = Command::new(env!("CARGO_BIN_EXE_walls-lint"))
                .args(["--isolated", "--format", "sarif", "--mode", mode])
                .args(&files)
                .output()
                .unwrap();
            assert!(
                out.status.code().unwrap() <= 1,
                "{}: {out:?}",
                case.display()
            );
            let log = out_dir.path().join(format!(
                "{}-{mode}.sarif",
                case.file_name().unwrap().to_string_lossy()
            ));
            std::fs::write(&log, &out.stdout).unwrap();
            logs.push(log);
        }
    }
    // A file that cannot be read: a tool execution notification, exit status 2.
    let out = Command::new(env!("CARGO_BIN_EXE_walls-lint"))
        .args(["--format", "sarif", "absent.walls"])
        .arg(root.join("tests/lint/lint-unreadable-sarif/bad.walls"))
        .current_dir(out_dir.path())
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2), "{out:?}");
    let log = out_dir.path().join("unreadable.sarif");
    std::fs::write(&log, &out.stdout).unwrap();
    logs.push(log);
    assert!(logs.len() >= 20, "too few SARIF logs: {}", logs.len());
    let check = Command::new("python3")
        .arg(root.join("tests/tools/validate_sarif.py"))
        .arg(&schema)
        .args(&logs)
        .output()
        .expect("python3 runs");
    assert!(
        check.status.success(),
        "SARIF violates the schema:\n{}{}",
        String::from_utf8_lossy(&check.stdout),
        String::from_utf8_lossy(&check.stderr)
    );
}
