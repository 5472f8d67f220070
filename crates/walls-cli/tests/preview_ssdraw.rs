//! `walls-sim preview --ssdraw FILE` end to end (docs/preview.md, "ssdraw's view"): an
//! ssdraw.par in pkdgrav's own layout draws, with what it does not use told on standard
//! error; `Wall time offset` 0 means the walls file's own `time`; a value that does not
//! read stops the preview at `ssdraw.par:LINE:` with exit 2; and hostile files (a 10 MB
//! line, a device, control characters, bytes that are not UTF-8, an empty file, numbers
//! beyond a double) end in a clear message, never a panic.

use std::path::Path;
use std::process::{Command, Output};

/// A disk of ssdraw's gold moving up at speed 1, in a file whose own `time` is 0.5.
const WALLS: &str = "time 0.5\nwall type disk\n  radius 1\n  color 8\n  velocity 0 0 1\n";

/// An ssdraw.par as pkdgrav's tests write them (soft_sphere_cube's layout: labels padded
/// with blanks, `!` comments after the values); `Wall time offset` is appended.
const SSDRAW: &str = "\
Length unit             1.0             ! Length unit (AU)
Time unit               1.0             ! Time unit (yr/2pi)
Frame size              512 512         ! Frame size in pixels (x y)
Light source option     0               ! 0 = at camera
Light source position   0 0 1           ! Abs or rel coords
Light source intensity  1.0             ! 0 to 1
Camera option           0               ! 0 = abs, 1 = rel
Camera position         1e-12 2e-12 3e-12 ! Abs or rel coords of camera
View option             0               ! 0 = look at, 1 = view direction
Look at/view direction  0 0 0           ! Abs or rel coords
Focus distance          0               ! 0 = auto
Sky vector              0 0 1           ! The up vector
Starting view size      0               ! 0 = auto
View scaling criterion  0
Scale length by radius? 0               ! 0 = no
View target zoom factor 1
Particle shape          1               ! 0 point, 1 solid sphere, 2 POV-Ray
Particle radius scaling 1
Color override          0               ! 0 = none
Draw color first        0
Start at COM?           0               ! 0 = no
Inertia control         0
Use sliding patches?    0               ! 0 = no
Wall data file          walls.dat       ! beside this file
";

fn walls_sim(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_walls-sim"))
        .args(args)
        .current_dir(dir)
        .env("NO_COLOR", "1")
        .output()
        .unwrap()
}

/// A folder with `walls.dat` and `ssdraw.par` holding `ssdraw`.
fn case(ssdraw: impl AsRef<[u8]>) -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("walls.dat"), WALLS).unwrap();
    std::fs::write(dir.path().join("ssdraw.par"), ssdraw).unwrap();
    dir
}

fn stderr(out: &Output) -> String {
    String::from_utf8(out.stderr.clone()).unwrap()
}

/// The `<Points>` of the `.vtp` that `args` write to `out.vtp`: where the walls are.
fn points(dir: &Path, args: &[&str]) -> String {
    let mut all = vec!["preview", "walls.dat", "--out", "out.vtp", "--force"];
    all.extend(args);
    let out = walls_sim(dir, &all);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let vtp = std::fs::read_to_string(dir.join("out.vtp")).unwrap();
    let start = vtp.find("<Points>").unwrap();
    let end = vtp.find("</Points>").unwrap();
    vtp[start..end].to_string()
}

#[test]
fn a_pkdgrav_style_ssdraw_par_draws() {
    let dir = case(format!(
        "{SSDRAW}Wall time offset        0               ! 0: the walls file's time\n"
    ));
    // The walls file is the par's `Wall data file`, beside it.
    let out = walls_sim(
        dir.path(),
        &["preview", "--ssdraw", "ssdraw.par", "--size", "40", "30"],
    );
    let err = stderr(&out);
    assert_eq!(out.status.code(), Some(0), "{err}");
    let svg = String::from_utf8(out.stdout).unwrap();
    assert!(
        svg.starts_with("<?xml") && svg.contains("<polygon"),
        "{svg}"
    );
    // Gold is ssdraw's (255, 215, 0), shaded: more red than green, no blue.
    assert!(svg.contains("fill=\"#debb00\""), "{svg}");
    assert!(!err.contains("error"), "{err}");
    assert!(
        err.contains("ssdraw.par:7: `Camera option` `0` is read but not followed"),
        "{err}"
    );
    assert!(err.contains("`Length unit` (line 1)"), "{err}");
    assert!(
        !err.contains("no line"),
        "every label ssdraw needs is there: {err}"
    );
}

