//! Throughput of linting and formatting against file size: chart `throughput`.
//!
//! Generates walls files of 10 to 300,000 walls, a spacecraft-like mix: mostly triangles
//! (a hull, as in `crates/walls-cli/benches/hull.rs`), one wall in 50 a plane, disk or
//! finite cylinder with a trailing comment, a comment every 100 walls and a `defaults`
//! block every 1,000. For each file it times, in this process:
//!
//! - *lint*: [`walls_ide::check_bytes`], everything `walls-lint` does to one file (decode,
//!   parse, resolve the scene, check, sort the diagnostics);
//! - *format*: [`walls_format::format_text`], parse and lay out, what `walls-fmt` does;
//! - *parse only*: [`walls_syntax::parse`], lexing, tree and syntax checks;
//!
//! and, as a separate process, *walls-lint binary*: the release `walls-lint` run on the
//! file written to a temporary folder (start-up, reading the file and the report
//! included). The binary is built first with `cargo build --release -p walls-cli`.
//!
//! Each figure is the file's bytes over the median time of one run, in MB/s (10⁶ bytes a
//! second). Runs are timed in batches long enough to time (5 ms or more, so small files
//! are repeated thousands of times), inputs prepared and outputs freed outside the
//! timed part; at least 50 ms is timed per figure. Runs are timed by CPU time (user
//! and system, page faults included), so that other work on a busy machine does not
//! count: in process, that of the measuring thread (`CLOCK_THREAD_CPUTIME_ID`, on
//! Unix); for the binary, that of the finished child processes (`/proc/self/stat`, on
//! Linux, in 10 ms ticks, so its batches last at least 0.5 s). Where these are not
//! available, wall time is used. The table printed also gives the binary's wall time.
//! Like the tools, this binary uses mimalloc. Run with
//! `cargo run --release -p walls-charts --bin throughput`, on a quiet machine.

use std::fmt::Write as _;
use std::hint::black_box;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};
use walls_charts::{Chart, Mark, Series};
use walls_model::Options;

/// mimalloc, as in `walls-lint` and `walls-fmt`.
#[global_allocator]
static GLOBAL: mimalloc::MiMalloc = mimalloc::MiMalloc;

/// The numbers of walls of the generated files.
const SIZES: [usize; 6] = [10, 100, 1_000, 10_000, 100_000, 300_000];

/// The shortest timed batch.
const MIN_BATCH: Duration = Duration::from_millis(5);

/// The least total time measured for one figure.
const MIN_TOTAL: Duration = Duration::from_millis(50);

/// The time budget of one figure, beyond which no more samples are taken (at least
/// [`MIN_SAMPLES`] are).
const BUDGET: Duration = Duration::from_millis(1500);

/// The fewest samples of which the median is taken.
const MIN_SAMPLES: usize = 5;

/// The most samples taken.
const MAX_SAMPLES: usize = 31;

/// A deterministic file of `n` walls: mostly triangles, with planes, disks and finite
/// cylinders, comments and `defaults` blocks. It lints clean with `max_walls >= n`.
fn mixed(n: usize) -> String {
    let mut out = String::with_capacity(n * 120 + 256);
    out.push_str("# generated spacecraft: hull panels and fittings\nlengthunit 1\ntimeunit 1\n");
    let mut x: u64 = 0x2545_F491_4F6C_DD1D;
    let mut next = || {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        (x % 20_000) as f64 / 1e4 - 1.0
    };
    for i in 0..n {
        if i % 1_000 == 0 {
            let k = i / 1_000;
            writeln!(
                out,
                "\n# section {k}\ndefaults\n  color {}\n  epsn 0.8\n  epst 0.9\n  transparency 0.{}\n",
                16 + k % 240,
                k % 10
            )
            .unwrap();
        }
        if i % 100 == 0 {
            writeln!(out, "# panel {}", i / 100).unwrap();
        }
        match (i % 50 == 0).then_some(i / 50 % 3) {
            Some(0) => writeln!(
                out,
                "wall type plane  # bulkhead\n  origin {:.4} {:.4} {:.4}\n  orient 0 0 1",
                next(),
                next(),
                next()
            ),
            Some(1) => writeln!(
                out,
                "wall type disk  # hatch\n  origin {:.4} {:.4} {:.4}\n  orient 1 0 0\n  radius 0.25\n  hole-radius 0.05",
                next(),
                next(),
                next()
            ),
            Some(_) => writeln!(
                out,
                "wall type cylinder-finite  # strut\n  origin {:.4} {:.4} {:.4}\n  orient 0 1 0\n  radius 0.02\n  length 0.5",
                next(),
                next(),
                next()
            ),
            None => writeln!(
                out,
                "wall type triangle\n  origin {:.4} {:.4} {:.4}\n  vertex1 {:.4} {:.4} {:.4}\n  vertex2 {:.4} {:.4} {:.4}",
                next(),
                next(),
                next(),
                next(),
                next(),
                next(),
                next(),
                next(),
                next()
            ),
        }
        .unwrap();
    }
    out
}

