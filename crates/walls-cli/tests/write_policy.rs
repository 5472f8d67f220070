//! Every command that writes a file, against every kind of place it could be asked to
//! write to (docs/reliability.md, "Files: what the tools write"): a device, a FIFO, a
//! symbolic link, a hard link, a read-only file, one of its own inputs and a full disk.
//! Each cell of the matrix is what the command did (its exit status) and what became of
//! the place; the whole matrix is a snapshot (`write_policy__matrix.snap`), so that any
//! change of behaviour shows, and the policy's promises are asserted cell by cell.

#![cfg(unix)]

use std::fmt::Write as _;
use std::os::unix::fs::{FileTypeExt, MetadataExt, PermissionsExt};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

/// The walls file the commands read (and walls-fmt and `walls-lint --fix` rewrite).
const MESSY: &str = "wall type plane\n origin 0 0 0\n  radius 1\n";
/// A mesh of one triangle.
const MESH: &str = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
/// One particle falling onto the floor.
const PARTICLES: &str = "mass,radius,x,y,z,vx,vy,vz\n1,0.1,0,0,0.3,0,0,0\n";
/// What a place holds before the command runs.
const OLD: &str = "old contents\n";

fn bin(name: &str) -> PathBuf {
    match name {
        "walls-lint" => env!("CARGO_BIN_EXE_walls-lint").into(),
        "walls-fmt" => env!("CARGO_BIN_EXE_walls-fmt").into(),
        "walls-mesh" => env!("CARGO_BIN_EXE_walls-mesh").into(),
        _ => env!("CARGO_BIN_EXE_walls-sim").into(),
    }
}

/// A writing command: how to run it with its output at `place` (a path relative to the
/// case's folder), and the inputs it reads there.
struct Writer {
    name: &'static str,
    /// The command line, `{}` standing for the place.
    args: &'static [&'static str],
    /// The place, relative to the case's folder.
    place: &'static str,
    /// Whether it rewrites the file it reads (walls-fmt, --fix): then "its own input" is
    /// its purpose, not a hazard.
    rewrites: bool,
    /// Whether the place is one the command names in a folder (not the user): a link
    /// there is refused rather than written through.
    in_folder: bool,
    /// The command line that reads the place as an input, for "its own input".
    own_input: Option<&'static [&'static str]>,
}

const WRITERS: &[Writer] = &[
    Writer {
        name: "walls-fmt FILE",
        args: &["walls-fmt", "{}"],
        place: "w.walls",
        rewrites: true,
        in_folder: false,
        own_input: None,
    },
    Writer {
        name: "walls-lint --fix FILE",
        args: &["walls-lint", "--isolated", "--fix", "{}"],
        place: "w.walls",
        rewrites: true,
        in_folder: false,
        own_input: None,
    },
    Writer {
        name: "walls-mesh -o OUT --force",
        args: &["walls-mesh", "tri.obj", "-o", "{}", "--force"],
        place: "out.walls",
        rewrites: false,
        in_folder: false,
        own_input: Some(&["walls-mesh", "{}", "-o", "{}", "--force"]),
    },
    Writer {
        name: "walls-sim run --out DIR --force (particles.csv)",
        args: &[
            "walls-sim",
            "run",
            "floor.walls",
            "--particles",
            "p.csv",
            "--t-end",
            "0.01",
            "--dt",
            "0.001",
            "--out",
            "o",
            "--force",
        ],
        place: "o/particles.csv",
        rewrites: false,
        in_folder: true,
        own_input: Some(&[
            "walls-sim",
            "run",
            "floor.walls",
            "--particles",
            "{}",
            "--t-end",
            "0.01",
            "--dt",
            "0.001",
            "--out",
            "o",
            "--force",
        ]),
    },
    Writer {
        name: "walls-sim run --ss-output --force (ss.00010)",
        args: &[
            "walls-sim",
            "run",
            "--par",
            "run.par",
            "--out",
            "o",
            "--ss-output",
            "--force",
        ],
        place: "o/ss.00010",
        rewrites: false,
        in_folder: true,
        own_input: Some(&[
            "walls-sim",
            "run",
            "--par",
            "run.par",
            "--particles",
            "{}",
            "--out",
            "o",
            "--ss-output",
            "--force",
        ]),
    },
    Writer {
        name: "walls-sim preview --out FILE.svg --force",
        args: &[
            "walls-sim",
            "preview",
            "floor.walls",
            "--out",
            "{}",
            "--force",
        ],
        place: "pic.svg",
        rewrites: false,
        in_folder: false,
        own_input: Some(&["walls-sim", "preview", "{}", "--out", "{}", "--force"]),
    },
    Writer {
        name: "walls-sim preview --out FILE.pov --force (walls.inc)",
        args: &[
            "walls-sim",
            "preview",
            "floor.walls",
            "--out",
            "scene.pov",
            "--force",
        ],
        place: "walls.inc",
        rewrites: false,
        in_folder: true,
        own_input: Some(&[
            "walls-sim",
            "preview",
            "{}",
            "--out",
            "scene.pov",
            "--force",
        ]),
    },
    Writer {
        name: "walls-sim preview --out FILE.pvd --force (a frame)",
        args: &[
            "walls-sim",
            "preview",
            "floor.walls",
            "--out",
            "m.pvd",
            "--frames",
            "2",
            "--until",
            "1",
            "--force",
        ],
        place: "m/m_000001.vtp",
        rewrites: false,
        in_folder: true,
        own_input: Some(&[
            "walls-sim",
            "preview",
            "floor.walls",
            "--particles",
            "{}",
            "--out",
            "m.pvd",
            "--frames",
            "2",
            "--until",
            "1",
            "--force",
        ]),
    },
];

