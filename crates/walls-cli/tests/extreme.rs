//! No panic, no hang, meaningful exits: every command (walls-lint, walls-fmt --check and
//! in place, walls-sim scene/run/plan/advise/preview) over a table of extreme values in
//! walls files, particle files and options (1e-300, 1e300, 1e308, -1e308, 1e-400, 1e999,
//! nan, inf, -0, 0, huge counts, empty files), each killed after a time limit: the exit
//! status must be 0, 1 or 2 and what it prints must not say "panicked"; a number no
//! double holds (1e-400, 1e999, nan, inf) in a particle file, an option or a `.par`
//! file's real must be refused with exit 2 and an error naming it where it is. Then the
//! interrupt of a run writing its outputs (whole rows, exit 1, `"stopped":
//! "interrupted"`), and a run with its standard streams closed. A second table holds
//! every input to the one rule for numbers: underflow refused like overflow, subnormals
//! warned about where they are, step counts that do not fit refused.

use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// The longest any one command may take before it counts as a hang.
const LIMIT: Duration = Duration::from_secs(20);

const VALUES: [&str; 12] = [
    "1e-300",
    "1e-320",
    "1e300",
    "1e308",
    "-1e308",
    "1e-400",
    "1e999",
    "nan",
    "inf",
    "-0",
    "0",
    "99999999999999999999",
];

fn bin(name: &str) -> PathBuf {
    match name {
        "walls-lint" => env!("CARGO_BIN_EXE_walls-lint").into(),
        "walls-fmt" => env!("CARGO_BIN_EXE_walls-fmt").into(),
        "walls-mesh" => env!("CARGO_BIN_EXE_walls-mesh").into(),
        _ => env!("CARGO_BIN_EXE_walls-sim").into(),
    }
}

/// Runs `args` (the binary first) in `dir`, killed after [`LIMIT`]; its exit status
/// and what it printed (standard output, where `walls-lint` writes its findings, then
/// standard error), or why it failed the test.
fn run_in(dir: &Path, args: &[String]) -> Result<(i32, String), String> {
    let mut child = Command::new(bin(&args[0]))
        .args(&args[1..])
        .current_dir(dir)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| e.to_string())?;
    let read = |mut stream: Box<dyn Read + Send>| {
        std::thread::spawn(move || {
            let mut text = String::new();
            let _ = stream.read_to_string(&mut text);
            text
        })
    };
    let stdout = read(Box::new(child.stdout.take().ok_or("no stdout")?));
    let stderr = read(Box::new(child.stderr.take().ok_or("no stderr")?));
    let start = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().map_err(|e| e.to_string())? {
            break status;
        }
        if start.elapsed() > LIMIT {
            let _ = child.kill();
            let _ = child.wait();
            return Err(format!("hung: killed after {LIMIT:?}"));
        }
        std::thread::sleep(Duration::from_millis(5));
    };
    let mut text = stdout.join().unwrap_or_default();
    text.push_str(&stderr.join().unwrap_or_default());
    Ok((status.code().unwrap_or(-1), text))
}

