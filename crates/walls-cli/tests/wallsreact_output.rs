//! `walls-sim run --par params.par --out DIR` on pkdgrav's golden reactive-wall run
//! directory: with `iRedOutInterval` set, the WALLSREACT lines come at pkdgrav's reduced
//! outputs (the start step and every `iRedOutInterval` steps after it,
//! docs/pkdgrav-physics.md §10), labelled as pkdgrav labels them, the first one
//! pkdgrav's byte for byte; the trajectory keeps `iOutInterval`.

use std::path::Path;
use std::process::Command;

/// The golden scene's folder.
fn scene(name: &str) -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../walls-sim/tests/golden")
        .join(name)
}

/// The build of the scene's `params.par` header.
const REACT: &str = "COLLISIONS WALLS DEM DEM_FIXED_BALL DEM_ROTATION_DASHPOT DEM_TRACK_ORIENT DEM_WALLS_REACT NUMREC";

/// Runs the reactive plate with its `params.par` changed by `edit`; the run's folder.
fn run_plate(edit: impl Fn(&str) -> String) -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    for file in ["walls.dat", "particles.ss"] {
        std::fs::copy(scene("reactive_plate").join(file), dir.path().join(file)).unwrap();
    }
    let par = std::fs::read_to_string(scene("reactive_plate").join("params.par")).unwrap();
    std::fs::write(dir.path().join("params.par"), edit(&par)).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_walls-sim"))
        .current_dir(dir.path())
        .args(["run", "--par", "params.par", "--out", "out"])
        .args(["--pkdgrav-build", REACT])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    dir
}

/// The first field of each line of `file` in the run's outputs (a CSV file's header
/// skipped).
fn labels(dir: &tempfile::TempDir, file: &str) -> Vec<u64> {
    std::fs::read_to_string(dir.path().join("out").join(file))
        .unwrap()
        .lines()
        .filter(|l| !l.starts_with("step,"))
        .map(|l| l.split([' ', ',']).next().unwrap().parse().unwrap())
        .collect()
}

#[test]
fn wallsreact_lines_come_at_pkdgrav_s_reduced_outputs() {
    // iRedOutInterval = 20 (and iOutInterval = 20), as pkdgrav ran it.
    let dir = run_plate(str::to_string);
    let golden = scene("reactive_plate");
    for file in ["WALLSREACTdata.out", "WALLSREACTviz.out"] {
        let theirs = std::fs::read_to_string(golden.join(file)).unwrap();
        let ours = std::fs::read_to_string(dir.path().join("out").join(file)).unwrap();
        let label = |l: &str| l.split(' ').next().unwrap().to_string();
        assert_eq!(
            ours.lines().map(label).collect::<Vec<_>>(),
            theirs.lines().map(label).collect::<Vec<_>>(),
            "{file}"
        );
        // The start step's line, before any step: pkdgrav's exactly.
        assert_eq!(ours.lines().next(), theirs.lines().next(), "{file}");
    }

    // iRedOutInterval = 50: the lines at 0, 50, …, 1200; the trajectory still at the
    // multiples of iOutInterval = 20 (and its start).
    let dir = run_plate(|par| par.replace("iRedOutInterval          = 20", "iRedOutInterval = 50"));
    let every_50: Vec<u64> = (0..=1200).step_by(50).collect();
    assert_eq!(labels(&dir, "WALLSREACTdata.out"), every_50);
    assert_eq!(labels(&dir, "WALLSREACTviz.out"), every_50);
    let mut steps = labels(&dir, "walls.csv");
    steps.dedup();
    assert_eq!(steps, (0..=1200).step_by(20).collect::<Vec<u64>>());

    // Without it, the lines come at the output steps, as before.
    let dir = run_plate(|par| par.replace("iRedOutInterval          = 20\n", ""));
    let every_20: Vec<u64> = (20..=1200).step_by(20).collect();
    assert_eq!(labels(&dir, "WALLSREACTdata.out"), every_20);
}
