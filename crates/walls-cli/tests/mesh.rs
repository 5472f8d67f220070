//! What `walls-mesh` writes is what the other tools accept: `walls-fmt --check` finds it
//! formatted and `walls-lint` finds nothing to say, for every mesh of `tests/mesh/` that
//! becomes walls, in every orientation, with rectangles merged or not.

use std::path::Path;
use std::process::Command;

#[test]
fn walls_from_meshes_are_formatted_and_lint_clean() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/mesh");
    let meshes = [
        "stl-binary-outward/slab.stl",
        "stl-ascii-inward/slab.stl",
        "obj-quads/box.obj",
    ];
    let work = tempfile::tempdir().unwrap();
    let mut made = 0;
    for mesh in meshes {
        for orientation in ["keep", "outward", "inward"] {
            for merge in [false, true] {
                let out = work.path().join(format!("{made}.walls"));
                made += 1;
                let mut mesh_cmd = Command::new(env!("CARGO_BIN_EXE_walls-mesh"));
                mesh_cmd
                    .arg(root.join(mesh))
                    .args(["--unit", "cm", "--orientation", orientation, "-o"])
                    .arg(&out);
                if merge {
                    mesh_cmd.arg("--merge-rectangles");
                }
                let status = mesh_cmd.status().unwrap();
                assert!(status.success(), "{mesh} {orientation} {merge}: {status}");
                for (tool, args) in [
                    (env!("CARGO_BIN_EXE_walls-fmt"), &["--check"][..]),
                    (env!("CARGO_BIN_EXE_walls-lint"), &["--deny-warnings"][..]),
                ] {
                    let run = Command::new(tool).args(args).arg(&out).output().unwrap();
                    assert!(
                        run.status.success(),
                        "{tool} on {mesh} {orientation} {merge}: {}",
                        String::from_utf8_lossy(&run.stderr)
                    );
                }
            }
        }
    }
}
