//! `walls-lint` on a run directory checks it before the job (the `R` codes,
//! `walls_sim::precheck`): each finding in the file it is about, at its exact place, in
//! every format; a particle's place (a record of the binary `.ss` file) shown as each
//! format shows it; and the files the `.par` names read only inside its folder.

use serde_json::Value;
use std::path::Path;
use std::process::{Command, Output};

fn lint(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_walls-lint"))
        .args(args)
        .arg("--color")
        .arg("never")
        .current_dir(dir)
        .output()
        .unwrap()
}

/// A standard `.ss` file of `particles` (mass, radius, x, y, z).
fn ss(particles: &[(f64, f64, [f64; 3])]) -> Vec<u8> {
    let mut b = Vec::new();
    b.extend(0f64.to_be_bytes());
    b.extend((particles.len() as i32).to_be_bytes());
    b.extend((-1i32).to_be_bytes());
    for (k, (m, r, p)) in particles.iter().enumerate() {
        for x in [*m, *r, p[0], p[1], p[2], 0.0, 0.0, 0.0, 0.0, 0.0, 0.0] {
            b.extend(x.to_be_bytes());
        }
        b.extend(3i32.to_be_bytes());
        b.extend((k as i32).to_be_bytes());
    }
    b
}

const PAR: &str = "achInFile            = particles.ss
achWallsFile         = walls.dat
iOutInterval         = 100
iForceOverrideOption = 2
iOutcomes            = 0
bDoSelfGravity       = 0
iCheckInterval       = 0
dDelta               = 1e-7
nSteps               = 1000
dKn                  = 1e5
";

const FLOOR: &str = "wall\n  type plane\n  origin 0 0 0\n  orient 0 0 1\n";

/// A run directory in `run/` of a fresh folder: particles 0 and 1 overlap by 110 % (an
/// error), particle 2 overlaps the floor by 20 % (a warning).
fn run_dir() -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    let run = dir.path().join("run");
    std::fs::create_dir(&run).unwrap();
    std::fs::write(run.join("params.par"), PAR).unwrap();
    std::fs::write(run.join("walls.dat"), FLOOR).unwrap();
    let particles = [
        (1.0, 1.0, [0.0, 0.0, 5.0]),
        (1.0, 1.0, [0.9, 0.0, 5.0]),
        (1.0, 1.0, [9.0, 0.0, 0.8]),
    ];
    std::fs::write(run.join("particles.ss"), ss(&particles)).unwrap();
    dir
}

const PAIR: &str = "particles 0 and 1 overlap by 110 % of the smaller radius at the start, above dErrorFrac = 0.5: pkdgrav aborts at step 0 (an assertion, nothing written)";
const WALL: &str = "particle 2 overlaps wall 0 (run/walls.dat line 1) by 20 % of its radius at the start, above dMajorFrac = 0.15: pkdgrav prints a major-overlap warning at step 0 and runs on";

#[test]
fn json_places_particles_at_their_records() {
    let dir = run_dir();
    for args in [
        &["--format", "json", "run"][..],
        &["--format", "json", "run/params.par"],
    ] {
        let out = lint(dir.path(), args);
        assert_eq!(out.status.code(), Some(1), "{out:?}");
        let report: Value = serde_json::from_slice(&out.stdout).unwrap();
        let ss = report["files"]
            .as_array()
            .unwrap()
            .iter()
            .find(|f| f["path"] == "run/particles.ss")
            .unwrap_or_else(|| panic!("{report:#}"));
        let d = &ss["diagnostics"];
        assert_eq!(d.as_array().unwrap().len(), 2, "{d:#}");
        assert_eq!(d[0]["code"], "R001");
        assert_eq!(d[0]["severity"], "error");
        assert_eq!(d[0]["message"], PAIR);
        assert_eq!(
            d[0]["record"],
            serde_json::json!({"kind": "particle", "index": 0})
        );
        assert_eq!(
            (d[0]["line"].as_u64(), d[0]["column"].as_u64()),
            (Some(1), Some(1))
        );
        assert_eq!(d[1]["code"], "R002");
        assert_eq!(d[1]["severity"], "warning");
        assert_eq!(d[1]["message"], WALL);
        assert_eq!(
            d[1]["record"],
            serde_json::json!({"kind": "particle", "index": 2})
        );
    }
}

