//! The pictures of `walls-sim preview`, by the extension of `--out`: an SVG (animated
//! for several frames, with numbered stills), numbered POV-Ray scenes, one VTK
//! PolyData, a ParaView collection of them, or the HTML page; the progress bar of a
//! long series; and the warning naming an earlier picture's numbered files that this
//! one did not write, left beside it.

use super::PreviewArgs;
use crate::movie::Movie;
use indicatif::ProgressBar;
use std::io::{IsTerminal, Write};
use std::path::{Path, PathBuf};
use walls_geometry::units::{Readout, Scale, System};
use walls_model::Scene;
use walls_output::{Outputs, Target, Tool, WriteError};
use walls_preview::MovieFrame;
use walls_preview::html::Particles;
use walls_preview::ssdraw::SsdrawView;

/// Series longer than this show a progress bar (on a terminal).
const LONG: usize = 20;

/// A bar on standard error counting `len` files `done` ("read", "written"), for a
/// series longer than [`LONG`] when standard error is a terminal; otherwise a hidden
/// one, which counts without drawing.
pub(super) fn progress(len: usize, done: &str) -> ProgressBar {
    if len <= LONG || !std::io::stderr().is_terminal() {
        return ProgressBar::hidden();
    }
    let bar = ProgressBar::new(len as u64);
    let template = format!("walls-sim {{bar:40}} {{pos}}/{{len}} frames {done}, {{eta}} left");
    if let Ok(style) = indicatif::ProgressStyle::with_template(&template) {
        bar.set_style(style);
    }
    bar
}

/// The pictures `--out` can name, by its extension.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Kind {
    Svg,
    Pov,
    Vtp,
    Pvd,
    Html,
}

impl Kind {
    /// The picture `out` asks for by its extension (`None`: no --out, or `-`, SVG on
    /// standard output), or why it names none.
    pub(super) fn of(out: Option<&Path>) -> Result<Option<Kind>, String> {
        let Some(path) = out.filter(|p| *p != Path::new("-")) else {
            return Ok(None);
        };
        let extension = path
            .extension()
            .map(|e| e.to_string_lossy().to_ascii_lowercase());
        let kind = match extension.as_deref() {
            Some("svg") => Kind::Svg,
            Some("pov") => Kind::Pov,
            Some("vtp") => Kind::Vtp,
            Some("pvd") => Kind::Pvd,
            Some("html") => Kind::Html,
            Some(other) => return Err(format!("cannot draw .{other} files: {NAMES}")),
            None => {
                return Err(format!(
                    "--out {} has no extension to tell the picture's format by: {NAMES}",
                    path.display()
                ));
            }
        };
        Ok(Some(kind))
    }
}

/// The formats, as the errors of [`Kind::of`] name them.
const NAMES: &str =
    "use .svg, .pov, .vtp, .pvd or .html (or no --out, or --out -, for SVG on standard output)";