/// A row of the table: the command line (the binary first), the files it needs, each a
/// name and its bytes, and, when the row must be refused, what it must print.
type Row = (Vec<String>, Vec<(&'static str, Vec<u8>)>, Option<String>);

/// The values no double holds: a run must refuse them (exit 2) and say where they are.
const UNREADABLE: [&str; 4] = ["1e-400", "1e999", "nan", "inf"];

/// `says` when `v` is [`UNREADABLE`].
fn refused(v: &str, says: impl FnOnce() -> String) -> Option<String> {
    UNREADABLE.contains(&v).then(says)
}

/// Every row of the table.
fn table() -> Vec<Row> {
    let mut rows = Vec::new();
    let s = |words: &str| -> Vec<String> { words.split_whitespace().map(String::from).collect() };
    let floor = b"wall type plane\n".to_vec();
    let ball = b"mass,radius,x,y,z,vx,vy,vz\n1,0.1,0,0,0.3,0,0,-2\n".to_vec();
    let walls_commands = [
        "walls-lint w.walls",
        "walls-fmt --check w.walls",
        "walls-fmt w.walls",
        "walls-sim scene w.walls",
        "walls-sim run w.walls --t-end 0.01 --max-steps 20000",
        "walls-sim plan w.walls",
        "walls-sim preview w.walls --out x.svg",
    ];
    let walls_templates = [
        "wall type plane origin 0 0 {v}\n",
        "wall type disk radius {v}\n",
        "wall type plane\n  velocity {v} 0 0\n",
        "wall type plane\n  epsn {v}\n",
        "wall type plane\n  color {v}\n",
    ];
    for template in walls_templates {
        for v in VALUES {
            let text = template.replace("{v}", v).into_bytes();
            for cmd in walls_commands {
                rows.push((s(cmd), vec![("w.walls", text.clone())], None));
            }
        }
    }
    for cmd in walls_commands {
        rows.push((s(cmd), vec![("w.walls", Vec::new())], None));
    }
    let particle_commands = [
        "walls-sim run w.walls --particles p.csv --t-end 0.01 --max-steps 20000",
        "walls-sim preview w.walls --particles p.csv --out x.svg",
    ];
    let columns = ["mass", "radius", "x", "y", "z", "vx", "vy", "vz"];
    for (column, name) in columns.iter().enumerate() {
        for v in VALUES {
            let mut row = ["1", "0.1", "0", "0", "0.3", "0", "0", "-2"];
            row[column] = v;
            let text = format!("{}\n{}\n", columns.join(","), row.join(",")).into_bytes();
            for cmd in particle_commands {
                rows.push((
                    s(cmd),
                    vec![("w.walls", floor.clone()), ("p.csv", text.clone())],
                    refused(v, || format!("error: p.csv: line 2: `{name}` is `{v}`, ")),
                ));
            }
        }
    }
    // Empty particle files, and a .ss file claiming 2³¹ − 1 particles.
    let mut huge = 0f64.to_be_bytes().to_vec();
    huge.extend(i32::MAX.to_be_bytes());
    huge.extend((-1i32).to_be_bytes());
    for particles in [Vec::new(), b"mass,radius,x,y,z,vx,vy,vz\n".to_vec(), huge] {
        for cmd in particle_commands {
            rows.push((
                s(cmd),
                vec![("w.walls", floor.clone()), ("p.csv", particles.clone())],
                None,
            ));
        }
    }
    let option_commands = [
        "walls-sim run w.walls --particles p.csv --t-end 0.01 --max-steps 20000 --dt {v}",
        "walls-sim run w.walls --particles p.csv --max-steps 20000 --t-end {v}",
        "walls-sim run w.walls --particles p.csv --t-end 0.01 --max-steps 20000 --k-n {v}",
        "walls-sim run w.walls --particles p.csv --t-end 0.01 --max-steps 20000 --gravity {v} 0 0",
        "walls-sim run w.walls --particles p.csv --t-end 0.01 --max-steps 20000 --epsn {v}",
        "walls-sim run w.walls --particles p.csv --t-end 0.01 --max-steps 20000 --mu-s {v}",
        "walls-sim run w.walls --particles p.csv --t-end 0.01 --max-steps {v}",
        "walls-sim run w.walls --particles p.csv --t-end 0.01 --max-steps 20000 --every {v}",
        "walls-sim plan w.walls --particles p.csv --dt {v}",
        "walls-sim scene w.walls --time {v}",
        "walls-sim preview w.walls --out x.svg --time {v}",
        "walls-sim preview w.walls --out x.svg --frames {v}",
        "walls-sim advise --mass {v} --radius 1 --speed 1",
        "walls-sim advise --mass 1 --radius {v} --speed 1",
        "walls-sim advise --mass 1 --radius 1 --speed {v}",
    ];
    for cmd in option_commands {
        for v in VALUES {
            // The option whose value `v` is: the word before it.
            let option = cmd
                .split_whitespace()
                .take_while(|w| *w != "{v}")
                .last()
                .unwrap_or_default();
            rows.push((
                s(&cmd.replace("{v}", v)),
                vec![("w.walls", floor.clone()), ("p.csv", ball.clone())],
                refused(v, || format!("error: invalid value '{v}' for '{option} ")),
            ));
        }
    }
    // .par files: empty, and extreme values of its keys.
    let reals = ["dDelta", "dKn", "dzUnifGrav"];
    for key in ["dDelta", "dKn", "nSteps", "bWallsEdgeDetect", "dzUnifGrav"] {
        for v in VALUES {
            // A run pkdgrav's DEM build accepts, but for the value tried on line 4.
            let par = format!(
                "achInFile = p.csv\ndDelta = 1e-4\nnSteps = 100\n{key} = {v}\niForceOverrideOption = 2\niCheckInterval = 0\n"
            );
            rows.push((
                s("walls-sim run w.walls --par run.par --max-steps 20000"),
                vec![
                    ("w.walls", floor.clone()),
                    ("p.csv", ball.clone()),
                    ("run.par", par.into_bytes()),
                ],
                refused(v, || {
                    format!("error: run.par: line 4: pkdgrav reads `{key}` = `{v}` as ")
                })
                .filter(|_| reals.contains(&key)),
            ));
        }
    }
    rows.push((
        s("walls-sim run w.walls --par run.par --max-steps 20000 --t-end 0.01"),
        vec![("w.walls", floor.clone()), ("run.par", Vec::new())],
        None,
    ));
    rows
}

#[test]
fn every_command_over_extreme_values_exits_0_1_or_2_and_refuses_what_no_double_holds() {
    let rows = table();
    let mut failures = Vec::new();
    for (args, files, refusal) in &rows {
        let dir = tempfile::tempdir().unwrap();
        for (name, bytes) in files {
            std::fs::write(dir.path().join(name), bytes).unwrap();
        }
        let line = args.join(" ");
        let contents = files
            .iter()
            .map(|(n, b)| format!("{n}: {:?}", String::from_utf8_lossy(&b[..b.len().min(80)])))
            .collect::<Vec<_>>()
            .join("; ");
        match run_in(dir.path(), args) {
            Ok((code, stderr)) if code != 2 && refusal.is_some() => {
                failures.push(format!("{line} [{contents}]: exit {code}, not 2: {stderr}"))
            }
            Ok((_, stderr)) if refusal.as_ref().is_some_and(|says| !stderr.contains(says)) => {
                failures.push(format!(
                    "{line} [{contents}]: standard error does not say {:?}: {stderr}",
                    refusal.as_deref().unwrap_or_default()
                ));
            }
            Ok((code, stderr)) if (0..=2).contains(&code) && !stderr.contains("panicked") => {}
            Ok((code, stderr)) => failures.push(format!(
                "{line} [{contents}]: exit {code}: {}",
                stderr
                    .lines()
                    .find(|l| l.contains("panicked"))
                    .unwrap_or("")
            )),
            Err(why) => failures.push(format!("{line} [{contents}]: {why}")),
        }
    }
    assert!(
        failures.is_empty(),
        "{} of {} rows failed:\n{}",
        failures.len(),
        rows.len(),
        failures.join("\n")
    );
}

/// A row of the rule's table: the command line (the binary first), its files, the exit
/// status it must give and what it must print.
type RuleRow = (Vec<String>, Vec<(&'static str, Vec<u8>)>, i32, String);

/// One rule for numbers in every input (docs/reliability.md, "Numbers pkdgrav would
/// misread"): each row is a command, its files, the exit status it must give and what
/// it must print: underflow refused like overflow with its place, a
/// subnormal read with a warning at its place, a step count or a C int that does not
/// fit refused, a length whose squares overflow reported.
#[test]
fn numbers_follow_one_rule_in_every_input() {
    let s = |words: &str| -> Vec<String> { words.split_whitespace().map(String::from).collect() };
    let floor = || ("w.walls", b"wall type plane\n".to_vec());
    let ball = |x: &str| {
        let row = format!("mass,radius,x,y,z,vx,vy,vz\n1,0.1,{x},0,0.3,0,0,-2\n");
        ("p.csv", row.into_bytes())
    };
    let par = |line: &str| {
        let text = format!(
            "achInFile = p.csv\ndDelta = 1e-4\nnSteps = 100\n{line}\niForceOverrideOption = 2\niCheckInterval = 0\n"
        );
        ("run.par", text.into_bytes())
    };
    let obj = |z: &str| {
        (
            "m.obj",
            format!("v 0 0 0\nv 1 0 0\nv 0 1 {z}\nf 1 2 3\n").into_bytes(),
        )
    };
    let stl = |z: &str| {
        let text = format!(
            "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 {z}\nvertex 0 1 0\nendloop\nendfacet\nendsolid s\n"
        );
        ("m.stl", text.into_bytes())
    };
    let subnormal = "is below the smallest normal double";
    let run = "walls-sim run w.walls --particles p.csv --t-end 0.01";
    let rows: Vec<RuleRow> = vec![
        // Step counts that do not fit (0 steps, exit 0 before).
        (
            s("walls-sim run w.walls --dt 1e-320"),
            vec![floor()],
            2,
            "steps a run can count exactly".into(),
        ),
        (
            s("walls-sim run w.walls --dt 1e-10 --t-end 1e299 --max-steps 18446744073709551615"),
            vec![floor()],
            2,
            "steps of 1e-10 (--dt) to t = 1e299 (--t-end)".into(),
        ),
        (
            s("walls-sim run w.walls --par run.par"),
            vec![floor(), ball("0"), par("nSteps = 2147483648")],
            2,
            "run.par: line 4: `nSteps` = `2147483648` is beyond a C int".into(),
        ),
        // Subnormals: warnings with their place, the run goes on.
        (
            s(&format!("{run} --mu-s 1e-320")),
            vec![floor(), ball("0")],
            0,
            format!("--mu-s: `1e-320` {subnormal}"),
        ),
        (
            s(run),
            vec![floor(), ball("2e-320")],
            0,
            format!("p.csv: line 2: `x`: `2e-320` {subnormal}"),
        ),
        (
            s("walls-sim run w.walls --par run.par"),
            vec![floor(), ball("0"), par("dMuS = 1e-310")],
            0,
            format!("run.par: line 4: `dMuS`: `1e-310` {subnormal}"),
        ),
        (
            s("walls-sim preview w.walls --out x.svg --time 1e-320"),
            vec![floor()],
            0,
            format!("--time: `1e-320` {subnormal}"),
        ),
        (
            s("walls-lint w.walls"),
            vec![("w.walls", b"wall type disk\n  radius 1e-320\n".to_vec())],
            0,
            "S110".into(),
        ),
        (
            s("walls-fmt w.walls"),
            vec![("w.walls", b"wall type disk\nradius 1e-320\n".to_vec())],
            0,
            "1 file reformatted".into(),
        ),
        (
            s("walls-mesh m.obj -o m.walls"),
            vec![obj("1e-320")],
            0,
            format!("m.obj:3: `1e-320` {subnormal}"),
        ),
        (
            s("walls-mesh m.stl -o m.walls"),
            vec![stl("1e-320")],
            0,
            format!("m.stl:5: `1e-320` {subnormal}"),
        ),
        // Underflow refused like overflow (read as 0 before, in meshes).
        (
            s("walls-mesh m.obj -o m.walls"),
            vec![obj("1e-400")],
            2,
            "m.obj:3: `1e-400` is too small for a double".into(),
        ),
        (
            s("walls-mesh m.stl -o m.walls"),
            vec![stl("1e-400")],
            2,
            "m.stl:5: `1e-400` is too small for a double".into(),
        ),
        (
            s("walls-mesh m.obj -o m.walls"),
            vec![obj("1e999")],
            2,
            "m.obj:3: `1e999` is too large for a double".into(),
        ),
        (
            s("walls-lint --min-radius 1e-400 w.walls"),
            vec![floor()],
            2,
            "`1e-400` is too small for a double".into(),
        ),
        (
            s("walls-mesh m.obj -o m.walls --set epsn=1e-400"),
            vec![obj("0")],
            2,
            "--set epsn=1e-400: `1e-400` is too small for a double".into(),
        ),
        (
            s(run),
            vec![floor(), ball("1e-400")],
            2,
            "p.csv: line 2: `x` is `1e-400`, too small for a double".into(),
        ),
        // A length whose squares overflow (lint-clean, NaN in pictures before).
        (
            s("walls-lint w.walls"),
            vec![(
                "w.walls",
                b"wall type plane\n  origin 1e308 1e308 1e308\n".to_vec(),
            )],
            1,
            "C121".into(),
        ),
        (
            s("walls-sim run w.walls"),
            vec![(
                "w.walls",
                b"wall type plane\n  origin 1e308 1e308 1e308\n".to_vec(),
            )],
            2,
            "nothing can be computed from it".into(),
        ),
    ];
    let mut failures = Vec::new();
    for (args, files, code, says) in &rows {
        let dir = tempfile::tempdir().unwrap();
        for (name, bytes) in files {
            std::fs::write(dir.path().join(name), bytes).unwrap();
        }
        let line = args.join(" ");
        match run_in(dir.path(), args) {
            Ok((got, stderr)) if got != *code || !stderr.contains(says.as_str()) => failures.push(
                format!("{line}: exit {got} (want {code}), printed {stderr:?} (want {says:?})"),
            ),
            Ok(_) => {}
            Err(why) => failures.push(format!("{line}: {why}")),
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// A floor and a ball bouncing on it for a long time, every step written.
fn long_run(dir: &Path) -> Command {
    std::fs::write(dir.join("w.walls"), "wall type plane\n").unwrap();
    std::fs::write(
        dir.join("p.csv"),
        "mass,radius,x,y,z,vx,vy,vz\n1,0.1,0,0,0.3,0,0,-2\n1,0.1,1,0,0.3,0,0,-1\n",
    )
    .unwrap();
    let mut cmd = Command::new(bin("walls-sim"));
    cmd.current_dir(dir).args([
        "run",
        "w.walls",
        "--particles",
        "p.csv",
        "--dt",
        "1e-4",
        "--t-end",
        "5000",
        "--every",
        "1",
        "--out",
        "out",
    ]);
    cmd
}

/// What is left to read of a child's piped stream.
fn rest_of(stream: Option<impl Read>) -> String {
    let mut text = String::new();
    stream.unwrap().read_to_string(&mut text).unwrap();
    text
}

/// The fields of a row of `particles.csv`.
const PARTICLE_FIELDS: usize = walls_sim::io::trajectory::PARTICLE_COLUMNS.len();

/// Every line of `path` has `columns` fields; the number of rows.
fn whole_rows(path: &Path, columns: usize) -> usize {
    let text = std::fs::read_to_string(path).unwrap();
    assert!(text.ends_with('\n'), "{} ends mid-row", path.display());
    for (n, line) in text.lines().enumerate() {
        assert_eq!(
            line.split(',').count(),
            columns,
            "{} line {}: {line}",
            path.display(),
            n + 1
        );
    }
    text.lines().count()
}

#[test]
fn an_interrupted_run_ends_its_outputs_on_whole_rows_and_exits_1() {
    let dir = tempfile::tempdir().unwrap();
    let mut child = long_run(dir.path())
        .arg("--json")
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let csv = dir.path().join("out/particles.csv");
    let start = Instant::now();
    while std::fs::metadata(&csv).map_or(0, |m| m.len()) < 200_000 {
        assert!(start.elapsed() < LIMIT, "no output");
        std::thread::sleep(Duration::from_millis(10));
    }
    let killed = Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status()
        .unwrap();
    assert!(killed.success());
    let stdout = rest_of(child.stdout.take());
    let stderr = rest_of(child.stderr.take());
    let status = child.wait().unwrap();
    assert_eq!(status.code(), Some(1), "{stderr}");
    assert!(stdout.contains("\"stopped\": \"interrupted\""), "{stdout}");
    assert!(stderr.contains("the run stopped early"), "{stderr}");
    assert!(stderr.contains(": interrupted"), "{stderr}");
    assert!(
        stderr.contains("particles.csv") && stderr.contains("walls.csv"),
        "{stderr}"
    );
    assert!(whole_rows(&csv, PARTICLE_FIELDS) > 100);
    // The step the message names is the last row's.
    let text = std::fs::read_to_string(&csv).unwrap();
    let last_row = text.lines().last().unwrap();
    let step = last_row.split(',').next().unwrap();
    assert!(
        stderr.contains(&format!("end at their last output, step {step} (t = ")),
        "{stderr}\nlast row: {last_row}"
    );
    whole_rows(&dir.path().join("out/walls.csv"), 6);
}

#[test]
fn a_run_whose_output_fails_stops_keeping_the_whole_rows_written_and_exits_2() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    // The disk fills at 200 KiB a file (a file-size limit; the signal it would send is
    // ignored, so that writes fail with EFBIG as a full disk's fail with ENOSPC).
    let run = long_run(dir.path());
    let args: Vec<_> = run.get_args().collect();
    let mut child = Command::new("bash")
        .current_dir(dir.path())
        .args(["-c", "trap '' XFSZ; ulimit -f 200; exec \"$0\" \"$@\""])
        .arg(run.get_program())
        .args(args)
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let start = Instant::now();
    while child.try_wait().unwrap().is_none() {
        // Rather than computing its 50 million steps for nothing.
        assert!(start.elapsed() < LIMIT, "the run went on");
        std::thread::sleep(Duration::from_millis(10));
    }
    let stderr = rest_of(child.stderr.take());
    assert_eq!(child.wait().unwrap().code(), Some(2), "{stderr}");
    // The message names the step being written, the file that failed, where the outputs
    // end and every file.
    let particles = out.join("particles.csv");
    let rows = whole_rows(&particles, PARTICLE_FIELDS);
    let text = std::fs::read_to_string(&particles).unwrap();
    let last = text.lines().last().unwrap().split(',').next().unwrap();
    let failed = last.parse::<u64>().unwrap() + 1;
    // Its time, 1e-4 a step, as the message writes it (no trailing zero: 0.154).
    let t = format!("0.{failed:04}");
    let t = t.trim_end_matches('0');
    assert!(
        stderr.contains(&format!(
            "error: at output step {failed} (t = {t}): cannot write out/particles.csv: File too large"
        )) && stderr.contains(&format!(
            "the outputs in out end at output step {last} (t = "
        )) && stderr.contains("out/particles.csv, out/walls.csv"),
        "{stderr}"
    );
    // Both files end at the same whole output step: two particles and one wall a step.
    assert_eq!(rows - 1, 2 * (whole_rows(&out.join("walls.csv"), 6) - 1));
    assert!(rows > 100);
}

#[test]
fn a_run_with_its_standard_streams_closed_still_writes_its_outputs() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let sim = bin("walls-sim");
    // Closed outright (`2>&- >&-`).
    let status = Command::new("sh")
        .current_dir(dir.path())
        .arg("-c")
        .arg(format!(
            "printf 'wall type plane\\n' > w.walls; printf 'mass,radius,x,y,z,vx,vy,vz\\n1,0.1,0,0,0.3,0,0,-2\\n' > p.csv; exec '{}' run w.walls --particles p.csv --t-end 0.2 --epsn 1.5 --out out 2>&- >&-",
            sim.display()
        ))
        .status()
        .unwrap();
    // --epsn 1.5 is a usage error, reported to nobody: exit 2, not a panic's 101.
    assert_eq!(status.code(), Some(2));
    let status = Command::new("sh")
        .current_dir(dir.path())
        .arg("-c")
        .arg(format!(
            "exec '{}' run w.walls --particles p.csv --t-end 0.2 --dt 1e-3 --gravity 1 0 0 --out out 2>&- >&-",
            sim.display()
        ))
        .status()
        .unwrap();
    assert_eq!(status.code(), Some(0));
    assert_eq!(
        whole_rows(&out.join("particles.csv"), PARTICLE_FIELDS),
        1 + 3
    );
    // A pipe whose reader has gone: every warning write fails.
    std::fs::remove_dir_all(&out).unwrap();
    let mut child = Command::new(&sim)
        .current_dir(dir.path())
        .args([
            "run",
            "w.walls",
            "--particles",
            "p.csv",
            "--t-end",
            "0.2",
            "--dt",
            "1e-3",
        ])
        .args(["--k-n", "10", "--out", "out", "--json"])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stdout.take());
    drop(child.stderr.take());
    let status = child.wait().unwrap();
    // The overlap stop is exit 1; stdout gone ends quietly (0); never 101.
    assert!(matches!(status.code(), Some(0 | 1)), "{status:?}");
    assert!(whole_rows(&out.join("particles.csv"), PARTICLE_FIELDS) > 1);
}

/// `walls-sim run --json` over 2,000 particles falling onto a floor, with standard output
/// as `stdout` says: its exit status and standard error.
fn json_run(stdout: Stdio, reader: impl FnOnce(&mut std::process::Child)) -> (i32, String) {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("w.walls"), "wall type plane\n").unwrap();
    let rows: String = (0..2000)
        .map(|k| format!("1,0.1,{},{},0.3,0,0,-2\n", k % 50, k / 50))
        .collect();
    std::fs::write(
        dir.path().join("p.csv"),
        format!("mass,radius,x,y,z,vx,vy,vz\n{rows}"),
    )
    .unwrap();
    let mut child = Command::new(bin("walls-sim"))
        .current_dir(dir.path())
        .args(["run", "w.walls", "--particles", "p.csv", "--t-end", "0.01"])
        .args(["--json"])
        .stdout(stdout)
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    reader(&mut child);
    let stderr = rest_of(child.stderr.take());
    (child.wait().unwrap().code().unwrap(), stderr)
}

#[test]
fn a_json_report_that_cannot_be_written_is_an_error_or_a_quiet_end_never_a_panic() {
    // A full disk behind the redirect: the error, exit 2.
    let full = std::fs::File::create("/dev/full").unwrap();
    let (status, stderr) = json_run(full.into(), |_| {});
    assert_eq!(
        (status, stderr.as_str()),
        (
            2,
            "error: cannot write to standard output: No space left on device (os error 28)\n"
        )
    );
    // A reader that takes the first line and goes (`| head -1`): the report is cut off
    // by a broken pipe, which ends the run quietly, as for every command.
    let (status, stderr) = json_run(Stdio::piped(), |child| {
        let mut first = [0u8; 2];
        let mut out = child.stdout.take().unwrap();
        out.read_exact(&mut first).unwrap();
        assert_eq!(&first, b"{\n");
    });
    assert_eq!((status, stderr.as_str()), (0, ""));
}
