//! `walls-mesh`: an STL or OBJ mesh as a walls file of triangle walls (docs/meshes.md).
//!
//! The mesh is read, each face turned into a triangle wall (oriented and merged into
//! rectangles when asked), the units and a defaults block from `--set` added, and the
//! file written in the canonical layout and checked as `walls-lint` checks it. It goes
//! to standard output, or to `-o OUT`, which is never replaced without `--force` and is
//! written whole or not at all (a new file renamed into place). Exit status: 0 success
//! (warnings on standard error), 1 the walls file would have errors (nothing written), 2
//! usage or I/O error, or a mesh that cannot be read or turned into walls.

use crate::interrupt;
use clap::Parser;
use clap::builder::{PossibleValuesParser, TypedValueParser};
use std::io::Write;
use std::path::{Path, PathBuf};
use walls_build::mesh::{self, MeshOptions, Orientation};
use walls_build::{CheckOptions, DumpOptions, Given, LengthUnit, Units, Wall, dumps};
use walls_diagnostics::render::{self, FileReport};

/// The command line of `walls-mesh`.
#[derive(Parser)]
#[command(
    name = "walls-mesh",
    version,
    about = "Turn an STL or OBJ mesh into pkdgrav triangle walls.",
    after_help = "Exit status: 0 success, 1 the walls file would have errors (nothing is written), 2 usage or I/O error, or a mesh that cannot be read or turned into walls (with the file and line or facet)."
)]
pub struct MeshArgs {
    /// The mesh: `.stl` (binary or ASCII) or `.obj`.
    #[arg(value_name = "INPUT", required = true)]
    pub input: Option<PathBuf>,
    /// Write the walls file here instead of to standard output.
    #[arg(short, long, value_name = "OUT")]
    pub output: Option<PathBuf>,
    /// Replace OUT if it exists.
    #[arg(long, requires = "output")]
    pub force: bool,
    /// The unit of the mesh's numbers, written as the file's `lengthunit`.
    #[arg(long, value_name = "UNIT", value_parser = unit_parser())]
    pub unit: Option<LengthUnit>,
    /// Which way the walls face: as each face is wound, or consistently out of (into)
    /// the volume each closed piece of the mesh encloses.
    #[arg(long, value_name = "WAY", default_value = "keep", value_parser = orientation_parser())]
    pub orientation: Orientation,
    /// Merge two triangles that make a rectangle into one rectangle wall.
    #[arg(long)]
    pub merge_rectangles: bool,
    /// A token of the defaults block every wall starts from, checked as it is read
    /// (`--set color=3`, `--set velocity=0,0,-1`); repeat for more.
    #[arg(long = "set", value_name = "KEY=VALUE")]
    pub set: Vec<String>,
    /// pkdgrav's MAX_NUM_WALLS, for the warning about too many walls.
    #[arg(long, value_name = "N", default_value_t = 20)]
    pub max_walls: usize,
    /// Print the completion script for SHELL to standard output and exit.
    #[arg(long, value_name = "SHELL", exclusive = true)]
    pub completions: Option<clap_complete::Shell>,
}

fn unit_parser() -> impl TypedValueParser<Value = LengthUnit> {
    PossibleValuesParser::new(LengthUnit::ALL.iter().map(|&(name, _)| name))
        .map(|name| LengthUnit::named(&name).unwrap_or(LengthUnit::Au))
}

fn orientation_parser() -> impl TypedValueParser<Value = Orientation> {
    PossibleValuesParser::new(Orientation::ALL.iter().map(|&(name, _)| name))
        .map(|name| Orientation::named(&name).unwrap_or_default())
}

fn error(message: impl std::fmt::Display) -> i32 {
    crate::errln!("walls-mesh: error: {message}");
    2
}

