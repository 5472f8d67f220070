//! `walls-sim preview`: draws the walls (and particles) at a time, their motion over a
//! span, or a run's outputs as a movie: SVG, POV-Ray, VTK (a `.vtp`, or a ParaView
//! collection `.pvd` of frames) or an interactive HTML page ([`walls_preview`]). The
//! frames are built by [`crate::movie`]; [`output`] writes them in each format.

mod output;

use super::{error, exit_status, read_walls};
use crate::input::display_name;
use crate::movie::{self, Snapshot, VizSteps};
use crate::{Checked, ContactModel};
use walls_geometry::units::System;
use walls_sim::cli::ruled;

use std::path::{Path, PathBuf};
use walls_preview::ssdraw::SsdrawView;
use walls_sim::io::par::Rule;

/// The most frames `--frames` asks for.
const MOST_FRAMES: u64 = crate::movie::MOST_FRAMES as u64;

/// `walls-sim preview`: pictures of the walls at a time, or over a span.
#[derive(clap::Args)]
pub struct PreviewArgs {
    /// The walls file; `-` reads standard input. Without it, the --par file's
    /// achWallsFile, else the `Wall data file` of --ssdraw.
    #[arg(value_name = "FILE", required_unless_present_any = ["ssdraw", "par"])]
    pub file: Option<String>,
    /// A pkdgrav run directory's .par file: the walls file (achWallsFile) and the
    /// particles (achInFile) when not named here, each beside the .par file. A .par
    /// file pkdgrav's default build refuses is refused, as `walls-sim run --par` refuses
    /// it.
    #[arg(long, value_name = "FILE")]
    pub par: Option<String>,
    /// The pkdgrav build the --par file is read for, as `run --pkdgrav-build` takes it
    /// (default pkdgrav's own).
    #[arg(long = "pkdgrav-build", value_name = "OPTIONS", value_parser = walls_sim::cli::build, requires = "par")]
    pub pkdgrav_build: Option<walls_sim::build::Build>,
    /// ssdraw's view: an ssdraw.par (read as ssdraw reads it) whose camera position,
    /// look-at point, sky vector, wall data file, wall time offset and aspect ratio the
    /// pictures take (--view, --up and --size win over it).
    #[arg(long, value_name = "FILE")]
    pub ssdraw: Option<PathBuf>,
    /// Where the walls are: at this time (pkdgrav units).
    #[arg(long, value_name = "T", default_value_t = 0.0, allow_negative_numbers = true, value_parser = ruled(Rule::Any))]
    pub time: f64,
    /// The picture, by its extension: .svg (the default, on standard output without
    /// --out or with `-`), .pov (POV-Ray, with walls.inc beside it), .vtp (VTK, for
    /// ParaView), .pvd (a ParaView collection of one .vtp per frame, in a folder named
    /// after it) or .html (an interactive page; with --until, of the walls' motion over
    /// [0, --until]).
    #[arg(long, value_name = "FILE")]
    pub out: Option<PathBuf>,
    /// Replace the files of an earlier picture (FILE, its numbered stills or frames,
    /// walls.inc): regular files that the preview does not read, not read-only, with
    /// one name.
    #[arg(long, requires = "out")]
    pub force: bool,
    /// Particles to draw too: a CSV or .ss file; or a run's outputs as a movie, one
    /// frame per output: several .ss files (ss.00000 ss.00100…), a particles.csv of
    /// `walls-sim run --out`, or such a folder (its particles.csv, else its .ss series,
    /// and its WALLSREACTviz.out).
    #[arg(long, value_name = "FILE", num_args = 1..)]
    pub particles: Vec<PathBuf>,
    /// Draw reactive walls where a run moved them: the WALLSREACTviz.out that
    /// `walls-sim run --out` (or pkdgrav) wrote; each frame of a movie at the line of
    /// its step, a single picture at the last line.
    #[arg(long, value_name = "FILE")]
    pub reactive: Option<PathBuf>,
    /// The units shown (the time and the scale bar of SVG and HTML) and written (VTK):
    /// auto shows a walls file that sets units in them (times in seconds), another in
    /// pkdgrav's; VTK in cgs or si is converted.
    #[arg(long, value_enum, default_value_t = System::Auto)]
    pub units: System,
    /// The particles.csv that `walls-sim run --out` writes, as a movie: the same as
    /// giving it to --particles (kept for earlier scripts).
    #[arg(long, value_name = "FILE")]
    pub trajectory: Option<PathBuf>,
    /// HTML: draw each particle's path over its last N frames.
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u64).range(1..=100000))]
    pub trails: Option<u64>,
    /// The direction to look from (towards the scene).
    #[arg(long, num_args = 3, value_names = ["X", "Y", "Z"], allow_negative_numbers = true, value_parser = ruled(Rule::Any))]
    pub view: Option<Vec<f64>>,
    /// Which way is up in the picture.
    #[arg(long, num_args = 3, value_names = ["X", "Y", "Z"], allow_negative_numbers = true, value_parser = ruled(Rule::Any))]
    pub up: Option<Vec<f64>>,
    /// The picture's size in pixels.
    #[arg(long, num_args = 2, value_names = ["W", "H"], value_parser = clap::value_parser!(u32).range(16..=16384))]
    pub size: Option<Vec<u32>>,
    /// Frames: of one set of particles, N from --time to --until (default 1); of a
    /// run's outputs, at most N of them evenly spaced, the first and the last among
    /// them (default 300).
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u64).range(1..=MOST_FRAMES))]
    pub frames: Option<u64>,
    /// Of a run's outputs, every Nth (the first, the N+1th…), rather than at most 300
    /// evenly spaced; refused if that makes more than 10000 frames.
    #[arg(long, value_name = "N", conflicts_with = "frames", value_parser = clap::value_parser!(u64).range(1..=u64::from(u32::MAX)))]
    pub every: Option<u64>,
    /// An SVG of several frames: write each frame as a numbered still too,
    /// FILE-000.svg… beside the animated FILE.svg.
    #[arg(long, requires = "out")]
    pub stills: bool,
    /// The end of the span the frames cover.
    #[arg(long, value_name = "T", allow_negative_numbers = true, value_parser = ruled(Rule::Any))]
    pub until: Option<f64>,
    /// Seconds the animation takes to play once.
    #[arg(long, value_name = "S", default_value_t = 4.0, value_parser = ruled(Rule::Positive))]
    pub seconds: f64,
    /// Segments around round shapes.
    #[arg(long, value_name = "N", default_value_t = 48, value_parser = clap::value_parser!(u64).range(3..=4096))]
    pub segments: u64,
}

