//! `walls-sim export`: the run directory it writes passes walls-lint with no finding, and
//! `walls-sim run --par DIR/ss.par` reproduces the direct run's outputs to 1e-12; what
//! pkdgrav cannot be told is refused with nothing written, and every file is planned
//! (refused if it must be) before any is written.

use std::path::Path;
use std::process::{Command, Output};

/// The golden scene's folder.
fn golden(name: &str) -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../walls-sim/tests/golden")
        .join(name)
}

fn sim(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_walls-sim"))
        .current_dir(dir)
        .args(args)
        .output()
        .unwrap()
}

fn stderr(out: &Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

/// Asserts that the command succeeded and said `text` on standard error.
fn succeeded_saying(out: &Output, text: &str) {
    assert!(out.status.success(), "{}", stderr(out));
    assert!(stderr(out).contains(text), "{}", stderr(out));
}

/// A cup: a floor and a cylinder around eight spheres that fall, meet each other and
/// the walls, with friction.
const CUP: &str = "wall type plane\n\nwall type cylinder-infinite\n  radius 0.03\n";

fn cup_particles() -> String {
    let mut csv = String::from("mass,radius,x,y,z,vx,vy,vz,wx,wy,wz,color\n");
    for k in 0..8 {
        // Two layers of four, the upper one shifted so that it lands on the lower.
        let (i, j, layer) = ((k % 2) as f64, ((k / 2) % 2) as f64, (k / 4) as f64);
        let x = 0.0105 * (i - 0.5) + 0.003 * layer;
        let y = 0.0105 * (j - 0.5) + 0.002 * layer;
        let z = 0.0052 + 0.012 * layer;
        csv.push_str(&format!(
            "5e-4,0.005,{x},{y},{z},0.01,-0.02,0,0,0,{},{}\n",
            0.5 * k as f64,
            2 + k % 3
        ));
    }
    csv
}

/// The numbers of each row of a trajectory CSV, keyed by its step and the row's place in
/// the step.
fn rows(path: &Path) -> std::collections::BTreeMap<(u64, usize), Vec<f64>> {
    let text = std::fs::read_to_string(path).unwrap();
    let mut out = std::collections::BTreeMap::new();
    let mut place = (u64::MAX, 0);
    for line in text.lines().skip(1) {
        let values: Vec<f64> = line.split(',').map(|x| x.parse().unwrap()).collect();
        let step = values[0] as u64;
        place = if place.0 == step {
            (step, place.1 + 1)
        } else {
            (step, 0)
        };
        out.insert(place, values);
    }
    out
}

/// Every row of `direct` is in `from_par`, each number within 1e-12 of it (relative to
/// the larger, or 1e-12 of the column's scale near 0).
fn reproduced(direct: &Path, from_par: &Path) {
    let (a, b) = (rows(direct), rows(from_par));
    assert!(a.len() > 10, "{} has {} rows", direct.display(), a.len());
    let columns = a.values().next().unwrap().len();
    let scale: Vec<f64> = (0..columns)
        .map(|c| a.values().map(|r| r[c].abs()).fold(0.0, f64::max))
        .collect();
    for (at, row) in &a {
        let other = b
            .get(at)
            .unwrap_or_else(|| panic!("{}: no row {at:?}", from_par.display()));
        for (c, (x, y)) in row.iter().zip(other).enumerate() {
            let bar = 1e-12 * x.abs().max(y.abs()).max(scale[c] * 1e-3);
            assert!(
                (x - y).abs() <= bar,
                "{}: step {}, row {}, column {c}: {x} against {y}",
                direct.display(),
                at.0,
                at.1
            );
        }
    }
}

#[test]
fn an_export_runs_as_the_direct_run_and_lints_clean() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::write(d.join("cup.walls"), CUP).unwrap();
    std::fs::write(d.join("balls.csv"), cup_particles()).unwrap();
    let options = [
        "--particles",
        "balls.csv",
        "--t-end",
        "0.08",
        "--gravity",
        "0",
        "0",
        "-9.8",
        "--k-n",
        "400",
        "--mu-s",
        "0.3",
        "--mu-r",
        "0.02",
        "--epsn",
        "0.6",
        "--every",
        "40",
    ];
    let export = sim(
        d,
        &[&["export", "cup.walls"][..], &options, &["--out", "job"]].concat(),
    );
    succeeded_saying(
        &export,
        "to job: ss.par, walls.dat, initial.ss, README.md, walls.toml (build: COLLISIONS DEM DEM_FIXED_BALL DEM_ROTATION_DASHPOT WALLS)",
    );
    assert_eq!(
        std::fs::read_to_string(d.join("job/walls.dat")).unwrap(),
        CUP
    );

    // What pkdgrav reads: every key with its origin above it, no line pkdgrav would split.
    let par = std::fs::read_to_string(d.join("job/ss.par")).unwrap();
    assert!(
        par.lines().all(|l| l.len() < 127 && !l.contains('!')),
        "{par}"
    );
    let lines: Vec<&str> = par.lines().collect();
    for (k, line) in lines.iter().enumerate() {
        if !line.starts_with('#') && !line.is_empty() {
            assert!(
                lines[k - 1].starts_with("# "),
                "{line} has no comment above it"
            );
        }
    }
    for (key, value, origin) in [
        ("dKn", "400", "from --k-n"),
        ("dMuS", "0.3", "from --mu-s"),
        ("dEpsN", "0.6", "from --epsn"),
        ("dzUnifGrav", "-9.8", "from --gravity"),
        ("dKt", "-1", "2/7 of dKn"),
        ("iOutInterval", "40", "from --every 40"),
        ("iForceOverrideOption", "2", "pkdgrav's default is 0"),
        ("iCheckInterval", "0", "pkdgrav's default is 10"),
        ("bDoSelfGravity", "0", "pkdgrav's default is 1"),
        ("iOutcomes", "0", "a DEM build ignores it"),
        ("dExtraStore", "1", "small runs on several ranks"),
        ("achInFile", "initial.ss", "the initial conditions"),
    ] {
        let at = lines
            .iter()
            .position(|l| l.starts_with(&format!("{key} ")))
            .unwrap_or_else(|| panic!("no {key} in\n{par}"));
        assert!(lines[at].ends_with(&format!("= {value}")), "{}", lines[at]);
        // The comment above it begins with its name.
        let start = (0..at)
            .rev()
            .take_while(|&k| lines[k].starts_with("# "))
            .find(|&k| lines[k].starts_with(&format!("# {key}: ")))
            .unwrap_or_else(|| panic!("{key} has no comment naming it"));
        let comment = lines[start..at].join(" ");
        assert!(comment.contains(origin), "{key}: {comment}");
    }
    let readme = std::fs::read_to_string(d.join("job/README.md")).unwrap();
    for says in [
        "COLLISIONS DEM DEM_FIXED_BALL DEM_ROTATION_DASHPOT WALLS",
        "pkdgrav ss.par",
        "mpirun -np 8 pkdgrav ss.par",
        "walls-lint .",
        "8 particle(s)",
    ] {
        assert!(readme.contains(says), "{says}: {readme}");
    }

    let lint = Command::new(env!("CARGO_BIN_EXE_walls-lint"))
        .arg(d.join("job"))
        .output()
        .unwrap();
    let findings = String::from_utf8_lossy(&lint.stdout);
    assert!(lint.status.success(), "{findings}{}", stderr(&lint));
    assert!(findings.contains("0 errors, 0 warnings"), "{findings}");

    let direct = sim(
        d,
        &[&["run", "cup.walls"][..], &options, &["--out", "direct"]].concat(),
    );
    assert!(direct.status.success(), "{}", stderr(&direct));
    let from_par = sim(d, &["run", "--par", "job/ss.par", "--out", "from-par"]);
    assert!(from_par.status.success(), "{}", stderr(&from_par));
    assert!(
        stderr(&direct).contains("particle contacts")
            && !stderr(&direct).contains(" 0 particle contacts"),
        "the scene must have particle contacts: {}",
        stderr(&direct)
    );
    for file in ["particles.csv", "walls.csv"] {
        reproduced(&d.join("direct").join(file), &d.join("from-par").join(file));
    }
}