#[test]
fn an_unreadable_vector_stops_the_preview_at_its_line() {
    let bad = SSDRAW.replace("1e-12 2e-12 3e-12", "1e-12 2e-12 3e-12x");
    let dir = case(&bad);
    let out = walls_sim(
        dir.path(),
        &["preview", "walls.dat", "--ssdraw", "ssdraw.par"],
    );
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty(), "nothing is drawn");
    assert_eq!(
        stderr(&out),
        "walls-sim: error: ssdraw.par:8: `Camera position` takes 3 numbers, not `1e-12 2e-12 3e-12x`: `3e-12x` is not a number\n"
    );
}

#[test]
fn a_missing_label_is_named_and_the_preview_draws() {
    let without = SSDRAW.replace(
        "Sky vector              0 0 1           ! The up vector\n",
        "",
    );
    let dir = case(&without);
    let out = walls_sim(dir.path(), &["preview", "--ssdraw", "ssdraw.par"]);
    assert_eq!(out.status.code(), Some(0));
    assert!(!out.stdout.is_empty());
    assert!(
        stderr(&out).contains(
            "walls-sim: warning: ssdraw.par: no lines for `Sky vector`, `Wall time offset`: ssdraw aborts at the first it asks for; walls-sim preview draws all the same\n"
        ),
        "{}",
        stderr(&out)
    );
}

#[test]
fn the_wall_time_offset_0_is_the_walls_files_own_time() {
    let dir = case("");
    let at = |t: &str| points(dir.path(), &["--time", t]);
    let with = |offset: Option<&str>| {
        let text = match offset {
            Some(o) => format!("{SSDRAW}Wall time offset        {o}      ! offset\n"),
            None => SSDRAW.to_string(),
        };
        std::fs::write(dir.path().join("ssdraw.par"), text).unwrap();
        points(dir.path(), &["--time", "0.25", "--ssdraw", "ssdraw.par"])
    };
    let (t075, t1) = (at("0.75"), at("1"));
    assert_ne!(t075, t1);
    // A frame's walls are at its time plus the offset; 0 (or no line) stands for the
    // walls file's `time 0.5`.
    assert_eq!(with(Some("0")), t075);
    assert_eq!(with(None), t075);
    assert_eq!(with(Some("0.75")), t1);
    // Without --ssdraw the walls file's `time` is not added.
    assert_eq!(at("0.25"), points(dir.path(), &["--time", "0.25"]));
    assert_ne!(at("0.25"), t075);
}

