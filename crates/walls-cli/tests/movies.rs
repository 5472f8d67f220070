//! Movies of a run as a new user makes them (issue 44, "the researcher's first hour"):
//! `walls-sim run --out DIR` then `walls-sim preview --particles DIR --out drop.svg`.
//! A long run's movie shows at most `MOVIE_FRAMES` outputs unless `--frames` or `--every`
//! asks for others, writes only the file `--out` names and says on standard error what
//! it wrote; `particles.csv`'s `color` column carries pkdgrav's colours into the movie
//! (a file without it still reads, green; a colour that is not pkdgrav's stops at its
//! file:line with exit 2); a scene whose walls file sets units is labelled in seconds.

use std::path::Path;
use std::process::{Command, Output};
use walls_cli::movie::{MOST_FRAMES, MOVIE_FRAMES};
use walls_sim::io::trajectory::PARTICLE_COLUMNS;

/// A floor of pkdgrav units.
const FLOOR: &str = "wall type plane\n  origin 0 0 0\n  color 2\n";

fn walls_sim(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_walls-sim"))
        .args(args)
        .current_dir(dir)
        .env("NO_COLOR", "1")
        .output()
        .unwrap()
}

fn stderr(out: &Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

/// A folder with `floor.walls` (`walls`) and `run/particles.csv`: one particle rising
/// through `outputs` output steps, in `color`'s colour (`None`: a file written before
/// the column).
fn run_folder(walls: &str, outputs: usize, color: Option<i32>) -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("floor.walls"), walls).unwrap();
    std::fs::create_dir(dir.path().join("run")).unwrap();
    let columns = match color {
        Some(_) => &PARTICLE_COLUMNS[..],
        None => &PARTICLE_COLUMNS[..15],
    };
    let mut csv = columns.join(",") + "\n";
    for k in 0..outputs {
        let t = k as f64 * 0.01;
        csv += &format!("{k},{t},0,1,1,0.1,0,0,{},0,0,1,0,0,0", 0.5 + t);
        if let Some(c) = color {
            csv += &format!(",{c}");
        }
        csv += "\n";
    }
    std::fs::write(dir.path().join("run/particles.csv"), csv).unwrap();
    dir
}

/// The frames of an SVG preview.
fn frames(svg: &str) -> usize {
    svg.matches("<g class=\"frame\"").count()
}

fn read(dir: &Path, name: &str) -> String {
    std::fs::read_to_string(dir.join(name)).unwrap()
}