#[test]
fn a_run_directory_exports_as_itself() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let par = golden("disk").join("params.par");
    let par = par.to_str().unwrap();
    let export = sim(d, &["export", "--par", par, "--out", "job"]);
    assert!(export.status.success(), "{}", stderr(&export));
    let written = std::fs::read_to_string(d.join("job/ss.par")).unwrap();
    // The source's keys that walls-sim does not write itself are copied, located by name
    // (not by the folders of the machine that exported).
    assert!(
        written.contains("# nSmooth: from params.par line 38\nnSmooth                  = 16\n"),
        "{written}"
    );
    assert!(!written.contains(d.to_str().unwrap()) && !written.contains("/golden/"));
    for (name, args) in [
        ("source", &["run", "--par", par, "--out", "a"][..]),
        ("export", &["run", "--par", "job/ss.par", "--out", "b"][..]),
    ] {
        let out = sim(d, args);
        assert!(out.status.success(), "{name}: {}", stderr(&out));
    }
    // A folder in achOutName is not kept, and the user is told.
    let text = std::fs::read_to_string(par).unwrap();
    let moved = text.replace("achOutName               = ss", "achOutName = out/ss");
    for file in ["walls.dat", "particles.ss"] {
        std::fs::copy(golden("disk").join(file), d.join(file)).unwrap();
    }
    std::fs::write(d.join("moved.par"), moved).unwrap();
    let out = sim(d, &["export", "--par", "moved.par", "--out", "moved"]);
    assert!(out.status.success(), "{}", stderr(&out));
    assert!(
        stderr(&out).contains("warning: moved.par line 8 names `out/ss`: its folder is not kept, the outputs are named ss.NNNNN beside ss.par"),
        "{}",
        stderr(&out)
    );
    let written = std::fs::read_to_string(d.join("moved/ss.par")).unwrap();
    assert!(
        written.contains("\nachOutName               = ss\n"),
        "{written}"
    );
    for file in ["particles.csv", "walls.csv"] {
        assert_eq!(
            std::fs::read(d.join("a").join(file)).unwrap(),
            std::fs::read(d.join("b").join(file)).unwrap(),
            "{file}"
        );
    }
}

