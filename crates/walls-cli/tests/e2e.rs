//! End-to-end tests as data: each folder under the repository's `tests/lint/`,
//! `tests/fmt/`, `tests/sim/` and `tests/mesh/` holds a `cmd` file (the command line, words separated by
//! spaces), the files it names, an optional `stdin`, and the snapshot `output.snap` of
//! exit status, stdout, stderr and every file the command changed or made. The real binary
//! (`walls-lint`, `walls-fmt`, `walls-sim` or `walls-mesh`) runs in a copy of that folder. Update the
//! snapshots with `INSTA_UPDATE=always cargo test -p walls-cli --test e2e`.

use std::path::Path;
use std::process::{Command, Stdio};

#[test]
fn lint_cases() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests");
    let mut cases: Vec<_> = ["lint", "fmt", "sim", "mesh"]
        .iter()
        .flat_map(|group| std::fs::read_dir(root.join(group)).unwrap())
        .map(|e| e.unwrap().path())
        .filter(|p| p.join("cmd").exists())
        .collect();
    cases.sort();
    assert!(
        cases.len() >= 30,
        "expected the cases under {}",
        root.display()
    );
    for case in cases {
        let cmd = std::fs::read_to_string(case.join("cmd")).unwrap();
        let mut words = cmd.split_whitespace();
        let bin = match words.next() {
            Some("walls-lint") => env!("CARGO_BIN_EXE_walls-lint"),
            Some("walls-fmt") => env!("CARGO_BIN_EXE_walls-fmt"),
            Some("walls-sim") => env!("CARGO_BIN_EXE_walls-sim"),
            Some("walls-mesh") => env!("CARGO_BIN_EXE_walls-mesh"),
            other => panic!("{}: unknown command {other:?}", case.display()),
        };
        // Run in a copy, so that commands that write files leave the case as it is.
        let work = tempfile::tempdir().unwrap();
        let mut originals = Vec::new();
        for entry in std::fs::read_dir(&case).unwrap() {
            let from = entry.unwrap().path();
            let name = from.file_name().unwrap().to_owned();
            if name == "output.snap" || name == "cmd" {
                continue;
            }
            std::fs::copy(&from, work.path().join(&name)).unwrap();
            originals.push((name, std::fs::read(&from).unwrap()));
        }
        originals.sort();
        let mut child = Command::new(bin)
            .args(words)
            .current_dir(work.path())
            .env_remove("NO_COLOR")
            .env_remove("CLICOLOR_FORCE")
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        let stdin = std::fs::read(case.join("stdin")).unwrap_or_default();
        // (`lint/fix-stdin-json` ends with a usage error before it reads its input.)
        walls_test_support::cli::feed(&mut child, &stdin);
        let out = child.wait_with_output().unwrap();
        let mut shown = format!(
            "$ {}exit: {}\n--- stdout ---\n{}--- stderr ---\n{}",
            cmd,
            out.status.code().unwrap(),
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        );
        for (name, before) in &originals {
            let now = std::fs::read(work.path().join(name)).unwrap();
            if &now != before {
                shown.push_str(&format!(
                    "--- {} now ---\n{}",
                    name.to_string_lossy(),
                    String::from_utf8_lossy(&now)
                ));
            }
        }
        // Files the command made, such as a trajectory, in path order.
        let mut made = Vec::new();
        files_under(work.path(), &mut made);
        made.sort();
        for path in made {
            let name = path.strip_prefix(work.path()).unwrap();
            if originals.iter().any(|(o, _)| Path::new(o) == name) {
                continue;
            }
            shown.push_str(&format!(
                "--- {} made ---\n{}",
                name.display(),
                String::from_utf8_lossy(&std::fs::read(&path).unwrap())
            ));
        }
        insta::with_settings!({
            snapshot_path => &case,
            prepend_module_to_snapshot => false,
            omit_expression => true,
        }, {
            insta::assert_snapshot!("output", shown);
        });
    }
}

/// Every file under `dir`, recursively.
fn files_under(dir: &Path, out: &mut Vec<std::path::PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            files_under(&path, out);
        } else {
            out.push(path);
        }
    }
}