/// The names in `dir`, sorted.
fn names(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

#[test]
fn a_long_runs_movie_is_capped_and_says_what_it_wrote() {
    let dir = run_folder(FLOOR, 1000, Some(3));
    let out = walls_sim(
        dir.path(),
        &[
            "preview",
            "floor.walls",
            "--particles",
            "run",
            "--out",
            "drop.svg",
        ],
    );
    assert!(out.status.success(), "{}", stderr(&out));
    assert_eq!(frames(&read(dir.path(), "drop.svg")), MOVIE_FRAMES);
    // The file asked for and no other: no stills beside it.
    assert_eq!(names(dir.path()), ["drop.svg", "floor.walls", "run"]);
    let told = stderr(&out);
    assert!(
        told.starts_with("walls-sim: wrote drop.svg (")
            && told.contains(&format!(
                "): {MOVIE_FRAMES} frames of 1000 outputs, evenly spaced; --frames N"
            ))
            && told.contains("--every N"),
        "{told}"
    );
    // The help says the same default.
    let help = walls_sim(dir.path(), &["preview", "--help"]);
    let help = String::from_utf8_lossy(&help.stdout);
    assert!(
        help.contains(&format!("(default {MOVIE_FRAMES})")),
        "{help}"
    );
}

#[test]
fn every_and_frames_pick_among_the_outputs() {
    let dir = run_folder(FLOOR, 1000, Some(3));
    let preview = |extra: &[&str]| {
        let mut args = vec!["preview", "floor.walls", "--particles", "run"];
        args.extend(extra);
        args.extend(["--out", "m.svg", "--force"]);
        walls_sim(dir.path(), &args)
    };
    let out = preview(&["--every", "100"]);
    assert!(out.status.success(), "{}", stderr(&out));
    assert_eq!(frames(&read(dir.path(), "m.svg")), 10);
    assert!(
        stderr(&out).contains("10 frames, 1 in every 100 of 1000 outputs"),
        "{}",
        stderr(&out)
    );
    // More than the default when asked; all when there are fewer than asked.
    let out = preview(&["--frames", "500"]);
    assert_eq!(frames(&read(dir.path(), "m.svg")), 500);
    assert!(stderr(&out).contains("500 frames of 1000 outputs, evenly spaced\n"));
    preview(&["--every", "1"]);
    assert_eq!(frames(&read(dir.path(), "m.svg")), 1000);
    preview(&["--every", "4294967295"]);
    assert_eq!(frames(&read(dir.path(), "m.svg")), 1);
    // The first and the last output are among the frames (t = 0 and t = 9.99).
    preview(&["--frames", "2"]);
    let svg = read(dir.path(), "m.svg");
    assert!(
        svg.contains(">t = 0<") && svg.contains(">t = 9.99<"),
        "{svg}"
    );
    // With stills, one file per frame too.
    let out = preview(&["--frames", "3", "--stills"]);
    assert!(out.status.success(), "{}", stderr(&out));
    assert!(dir.path().join("m-002.svg").is_file());
    assert!(
        stderr(&out).contains("wrote m.svg … m-002.svg, 4 files ("),
        "{}",
        stderr(&out)
    );
    // What makes no sense is refused with exit 2, before anything is written.
    for bad in [
        &["--frames", "0"][..],
        &["--every", "0"],
        &["--frames", "100000"],
        &["--every", "99999999999999999999"],
        &["--frames", "5", "--every", "2"],
        &["--until", "1"],
    ] {
        let out = preview(bad);
        assert_eq!(out.status.code(), Some(2), "{bad:?}: {}", stderr(&out));
        assert!(!stderr(&out).contains("panicked"), "{}", stderr(&out));
    }
    let out = walls_sim(
        dir.path(),
        &["preview", "floor.walls", "--every", "2", "--out", "one.svg"],
    );
    assert_eq!(out.status.code(), Some(2), "{}", stderr(&out));
    let out = walls_sim(
        dir.path(),
        &[
            "preview",
            "floor.walls",
            "--particles",
            "run",
            "--stills",
            "--out",
            "m.html",
        ],
    );
    assert_eq!(out.status.code(), Some(2), "{}", stderr(&out));
    assert!(stderr(&out).contains("--stills"), "{}", stderr(&out));
}

#[test]
fn a_run_with_one_output_is_one_picture() {
    let dir = run_folder(FLOOR, 1, Some(3));
    let out = walls_sim(
        dir.path(),
        &[
            "preview",
            "floor.walls",
            "--particles",
            "run",
            "--out",
            "one.svg",
        ],
    );
    assert!(out.status.success(), "{}", stderr(&out));
    assert_eq!(frames(&read(dir.path(), "one.svg")), 1);
    assert_eq!(stderr(&out), "");
    // --every picks among its one output.
    let out = walls_sim(
        dir.path(),
        &[
            "preview",
            "floor.walls",
            "--particles",
            "run",
            "--every",
            "5",
            "--out",
            "e.svg",
        ],
    );
    assert!(out.status.success(), "{}", stderr(&out));
    assert_eq!(frames(&read(dir.path(), "e.svg")), 1);
}

#[test]
fn a_runs_movie_keeps_pkdgravs_colours() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("floor.walls"), FLOOR).unwrap();
    // Blue and cyan.
    std::fs::write(
        dir.path().join("balls.csv"),
        "mass,radius,x,y,z,vx,vy,vz,color\n1,0.1,0,0,0.5,0,0,0,4\n1,0.1,0.5,0,0.5,0,0,0,7\n",
    )
    .unwrap();
    let run = walls_sim(
        dir.path(),
        &[
            "run",
            "floor.walls",
            "--particles",
            "balls.csv",
            "--t-end",
            "0.05",
            "--dt",
            "0.001",
            "--every",
            "10",
            "--out",
            "run",
        ],
    );
    assert!(run.status.success(), "{}", stderr(&run));
    let csv = read(dir.path(), "run/particles.csv");
    let mut lines = csv.lines();
    assert!(lines.next().unwrap().ends_with(",wz,color"));
    let colours: Vec<&str> = lines.map(|l| l.rsplit(',').next().unwrap()).collect();
    assert_eq!(colours.len(), 12, "{csv}");
    assert!(colours.chunks(2).all(|c| c == ["4", "7"]), "{colours:?}");
    let out = walls_sim(
        dir.path(),
        &[
            "preview",
            "floor.walls",
            "--particles",
            "run",
            "--out",
            "m.svg",
        ],
    );
    assert!(out.status.success(), "{}", stderr(&out));
    let svg = read(dir.path(), "m.svg");
    let particles = svg.matches("class=\"particle\"").count();
    assert_eq!(particles, 12);
    assert_eq!(svg.matches("fill=\"#0000ff\"").count(), 6, "blue");
    assert_eq!(svg.matches("fill=\"#00ffff\"").count(), 6, "cyan");
    assert_eq!(svg.matches("fill=\"#00ff00\"").count(), 0, "green");
}