/// Hard-sphere and cohesion run directories export as themselves too; the directory's
/// `walls.toml` names its build, so that `walls-lint DIR` checks for it.
#[test]
fn other_builds_export_as_themselves() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for (scene, build) in [
        ("hs_moving", "NUMREC"),
        (
            "cohesion",
            "DEM DEM_FIXED_BALL DEM_ROTATION_DASHPOT DEM_COHESION",
        ),
    ] {
        let par = golden(scene).join("params.par");
        let par = par.to_str().unwrap();
        let job = d.join(scene);
        let job = job.to_str().unwrap();
        let out = sim(
            d,
            &[
                "export",
                "--par",
                par,
                "--pkdgrav-build",
                build,
                "--out",
                job,
            ],
        );
        assert!(out.status.success(), "{scene}: {}", stderr(&out));
        let lint = Command::new(env!("CARGO_BIN_EXE_walls-lint"))
            .arg(job)
            .output()
            .unwrap();
        let findings = String::from_utf8_lossy(&lint.stdout);
        assert!(
            lint.status.success() && findings.contains("0 errors, 0 warnings"),
            "{scene}: {findings}{}",
            stderr(&lint)
        );
        let written = std::fs::read_to_string(d.join(scene).join("ss.par")).unwrap();
        if build == "NUMREC" {
            // No DEM: no DEM-only key, and the merge limit that silences B19.
            assert!(!written.contains("iForceOverrideOption"), "{written}");
            assert!(
                written.contains("\ndMergeLimit              = 0\n"),
                "{written}"
            );
        }
        let mut runs = Vec::new();
        for (name, par) in [("a", par.to_string()), ("b", format!("{job}/ss.par"))] {
            let out_dir = d.join(format!("{scene}-{name}"));
            let args = ["run", "--par", &par, "--pkdgrav-build", build, "--out"];
            let out = sim(d, &[&args[..], &[out_dir.to_str().unwrap()]].concat());
            assert!(out.status.success(), "{scene} {name}: {}", stderr(&out));
            runs.push(std::fs::read(out_dir.join("particles.csv")).unwrap());
        }
        assert_eq!(runs[0], runs[1], "{scene}");
    }
}