#[test]
fn human_github_gitlab_and_sarif_show_the_particle() {
    let dir = run_dir();
    let out = lint(dir.path(), &["run/params.par"]);
    let human = String::from_utf8(out.stdout).unwrap();
    assert!(
        human.contains(&format!(
            "[R001] Error: {PAIR}\n   ╭─[ run/particles.ss: particle 0 ]\n   │ \n   │ ─ particle 1\n"
        )),
        "{human}"
    );
    assert!(
        human.contains(&format!(
            "[R002] Warning: {WALL}\n   ╭─[ run/particles.ss: particle 2 ]\n"
        )),
        "{human}"
    );
    assert!(
        human.ends_with("1 error, 1 warning in 2 files\n"),
        "{human}"
    );

    let out = lint(dir.path(), &["--format", "github", "run/params.par"]);
    let github = String::from_utf8(out.stdout).unwrap();
    let pair = PAIR.replace('%', "%25");
    assert!(
        github.contains(&format!(
            "::error file=run/particles.ss,title=walls-lint (R001)::particle 0: {pair}%0A"
        )),
        "{github}"
    );

    let out = lint(dir.path(), &["--format", "gitlab", "run/params.par"]);
    let gitlab: Value = serde_json::from_slice(&out.stdout).unwrap();
    let issue = &gitlab[0];
    assert_eq!(issue["check_name"], "R001");
    assert_eq!(issue["severity"], "critical");
    assert_eq!(issue["location"]["path"], "run/particles.ss");
    assert_eq!(issue["location"]["lines"]["begin"], 1);
    assert!(
        issue["description"]
            .as_str()
            .unwrap()
            .starts_with(&format!("particle 0: {PAIR}"))
    );
    assert_ne!(gitlab[0]["fingerprint"], gitlab[1]["fingerprint"]);

    let out = lint(dir.path(), &["--format", "sarif", "run/params.par"]);
    let sarif: Value = serde_json::from_slice(&out.stdout).unwrap();
    let result = &sarif["runs"][0]["results"][0];
    assert_eq!(result["ruleId"], "R001");
    assert_eq!(result["level"], "error");
    let location = &result["locations"][0];
    assert_eq!(
        location["physicalLocation"]["region"],
        serde_json::json!({"byteOffset": 16, "byteLength": 96})
    );
    assert_eq!(
        location["logicalLocations"],
        serde_json::json!([{"kind": "element", "name": "particle 0"}])
    );
    assert_eq!(
        result["relatedLocations"][0]["physicalLocation"]["region"],
        serde_json::json!({"byteOffset": 112, "byteLength": 96})
    );
    assert!(
        sarif["runs"][0]["tool"]["driver"]["rules"]
            .as_array()
            .unwrap()
            .iter()
            .any(|r| r["id"] == "R001")
    );
}

#[test]
fn par_and_walls_findings_carry_their_spans() {
    let dir = tempfile::tempdir().unwrap();
    let par = PAR.replace("dDelta               = 1e-7", "dDelta               = 1e-3");
    std::fs::write(dir.path().join("params.par"), &par).unwrap();
    std::fs::write(
        dir.path().join("walls.dat"),
        format!("{FLOOR}  cohesive_coeff 1e-3\n"),
    )
    .unwrap();
    let particles = [(1.0, 1.0, [0.0, 0.0, 5.0]), (1.0, 1.0, [5.0, 0.0, 5.0])];
    std::fs::write(dir.path().join("particles.ss"), ss(&particles)).unwrap();
    let out = lint(dir.path(), &["--format", "json", "params.par"]);
    assert_eq!(out.status.code(), Some(0), "{out:?}");
    let report: Value = serde_json::from_slice(&out.stdout).unwrap();
    let files = report["files"].as_array().unwrap();
    let r004 = &files[0]["diagnostics"][0];
    assert_eq!(files[0]["path"], "params.par");
    assert_eq!(r004["code"], "R004");
    assert_eq!(
        (&r004["line"], &r004["column"], &r004["end_column"]),
        (&Value::from(8), &Value::from(24), &Value::from(28))
    );
    let r006 = &files[1]["diagnostics"][0];
    assert_eq!(files[1]["path"], "walls.dat");
    assert_eq!(r006["code"], "R006");
    assert_eq!(
        (&r006["line"], &r006["column"], &r006["end_column"]),
        (&Value::from(5), &Value::from(18), &Value::from(22))
    );
    // The walls file named on the command line too: one report, with both its own
    // findings and the run's.
    let out = lint(dir.path(), &["--format", "json", "params.par", "walls.dat"]);
    let report: Value = serde_json::from_slice(&out.stdout).unwrap();
    let walls: Vec<_> = report["files"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|f| f["path"] == "walls.dat")
        .collect();
    assert_eq!(walls.len(), 1, "{report:#}");
}