#[test]
fn an_older_particles_csv_reads_green_and_a_bad_colour_is_located() {
    let dir = run_folder(FLOOR, 3, None);
    let out = walls_sim(
        dir.path(),
        &[
            "preview",
            "floor.walls",
            "--particles",
            "run",
            "--out",
            "m.svg",
        ],
    );
    assert!(out.status.success(), "{}", stderr(&out));
    assert_eq!(
        read(dir.path(), "m.svg")
            .matches("fill=\"#00ff00\"")
            .count(),
        3
    );
    for (bad, why) in [
        (
            "banana",
            "`color` is `banana`, not one of pkdgrav's colours",
        ),
        ("256", "`color` is `256`"),
        ("2.5", "`color` is `2.5`"),
    ] {
        let csv = read(dir.path(), "run/particles.csv");
        let header = PARTICLE_COLUMNS.join(",");
        let rows: Vec<&str> = csv.lines().skip(1).collect();
        let csv = format!(
            "{header}\n{},3\n{},{bad}\n{},3\n",
            rows[0], rows[1], rows[2]
        );
        std::fs::write(dir.path().join("run/particles.csv"), csv).unwrap();
        let out = walls_sim(
            dir.path(),
            &[
                "preview",
                "floor.walls",
                "--particles",
                "run",
                "--out",
                "m.svg",
                "--force",
            ],
        );
        assert_eq!(out.status.code(), Some(2), "{}", stderr(&out));
        let told = stderr(&out);
        let at = Path::new("run").join("particles.csv");
        assert!(
            told.starts_with(&format!("walls-sim: error: {}:3: {why}", at.display())),
            "{told}"
        );
        // Back to the file without the column.
        std::fs::write(
            dir.path().join("run/particles.csv"),
            format!(
                "{}\n{}\n",
                PARTICLE_COLUMNS[..15].join(","),
                rows.join("\n")
            ),
        )
        .unwrap();
    }
}

#[test]
fn a_scene_with_units_is_labelled_in_seconds() {
    // Centimetres and grams, and no timeunit: the labels are in seconds all the same.
    let cm_g = format!("lengthunit 6.68459e-14\nmassunit 5.02739933e-34\n{FLOOR}");
    let dir = run_folder(&cm_g, 3, Some(3));
    let preview = |out: &str, extra: &[&str]| {
        let mut args = vec!["preview", "floor.walls", "--particles", "run", "--out", out];
        args.extend(extra);
        let done = walls_sim(dir.path(), &args);
        assert!(done.status.success(), "{}", stderr(&done));
        read(dir.path(), out)
    };
    // Output 1 is at t = 0.01 pkdgrav units: 50,226 s.
    let svg = preview("m.svg", &[]);
    assert!(svg.contains(">t = 50230 s<"), "{svg}");
    let html = preview("m.html", &[]);
    assert!(
        html.contains("\"readout\":{\"time\":[\"s\",") && html.contains("\"withPkdgrav\":false"),
        "the page labels time in seconds"
    );
    // pkdgrav's, when asked.
    let svg = preview("p.svg", &["--units", "pkdgrav"]);
    assert!(svg.contains(">t = 0.01<"), "{svg}");
    // A scene without units keeps pkdgrav's.
    std::fs::write(dir.path().join("floor.walls"), FLOOR).unwrap();
    let svg = preview("n.svg", &[]);
    assert!(svg.contains(">t = 0.01<"), "{svg}");
    let html = preview("n.html", &[]);
    assert!(
        html.contains("\"readout\":{\"time\":[\"\",1"),
        "pkdgrav's time"
    );
}