/// Writes `frames` as `kind` (`None`: SVG on standard output). `series`: the frames
/// are of a run's outputs, this many read (not --frames of one picture). Every file is
/// planned through `outputs` (the one writer's policy) before any is written; a movie
/// then says on standard error what it wrote ([`tell`]).
#[allow(
    clippy::too_many_arguments,
    reason = "the preview's parts, each used once"
)]
pub(super) fn write(
    args: &PreviewArgs,
    file: &str,
    ssdraw: Option<&SsdrawView>,
    kind: Option<Kind>,
    scene: &Scene,
    movie: &Movie,
    series: Option<usize>,
    outputs: &Outputs,
) -> Result<(), String> {
    let frames = &movie.frames[..];
    let readout = Readout::picture(args.units, &scene.units);
    let view = svg_view(args, ssdraw, movie);
    let (Some(kind), Some(path)) = (kind, args.out.as_deref()) else {
        let mut out = std::io::BufWriter::new(std::io::stdout().lock());
        return svg(&mut out, &view, args.seconds, movie, frames, &readout)
            .and_then(|()| out.flush())
            .map_err(|e| format!("cannot write the picture: {e}"));
    };
    let files = Files::plan(outputs, path, kind, frames.len(), args.stills)?;
    let replaced: Vec<PathBuf> = files
        .replaced()
        .into_iter()
        .map(Path::to_path_buf)
        .collect();
    let write = |target: &Target, what: &mut dyn FnMut(&mut dyn Write) -> std::io::Result<()>| {
        target.write_with(what).map_err(|e| target.message(&e))
    };
    let bar = progress(files.frames.len(), "written");
    match kind {
        Kind::Svg => {
            write(&files.main, &mut |mut out| {
                svg(&mut out, &view, args.seconds, movie, frames, &readout)
            })?;
            for (target, frame) in files.frames.iter().zip(frames) {
                write(target, &mut |mut out| {
                    let one = std::slice::from_ref(frame);
                    svg(&mut out, &view, args.seconds, movie, one, &readout)
                })?;
                bar.inc(1);
            }
        }
        Kind::Pov => {
            let pov_view = pov_view(args, ssdraw, movie, &view);
            // One scene, or numbered scenes FILE-000.pov…, each wall where the frame
            // places it, in the movie's box; the styles' include beside them.
            let scenes = if frames.len() > 1 {
                &files.frames[..]
            } else {
                std::slice::from_ref(&files.main)
            };
            for (target, frame) in scenes.iter().zip(frames) {
                write(target, &mut |mut out| {
                    walls_preview::pov::write_frame(&mut out, scene, frame, movie.bounds, &pov_view)
                })?;
                bar.inc(1);
            }
            if let Some(include) = &files.include {
                include
                    .write(walls_preview::pov::INCLUDE.as_bytes())
                    .map_err(|e| include.message(&e))?;
            }
        }
        Kind::Vtp => {
            let [frame] = frames else {
                return Err(format!(
                    "{} frames do not fit in one .vtp: write a ParaView collection, --out {}",
                    frames.len(),
                    path.with_extension("pvd").display()
                ));
            };
            write(&files.main, &mut |mut out| {
                walls_preview::vtk::write(
                    &mut out,
                    &frame.walls,
                    &frame.particles,
                    frame.t,
                    &vtk_scale(args.units, &readout),
                )
            })?;
        }
        Kind::Pvd => {
            let scale = vtk_scale(args.units, &readout);
            for (target, frame) in files.frames.iter().zip(frames) {
                write(target, &mut |mut out| {
                    walls_preview::vtk::write(
                        &mut out,
                        &frame.walls,
                        &frame.particles,
                        frame.t,
                        &scale,
                    )
                })?;
                bar.inc(1);
            }
            let names = walls_preview::pvd::frame_files(path, frames.len());
            write(&files.main, &mut |mut out| {
                walls_preview::pvd::write(&mut out, frames, &names, &scale)
            })?;
        }
        Kind::Html => {
            write(&files.main, &mut |mut out| {
                match (frames, args.until) {
                    // One set of particles with the walls' motion over [0, --until],
                    // sampled at 101 times.
                    ([frame], Some(until)) if series.is_none() => {
                        let moving = html_particles(frame);
                        walls_preview::html::write(&mut out, scene, moving.as_ref(), until, 101)
                    }
                    // A run's outputs, --frames, or a still: the frames as they are,
                    // reactive walls placed, particles matched by index.
                    _ => {
                        let options = walls_preview::html::MovieOptions {
                            readout: readout.clone(),
                            trails: args.trails.map(|n| n as usize),
                            title: format!("walls preview: {file}"),
                        };
                        walls_preview::html::write_movie(&mut out, scene, frames, &options)
                    }
                }
            })?;
        }
    }
    bar.finish_and_clear();
    if frames.len() > 1 || series.is_some() {
        tell(args, &files.written(kind), frames.len(), series);
    }
    if !replaced.is_empty() {
        let names: Vec<&Path> = replaced.iter().map(PathBuf::as_path).collect();
        crate::errln!(
            "walls-sim: replaced {} (--force)",
            walls_output::name_files(&names)
        );
    }
    let left = leftovers(path, kind, files.frames.len());
    if !left.is_empty() {
        let names: Vec<&Path> = left.iter().map(PathBuf::as_path).collect();
        crate::errln!(
            "walls-sim: warning: {} named as this picture's numbered frames but not written by it (an earlier picture's?) were left as they were: remove them, or a glob of the frames mixes two pictures",
            walls_output::name_files(&names)
        );
    }
    Ok(())
}