/// Writes `params.par` naming `in_file` in a fresh run directory `run/` (beside a
/// `secret` file outside it), with `ss_bytes` as `run/particles.ss`; walls-lint's JSON
/// report, its status and its standard error.
fn attack(in_file: &str, ss_bytes: Option<Vec<u8>>) -> (Value, i32, String) {
    let dir = tempfile::tempdir().unwrap();
    let run = dir.path().join("run");
    std::fs::create_dir(&run).unwrap();
    std::fs::write(dir.path().join("secret"), "TOP-SECRET-CONTENT\n").unwrap();
    std::fs::write(
        run.join("params.par"),
        PAR.replace(
            "achInFile            = particles.ss",
            &format!("achInFile            = {in_file}"),
        ),
    )
    .unwrap();
    std::fs::write(run.join("walls.dat"), FLOOR).unwrap();
    if let Some(bytes) = ss_bytes {
        std::fs::write(run.join("particles.ss"), bytes).unwrap();
    }
    #[cfg(unix)]
    std::os::unix::fs::symlink(dir.path().join("secret"), run.join("link.ss")).unwrap();
    let out = lint(dir.path(), &["--format", "json", "run"]);
    let report: Value =
        serde_json::from_slice(&out.stdout).unwrap_or_else(|e| panic!("{e}: {out:?}"));
    let stderr = String::from_utf8(out.stderr).unwrap();
    assert!(!stderr.contains("TOP-SECRET") && !report.to_string().contains("TOP-SECRET"));
    assert!(!stderr.contains("panicked"), "{stderr}");
    (report, out.status.code().unwrap(), stderr)
}

/// The I/O error entries of a report.
fn errors(report: &Value) -> Vec<(String, Option<u64>)> {
    report["files"]
        .as_array()
        .unwrap()
        .iter()
        .filter_map(|f| Some((f["error"].as_str()?.to_string(), f["line"].as_u64())))
        .collect()
}

#[test]
fn files_outside_the_run_directory_are_never_read() {
    for name in [
        "../secret",
        "/etc/passwd",
        "../../../../../../etc/passwd",
        "link.ss",
    ] {
        let (report, status, _) = attack(name, None);
        assert_eq!(status, 2, "{name}: {report:#}");
        assert_eq!(
            errors(&report),
            [(
                format!(
                    "run/params.par:1: achInFile = {name}: leaves run, the folder checked: not read; name a run directory that holds it"
                ),
                Some(1)
            )],
            "{name}"
        );
    }
    let (report, status, _) = attack("missing.ss", None);
    assert_eq!(status, 2);
    assert_eq!(
        errors(&report),
        [(
            "run/params.par:1: achInFile = missing.ss: no such file".to_string(),
            Some(1)
        )]
    );
}

#[test]
fn broken_particle_files_are_io_errors_where_they_stop() {
    let good = ss(&[(1.0, 1.0, [0.0, 0.0, 5.0])]);
    let cases: [(Vec<u8>, &str); 4] = [
        (
            good[..60].to_vec(),
            "byte 8: 1 particles of 96 bytes need 112 bytes, the file has 60",
        ),
        (
            good[..10].to_vec(),
            "byte 8: the file ends inside a record (10 bytes in all)",
        ),
        (
            ss(&[(1.0, f64::NAN, [0.0, 0.0, 5.0])]),
            "byte 16: particle 0: mass and radius must be positive",
        ),
        (
            ss(&[(1.0, 1e308, [0.0, 0.0, 5.0])]),
            "byte 16: particle 0: its moment of inertia",
        ),
    ];
    for (bytes, says) in cases {
        let (report, status, _) = attack("particles.ss", Some(bytes));
        assert_eq!(status, 2, "{report:#}");
        let errors = errors(&report);
        assert_eq!(errors.len(), 1, "{errors:?}");
        assert!(
            errors[0].0.starts_with(&format!(
                "run/params.par:1: achInFile = particles.ss: not a pkdgrav .ss file: run/particles.ss: {says}"
            )),
            "{errors:?}"
        );
        assert_eq!(errors[0].1, Some(1));
    }
    // No particles: nothing to check, and nothing wrong.
    let (report, status, _) = attack("particles.ss", Some(ss(&[])));
    assert_eq!(status, 0, "{report:#}");
    assert!(errors(&report).is_empty());
}

