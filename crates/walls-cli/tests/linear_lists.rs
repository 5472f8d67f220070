//! Every list the command line takes is handled in time linear in its length:
//! `walls-lint`'s and `walls-fmt`'s files, `--include` and `--exclude`, and `walls-mesh
//! --set`, each with 100,000 entries (a quarter of that in a debug build;
//! `WALLS_LINEAR_SCALE` sets the factor), run in this process through
//! `walls_cli::entry` (100,000 arguments pass no `execve`). Four times the entries must
//! take less than eight times as long (linear time gives four, quadratic sixteen), the
//! best of two runs each; times under 50 ms count as 50 ms. The settings files' lists
//! are timed in crates/walls-config/tests/linear.rs. The times are printed
//! (`--nocapture`).

use std::ffi::OsString;
use std::path::Path;
use std::time::{Duration, Instant};

/// Times below this are noise: they count as this.
const FLOOR: Duration = Duration::from_millis(50);

/// The sizes' factor: `WALLS_LINEAR_SCALE`, else 1 in an optimised build and 0.25 in a
/// debug build.
fn scale() -> f64 {
    std::env::var("WALLS_LINEAR_SCALE")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(if cfg!(debug_assertions) { 0.25 } else { 1.0 })
}

type Tool = fn(Vec<OsString>) -> i32;

/// The arguments of a case for a number of entries.
type Args<'a> = &'a dyn Fn(usize) -> Vec<String>;

/// The time `tool` takes on the argv `program` then `args(n)`, and its status.
fn time(
    tool: Tool,
    program: &str,
    args: &dyn Fn(usize) -> Vec<String>,
    n: usize,
) -> (Duration, i32) {
    let argv: Vec<OsString> = std::iter::once(program.to_string())
        .chain(args(n))
        .map(OsString::from)
        .collect();
    let start = Instant::now();
    let status = tool(argv);
    (start.elapsed(), status)
}

#[test]
fn every_list_of_the_command_line_is_linear() {
    let n = ((100_000.0 * scale()) as usize).max(1000);
    // In memory where the machine has it: 100,000 files on a busy disk take minutes.
    let shm = Path::new("/dev/shm");
    let dir = if shm.is_dir() {
        tempfile::tempdir_in(shm)
    } else {
        tempfile::tempdir()
    }
    .unwrap();
    let root = dir.path();
    // The files to name, and a folder of two to walk with the globs.
    std::fs::create_dir_all(root.join("files")).unwrap();
    std::fs::create_dir_all(root.join("walked/g1")).unwrap();
    for i in 0..n {
        let path = root.join(format!("files/f{i}.walls"));
        std::fs::write(path, "wall type plane\n").unwrap();
    }
    for name in ["walked/f1.walls", "walked/g1/f2.walls"] {
        std::fs::write(root.join(name), "wall type plane\n").unwrap();
    }
    let stl = root.join("t.stl");
    std::fs::write(
        &stl,
        "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid t\n",
    )
    .unwrap();
    let folder = root.join("walked").display().to_string();
    let files = |n: usize| -> Vec<String> {
        (0..n)
            .map(|i| root.join(format!("files/f{i}.walls")).display().to_string())
            .collect()
    };
    let flags = |flag: &'static str, glob: &'static str| {
        let folder = folder.clone();
        move |n: usize| -> Vec<String> {
            let mut args: Vec<String> = (0..n)
                .map(|i| format!("--{flag}={}", glob.replace("N", &i.to_string())))
                .collect();
            args.extend(["--isolated".into(), folder.clone()]);
            args
        }
    };
    let out = |i: usize| root.join(format!("out{i}.walls")).display().to_string();
    let runs = std::cell::Cell::new(0);
    let sets = |n: usize| -> Vec<String> {
        runs.set(runs.get() + 1);
        let mut args: Vec<String> = (0..n).map(|i| format!("--set=color={}", i % 7)).collect();
        args.extend([stl.display().to_string(), "-o".into(), out(runs.get())]);
        args
    };
    let lint: Tool = walls_cli::entry::lint;
    let fmt: Tool = walls_cli::entry::fmt;
    let mesh: Tool = walls_cli::entry::mesh;
    let checked_files = |n: usize| {
        let mut args = files(n);
        args.insert(0, "--isolated".into());
        args
    };
    let fmt_files = |n: usize| {
        let mut args = files(n);
        args.insert(0, "--check".into());
        args
    };
    let include = flags("include", "fN.walls");
    let exclude = flags("exclude", "gN/");
    let cases: [(&str, Tool, &str, Args); 5] = [
        ("walls-lint FILE...", lint, "walls-lint", &checked_files),
        ("walls-fmt --check FILE...", fmt, "walls-fmt", &fmt_files),
        ("walls-lint --include", lint, "walls-lint", &include),
        ("walls-lint --exclude", lint, "walls-lint", &exclude),
        ("walls-mesh --set", mesh, "walls-mesh", &sets),
    ];
    let mut slow = Vec::new();
    for (name, tool, program, args) in cases {
        let mut best = [Duration::MAX; 2];
        for _ in 0..2 {
            for (k, size) in [n / 4, n].into_iter().enumerate() {
                let (t, status) = time(tool, program, args, size);
                assert_eq!(status, 0, "{name} with {size} entries");
                best[k] = best[k].min(t);
            }
        }
        println!(
            "{name}: {} entries {:.2?}, {n} entries {:.2?}",
            n / 4,
            best[0],
            best[1]
        );
        if best[1].max(FLOOR) >= best[0].max(FLOOR) * 8 {
            slow.push(format!("{name}: {:?} then {:?}", best[0], best[1]));
        }
    }
    assert!(slow.is_empty(), "not linear: {slow:?}");
}