/// What a figure is timed by.
#[derive(Clone, Copy)]
enum Clock {
    /// Time on the CPU of this thread.
    Cpu,
    /// Time on the CPU of the child processes that have finished.
    Children,
    /// Time on the wall.
    Wall,
}

impl Clock {
    /// The clock's reading now: since some fixed moment, only differences count.
    fn now(self) -> Duration {
        static ORIGIN: std::sync::OnceLock<Instant> = std::sync::OnceLock::new();
        let cpu = match self {
            Clock::Cpu => thread_cpu_time(),
            Clock::Children => children_cpu_time(),
            Clock::Wall => None,
        };
        cpu.unwrap_or_else(|| ORIGIN.get_or_init(Instant::now).elapsed())
    }

    /// The shortest batch this clock times well.
    fn min_batch(self) -> Duration {
        match self {
            Clock::Children if children_cpu_time().is_some() => Duration::from_millis(500),
            _ => MIN_BATCH,
        }
    }
}

/// The CPU time (user and system) of the finished child processes, on Linux.
#[cfg(unix)]
fn children_cpu_time() -> Option<Duration> {
    let stat = std::fs::read_to_string("/proc/self/stat").ok()?;
    // After the command's name in parentheses: fields 3 on; cutime and cstime are 16, 17.
    let fields: Vec<&str> = stat.rsplit_once(')')?.1.split_whitespace().collect();
    let ticks: u64 = fields.get(13)?.parse::<u64>().ok()? + fields.get(14)?.parse::<u64>().ok()?;
    let per_second = rustix::param::clock_ticks_per_second();
    (per_second > 0).then(|| Duration::from_secs_f64(ticks as f64 / per_second as f64))
}

/// The CPU time of the finished child processes: not measured here.
#[cfg(not(unix))]
fn children_cpu_time() -> Option<Duration> {
    None
}

/// The CPU time of the calling thread (user and system), on Unix.
#[cfg(unix)]
fn thread_cpu_time() -> Option<Duration> {
    use rustix::time::{ClockId, clock_gettime};
    let t = clock_gettime(ClockId::ThreadCPUTime);
    Some(Duration::new(
        u64::try_from(t.tv_sec).ok()?,
        u32::try_from(t.tv_nsec).ok()?,
    ))
}

/// The CPU time of the calling thread: not measured here.
#[cfg(not(unix))]
fn thread_cpu_time() -> Option<Duration> {
    None
}

/// The median time by `clock` of one call of `run` on an input from `prepare`. Calls
/// are timed in batches of at least [`MIN_BATCH`]; the inputs of a batch are prepared
/// before it and its outputs dropped after it.
fn median_time<I, O>(
    clock: Clock,
    mut prepare: impl FnMut() -> I,
    mut run: impl FnMut(I) -> O,
) -> Duration {
    let min_batch = clock.min_batch();
    // Calibrate (and warm up): how many calls fill a batch.
    let start = clock.now();
    let mut calls = 0u32;
    while calls == 0 || clock.now() - start < min_batch {
        let input = prepare();
        let t = clock.now();
        drop(black_box(run(input)));
        calls += 1;
        if calls == 1 && clock.now() - t >= min_batch {
            break;
        }
    }
    let one = (clock.now() - start) / calls;
    let batch = (min_batch.as_secs_f64() / one.as_secs_f64().max(1e-9)).ceil() as usize;
    let batch = batch.max(1);
    let mut samples: Vec<Duration> = Vec::new();
    let mut total = Duration::ZERO;
    while samples.len() < MIN_SAMPLES
        || total < MIN_TOTAL
        || (total < BUDGET && samples.len() < MAX_SAMPLES)
    {
        let inputs: Vec<I> = (0..batch).map(|_| prepare()).collect();
        let mut outputs: Vec<O> = Vec::with_capacity(batch);
        let t = clock.now();
        for input in inputs {
            outputs.push(black_box(run(black_box(input))));
        }
        let elapsed = clock.now() - t;
        drop(outputs);
        total += elapsed;
        samples.push(elapsed / batch as u32);
    }
    samples.sort();
    samples[samples.len() / 2]
}

/// MB/s (10⁶ bytes a second) of `bytes` done in `time`.
fn mb_per_s(bytes: usize, time: Duration) -> f64 {
    bytes as f64 / time.as_secs_f64() / 1e6
}

