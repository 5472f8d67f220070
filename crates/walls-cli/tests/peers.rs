//! The peer benchmark's scenes (`scripts/bench-peers scene`, docs/performance.md "Against
//! LAMMPS and LIGGGHTS"): the generator writes each scene's input sets as expected (the
//! files under `tests/data/peers/<scene>/`; `UPDATE_PEERS=1` rewrites them; the `1e6`
//! scene is the drop's files under its own name; the cup is written with about the
//! triangles asked for), walls-sim runs its own set, and a bad count is refused; `run` on
//! one core and two starts each
//! tool as it should (stand-ins record how LAMMPS, LIGGGHTS and the MPI launcher were
//! started), a sweep of the cup's triangles gives each count rows of their own, and
//! `count` takes a run of one step from a run of the scene (a stand-in for
//! valgrind makes up the counts). LAMMPS and LIGGGHTS are not needed:
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

/// `scripts/bench-peers scene` of 8 particles and 1,000 steps into `dir`.
fn write_scene(dir: &Path, scene: &str, friction: bool) -> Output {
    let out_dir = dir.to_str().unwrap();
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
    bench_peers(&args)
}

/// The files a scene is written as: the cup has triangles for walls-sim and LIGGGHTS,
/// and no LAMMPS set.
fn files(scene: &str) -> Vec<&'static str> {
    let mut files = vec!["walls-sim/particles.csv", "walls-sim/args"];
    match scene {
        "cup" => files.extend(["walls-sim/cup.walls", "liggghts/cup.stl"]),
        "oscillating" => files.extend(["walls-sim/box.walls", "liggghts/floor.stl"]),
        _ => files.push("walls-sim/box.walls"),
    }
    if scene != "cup" {
        files.extend(["lammps/data.lmp", "lammps/in.lmp"]);
    }
    files.extend(["liggghts/data.lig", "liggghts/in.lig"]);
    files
}

/// The generated files of `scene` against the expected ones, then walls-sim on its set.
fn scene_is_written_and_runs(scene: &str, friction: bool, summary: &str) {
    let dir = tempfile::tempdir().unwrap();
    let out_dir = dir.path().to_str().unwrap();
    let out = write_scene(dir.path(), scene, friction);
    assert!(out.status.success(), "{out:?}");
    let lammps = if scene == "cup" {
        String::new()
    } else {
        format!("lammps: {out_dir}/lammps\n")
    };
    assert_eq!(
        String::from_utf8_lossy(&out.stdout),
        format!("walls-sim: {out_dir}/walls-sim\n{lammps}liggghts: {out_dir}/liggghts\n")
    );

    let expected_dir = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/peers")
        .join(scene);
    let update = std::env::var_os("UPDATE_PEERS").is_some();
    for file in files(scene) {
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
/// it, after `RAN` (the oscillating floor gives the particles energy; the cup's 8 spheres
/// settle on its fan of triangles; the poly box's start ten times as fast, and one hits a
/// wall hard enough for pkdgrav's 3 % overlap warning).
const SCENES: [(&str, bool, &str); 4] = [
    (
        "drop",
        false,
        "8 wall events, 2 particle contacts, energy 1.886170e-6 → 1.811994e-6\n",
    ),
    (
        "oscillating",
        true,
        "12 wall events, 10 particle contacts, energy 1.886170e-6 → 2.667511e-6\n",
    ),
    (
        "cup",
        true,
        "7 wall events, 0 particle contacts, energy 9.918228e-7 → 9.023837e-7\n",
    ),
    (
        "poly",
        true,
        "2 wall events, 1 particle contacts, energy 1.498122e-5 → 9.441751e-6; \
         overlaps past pkdgrav's levels (minor/major/error): pairs 19/0/0, walls 57/0/0\n\
         walls-sim: warning: overlap of 3.1% of the particle's radius (particle 7, wall 4, \
         t = 0.00186): above dMinorFrac = 0.03 of the particle's radius; pkdgrav prints such an \
         overlap only when its count of them (pairs and walls apart, every level) is 1 or a \
         multiple of 1,000,000: the run warns of the first and counts them all\n",
    ),
];

/// The start of walls-sim's summary of every scene's run.
const RAN: &str = "walls-sim: t = 0.005 after 1000 steps of 5e-6: 8 particles (8 alive), ";

#[test]
fn each_scene_is_written_for_its_tools_and_walls_sim_runs_it() {
    for (scene, friction, summary) in SCENES {
        scene_is_written_and_runs(scene, friction, &format!("{RAN}{summary}"));
    }
}

#[test]
fn the_1e6_scene_is_the_drop_under_its_own_name() {
    let (drop, million) = (tempfile::tempdir().unwrap(), tempfile::tempdir().unwrap());
    for (dir, scene) in [(&drop, "drop"), (&million, "1e6")] {
        let out = write_scene(dir.path(), scene, true);
        assert!(out.status.success(), "{out:?}");
    }
    for file in files("drop") {
        let read =
            |dir: &tempfile::TempDir| std::fs::read_to_string(dir.path().join(file)).unwrap();
        let named = read(&million).replace("scene 1e6 ", "scene drop ");
        assert_eq!(named, read(&drop), "{file}");
    }
}

/// `scripts/bench-peers scene DIR --scene cup` with `more` arguments.
fn write_cup(dir: &Path, more: &[&str]) -> Output {
    let front = ["scene", dir.to_str().unwrap(), "--scene", "cup"];
    bench_peers(&[&front[..], more].concat())
}

#[test]
fn a_cup_of_more_spheres_than_its_lattice_holds_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let out = write_cup(dir.path(), &["--particles", "10641"]);
    assert_eq!(out.status.code(), Some(2), "{out:?}");
    assert_eq!(
        String::from_utf8_lossy(&out.stderr),
        "bench-peers: the cup holds at most 10640 particles, not 10641\n"
    );
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 0);
}