/// A particle file whose header does not match its length is refused from its 16-byte
/// header, as a run refuses it, however large the file: a 2 GiB hole is not read.
#[test]
fn a_particle_file_that_lies_in_its_header_is_refused_unread() {
    let dir = tempfile::tempdir().unwrap();
    let run = dir.path().join("run");
    std::fs::create_dir(&run).unwrap();
    std::fs::write(run.join("params.par"), PAR).unwrap();
    std::fs::write(run.join("walls.dat"), FLOOR).unwrap();
    let file = std::fs::File::create(run.join("particles.ss")).unwrap();
    std::io::Write::write_all(&mut &file, &ss(&[(1.0, 1.0, [0.0, 0.0, 5.0])])[..16]).unwrap();
    file.set_len(2 << 30).unwrap();
    let start = std::time::Instant::now();
    let out = lint(dir.path(), &["--format", "json", "run"]);
    let took = start.elapsed();
    let report: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(out.status.code(), Some(2), "{report:#}");
    assert_eq!(
        errors(&report),
        [(
            format!(
                "run/params.par:1: achInFile = particles.ss: not a pkdgrav .ss file: run/particles.ss: byte 8: 1 particles of 96 bytes need 112 bytes, the file has {}",
                2u64 << 30
            ),
            Some(1)
        )]
    );
    assert!(took < std::time::Duration::from_secs(2), "{took:?}");
}

#[test]
fn explain_knows_the_run_codes() {
    let out = Command::new(env!("CARGO_BIN_EXE_walls-lint"))
        .args(["--explain", "R001"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.starts_with("R001 (initial-pair-overlap): "), "{text}");
}

/// The build a golden `params.par` names in its first comment lines, as
/// `--pkdgrav-build` takes it.
fn build_of(text: &str) -> String {
    let header: Vec<&str> = text.lines().take_while(|l| l.starts_with('#')).collect();
    let at = (header.iter())
        .position(|l| l.contains("compile options:"))
        .expect("a build line");
    let mut words = Vec::new();
    for line in &header[at..(at + 2).min(header.len())] {
        let line = line.split("compile options:").last().unwrap();
        let line = line.split('(').next().unwrap();
        for w in line.split_whitespace() {
            if walls_par::options::OPTIONS.contains(&w) {
                words.push(w);
            }
        }
    }
    words.join(" ")
}

#[test]
fn golden_run_directories_pkdgrav_ran_have_no_run_error() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../walls-sim/tests/golden");
    let mut dirs: Vec<_> = std::fs::read_dir(&root)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.join("params.par").exists())
        .collect();
    dirs.sort();
    assert_eq!(dirs.len(), 30);
    let mut found = Vec::new();
    for dir in &dirs {
        let text = std::fs::read_to_string(dir.join("params.par")).unwrap();
        let out = lint(
            dir,
            &[
                "--format",
                "json",
                "--pkdgrav-build",
                &build_of(&text),
                "params.par",
            ],
        );
        assert_eq!(out.status.code(), Some(0), "{}: {out:?}", dir.display());
        let report: Value = serde_json::from_slice(&out.stdout).unwrap();
        for f in report["files"].as_array().unwrap() {
            for d in f["diagnostics"].as_array().unwrap() {
                let code = d["code"].as_str().unwrap();
                if code.starts_with('R') {
                    let name = dir.file_name().unwrap().to_string_lossy().to_string();
                    found.push((name, code.to_string(), d["severity"].to_string()));
                }
            }
        }
    }
    // pkdgrav's own soft_sphere_cube timestep: 6.8 steps a contact for the aggregate.
    assert_eq!(
        found,
        [(
            "agg_cube".to_string(),
            "R004".to_string(),
            "\"warning\"".to_string()
        )]
    );
}

#[test]
fn two_par_files_of_one_run_directory_report_its_findings_once() {
    let dir = run_dir();
    std::fs::copy(
        dir.path().join("run/params.par"),
        dir.path().join("run/again.par"),
    )
    .unwrap();
    let out = lint(dir.path(), &["--format", "json", "run"]);
    let report: Value = serde_json::from_slice(&out.stdout).unwrap();
    let ss: Vec<_> = (report["files"].as_array().unwrap().iter())
        .filter(|f| f["path"] == "run/particles.ss")
        .collect();
    assert_eq!(ss.len(), 1, "{report:#}");
    assert_eq!(
        ss[0]["diagnostics"].as_array().unwrap().len(),
        2,
        "{report:#}"
    );
}