/// `--every N` is held to the cap of `--frames` (`MOST_FRAMES`): a choice that makes
/// more frames is refused with exit 2, saying how many and the smallest N that fits,
/// before anything is written.
#[test]
fn every_that_makes_too_many_frames_is_refused() {
    let dir = run_folder(FLOOR, MOST_FRAMES + 1, Some(3));
    for out in ["m.svg", "m.pvd", "m.pov"] {
        let run = walls_sim(
            dir.path(),
            &[
                "preview",
                "floor.walls",
                "--particles",
                "run",
                "--every",
                "1",
                "--out",
                out,
            ],
        );
        assert_eq!(run.status.code(), Some(2), "{}", stderr(&run));
        let e = stderr(&run);
        assert!(
            e.contains(&format!(
                "--every 1 of {} outputs would make {} frames",
                MOST_FRAMES + 1,
                MOST_FRAMES + 1
            )) && e.contains("--every 2 or more fits"),
            "{e}"
        );
    }
    assert_eq!(names(dir.path()), ["floor.walls", "run"]);
}

/// A run folder holding both `particles.csv` and `.ss` files (`walls-sim run --out DIR
/// --ss-output`) is read from its `particles.csv`, as `--help` says: every output, the
/// first too, in the CSV's colours; not the one `.ss` file beside it as a still.
#[test]
fn a_run_folder_is_read_from_its_particles_csv() {
    let dir = run_folder(FLOOR, 3, Some(5));
    let p = walls_geometry::Particle::at_rest(0.1, nalgebra::Vector3::new(0.0, 0.0, 9.0), 0);
    std::fs::write(
        dir.path().join("run/ss.00100"),
        walls_sim::io::particles::write_ss(1.0, &[p]),
    )
    .unwrap();
    let out = walls_sim(
        dir.path(),
        &[
            "preview",
            "floor.walls",
            "--particles",
            "run",
            "--out",
            "m.svg",
        ],
    );
    assert!(out.status.success(), "{}", stderr(&out));
    let svg = read(dir.path(), "m.svg");
    assert_eq!(frames(&svg), 3);
    assert!(svg.contains(">t = 0<") && !svg.contains(">t = 1<"), "{svg}");
    // Colour 5 (yellow), not the .ss file's 3 (green).
    let discs: Vec<&str> = svg.lines().filter(|l| l.starts_with("<circle")).collect();
    assert_eq!(discs.len(), 3, "{svg}");
    assert!(
        discs.iter().all(|d| d.contains("fill=\"#ffff00\"")),
        "{discs:?}"
    );
    // Named, the .ss file is drawn.
    let out = walls_sim(
        dir.path(),
        &[
            "preview",
            "floor.walls",
            "--particles",
            "run/ss.00100",
            "--out",
            "ss.svg",
        ],
    );
    assert!(out.status.success(), "{}", stderr(&out));
    let ss = read(dir.path(), "ss.svg");
    assert!(ss.contains("fill=\"#00ff00\""), "{ss}");
}

/// A shorter picture over an earlier, longer one (`--force`) leaves the earlier one's
/// other numbered files, and a warning names them: exactly the names the preview
/// numbers its frames with, regular files only, none removed.
#[test]
fn an_earlier_pictures_other_frames_are_named_and_left() {
    let dir = run_folder(FLOOR, 10, Some(3));
    let preview = |frames: &str, out: &str, extra: &[&str]| {
        let mut args = vec!["preview", "floor.walls", "--particles", "run"];
        args.extend(["--frames", frames, "--out", out, "--force"]);
        args.extend(extra);
        walls_sim(dir.path(), &args)
    };
    // The k-th numbered file of the picture `out`.
    let numbered = |out: &str, k: usize| match out {
        "m.svg" => format!("m-{k:03}.svg"),
        "m.pov" => format!("m-{k:03}.pov"),
        _ => format!("m/m_{k:06}.vtp"),
    };
    let cases: [(&str, &[&str]); 3] = [("m.svg", &["--stills"]), ("m.pov", &[]), ("m.pvd", &[])];
    for (out, extra) in cases {
        let frame = |k| numbered(out, k);
        let first = preview("10", out, extra);
        assert!(first.status.success(), "{}", stderr(&first));
        assert!(!stderr(&first).contains("warning"), "{}", stderr(&first));
        let again = preview("3", out, extra);
        assert!(again.status.success(), "{}", stderr(&again));
        let e = stderr(&again);
        assert!(
            e.contains(&format!(
                "warning: {} … {}, 7 files named as this picture's numbered frames but not written by it",
                frame(3),
                frame(9)
            )),
            "{e}"
        );
        for k in 0..10 {
            assert!(dir.path().join(frame(k)).is_file(), "{}", frame(k));
        }
    }
    // Only exact names, only regular files: `m-0003.svg`, `m-3.svg`, a folder and a
    // link named as a frame are not named; an SVG without stills names the stills left.
    for name in ["m-0003.svg", "m-3.svg", "m-x03.svg"] {
        std::fs::write(dir.path().join(name), "mine").unwrap();
    }
    for k in 3..10 {
        std::fs::remove_file(dir.path().join(format!("m-{k:03}.svg"))).unwrap();
    }
    std::fs::create_dir(dir.path().join("m-005.svg")).unwrap();
    #[cfg(unix)]
    std::os::unix::fs::symlink("m-0003.svg", dir.path().join("m-006.svg")).unwrap();
    let out = preview("2", "m.svg", &[]);
    assert!(out.status.success(), "{}", stderr(&out));
    let e = stderr(&out);
    assert!(
        e.contains("warning: m-000.svg, m-001.svg and m-002.svg named as"),
        "{e}"
    );
    let out = preview("3", "m.svg", &["--stills"]);
    assert!(!stderr(&out).contains("warning"), "{}", stderr(&out));
}

