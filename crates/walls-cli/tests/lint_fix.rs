//! `walls-lint --fix` writes files as walls-fmt does (the end-to-end cases under
//! `tests/lint/fix-*` show the rest): a file it may not replace is left as it was and
//! reported, with status 2 and advice worded for walls-lint; a file it fixes keeps its
//! mode.

use std::os::unix::fs::PermissionsExt;
use std::path::{Path, PathBuf};
use std::process::Command;

const GLUED: &str = "wall type plane\n  origin 0 0 0.5#raised\n";
const FIXED: &str = "wall type plane\n  origin 0 0 0.5 #raised\n";

/// A folder holding `scene.walls` with the glued comment, given `mode`.
fn scene_with_mode(mode: u32) -> (tempfile::TempDir, PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("scene.walls");
    std::fs::write(&path, GLUED).unwrap();
    std::fs::set_permissions(&path, std::fs::Permissions::from_mode(mode)).unwrap();
    (dir, path)
}

fn fix(dir: &Path) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_walls-lint"))
        .args(["--color", "never", "--fix", "scene.walls"])
        .current_dir(dir)
        .output()
        .unwrap()
}

#[test]
fn a_read_only_file_is_not_written_and_its_findings_are_reported() {
    let (dir, path) = scene_with_mode(0o444);
    let out = fix(dir.path());
    let stderr = String::from_utf8_lossy(&out.stderr);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert_eq!(
        stderr,
        "walls-lint: error: not writing scene.walls: it is read-only (mode 0444); make it \
         writable first (chmod u+w)\n"
    );
    assert!(
        stdout.starts_with("[S004] Error: comment glued to `0.5`\n"),
        "{stdout}"
    );
    assert!(
        stdout.ends_with("1 error, 0 warnings in 1 file; 0 fixed\n"),
        "{stdout}"
    );
    assert_eq!(std::fs::read_to_string(&path).unwrap(), GLUED);
}

#[test]
fn a_fixed_file_keeps_its_mode() {
    let (dir, path) = scene_with_mode(0o640);
    let out = fix(dir.path());
    assert_eq!(out.status.code(), Some(0));
    assert_eq!(
        String::from_utf8_lossy(&out.stdout),
        "0 errors, 0 warnings in 1 file; 1 fixed\n"
    );
    assert_eq!(String::from_utf8_lossy(&out.stderr), "");
    assert_eq!(std::fs::read_to_string(&path).unwrap(), FIXED);
    let mode = std::fs::metadata(&path).unwrap().permissions().mode();
    assert_eq!(mode & 0o7777, 0o640);
}

#[test]
fn a_refusal_says_what_to_do_with_walls_lint() {
    let (dir, path) = scene_with_mode(0o644);
    std::fs::hard_link(&path, dir.path().join("other-name.walls")).unwrap();
    let out = fix(dir.path());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(
        stderr.starts_with(
            "walls-lint: error: not writing scene.walls: it has 2 hard links, which a rewrite \
             would part; fix a copy (walls-lint --fix - < FILE > COPY) and copy it back over \
             the file\n"
        ),
        "{stderr}"
    );
    assert_eq!(std::fs::read_to_string(&path).unwrap(), GLUED);
}