/// The hazards: what the place is made before the command runs.
#[derive(Clone, Copy, PartialEq)]
enum Hazard {
    Device,
    Fifo,
    Symlink,
    HardLink,
    ReadOnly,
    OwnInput,
    FullDisk,
}

const HAZARDS: [(Hazard, &str); 7] = [
    (Hazard::Device, "device"),
    (Hazard::Fifo, "FIFO"),
    (Hazard::Symlink, "symlink"),
    (Hazard::HardLink, "hard link"),
    (Hazard::ReadOnly, "read-only"),
    (Hazard::OwnInput, "own input"),
    (Hazard::FullDisk, "full disk"),
];

/// A fresh case folder with the commands' inputs.
fn case() -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::write(d.join("w.walls"), MESSY).unwrap();
    std::fs::write(d.join("floor.walls"), "wall type plane\n").unwrap();
    std::fs::write(d.join("tri.obj"), MESH).unwrap();
    std::fs::write(d.join("p.csv"), PARTICLES).unwrap();
    std::fs::write(
        d.join("run.par"),
        "achWallsFile = floor.walls\nachInFile = p.csv\ndDelta = 0.001\nnSteps = 20\n\
         iOutInterval = 10\ndKn = 1e4\nbDoSelfGravity = 0\niForceOverrideOption = 2\n\
         iCheckInterval = 0\n",
    )
    .unwrap();
    std::fs::create_dir_all(d.join("o")).unwrap();
    std::fs::create_dir_all(d.join("m")).unwrap();
    dir
}