/// Builds the release `walls-lint` beside this binary and returns its path, or `None`
/// (with a note) when that fails.
fn build_walls_lint() -> Option<PathBuf> {
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let built = Command::new(cargo)
        .args([
            "build",
            "--release",
            "--quiet",
            "-p",
            "walls-cli",
            "--bin",
            "walls-lint",
        ])
        .status();
    let exe = std::env::current_exe()
        .ok()?
        .with_file_name(format!("walls-lint{}", std::env::consts::EXE_SUFFIX));
    match built {
        Ok(status) if status.success() && exe.is_file() => Some(exe),
        other => {
            eprintln!(
                "throughput: no walls-lint binary ({other:?}, looked for {}); skipping that series",
                exe.display()
            );
            None
        }
    }
}

/// The median time by `clock` of the `walls-lint` binary `exe` on the file `path` of
/// `walls` walls.
fn binary_time(clock: Clock, exe: &Path, path: &Path, walls: usize) -> Duration {
    let max_walls = walls.max(20).to_string();
    median_time(
        clock,
        || (),
        |()| {
            let status = Command::new(exe)
                .args(["--max-walls", &max_walls, "--color", "never"])
                .arg(path)
                .stdout(Stdio::null())
                .stderr(Stdio::null())
                .status()
                .expect("walls-lint runs");
            assert!(status.success(), "walls-lint found errors in {path:?}");
        },
    )
}

fn main() -> std::io::Result<()> {
    let exe = build_walls_lint();
    let dir = std::env::temp_dir().join(format!("walls-throughput-{}", std::process::id()));
    std::fs::create_dir_all(&dir)?;
    let format_options = walls_format::FormatOptions::default();
    let (mut lint, mut format, mut parse, mut binary) = (vec![], vec![], vec![], vec![]);
    println!(
        "{:>8} {:>11} {:>10} {:>10} {:>10} {:>10} {:>10}   (MB/s)",
        "walls", "bytes", "lint", "format", "parse", "bin (cpu)", "bin (wall)"
    );
    for &n in &SIZES {
        let text = mixed(n);
        let bytes = text.len();
        let options = Options {
            max_walls: n.max(20),
            ..Options::default()
        };
        let checked = walls_ide::check_bytes(text.as_bytes().to_vec(), &options);
        assert!(
            checked.diagnostics.is_empty(),
            "the generated file of {n} walls should lint clean: {:?}",
            checked.diagnostics.first()
        );
        assert_eq!(checked.scene.walls.len(), n);
        assert!(walls_format::format_text(&text, &format_options).is_ok());

        let t_lint = median_time(
            Clock::Cpu,
            || text.as_bytes().to_vec(),
            |b| walls_ide::check_bytes(b, &options),
        );
        let t_format = median_time(
            Clock::Cpu,
            || (),
            |()| walls_format::format_text(&text, &format_options),
        );
        let t_parse = median_time(Clock::Cpu, || (), |()| walls_syntax::parse(text.as_str()));
        let x = bytes as f64;
        lint.push((x, mb_per_s(bytes, t_lint)));
        format.push((x, mb_per_s(bytes, t_format)));
        parse.push((x, mb_per_s(bytes, t_parse)));
        let t_binary = exe.as_ref().map(|exe| {
            let path = dir.join(format!("mixed-{n}.walls"));
            std::fs::write(&path, &text)?;
            let cpu = binary_time(Clock::Children, exe, &path, n);
            let wall = binary_time(Clock::Wall, exe, &path, n);
            std::fs::remove_file(&path)?;
            Ok::<_, std::io::Error>((cpu, wall))
        });
        let binary_figure = match t_binary.transpose()? {
            Some((cpu, wall)) => {
                binary.push((x, mb_per_s(bytes, cpu)));
                format!(
                    "{:10.2} {:10.2}",
                    mb_per_s(bytes, cpu),
                    mb_per_s(bytes, wall)
                )
            }
            None => format!("{:>10} {:>10}", "-", "-"),
        };
        println!(
            "{n:>8} {bytes:>11} {:10.1} {:10.1} {:10.1} {binary_figure}",
            mb_per_s(bytes, t_lint),
            mb_per_s(bytes, t_format),
            mb_per_s(bytes, t_parse),
        );
    }
    std::fs::remove_dir_all(&dir)?;

    let mut series = vec![
        Series::new("lint", lint, Mark::Line),
        Series::new("format", format, Mark::Line),
        Series::new("parse only", parse, Mark::Line),
    ];
    if !binary.is_empty() {
        series.push(Series::new(
            "walls-lint binary (whole process)",
            binary,
            Mark::Line,
        ));
    }
    walls_charts::write(
        &walls_charts::out_dir(),
        &Chart {
            name: "throughput".into(),
            title: "Throughput against file size (generated hull with fittings)".into(),
            x_label: "file size (bytes)".into(),
            y_label: "MB/s (median)".into(),
            log_x: true,
            log_y: true,
        },
        &series,
    )
}