/// Asserts that bench-peers refused `case` with exit 2 and an error that says `says`,
/// not a traceback.
fn assert_refused(out: &Output, says: &str, case: &str) {
    assert_eq!(out.status.code(), Some(2), "{case}: {out:?}");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains(says) && !stderr.contains("Traceback"),
        "{case}: {stderr}"
    );
}

#[test]
fn a_particle_count_below_one_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let out = bench_peers(&["scene", dir.path().to_str().unwrap(), "--particles", "0"]);
    assert_refused(&out, "error: argument --particles: not a count: '0'\n", "0");
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 0);
}

#[test]
fn a_core_or_particle_count_that_is_not_a_whole_number_is_refused() {
    for (flag, word) in [
        ("--threads", "inf"),
        ("--threads", "1,x"),
        ("--threads", "1.5"),
        ("--particles", "1e400"),
    ] {
        let out = bench_peers(&["--walls-sim", "/bin/true", "run", flag, word]);
        let bad = word.rsplit(',').next().unwrap();
        let says = format!("error: argument {flag}: not a count: '{bad}'\n");
        assert_refused(&out, &says, &format!("{flag} {word}"));
    }
}

/// A stand-in for a peer or the MPI launcher: appends its name, arguments and the
/// variables the benchmark sets to `calls`, then exits 0.
fn stand_in(dir: &Path, name: &str, calls: &Path) -> PathBuf {
    let script = format!(
        "#!/bin/sh\necho \"{name} $* OMP=$OMP_NUM_THREADS ROOT=$OMPI_ALLOW_RUN_AS_ROOT\" >> {}\n",
        calls.display()
    );
    executable(dir, name, &script)
}

/// `script` written to `dir`/`name`, executable.
fn executable(dir: &Path, name: &str, script: &str) -> PathBuf {
    use std::os::unix::fs::PermissionsExt;
    let path = dir.join(name);
    std::fs::write(&path, script).unwrap();
    std::fs::set_permissions(&path, std::fs::Permissions::from_mode(0o755)).unwrap();
    path
}