/// The regular files beside a picture of `kind` at `path` that are named exactly as
/// its numbered frames are (`NAME-007.svg` of an SVG's stills, `NAME-007.pov` of
/// POV-Ray's scenes, `NAME/NAME_000007.vtp` of a collection's frames) with a number
/// this picture, writing `written` of them, did not write: an earlier, longer
/// picture's, which a glob would mix with this one's. They are named in a warning and
/// never removed (a file of that name may be the user's own).
fn leftovers(path: &Path, kind: Kind, written: usize) -> Vec<PathBuf> {
    let name = |p: &Path| p.file_stem().map(|s| s.to_string_lossy().into_owned());
    let Some(stem) = name(path) else {
        return Vec::new();
    };
    let parent = path
        .parent()
        .filter(|d| !d.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    let (folder, prefix, width, suffix) = match kind {
        Kind::Svg => (PathBuf::new(), format!("{stem}-"), 3, ".svg"),
        Kind::Pov => (PathBuf::new(), format!("{stem}-"), 3, ".pov"),
        Kind::Pvd => (PathBuf::from(&stem), format!("{stem}_"), 6, ".vtp"),
        Kind::Vtp | Kind::Html => return Vec::new(),
    };
    // The number of a name written as the preview writes it (`{k:03}`, `{k:06}`).
    let number = |file: &str| -> Option<usize> {
        let digits = file.strip_prefix(&prefix)?.strip_suffix(suffix)?;
        let k: usize = digits
            .bytes()
            .all(|b| b.is_ascii_digit())
            .then(|| digits.parse().ok())??;
        (format!("{k:0width$}") == digits).then_some(k)
    };
    let Ok(entries) = std::fs::read_dir(parent.join(&folder)) else {
        return Vec::new();
    };
    let mut left: Vec<(usize, PathBuf)> = entries
        .filter_map(Result::ok)
        .filter(|e| e.file_type().is_ok_and(|t| t.is_file()))
        .filter_map(|e| {
            let k = number(e.file_name().to_str()?)?;
            let shown = walls_output::path_in(parent, &folder.join(e.file_name()));
            (k >= written).then_some((k, shown))
        })
        .collect();
    left.sort();
    left.into_iter().map(|(_, p)| p).collect()
}

/// The files of a picture, planned: the one `--out` names, the numbered stills or
/// scenes (or a collection's frames), and POV-Ray's include.
struct Files {
    main: Target,
    frames: Vec<Target>,
    include: Option<Target>,
}

/// Says on standard error what a movie wrote: its `files` and their size, its `frames`
/// and, of a run's outputs (`series`, how many), which, and how to have others.
fn tell(args: &PreviewArgs, files: &[&Path], frames: usize, series: Option<usize>) {
    let bytes: u64 = (files.iter())
        .filter_map(|f| std::fs::metadata(f).ok())
        .map(|m| m.len())
        .sum();
    let many = |n: usize, what: &str| match n {
        1 => format!("1 {what}"),
        n => format!("{n} {what}s"),
    };
    let shown = many(frames, "frame");
    let which = match (series, args.every) {
        (None, _) => shown,
        (Some(m), Some(n)) => format!("{shown}, 1 in every {n} of {}", many(m, "output")),
        (Some(m), None) if frames == m => format!("{shown}, one per output"),
        (Some(m), None) if args.frames.is_some() => {
            format!("{shown} of {m} outputs, evenly spaced")
        }
        (Some(m), None) => format!(
            "{shown} of {m} outputs, evenly spaced; --frames N for up to N (at most {}), --every N for 1 in every N",
            super::MOST_FRAMES
        ),
    };
    crate::errln!(
        "walls-sim: wrote {} ({}): {which}",
        walls_output::name_files(files),
        size(bytes)
    );
}

/// `bytes` as people read a file's size: `812 bytes`, `12.3 kB`, `340 MB`.
fn size(bytes: u64) -> String {
    let units = ["kB", "MB", "GB", "TB"];
    let mut x = bytes as f64;
    let mut unit = "bytes";
    for u in units {
        if x < 1000.0 {
            break;
        }
        x /= 1000.0;
        unit = u;
    }
    match unit {
        "bytes" => format!("{bytes} bytes"),
        _ if x < 10.0 => format!("{x:.1} {unit}"),
        _ => format!("{x:.0} {unit}"),
    }
}

impl Files {
    /// Plans every file a picture of `kind` with `frames` frames at `path` writes, in
    /// `path`'s folder (an SVG's numbered stills only with `stills`): refused before
    /// anything is written if any may not be.
    fn plan(
        outputs: &Outputs,
        path: &Path,
        kind: Kind,
        frames: usize,
        stills: bool,
    ) -> Result<Files, String> {
        let refused =
            |shown: &Path, e: WriteError| e.message(&shown.display().to_string(), Tool::PREVIEW);
        // The file named is the user's: a link to a file is written through.
        let main = outputs.plan(path).map_err(|e| refused(path, e))?;
        // The others are the command's, in the same folder opened once, through no link.
        let parent = path
            .parent()
            .filter(|d| !d.as_os_str().is_empty())
            .unwrap_or(Path::new("."));
        let folder = outputs.folder(parent, false).map_err(|e| match e {
            WriteError::Io(e) => format!("cannot write {}: {e}", path.display()),
            e => refused(parent, e),
        })?;
        let plan = |name: &Path| {
            folder
                .plan(name)
                .map_err(|e| refused(&walls_output::path_in(parent, name), e))
        };
        let name = |p: &Path| p.file_name().map(PathBuf::from).unwrap_or_default();
        let numbered_names = |extension: &str| -> Vec<PathBuf> {
            (0..frames)
                .map(|k| name(&numbered(path, k, extension)))
                .collect()
        };
        let frame_names = match kind {
            Kind::Svg if frames > 1 && stills => numbered_names("svg"),
            Kind::Pov if frames > 1 => numbered_names("pov"),
            Kind::Pvd => walls_preview::pvd::frame_files(path, frames),
            _ => Vec::new(),
        };
        let frames = frame_names
            .iter()
            .map(|n| plan(n))
            .collect::<Result<Vec<_>, _>>()?;
        // The include is the same for every scene: one already there as written is kept.
        let include = match kind {
            Kind::Pov => {
                let name = Path::new(walls_preview::pov::INCLUDE_NAME);
                match is_the_include(&parent.join(name)) {
                    true => None,
                    false => Some(plan(name)?),
                }
            }
            _ => None,
        };
        Ok(Files {
            main,
            frames,
            include,
        })
    }
}

impl Files {
    /// The files a picture of `kind` writes, in the order written: an SVG, then its
    /// stills; a collection's frames, then it; a POV-Ray movie's scenes (without the file
    /// `--out` names), then the include.
    fn written(&self, kind: Kind) -> Vec<&Path> {
        let main = std::iter::once(&self.main);
        let files: Vec<&Target> = match kind {
            Kind::Pov if !self.frames.is_empty() => self.frames.iter().collect(),
            Kind::Pvd => self.frames.iter().chain(main).collect(),
            _ => main.chain(&self.frames).collect(),
        };
        (files.into_iter())
            .chain(&self.include)
            .map(Target::path)
            .collect()
    }

    /// The files there already, which writing replaces (with `--force`).
    fn replaced(&self) -> Vec<&Path> {
        std::iter::once(&self.main)
            .chain(&self.frames)
            .chain(&self.include)
            .filter(|t| t.exists())
            .map(Target::path)
            .collect()
    }
}

/// Whether the file at `path` is a regular file holding the include this preview writes
/// (read only if its size is the include's, and without blocking on a FIFO).
fn is_the_include(path: &Path) -> bool {
    use std::io::Read;
    let include = walls_preview::pov::INCLUDE.as_bytes();
    let same_size = std::fs::symlink_metadata(path)
        .is_ok_and(|m| m.is_file() && m.len() == include.len() as u64);
    if !same_size {
        return false;
    }
    let mut there = Vec::new();
    let flags =
        rustix::fs::OFlags::RDONLY | rustix::fs::OFlags::NONBLOCK | rustix::fs::OFlags::NOFOLLOW;
    rustix::fs::open(path, flags, rustix::fs::Mode::empty())
        .map(std::fs::File::from)
        .map_err(std::io::Error::from)
        .and_then(|f| f.take(include.len() as u64 + 1).read_to_end(&mut there))
        .is_ok()
        && there == include
}

/// The POV-Ray view: the SVG view's direction and aspect, ssdraw's camera and sky where
/// `--view` and `--up` do not say otherwise.
fn pov_view(
    args: &PreviewArgs,
    ssdraw: Option<&SsdrawView>,
    movie: &Movie,
    view: &walls_preview::svg::View,
) -> walls_preview::pov::View {
    let default = walls_preview::pov::View::default();
    // ssdraw's camera where --view does not say otherwise, looking at its look-at point
    // or the scene's centre.
    let camera = ssdraw.filter(|_| args.view.is_none()).and_then(|s| {
        let centre = (movie.bounds.0 + movie.bounds.1) / 2.0;
        s.camera.map(|at| (at, s.look_at.unwrap_or(centre)))
    });
    walls_preview::pov::View {
        from: view.from,
        aspect: f64::from(view.width) / f64::from(view.height),
        camera,
        sky: args
            .up
            .is_none()
            .then(|| ssdraw.and_then(|s| s.up))
            .flatten(),
        ..default
    }
}

/// `path` numbered: `frame.svg` → `frame-007.svg`.
fn numbered(path: &Path, k: usize, extension: &str) -> std::path::PathBuf {
    let stem = path.with_extension("");
    std::path::PathBuf::from(format!("{}-{k:03}.{extension}", stem.display()))
}

/// The SVG view of --view, --up and --size, else of ssdraw's camera (the direction
/// from its look-at point, or the scene's centre, to its position), sky vector and
/// aspect ratio, else the default.
fn svg_view(
    args: &PreviewArgs,
    ssdraw: Option<&SsdrawView>,
    movie: &Movie,
) -> walls_preview::svg::View {
    use nalgebra::Vector3;
    let v3 = |v: &Option<Vec<f64>>| v.as_ref().map(|v| Vector3::new(v[0], v[1], v[2]));
    let default = walls_preview::svg::View::default();
    let centre = (movie.bounds.0 + movie.bounds.1) / 2.0;
    // Halves first: the direction is the same, and 1e308 − (−1e308) would overflow.
    let from = ssdraw.and_then(|s| {
        s.camera
            .map(|at| at / 2.0 - s.look_at.unwrap_or(centre) / 2.0)
    });
    let width = args.size.as_ref().map_or(default.width, |s| s[0]);
    let height = match (&args.size, ssdraw.and_then(|s| s.aspect)) {
        (Some(s), _) => s[1],
        (None, Some(aspect)) => ((f64::from(width) / aspect).round() as u32).clamp(16, 16384),
        (None, None) => default.height,
    };
    walls_preview::svg::View {
        from: v3(&args.view).or(from).unwrap_or(default.from),
        up: v3(&args.up)
            .or(ssdraw.and_then(|s| s.up))
            .unwrap_or(default.up),
        width,
        height,
    }
}

/// One SVG of `frames` of `movie` (animated when several), in the movie's box.
fn svg(
    out: &mut impl Write,
    view: &walls_preview::svg::View,
    seconds: f64,
    movie: &Movie,
    frames: &[MovieFrame],
    readout: &Readout,
) -> std::io::Result<()> {
    use walls_preview::svg::Frame;
    let drawn: Vec<Frame> = frames
        .iter()
        .map(|f| Frame {
            t: f.t,
            walls: &f.walls,
            particles: &f.particles,
        })
        .collect();
    walls_preview::svg::write(out, &drawn, view, movie.bounds, seconds, readout)
}

/// The units VTK files are written in: SI or cgs converted, else pkdgrav's own.
fn vtk_scale(units: System, readout: &Readout) -> Scale {
    match units {
        System::Si | System::Cgs => readout.scale.clone(),
        System::Auto | System::Pkdgrav => Scale::PKDGRAV,
    }
}

/// One frame's particles as the HTML page plays them through the walls' motion;
/// `None` without particles.
fn html_particles(frame: &MovieFrame) -> Option<Particles> {
    (!frame.particles.is_empty()).then(|| Particles {
        radii: frame.particles.iter().map(|p| p.radius).collect(),
        colors: frame.particles.iter().map(|p| i64::from(p.color)).collect(),
        times: vec![frame.t],
        frames: vec![frame.particles.iter().map(|p| p.pos).collect()],
    })
}