/// Turns the mesh `args` names into walls and writes them; the exit status.
pub fn run(args: &MeshArgs) -> i32 {
    if let Some(out) = args.output.as_ref().filter(|_| !args.force)
        && out.exists()
    {
        return error(exists(out));
    }
    let mut defaults = Wall::new();
    for token in &args.set {
        let Some((key, value)) = token.split_once('=') else {
            return error(format!("--set {token}: give a token as KEY=VALUE"));
        };
        let set = Given::parse(value).and_then(|v| {
            defaults.set(key.trim(), v).map_err(|e| e.to_string())?;
            Ok(())
        });
        if let Err(e) = set {
            return error(format!("--set {token}: {e}"));
        }
    }
    // clap asks for INPUT unless --completions, which never reaches here.
    let Some(input) = &args.input else {
        crate::errln!("walls-mesh: error: no mesh named");
        return 2;
    };
    let name = input.display().to_string();
    let read = match mesh::read_mesh(input) {
        Ok(read) => read,
        Err(problem) => return error(problem.in_file(&name)),
    };
    for warning in &read.warnings {
        crate::errln!("walls-mesh: warning: {}", warning.in_file(&name));
    }
    let options = MeshOptions {
        orientation: args.orientation,
        merge_rectangles: args.merge_rectangles,
    };
    let walls = match mesh::to_walls(&read.mesh, &options) {
        Ok(walls) => walls,
        Err(problem) => return error(problem.in_file(&name)),
    };
    let way = Orientation::ALL
        .iter()
        .find(|&&(_, o)| o == args.orientation)
        .map_or("keep", |&(n, _)| n);
    let comment = format!(
        "Made by walls-mesh from {name}: {} as {}, orientation {way}.",
        count(read.mesh.faces.len(), "face"),
        count(walls.len(), "wall")
    );
    let dump = DumpOptions {
        units: args.unit.map(Units::length).unwrap_or_default(),
        defaults: Some(defaults),
        comment: Some(comment),
        check: CheckOptions {
            max_walls: args.max_walls,
            ..CheckOptions::default()
        },
        ..DumpOptions::default()
    };
    let shown = args
        .output
        .as_ref()
        .map_or("<stdout>".to_string(), |p| p.display().to_string());
    let report = |text: &str, diagnostics| {
        let file = FileReport {
            path: &shown,
            source: text,
            diagnostics,
        };
        let mut err = std::io::stderr().lock();
        // Standard error is for people: if it is gone there is nobody to tell.
        let _ = render::human(&mut err, &file, crate::console::color_stderr());
    };
    let dumped = match dumps(&walls, &dump) {
        Ok(dumped) => dumped,
        Err(e) => {
            report(&e.text, &e.diagnostics);
            crate::errln!("walls-mesh: error: the walls file would have errors: nothing written");
            return 1;
        }
    };
    report(&dumped.text, &dumped.warnings);
    match &args.output {
        None => {
            let mut stdout = std::io::stdout().lock();
            match stdout
                .write_all(dumped.text.as_bytes())
                .and_then(|()| stdout.flush())
            {
                // A reader that stopped reading wants no more.
                Err(e) if e.kind() != std::io::ErrorKind::BrokenPipe => {
                    error(format!("cannot write standard output: {e}"))
                }
                _ => 0,
            }
        }
        Some(out) => match write_new(out, dumped.text.as_bytes(), args.force) {
            Ok(()) => 0,
            Err(e) => error(e),
        },
    }
}

/// `n` things, with the plural when it needs one.
fn count(n: usize, thing: &str) -> String {
    format!("{n} {thing}{}", if n == 1 { "" } else { "s" })
}

fn exists(out: &Path) -> String {
    format!("{} exists: pass --force to replace it", out.display())
}

/// Writes `bytes` to a new file beside `out` and renames it into place: `out` is the
/// whole text or what it was, never half of it, and is not replaced unless `force`.
fn write_new(out: &Path, bytes: &[u8], force: bool) -> Result<(), String> {
    let dir = out
        .parent()
        .filter(|d| !d.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    let cannot = |e: std::io::Error| format!("cannot write {}: {e}", out.display());
    interrupt::install();
    let mut new = tempfile::Builder::new()
        .prefix(".walls-mesh")
        .make_in(dir, |path| {
            let file = std::fs::OpenOptions::new()
                .write(true)
                .create_new(true)
                .open(path)?;
            Ok((file, interrupt::remove_on_signal(path)))
        })
        .map_err(cannot)?;
    let file = &mut new.as_file_mut().0;
    file.write_all(bytes)
        .and_then(|()| file.sync_all())
        .map_err(cannot)?;
    let placed = if force {
        new.persist(out)
    } else {
        new.persist_noclobber(out)
    };
    match placed {
        Ok(_) => Ok(()),
        Err(e) if e.error.kind() == std::io::ErrorKind::AlreadyExists => Err(exists(out)),
        Err(e) => Err(cannot(e.error)),
    }
}