/// Draws what `args` ask for; the exit status.
pub fn run(args: &PreviewArgs) -> i32 {
    draw(args).unwrap_or_else(error)
}

fn draw(args: &PreviewArgs) -> Result<i32, String> {
    let vector = |name: &'static str, v: &Option<Vec<f64>>| {
        v.iter()
            .flatten()
            .map(move |&x| (name, x))
            .collect::<Vec<_>>()
    };
    let options = [("--time", args.time), ("--seconds", args.seconds)];
    let options = options
        .into_iter()
        .chain(args.until.map(|t| ("--until", t)));
    super::warn_subnormal(
        options
            .chain(vector("--view", &args.view))
            .chain(vector("--up", &args.up)),
    );
    // The format first: a wrong --out is told before any input is read.
    let kind = output::Kind::of(args.out.as_deref())?;
    if args.stills && kind != Some(output::Kind::Svg) {
        return Err(
            "--stills writes an SVG movie's frames as numbered stills: name an .svg with --out"
                .into(),
        );
    }
    let ssdraw = args.ssdraw.as_deref().map(read_ssdraw).transpose()?;
    let first = args
        .particles
        .first()
        .map(|p| p.to_string_lossy().into_owned());
    let run_directory = (args.par.as_deref())
        .map(|p| super::run_directory(p, first, args.pkdgrav_build.clone()))
        .transpose()?;
    let file = walls_file(args, run_directory.as_ref(), ssdraw.as_ref())?;
    let (checked, errors) = read_walls(&file, ContactModel::Ssdem, Some("drawing"))?;
    let scene = &checked.scene;
    // The .par file's particles when none are named.
    let from_par = (run_directory.as_ref())
        .filter(|_| args.particles.is_empty())
        .and_then(|r| r.particles.clone());
    let inputs: Vec<PathBuf> = args
        .particles
        .iter()
        .chain(&from_par)
        .chain(&args.trajectory)
        .cloned()
        .collect();
    let ParticlesRead {
        snapshots,
        viz: found_viz,
        files: read_files,
    } = read_particles(&inputs)?;
    // Every format draws reactive walls where a run moved them.
    let viz_file = args.reactive.clone().or(found_viz);
    let viz = match &viz_file {
        Some(f) => {
            let text = std::fs::read_to_string(f)
                .map_err(|e| format!("cannot read {}: {e}", f.display()))?;
            Some(VizSteps::parse(&text).map_err(|e| format!("{}: {e}", f.display()))?)
        }
        None => None,
    };
    if let Some(until) = args.until
        && !(until - args.time).is_finite()
    {
        return Err(format!(
            "--time {:e} and --until {until:e} are farther apart than a double holds (about 1.8e308): the frames' times cannot be computed",
            args.time
        ));
    }
    let read = snapshots.len();
    let series = read > 1;
    if series && args.until.is_some() {
        return Err(
            "--until makes the frames of one set of particles; a series of outputs makes its own (--frames N or --every N picks among them)"
                .into(),
        );
    }
    // A run's one output (it has a step) is all of its outputs --every picks from.
    let output = snapshots.first().is_some_and(|s| s.step.is_some());
    if let (false, false, Some(n)) = (series, output, args.every) {
        return Err(format!(
            "--every {n} picks among a run's outputs, and the particles given are one set: --frames N --until T makes frames of it"
        ));
    }
    if let Some(n) = args.every {
        every_fits(n, read)?;
    }
    let snapshots = if series {
        movie::pick(snapshots, args.time, picked(args))
    } else {
        // One picture, or --frames over [--time, --until], with the particles (if any)
        // on every frame.
        let particles = snapshots
            .into_iter()
            .next()
            .map(|s| s.particles)
            .unwrap_or_default();
        times(args)
            .into_iter()
            .map(|t| Snapshot {
                t: Some(t),
                step: None,
                particles: particles.clone(),
            })
            .collect()
    };
    // ssdraw's `Wall time offset`, 0 (or none) meaning the walls file's own `time`.
    let wall_offset = match ssdraw.as_ref().and_then(|s| s.wall_time_offset) {
        Some(offset) if offset != 0.0 => offset,
        _ if ssdraw.is_some() => walls_time(&checked),
        _ => 0.0,
    };
    let movie = movie::frames(
        scene,
        snapshots,
        args.time,
        wall_offset,
        viz.as_ref(),
        args.segments as usize,
    );
    if let Some(w) = &movie.warning {
        crate::errln!("walls-sim: warning: {w}");
    }
    drawable(&movie, &file, &checked).map_err(|e| match wall_offset {
        0.0 => e,
        offset => format!(
            "{e} (each frame's walls are drawn {offset:e} later than its time: the ssdraw.par's `Wall time offset`, 0 standing for the walls file's `time`)"
        ),
    })?;
    // Every input, so that no output replaces one (`walls.inc` named as the walls file).
    let mut outputs = walls_output::Outputs::new(walls_output::Tool::PREVIEW, args.force);
    outputs.reads(&file);
    for read in inputs
        .iter()
        .chain(&args.ssdraw)
        .chain(&viz_file)
        .chain(&read_files)
    {
        outputs.reads(read);
    }
    output::write(
        args,
        &file,
        ssdraw.as_ref(),
        kind,
        scene,
        &movie,
        series.then_some(read),
        &outputs,
    )?;
    Ok(exit_status(errors))
}

