//! The peer benchmark's scenes (`scripts/bench-peers scene`, docs/performance.md "Against
//! LAMMPS and LIGGGHTS"): the generator writes the three input sets as expected (the
//! files under `tests/data/peers/<scene>/`; `UPDATE_PEERS=1` rewrites them), walls-sim
//! runs its own set, and a bad count is refused. LAMMPS and LIGGGHTS are not needed:
//! `scripts/bench-peers check` runs them where they are installed.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn bench_peers(args: &[&str]) -> Output {
    Command::new("python3")
        .arg(root().join("scripts/bench-peers"))
        .args(args)
        .output()
        .expect("python3 runs")
}

/// The generated files of `scene` against the expected ones, then walls-sim on its set.
fn scene_is_written_and_runs(scene: &str, friction: bool, summary: &str) {
    let dir = tempfile::tempdir().unwrap();
    let out_dir = dir.path().to_str().unwrap();
    let mut args = vec![
        "scene",
        out_dir,
        "--scene",
        scene,
        "--particles",
        "8",
        "--steps",
        "1000",
    ];
    if !friction {
        args.push("--no-friction");
    }
    let out = bench_peers(&args);
    assert!(out.status.success(), "{out:?}");
    assert_eq!(
        String::from_utf8_lossy(&out.stdout),
        format!(
            "walls-sim: {out_dir}/walls-sim\nlammps: {out_dir}/lammps\nliggghts: {out_dir}/liggghts\n"
        )
    );

    let expected_dir = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/peers")
        .join(scene);
    let mut files = vec![
        "walls-sim/box.walls",
        "walls-sim/particles.csv",
        "walls-sim/args",
        "lammps/data.lmp",
        "lammps/in.lmp",
        "liggghts/data.lig",
        "liggghts/in.lig",
    ];
    if scene == "oscillating" {
        files.push("liggghts/floor.stl");
    }
    let update = std::env::var_os("UPDATE_PEERS").is_some();
    for file in files {
        let written = std::fs::read_to_string(dir.path().join(file)).unwrap();
        let expected_path = expected_dir.join(file);
        if update {
            std::fs::create_dir_all(expected_path.parent().unwrap()).unwrap();
            std::fs::write(&expected_path, &written).unwrap();
        }
        let expected = std::fs::read_to_string(&expected_path).unwrap_or_default();
        assert_eq!(
            written,
            expected,
            "{scene}: {file} differs from {} (UPDATE_PEERS=1 rewrites it)",
            expected_path.display()
        );
    }

    let walls_sim = dir.path().join("walls-sim");
    let args = std::fs::read_to_string(walls_sim.join("args")).unwrap();
    let run = Command::new(env!("CARGO_BIN_EXE_walls-sim"))
        .args(args.split_whitespace())
        .current_dir(&walls_sim)
        .output()
        .unwrap();
    assert_eq!(run.status.code(), Some(0), "{run:?}");
    assert_eq!(String::from_utf8_lossy(&run.stderr), summary);
}

/// Each scene, with or without friction, and the summary walls-sim prints after running
/// it (the oscillating floor gives the particles energy).
const SCENES: [(&str, bool, &str); 2] = [
    (
        "drop",
        false,
        "walls-sim: t = 0.005 after 1000 steps of 5e-6: 8 particles (8 alive), 8 wall events, \
         2 particle contacts, energy 1.886170e-6 → 1.811994e-6\n",
    ),
    (
        "oscillating",
        true,
        "walls-sim: t = 0.005 after 1000 steps of 5e-6: 8 particles (8 alive), 12 wall events, \
         10 particle contacts, energy 1.886170e-6 → 2.667511e-6\n",
    ),
];

#[test]
fn each_scene_is_written_for_the_three_tools_and_walls_sim_runs_it() {
    for (scene, friction, summary) in SCENES {
        scene_is_written_and_runs(scene, friction, summary);
    }
}

#[test]
fn a_particle_count_below_one_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let out = bench_peers(&["scene", dir.path().to_str().unwrap(), "--particles", "0"]);
    assert_eq!(out.status.code(), Some(2), "{out:?}");
    assert_eq!(
        String::from_utf8_lossy(&out.stderr),
        "bench-peers: the particle count must be at least 1, not 0\n"
    );
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 0);
}