#[test]
fn a_run_on_one_core_and_two_starts_walls_sim_on_threads_and_the_peers_on_mpi_ranks() {
    let dir = tempfile::tempdir().unwrap();
    let calls = dir.path().join("calls");
    let lammps = stand_in(dir.path(), "lmp", &calls);
    let liggghts = stand_in(dir.path(), "liggghts", &calls);
    let mpirun = stand_in(dir.path(), "mpirun", &calls);
    let out = bench_peers(&[
        "--walls-sim",
        env!("CARGO_BIN_EXE_walls-sim"),
        "--lammps",
        lammps.to_str().unwrap(),
        "--liggghts",
        liggghts.to_str().unwrap(),
        "run",
        "--particles",
        "8",
        "--scenes",
        "drop",
        "--steps",
        "10",
        "--rounds",
        "2",
        "--threads",
        "1,2",
        "--mpirun",
        mpirun.to_str().unwrap(),
        "--csv",
        "",
    ]);
    assert!(out.status.success(), "{out:?}");
    // Round by round, each core count in turn, each tool in turn.
    let (lmp, lig) = (lammps.display(), liggghts.display());
    let once = format!(
        "lmp -in in.lmp -log none OMP=1 ROOT=\n\
         liggghts -in in.lig -log none OMP=1 ROOT=\n\
         mpirun -np 2 {lmp} -in in.lmp -log none OMP=1 ROOT=1\n\
         mpirun -np 2 {lig} -in in.lig -log none OMP=1 ROOT=1\n"
    );
    assert_eq!(std::fs::read_to_string(&calls).unwrap(), once.repeat(2));
    let stdout = String::from_utf8_lossy(&out.stdout);
    let tools: Vec<&str> = stdout
        .lines()
        .filter(|l| l.starts_with("drop "))
        .map(|l| l.split_whitespace().nth(6).unwrap())
        .collect();
    let round = [
        "walls-sim",
        "lammps",
        "liggghts",
        "walls-sim-2threads",
        "lammps-2ranks",
        "liggghts-2ranks",
    ];
    assert_eq!(tools, [round, round].concat());
    // The ratios against walls-sim on as many cores, and each tool's one core against
    // two.
    for tool in ["lammps", "liggghts", "lammps-2ranks", "liggghts-2ranks"] {
        let row = format!("| drop | 8 | 10 | {tool} |");
        let line = stdout.lines().find(|l| l.starts_with(&row)).unwrap();
        assert!(!line.ends_with("| |"), "no ratio: {line}");
    }
    for tool in ["walls-sim", "lammps", "liggghts"] {
        let row = format!("| drop | 8 | {tool} | 2 | ");
        assert!(
            stdout.lines().any(|l| l.starts_with(&row)),
            "{tool}: {stdout}"
        );
    }
}

#[test]
fn the_cup_is_written_with_about_the_triangles_asked_for() {
    let dir = tempfile::tempdir().unwrap();
    let out = write_cup(dir.path(), &["--particles", "8", "--triangles", "1000"]);
    assert!(out.status.success(), "{out:?}");
    let walls = std::fs::read_to_string(dir.path().join("walls-sim/cup.walls")).unwrap();
    assert!(walls.starts_with(
        "# The peer benchmark's cup (scripts/peers/scene.py): an open cylinder of 999\n\
         # triangles, its side 111 segments x 4 rings of two, its bottom a fan of 111.\n"
    ));
    assert_eq!(walls.matches("type triangle").count(), 999);
    let stl = std::fs::read_to_string(dir.path().join("liggghts/cup.stl")).unwrap();
    assert_eq!(stl.matches("facet normal").count(), 999);
}

#[test]
fn a_cup_of_too_few_or_too_many_triangles_is_refused_before_anything_is_written() {
    for (triangles, says) in [
        ("3", "the cup needs at least 9 triangles, not 3"),
        (
            "1000000000",
            "the cup takes at most 1,000,000 triangles (about 520 bytes of walls file and STL each), not 1,000,000,000",
        ),
        ("0", "argument --triangles: not a count: '0'"),
        ("-1", "argument --triangles: not a count: '-1'"),
        ("1e308", "argument --triangles: not a count: '1e308'"),
        ("nan", "argument --triangles: not a count: 'nan'"),
    ] {
        let dir = tempfile::tempdir().unwrap();
        let out = write_cup(dir.path(), &["--particles", "8", "--triangles", triangles]);
        assert_refused(&out, says, triangles);
        assert_eq!(
            std::fs::read_dir(dir.path()).unwrap().count(),
            0,
            "{triangles}"
        );
    }
}