#[test]
fn a_ss_output_whose_header_lies_is_refused_before_it_is_read() {
    // pkdgrav's name (`NAME.STEP`, no `.ss`): a header of one particle in a 2 GiB file.
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("floor.walls"), "wall type plane\n").unwrap();
    let mut header = 0f64.to_be_bytes().to_vec();
    header.extend(1i32.to_be_bytes());
    header.extend((-1i32).to_be_bytes());
    std::fs::write(dir.path().join("ss.00100"), header).unwrap();
    let file = std::fs::OpenOptions::new()
        .write(true)
        .open(dir.path().join("ss.00100"))
        .unwrap();
    file.set_len(2 << 30).unwrap();
    let started = std::time::Instant::now();
    let out = walls_sim(
        dir.path(),
        &[
            "preview",
            "floor.walls",
            "--particles",
            "ss.00100",
            "--out",
            "m.svg",
        ],
    );
    assert!(
        started.elapsed().as_secs_f64() < 1.0,
        "{:?}",
        started.elapsed()
    );
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(
        stderr(&out),
        "walls-sim: error: ss.00100: byte 8: 1 particles of 96 bytes need 112 bytes, the file has 2147483648\n"
    );
    assert!(!dir.path().join("m.svg").exists());
}

/// A `particles.csv` of a header alone, a particle file of no particles and a trajectory
/// whose step holds a particle twice (two runs written into one file) still draw, and
/// each is said on standard error.
#[test]
fn empty_and_doubled_particle_files_are_drawn_and_said() {
    let dir = run_folder(FLOOR, 0, Some(3));
    let preview = |particles: &str, out: &str| {
        walls_sim(
            dir.path(),
            &[
                "preview",
                "floor.walls",
                "--particles",
                particles,
                "--out",
                out,
            ],
        )
    };
    let out = preview("run", "a.svg");
    assert!(out.status.success(), "{}", stderr(&out));
    let csv = Path::new("run").join("particles.csv");
    assert_eq!(
        stderr(&out),
        format!(
            "walls-sim: warning: {}: no rows after its header: the run wrote no output into it\n",
            csv.display()
        )
    );
    std::fs::write(dir.path().join("none.csv"), "mass,radius,x,y,z,vx,vy,vz\n").unwrap();
    let out = preview("none.csv", "b.svg");
    assert!(out.status.success(), "{}", stderr(&out));
    assert_eq!(
        stderr(&out),
        "walls-sim: warning: none.csv: it holds no particles\n"
    );
    let twice = run_folder(FLOOR, 2, Some(3));
    let text = read(twice.path(), "run/particles.csv");
    let doubled = text.clone() + text.lines().nth(2).unwrap() + "\n";
    std::fs::write(dir.path().join("run/particles.csv"), doubled).unwrap();
    let out = preview("run", "c.svg");
    assert!(out.status.success(), "{}", stderr(&out));
    let said = stderr(&out);
    let warning = format!(
        "walls-sim: warning: {}: particle 0 is in output step 1 twice (two runs written into one file?); both are drawn\n",
        csv.display()
    );
    assert!(said.starts_with(&warning), "{said}");
    assert!(said.ends_with("2 frames, one per output\n"), "{said}");
}