#[test]
fn what_pkdgrav_cannot_be_told_is_refused_with_nothing_written() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::write(d.join("cup.walls"), CUP).unwrap();
    std::fs::write(d.join("bad.walls"), "wall type plane\n  radius -1\n").unwrap();
    std::fs::write(d.join("balls.csv"), cup_particles()).unwrap();
    std::fs::write(
        d.join("late.par"),
        "achInFile = balls.csv\ndDelta = 1e-5\niStartStep = 200\nnSteps = 300\niForceOverrideOption = 2\niCheckInterval = 0\n",
    )
    .unwrap();
    std::fs::write(
        d.join("latin1.par"),
        b"iForceOverrideOption = 2\nachOutName = d\xe9j\xe0\niCheckInterval = 0\n",
    )
    .unwrap();
    for (args, status, says) in [
        (
            &[
                "cup.walls",
                "--particles",
                "balls.csv",
                "--no-particle-contacts",
            ][..],
            2,
            "--no-particle-contacts has no pkdgrav key",
        ),
        (
            &["cup.walls", "--no-particles"][..],
            2,
            "no particles to export",
        ),
        (
            &[
                "cup.walls",
                "--particles",
                "balls.csv",
                "--dt",
                "1e-12",
                "--t-end",
                "1",
            ][..],
            2,
            "pkdgrav counts steps in an int (nSteps at most 2147483647)",
        ),
        (
            &["cup.walls", "--par", "late.par", "--t-end", "1e-3"][..],
            2,
            "the run takes no step: it starts at t = 2e-3 (step 200)",
        ),
        (
            &[
                "cup.walls",
                "--par",
                "latin1.par",
                "--particles",
                "balls.csv",
            ][..],
            2,
            "latin1.par: line 2 is not UTF-8 text",
        ),
        (
            &["bad.walls", "--particles", "balls.csv"][..],
            1,
            "bad.walls: 1 error(s) (shown above): pkdgrav would refuse or misread it; nothing is exported",
        ),
    ] {
        let out = sim(d, &[&["export"][..], args, &["--out", "job"]].concat());
        assert_eq!(
            out.status.code(),
            Some(status),
            "{args:?}: {}",
            stderr(&out)
        );
        assert!(stderr(&out).contains(says), "{args:?}: {}", stderr(&out));
        assert!(
            !stderr(&out).contains("what could be resolved"),
            "{}",
            stderr(&out)
        );
        assert!(!d.join("job").exists(), "{args:?} made the folder");
    }
}

