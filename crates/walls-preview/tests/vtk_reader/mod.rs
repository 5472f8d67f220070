//! Reading written files back with VTK's own reader, the independent check of the VTK
//! and ParaView tests: a Python script run on the file with `python3` and the `vtk`
//! wheel (`scripts/install-test-tools` installs it), printing what it read as JSON.

use serde_json::Value;
use std::path::Path;
use std::process::Command;

/// What `script` prints as JSON when run on `path`; fails the test, saying why, when
/// python3 or VTK is missing or the reader reports an error.
pub fn read_back(script: &str, path: &Path) -> Value {
    let out = Command::new("python3")
        .args(["-c", script])
        .arg(path)
        .output()
        .expect("python3 runs");
    assert!(
        out.status.success(),
        "reading {} back with VTK failed (python3 with the `vtk` package is needed: run \
         scripts/install-test-tools):\n{}",
        path.display(),
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).expect("the reader prints JSON")
}
