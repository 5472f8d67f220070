//! End-to-end tests as data: each folder under the repository's `tests/lint/` holds a
//! `cmd` file (the command line, words separated by spaces), the files it names, an
//! optional `stdin`, and the snapshot `output.snap` of exit status, stdout and stderr.
//! The real binary (`walls-lint` or `walls-sim`) runs in that folder. Update the snapshots with
//! `INSTA_UPDATE=always cargo test -p walls-cli --test e2e`.

use std::io::Write;
use std::path::Path;
use std::process::{Command, Stdio};

#[test]
fn lint_cases() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/lint");
    let mut cases: Vec<_> = std::fs::read_dir(&root)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.join("cmd").exists())
        .collect();
    cases.sort();
    assert!(
        cases.len() >= 10,
        "expected the lint cases under {}",
        root.display()
    );
    for case in cases {
        let cmd = std::fs::read_to_string(case.join("cmd")).unwrap();
        let mut words = cmd.split_whitespace();
        let bin = match words.next() {
            Some("walls-lint") => env!("CARGO_BIN_EXE_walls-lint"),
            Some("walls-sim") => env!("CARGO_BIN_EXE_walls-sim"),
            other => panic!("{}: unknown command {other:?}", case.display()),
        };
        let mut child = Command::new(bin)
            .args(words)
            .current_dir(&case)
            .env_remove("NO_COLOR")
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        let stdin = std::fs::read(case.join("stdin")).unwrap_or_default();
        child.stdin.take().unwrap().write_all(&stdin).unwrap();
        let out = child.wait_with_output().unwrap();
        let shown = format!(
            "$ {}exit: {}\n--- stdout ---\n{}--- stderr ---\n{}",
            cmd,
            out.status.code().unwrap(),
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        );
        insta::with_settings!({
            snapshot_path => &case,
            prepend_module_to_snapshot => false,
            omit_expression => true,
        }, {
            insta::assert_snapshot!("output", shown);
        });
    }
}