#[test]
fn hostile_files_end_in_clear_messages() {
    for (name, bytes, code, says) in [
        (
            "a 10 MB line",
            [
                b"Camera position 1 2 3 ! ".as_slice(),
                &vec![b'x'; 10_000_000],
            ]
            .concat(),
            2,
            "walls-sim: error: ssdraw.par:1: longer than the 256 characters a line ssdraw reads (it would split the line)\n",
        ),
        (
            "1001 lines",
            "!\n".repeat(1001).into_bytes(),
            2,
            "walls-sim: error: ssdraw.par:1001: ssdraw reads at most 1000 lines; this file has more\n",
        ),
        (
            "1e400",
            b"Sky vector 0 0 1e400\n".to_vec(),
            2,
            "walls-sim: error: ssdraw.par:1: `Sky vector` takes 3 numbers, not `0 0 1e400`: `1e400` is too large for a double: pkdgrav reads it as infinity\n",
        ),
        (
            "1e-400",
            b"\n\nLook at/view direction 1e-400 0 0\n".to_vec(),
            2,
            "walls-sim: error: ssdraw.par:3: `Look at/view direction` takes 3 numbers, not `1e-400 0 0`: `1e-400` is too small for a double: pkdgrav reads it as 0\n",
        ),
        (
            "control characters",
            b"Camera position 1 2 \x1b]0;owned\x07\n".to_vec(),
            2,
            "walls-sim: error: ssdraw.par:1: `Camera position` takes 3 numbers, not `1 2 \\u{1b}]0;owned\\u{7}`: `\\u{1b}]0;owned\\u{7}` is not a number\n",
        ),
        (
            "bytes that are not UTF-8 in a value",
            b"Wall data file \xff\xfe.walls\n".to_vec(),
            2,
            "walls-sim: error: ssdraw.par:1: `Wall data file`'s value is not UTF-8 text\n",
        ),
        (
            "a label with trailing junk",
            b"Aspect ratiox 2\n".to_vec(),
            2,
            "walls-sim: error: ssdraw.par:1: `Aspect ratio` takes 1 number, not `x 2`: `x` is not a number\n",
        ),
    ] {
        let dir = case(&bytes);
        let out = walls_sim(
            dir.path(),
            &["preview", "walls.dat", "--ssdraw", "ssdraw.par"],
        );
        assert_eq!(out.status.code(), Some(code), "{name}: {}", stderr(&out));
        assert_eq!(stderr(&out), says, "{name}");
        assert!(out.stdout.is_empty(), "{name}");
    }
    // A wall time offset that takes the walls beyond what a picture can draw: the
    // message says where the time came from.
    let dir = case("Wall time offset 1e308\n");
    let out = walls_sim(
        dir.path(),
        &["preview", "walls.dat", "--ssdraw", "ssdraw.par"],
    );
    assert_eq!(out.status.code(), Some(2));
    assert!(
        stderr(&out).contains(
            "nothing was drawn (each frame's walls are drawn 1e308 later than its time: the ssdraw.par's `Wall time offset`"
        ),
        "{}",
        stderr(&out)
    );
    // An empty file: every label ssdraw always reads is missing, named; the walls of
    // the command line are drawn.
    let dir = case("");
    let out = walls_sim(
        dir.path(),
        &["preview", "walls.dat", "--ssdraw", "ssdraw.par"],
    );
    assert_eq!(out.status.code(), Some(0));
    assert!(
        stderr(&out).contains("no lines for `Length unit`, `Time unit`"),
        "{}",
        stderr(&out)
    );
    // Bytes that are not UTF-8, and control characters, in lines the preview does not
    // read are told, escaped; the file is read.
    let dir = case(b"Caf\xe9 \x1b[2J\nSky vector 0 0 1 ! \xff\n");
    let out = walls_sim(
        dir.path(),
        &["preview", "walls.dat", "--ssdraw", "ssdraw.par"],
    );
    assert_eq!(out.status.code(), Some(0));
    let err = stderr(&out);
    assert!(
        err.contains("ssdraw.par:1: `Caf\u{fffd} \\u{1b}[2J` starts with no label ssdraw reads"),
        "{err}"
    );
    assert!(
        !err.contains('\x1b'),
        "no control character reaches the terminal: {err:?}"
    );
}

#[test]
fn files_that_cannot_be_read_are_usage_errors() {
    let dir = case("");
    // A device is read no further than a file ssdraw could read: its first line is too
    // long.
    let out = walls_sim(
        dir.path(),
        &["preview", "walls.dat", "--ssdraw", "/dev/zero"],
    );
    assert_eq!(out.status.code(), Some(2));
    assert!(
        stderr(&out).starts_with("walls-sim: error: /dev/zero:1: "),
        "{}",
        stderr(&out)
    );
    for (path, says) in [
        (".", "walls-sim: error: cannot read .: "),
        ("missing.par", "walls-sim: error: cannot read missing.par: "),
    ] {
        let out = walls_sim(dir.path(), &["preview", "walls.dat", "--ssdraw", path]);
        assert_eq!(out.status.code(), Some(2), "{path}");
        assert!(stderr(&out).starts_with(says), "{path}: {}", stderr(&out));
    }
}