/// Whether every frame of `movie` can be drawn ([`walls_preview::finite`]), before any
/// file is opened: else why not, a wall named by its line in `file` (as `checked`
/// read it).
fn drawable(movie: &movie::Movie, file: &str, checked: &Checked) -> Result<(), String> {
    use walls_preview::finite::{Subject, check, check_box};
    let t0 = movie.frames.first().map_or(0.0, |f| f.t);
    let e = match check(&movie.frames).and_then(|()| check_box(&movie.bounds, t0)) {
        Ok(()) => return Ok(()),
        Err(e) => e,
    };
    let at = match e.subject {
        Subject::Wall { index, .. } => checked.scene.walls.get(index).map(|w| {
            let lines = walls_diagnostics::LineIndex::new(&checked.text);
            let place = lines.line_col(&checked.text, w.span.start);
            format!("{}:{}:{}: ", display_name(file), place.line, place.column)
        }),
        _ => None,
    };
    Err(format!("{}{e}; nothing was drawn", at.unwrap_or_default()))
}

/// Which of a run's outputs the movie shows: --every's, else at most --frames (by
/// default [`movie::MOVIE_FRAMES`]).
fn picked(args: &PreviewArgs) -> movie::Pick {
    let size = |n: u64| usize::try_from(n).unwrap_or(usize::MAX);
    match (args.every, args.frames) {
        (Some(n), _) => movie::Pick::Every(size(n)),
        (None, Some(n)) => movie::Pick::AtMost(size(n)),
        (None, None) => movie::Pick::AtMost(movie::MOVIE_FRAMES),
    }
}

/// Whether `--every n` of `outputs` makes no more than [`movie::MOST_FRAMES`] frames,
/// the most `--frames` may ask for: else how many it would make, and the smallest N
/// that fits.
fn every_fits(n: u64, outputs: usize) -> Result<(), String> {
    let outputs = outputs as u64;
    let frames = outputs.div_ceil(n.max(1));
    if frames <= MOST_FRAMES {
        return Ok(());
    }
    Err(format!(
        "--every {n} of {outputs} outputs would make {frames} frames, more than a movie may have ({MOST_FRAMES}, as with --frames): --every {} or more fits",
        outputs.div_ceil(MOST_FRAMES)
    ))
}