#[test]
fn a_sweep_of_the_cups_triangles_writes_rows_of_their_own() {
    let dir = tempfile::tempdir().unwrap();
    let calls = dir.path().join("calls");
    // LIGGGHTS's stand-in records the facets of the mesh it was given.
    let script = format!(
        "#!/bin/sh\necho \"liggghts $* facets=$(grep -c 'facet normal' cup.stl)\" >> {}\n",
        calls.display()
    );
    let liggghts = executable(dir.path(), "liggghts", &script);
    let sweep = dir.path().join("sweep.csv");
    let out = bench_peers(&[
        "--walls-sim",
        env!("CARGO_BIN_EXE_walls-sim"),
        "--liggghts",
        liggghts.to_str().unwrap(),
        "run",
        "--scenes",
        "cup",
        "--particles",
        "8",
        "--steps",
        "10",
        "--rounds",
        "1",
        "--triangles",
        "100,1000",
        "--csv",
        sweep.to_str().unwrap(),
    ]);
    assert!(out.status.success(), "{out:?}");
    assert_eq!(
        std::fs::read_to_string(&calls).unwrap(),
        "liggghts -in in.lig -log none facets=99\n\
         liggghts -in in.lig -log none facets=999\n"
    );
    let rows: Vec<String> = (std::fs::read_to_string(&sweep).unwrap().lines())
        .map(|l| l.split(',').take(4).collect::<Vec<_>>().join(","))
        .collect();
    assert_eq!(
        rows,
        [
            "tool,scene,particles,steps",
            "liggghts,cup-99,8,10",
            "walls-sim,cup-99,8,10",
            "liggghts,cup-999,8,10",
            "walls-sim,cup-999,8,10",
        ]
    );

    let out = bench_peers(&["--walls-sim", "/bin/true", "run", "--triangles", "100"]);
    assert_eq!(out.status.code(), Some(2), "{out:?}");
    assert!(
        String::from_utf8_lossy(&out.stderr)
            .ends_with("error: --triangles: only the cup's (--scenes cup)\n"),
        "{out:?}"
    );
}

/// A stand-in for valgrind: appends to `calls` the tool it was asked to count, with its
/// steps (walls-sim's `--t-end` over the time step, the peers' `run N`) and the variable
/// that sets its cores, then prints callgrind's count line, made up as a set-up and a
/// cost a step: walls-sim 5·10⁶ + 3,200 a step, LAMMPS 9·10⁶ + 6,400, LIGGGHTS
/// 7·10⁶ + 8,000 (400, 800 and 1,000 a particle-step for 8 particles).
fn valgrind_stand_in(dir: &Path, calls: &Path) -> PathBuf {
    let script = format!(
        r#"#!/bin/sh
[ "$1 $2" = "--tool=callgrind --callgrind-out-file=/dev/null" ] || exit 9
program=$(basename "$3")
case "$program" in
  walls-sim)
    prev=; for a in "$@"; do [ "$prev" = --t-end ] && t=$a; prev=$a; done
    steps=$(awk "BEGIN {{ printf \"%d\", $t / 5e-6 + 0.5 }}")
    cores="RAYON=$RAYON_NUM_THREADS"; base=5000000; step=3200 ;;
  lmp) steps=$(sed -n 's/^run //p' in.lmp); cores="OMP=$OMP_NUM_THREADS"; base=9000000; step=6400 ;;
  liggghts) steps=$(sed -n 's/^run //p' in.lig); cores="OMP=$OMP_NUM_THREADS"; base=7000000; step=8000 ;;
esac
echo "$program $steps steps $cores" >> {}
echo "==1== Collected : $((base + step * steps))" >&2
"#,
        calls.display()
    );
    executable(dir, "valgrind", &script)
}

/// `scripts/bench-peers FRONT… count --particles 8 --scenes drop --steps STEPS BACK…`.
fn count_drop_of_8(front: &[&str], steps: &str, back: &[&str]) -> Output {
    let middle = [
        "count",
        "--particles",
        "8",
        "--scenes",
        "drop",
        "--steps",
        steps,
    ];
    bench_peers(&[front, &middle, back].concat())
}