#[test]
fn every_file_is_planned_before_any_is_written() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::write(d.join("cup.walls"), CUP).unwrap();
    std::fs::write(d.join("balls.csv"), cup_particles()).unwrap();
    let export = |out: &str, force: bool| {
        let mut args = vec![
            "export",
            "cup.walls",
            "--particles",
            "balls.csv",
            "--out",
            out,
        ];
        if force {
            args.push("--force");
        }
        sim(d, &args)
    };
    // An earlier README, without --force: nothing is written, not even ss.par.
    std::fs::create_dir(d.join("job")).unwrap();
    std::fs::write(d.join("job/README.md"), "mine").unwrap();
    let out = export("job", false);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        stderr(&out).contains("not writing job/README.md: it exists: pass --force"),
        "{}",
        stderr(&out)
    );
    assert!(!d.join("job/ss.par").exists());
    assert_eq!(
        std::fs::read_to_string(d.join("job/README.md")).unwrap(),
        "mine"
    );
    // A link in the folder is never followed, even with --force.
    std::fs::write(d.join("victim"), "keep").unwrap();
    std::os::unix::fs::symlink(d.join("victim"), d.join("job/ss.par")).unwrap();
    let out = export("job", true);
    assert_eq!(out.status.code(), Some(2));
    assert!(stderr(&out).contains("symbolic link"), "{}", stderr(&out));
    assert_eq!(std::fs::read_to_string(d.join("victim")).unwrap(), "keep");
    // An export of an export, into its own folder: its inputs are not replaced.
    assert!(export("first", false).status.success());
    let again = sim(
        d,
        &[
            "export",
            "--par",
            "first/ss.par",
            "--out",
            "first",
            "--force",
        ],
    );
    assert_eq!(again.status.code(), Some(2));
    assert!(
        stderr(&again).contains("walls-sim export reads it"),
        "{}",
        stderr(&again)
    );
    // With --force, an earlier export is replaced whole.
    let out = export("first", true);
    assert!(out.status.success(), "{}", stderr(&out));
}

/// The run directory's check (R…) is silenced as any code is: by the settings file's
/// `ignore`. The golden `agg_cube` runs at pkdgrav's own timestep, under 10 steps per
/// contact for its aggregate (R004), and with the particles' rolling friction that
/// pkdgrav zeroes with aggregates (P009, B31).
#[test]
fn run_directory_findings_are_ignored_as_any_code() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let par = golden("agg_cube").join("params.par");
    let build = "DEM DEM_FIXED_BALL DEM_ROTATION_DASHPOT AGGS";
    let out = sim(
        d,
        &[
            "export",
            "--par",
            par.to_str().unwrap(),
            "--pkdgrav-build",
            build,
            "--out",
            "job",
        ],
    );
    assert!(out.status.success(), "{}", stderr(&out));
    let lint = || {
        Command::new(env!("CARGO_BIN_EXE_walls-lint"))
            .arg(d.join("job"))
            .output()
            .unwrap()
    };
    let before = String::from_utf8_lossy(&lint().stdout).into_owned();
    assert!(
        before.contains("[R004]") && before.contains("0 errors, 2 warnings"),
        "{before}"
    );
    let settings = d.join("job/walls.toml");
    let mut text = std::fs::read_to_string(&settings).unwrap();
    text.push_str("[lint]\nignore = [\"R004\", \"par-pkdgrav-warns\"]\n");
    std::fs::write(&settings, text).unwrap();
    let after = lint();
    let findings = String::from_utf8_lossy(&after.stdout);
    assert!(after.status.success(), "{findings}{}", stderr(&after));
    assert!(findings.contains("0 errors, 0 warnings"), "{findings}");
}

#[test]
fn outputs_names_keep_their_order_however_many_steps() {
    // The drum's ss.par says nDigits = 6; a run of 10⁶ steps names its last output with 7.
    let d = tempfile::tempdir().unwrap();
    let drum = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/drum/ss.par");
    let out = sim(
        d.path(),
        &[
            "export",
            "--par",
            drum.to_str().unwrap(),
            "--t-end",
            "1.99102e-6",
            "--out",
            "job",
        ],
    );
    succeeded_saying(
        &out,
        "gives nDigits = 6, narrower than the last step's 7 digits: written 7, so that the outputs' names sort in step order",
    );
    let par = std::fs::read_to_string(d.path().join("job/ss.par")).unwrap();
    assert!(par.contains("\nnDigits                  = 7\n"), "{par}");
    assert!(
        par.contains("\nnSteps                   = 1000000\n"),
        "{par}"
    );
    let lint = Command::new(env!("CARGO_BIN_EXE_walls-lint"))
        .arg(d.path().join("job"))
        .output()
        .unwrap();
    let findings = String::from_utf8_lossy(&lint.stdout);
    assert!(findings.contains("0 errors, 0 warnings"), "{findings}");
}