/// The times of --frames (default 1) over [--time, --until].
fn times(args: &PreviewArgs) -> Vec<f64> {
    let n = args.frames.unwrap_or(1) as usize;
    let until = args.until.unwrap_or(args.time);
    (0..n)
        .map(|k| {
            if n == 1 {
                args.time
            } else {
                args.time + (until - args.time) * k as f64 / (n - 1) as f64
            }
        })
        .collect()
}

/// The snapshots of the particle files and folders `paths`, in the order given, and
/// the `WALLSREACTviz.out` of a folder among them, and the files read; a progress bar
/// for a long series.
fn read_particles(paths: &[PathBuf]) -> Result<ParticlesRead, String> {
    let mut files = Vec::new();
    let mut viz = None;
    for p in paths {
        if p.is_dir() {
            let folder = movie::run_folder(p)?;
            files.extend(folder.particles);
            viz = viz.or(folder.viz);
        } else {
            files.push(p.clone());
        }
    }
    let bar = output::progress(files.len(), "read");
    let mut snapshots = Vec::new();
    for f in &files {
        snapshots.extend(movie::read_snapshots(Path::new(f))?);
        bar.inc(1);
    }
    bar.finish_and_clear();
    Ok(ParticlesRead {
        snapshots,
        viz,
        files,
    })
}

/// What [`read_particles`] read.
struct ParticlesRead {
    /// The snapshots, in the order given.
    snapshots: Vec<Snapshot>,
    /// The `WALLSREACTviz.out` of a folder among them.
    viz: Option<PathBuf>,
    /// The particle files read.
    files: Vec<PathBuf>,
}

/// The `ssdraw.par` at `path`; what of it the preview does not use, and the labels
/// ssdraw would miss, told on standard error.
fn read_ssdraw(path: &Path) -> Result<SsdrawView, String> {
    use std::io::Read;
    use walls_preview::ssdraw::{MAX_LINE, MAX_LINES, read};
    let shown = path.display();
    // No more than a file ssdraw can read holds, and a little more, so that a device or
    // a huge file is refused by its first line too long or too many, not read whole.
    let most = (MAX_LINES as u64 + 1) * (MAX_LINE as u64 + 2);
    let mut bytes = Vec::new();
    std::fs::File::open(path)
        .and_then(|f| f.take(most).read_to_end(&mut bytes))
        .map_err(|e| format!("cannot read {shown}: {e}"))?;
    let view = read(&bytes).map_err(|e| format!("{shown}:{}: {}", e.line, e.message))?;
    for note in &view.notes {
        crate::errln!(
            "walls-sim: warning: {shown}:{}: {}",
            note.line,
            note.message
        );
    }
    if !view.unused.is_empty() {
        let lines: Vec<String> = (view.unused.iter())
            .map(|(line, label)| format!("`{label}` (line {line})"))
            .collect();
        crate::errln!(
            "walls-sim: note: {shown}: lines ssdraw reads that walls-sim preview does not use: {}",
            lines.join(", ")
        );
    }
    match &view.missing[..] {
        [] => {}
        [label] => crate::errln!(
            "walls-sim: warning: {shown}: no `{label}` line: ssdraw aborts without it; walls-sim preview draws all the same"
        ),
        labels => {
            let labels: Vec<String> = labels.iter().map(|l| format!("`{l}`")).collect();
            crate::errln!(
                "walls-sim: warning: {shown}: no lines for {}: ssdraw aborts at the first it asks for; walls-sim preview draws all the same",
                labels.join(", ")
            );
        }
    }
    Ok(view)
}

/// The walls file's own `time` (the last one written, in pkdgrav units: times the
/// `timeunit` in force there), or 0 without one: what ssdraw's `Wall time offset` 0
/// stands for.
fn walls_time(checked: &Checked) -> f64 {
    checked.scene.time.filter(|t| t.is_finite()).unwrap_or(0.0)
}

/// The walls file: the command line's, else the `.par` file's, else the `Wall data
/// file` of --ssdraw, taken relative to the ssdraw.par's folder.
fn walls_file(
    args: &PreviewArgs,
    run_directory: Option<&super::RunDirectory>,
    ssdraw: Option<&SsdrawView>,
) -> Result<String, String> {
    if let Some(f) = (args.file.clone()).or_else(|| run_directory?.walls.clone()) {
        return Ok(f);
    }
    let named = ssdraw
        .and_then(|s| s.walls_file.as_deref())
        .ok_or_else(|| match &args.par {
            Some(par) => format!("no walls file: name one, or give {par} an achWallsFile line"),
            None => "no walls file: name one, or give an ssdraw.par that has a `Wall data file`"
                .to_string(),
        })?;
    let dir = args
        .ssdraw
        .as_deref()
        .and_then(Path::parent)
        .unwrap_or(Path::new(""));
    Ok(dir.join(named).to_string_lossy().into_owned())
}