#[test]
fn count_takes_a_run_of_one_step_from_a_run_of_the_scene_and_prints_the_ratios() {
    let dir = tempfile::tempdir().unwrap();
    let calls = dir.path().join("calls");
    let valgrind = valgrind_stand_in(dir.path(), &calls);
    let walls_sim = env!("CARGO_BIN_EXE_walls-sim");
    let front = [
        "--walls-sim",
        walls_sim,
        "--lammps",
        "lmp",
        "--liggghts",
        "liggghts",
    ];
    let out = count_drop_of_8(&front, "10", &["--valgrind", valgrind.to_str().unwrap()]);
    assert!(out.status.success(), "{out:?}");
    // Each tool on one core, its run of one step, then of the scene's ten.
    assert_eq!(
        std::fs::read_to_string(&calls).unwrap(),
        "walls-sim 1 steps RAYON=1\nwalls-sim 10 steps RAYON=1\n\
         lmp 1 steps OMP=1\nlmp 10 steps OMP=1\n\
         liggghts 1 steps OMP=1\nliggghts 10 steps OMP=1\n"
    );
    let stdout = String::from_utf8_lossy(&out.stdout);
    let table: Vec<&str> = stdout.lines().filter(|l| l.starts_with('|')).collect();
    assert_eq!(
        table,
        [
            "| scene | particles | steps | tool | instructions a particle-step | set-up (10⁶) | walls-sim / tool |",
            "|---|---|---|---|---|---|---|",
            "| drop | 8 | 10 | walls-sim | 400.0 | 5.0 |  |",
            "| drop | 8 | 10 | lammps | 800.0 | 9.0 | 0.50 |",
            "| drop | 8 | 10 | liggghts | 1000.0 | 7.0 | 0.40 |",
        ]
    );
}

#[test]
fn count_refuses_a_single_step() {
    let out = count_drop_of_8(&["--walls-sim", "/bin/true"], "1", &[]);
    assert_eq!(out.status.code(), Some(2), "{out:?}");
    assert_eq!(
        String::from_utf8_lossy(&out.stderr),
        "bench-peers: count needs at least 2 steps, not 1\n"
    );
}

#[test]
fn bad_arguments_are_refused_with_exit_2_before_anything_is_run_or_written() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("a-file");
    std::fs::write(&file, "").unwrap();
    let d = dir.path().to_str().unwrap();
    let f = file.to_str().unwrap();
    let cases: [(&[&str], &str); 7] = [
        (
            &["scene", d, "--scene", "drop", "--steps", "0"],
            "argument --steps: not a count: '0'",
        ),
        (
            &["scene", f, "--scene", "drop", "--particles", "8"],
            &format!("error: {f} is not a folder\n"),
        ),
        (
            &["scene", d, "--scene", "drop", "--particles", "100000000"],
            "at most 10,000,000 particles",
        ),
        // A CSV that could not be rewritten is found before the runs it would lose.
        (
            &[
                "--walls-sim",
                "/nonexistent/walls-sim",
                "run",
                "--scenes",
                "drop",
                "--particles",
                "8",
                "--tools",
                "walls-sim",
                "--csv",
                d,
            ],
            "Is a directory",
        ),
        // Nor one whose folder takes no file (/proc, even as root).
        (
            &[
                "--walls-sim",
                "/nonexistent/walls-sim",
                "run",
                "--scenes",
                "drop",
                "--particles",
                "8",
                "--tools",
                "walls-sim",
                "--csv",
                "/proc/peers.csv",
            ],
            "bench-peers: --csv: cannot write in /proc: ",
        ),
        // The same cup twice would time it twice and write its rows twice.
        (
            &[
                "--walls-sim",
                "/nonexistent/walls-sim",
                "run",
                "--scenes",
                "cup",
                "--triangles",
                "1000,1001",
                "--csv",
                "",
            ],
            "error: --triangles: two counts make the same cup (1000 → 999, 1001 → 999)\n",
        ),
        // LAMMPS alone on the cup would run nothing and report success.
        (
            &[
                "--walls-sim",
                "/nonexistent/walls-sim",
                "run",
                "--scenes",
                "cup",
                "--tools",
                "lammps",
                "--csv",
                "",
            ],
            "error: --tools: none of lammps runs the cup scene\n",
        ),
    ];
    for (args, says) in cases {
        assert_refused(&bench_peers(args), says, &format!("{args:?}"));
    }
    assert_eq!(
        std::fs::read_dir(dir.path()).unwrap().count(),
        1,
        "only the file"
    );
}