/// Runs `args` (`{}` replaced by `place`) in `dir`, with a file-size limit of 0 when
/// `full` (writes past it fail, as on a full disk); the exit status and standard error.
fn run(dir: &Path, args: &[&str], place: &str, full: bool) -> (i32, String) {
    let args: Vec<String> = args.iter().map(|a| a.replace("{}", place)).collect();
    let program = bin(&args[0]);
    let mut cmd = if full {
        let mut c = Command::new("bash");
        c.args(["-c", "trap '' XFSZ; ulimit -f 0; exec \"$0\" \"$@\""])
            .arg(program);
        c
    } else {
        Command::new(program)
    };
    let mut child = cmd
        .args(&args[1..])
        .current_dir(dir)
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    // Never a hang: a command still running after a minute fails the test.
    let start = std::time::Instant::now();
    while child.try_wait().unwrap().is_none() {
        if start.elapsed() > std::time::Duration::from_secs(60) {
            let _ = child.kill();
            panic!("{args:?} hung");
        }
        std::thread::sleep(std::time::Duration::from_millis(5));
    }
    let out = child.wait_with_output().unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// What a place is now, in a few words: `old` if it holds `old`.
fn what(path: &Path, old: &str) -> String {
    let Ok(m) = std::fs::symlink_metadata(path) else {
        return "missing".into();
    };
    let t = m.file_type();
    if t.is_symlink() {
        return "link kept".into();
    }
    if t.is_char_device() {
        return "device kept".into();
    }
    if t.is_fifo() {
        return "FIFO kept".into();
    }
    let text = std::fs::read_to_string(path).unwrap_or_default();
    let contents = if text == old { "old" } else { "new" };
    format!("{contents}, {} link(s), {:o}", m.nlink(), m.mode() & 0o777)
}

#[test]
fn matrix() {
    let mut table = String::from("| command | ");
    table.push_str(&HAZARDS.map(|(_, n)| n).join(" | "));
    table.push_str(" |\n|---|");
    table.push_str(&"---|".repeat(HAZARDS.len()));
    table.push('\n');
    for w in WRITERS {
        let _ = write!(table, "| {} |", w.name);
        for (hazard, _) in HAZARDS {
            let cell = cell(w, hazard);
            let _ = write!(table, " {cell} |");
        }
        table.push('\n');
    }
    insta::assert_snapshot!(table);
}

/// One cell: the command `w` against `hazard`, asserted against the policy; what it did.
fn cell(w: &Writer, hazard: Hazard) -> String {
    let dir = case();
    let d = dir.path();
    let place = d.join(w.place);
    // The place is made anew for the hazard (the rewriters' input is in the case).
    let _ = std::fs::remove_file(&place);
    // What it holds before: the rewriters' input, or an old file.
    let old = if w.rewrites { MESSY } else { OLD };
    let mut args = w.args;
    let mut full = false;
    match hazard {
        Hazard::Device => {
            let made = rustix::fs::mknodat(
                rustix::fs::CWD,
                &place,
                rustix::fs::FileType::CharacterDevice,
                rustix::fs::Mode::from_raw_mode(0o666),
                rustix::fs::makedev(1, 3),
            );
            if made.is_err() {
                // Not root: a link to /dev/null is the device to a writer that follows it.
                std::os::unix::fs::symlink("/dev/null", &place).unwrap();
            }
        }
        Hazard::Fifo => {
            if w.rewrites {
                // A rewriter reads its file first: a FIFO with nobody writing would block
                // the read, as it blocks `cat`; one with a writer is read, then refused.
                return rewriter_on_fifo(w, d);
            }
            mkfifo(&place);
        }
        Hazard::Symlink => {
            // To a file beside it: an output in a folder may not lead out of it.
            std::fs::write(place.with_file_name("real"), old).unwrap();
            std::os::unix::fs::symlink("real", &place).unwrap();
        }
        Hazard::HardLink => {
            std::fs::write(&place, old).unwrap();
            std::fs::hard_link(&place, d.join("other-name")).unwrap();
        }
        Hazard::ReadOnly => {
            std::fs::write(&place, old).unwrap();
            std::fs::set_permissions(&place, std::fs::Permissions::from_mode(0o444)).unwrap();
        }
        Hazard::OwnInput => match w.own_input {
            None => return "n/a (rewrites its input)".into(),
            Some(own) => {
                // The place holds a valid input of the kind the command reads there.
                let input = match w.place {
                    p if p.ends_with(".csv") || p.contains("ss.") || p.ends_with(".vtp") => {
                        PARTICLES
                    }
                    "out.walls" => MESH,
                    _ => "wall type plane\n",
                };
                std::fs::write(&place, input).unwrap();
                args = own;
                let (status, stderr) = run(d, args, w.place, false);
                let now = std::fs::read_to_string(&place).unwrap();
                assert_eq!(now, input, "{}: its input changed\n{stderr}", w.name);
                assert_eq!(status, 2, "{}: {stderr}", w.name);
                assert!(stderr.contains("reads it"), "{}: {stderr}", w.name);
                return "refused (2), input kept".to_string();
            }
        },
        Hazard::FullDisk => {
            std::fs::write(&place, old).unwrap();
            full = true;
        }
    }
    let (status, stderr) = run(d, args, w.place, full);
    let now = what(&place, old);
    let shown = format!("{} ({status}), {now}", verdict(status, &stderr));
    match hazard {
        Hazard::Device | Hazard::Fifo => {
            assert!(now.ends_with("kept"), "{}: {now}\n{stderr}", w.name);
            if !w.rewrites {
                assert_eq!(status, 2, "{}: {stderr}", w.name);
            }
        }
        Hazard::Symlink if w.in_folder => {
            assert_eq!(now, "link kept", "{}: {stderr}", w.name);
            assert_eq!(status, 2, "{}: {stderr}", w.name);
            let real = std::fs::read(place.with_file_name("real")).unwrap();
            assert_eq!(real, old.as_bytes(), "{}: written through the link", w.name);
            return format!("refused: a link ({status}), link and file kept");
        }
        Hazard::Symlink => {
            assert_eq!(now, "link kept", "{}: {stderr}", w.name);
            assert_eq!(status, 0, "{}: {stderr}", w.name);
            let real = std::fs::read(place.with_file_name("real")).unwrap();
            assert_ne!(
                real,
                old.as_bytes(),
                "{}: not written through the link",
                w.name
            );
            return format!("written through ({status}), link kept");
        }
        Hazard::HardLink | Hazard::ReadOnly => {
            assert_eq!(status, 2, "{}: {stderr}", w.name);
            let kept = std::fs::read_to_string(&place).unwrap();
            assert_eq!(kept, old, "{}: {stderr}", w.name);
        }
        Hazard::FullDisk => {
            assert_eq!(status, 2, "{}: {stderr}", w.name);
            assert!(
                stderr.contains("File too large") || stderr.contains("No space left"),
                "{}: {stderr}",
                w.name
            );
            // A whole file written to a new file and renamed leaves the old one; a file
            // written row by row ends on whole rows.
            let text = std::fs::read_to_string(&place).unwrap_or_default();
            assert!(text == old || text.ends_with('\n'), "{}: {text:?}", w.name);
        }
        Hazard::OwnInput => unreachable!(),
    }
    shown
}

/// Makes a FIFO at `path`.
fn mkfifo(path: &Path) {
    rustix::fs::mknodat(
        rustix::fs::CWD,
        path,
        rustix::fs::FileType::Fifo,
        rustix::fs::Mode::from_raw_mode(0o644),
        0,
    )
    .unwrap();
}

/// A rewriter given a FIFO that another process writes its text to.
fn rewriter_on_fifo(w: &Writer, d: &Path) -> String {
    let place = d.join(w.place);
    mkfifo(&place);
    let feeder = {
        let place = place.clone();
        std::thread::spawn(move || std::fs::write(place, MESSY))
    };
    let (status, stderr) = run(d, w.args, w.place, false);
    feeder.join().unwrap().unwrap();
    assert_eq!(status, 2, "{}: {stderr}", w.name);
    assert!(stderr.contains("FIFO"), "{}: {stderr}", w.name);
    assert_eq!(what(&place, MESSY), "FIFO kept");
    format!("read, refused ({status}), FIFO kept")
}

/// How the command ended: refused (with the reason's key words) or written.
fn verdict(status: i32, stderr: &str) -> &'static str {
    let refused = [
        ("character device", "refused: a device"),
        ("FIFO", "refused: a FIFO"),
        ("hard links", "refused: hard links"),
        ("read-only", "refused: read-only"),
        ("File too large", "failed: disk full"),
        ("No space left", "failed: disk full"),
    ];
    if status == 0 {
        return "done";
    }
    refused
        .iter()
        .find(|(k, _)| stderr.contains(k))
        .map_or("failed", |(_, v)| v)
}
