//! The adversarial cases as data (`tests/adversarial/README.md`): each folder of the
//! repository's `tests/adversarial/` with a `run` file is one attack, a bash script run in
//! a copy of its folder with the tools first on `PATH`, whose output (standard output and
//! error, then its exit status) is compared with the folder's `output.snap`. Update the
//! snapshots with `INSTA_UPDATE=always cargo test -p walls-cli --test adversarial`.

use std::path::{Path, PathBuf};
use std::process::Command;

/// The folder of the tools: walls-cli's four binaries, and `walls-lsp`, which a
/// workspace build puts beside them.
fn tools() -> PathBuf {
    let dir = Path::new(env!("CARGO_BIN_EXE_walls-lint"))
        .parent()
        .unwrap()
        .to_path_buf();
    assert!(
        dir.join("walls-lsp").exists(),
        "the adversarial cases run walls-lsp too: build it first (cargo build -p walls-lsp, \
         or cargo test --workspace)"
    );
    dir
}

/// Copies the folder `from` into `to`, recursively.
fn copy_dir(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).unwrap();
    for entry in std::fs::read_dir(from).unwrap() {
        let path = entry.unwrap().path();
        let name = path.file_name().unwrap();
        if name == "output.snap" {
            continue;
        }
        if path.is_dir() {
            copy_dir(&path, &to.join(name));
        } else {
            std::fs::copy(&path, to.join(name)).unwrap();
        }
    }
}

#[test]
fn adversarial_cases() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/adversarial");
    let root = root.canonicalize().unwrap();
    let mut cases: Vec<_> = std::fs::read_dir(&root)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.join("run").exists())
        .collect();
    cases.sort();
    assert!(!cases.is_empty(), "no cases under {}", root.display());
    let tools = tools();
    let path = format!(
        "{}:{}",
        tools.display(),
        std::env::var("PATH").unwrap_or_default()
    );
    let mut failed = Vec::new();
    for case in cases {
        let work = tempfile::tempdir().unwrap();
        let dir = work.path().join("case");
        copy_dir(&case, &dir);
        // Standard error joins standard output, so that the snapshot keeps their order.
        let out = Command::new("bash")
            .args(["-c", "exec bash run 2>&1"])
            .current_dir(&dir)
            .env("PATH", &path)
            .env("ADV_LIB", root.join("lib.sh"))
            .env("NO_COLOR", "1")
            .env("LC_ALL", "C")
            .env_remove("CLICOLOR_FORCE")
            .output()
            .unwrap();
        let shown = format!(
            "{}{}exit: {}\n",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr),
            out.status.code().map_or("signal".into(), |c| c.to_string())
        );
        // The temporary folder's path, and the file-size limit's error (where the
        // machine gives no small filesystem) as a full disk's.
        let shown = shown.replace(&dir.display().to_string(), "$WORK").replace(
            "File too large (os error 27)",
            "No space left on device (os error 28)",
        );
        let result = std::panic::catch_unwind(|| {
            insta::with_settings!({
                snapshot_path => &case,
                prepend_module_to_snapshot => false,
                omit_expression => true,
            }, {
                insta::assert_snapshot!("output", shown);
            });
        });
        if result.is_err() {
            failed.push(case.file_name().unwrap().to_string_lossy().into_owned());
        }
    }
    assert!(
        failed.is_empty(),
        "adversarial cases that failed: {failed:?}"
    );
}
