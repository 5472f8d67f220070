//! `walls-mesh`: an STL or OBJ mesh as a walls file of triangle walls (docs/meshes.md).
//!
//! The mesh is read, each face turned into a triangle wall (oriented and merged into
//! rectangles when asked), the units and a defaults block from `--set` added, and the
//! file written in the canonical layout and checked as `walls-lint` checks it. It goes
//! to standard output (no `-o`, or `-o -`), or to `-o OUT` through the one writer,
//! `walls-output`: OUT is looked at before the mesh is read, replaced only with `--force`
//! and only if it is a regular file the user may replace (never a device, a FIFO, a hard
//! link, a read-only file or the mesh itself; a symbolic link is written through), and
//! written whole or not at all. Exit status: 0 success
//! (warnings on standard error), 1 the walls file would have errors (nothing written), 2
//! usage or I/O error, or a mesh that cannot be read or turned into walls.

use clap::Parser;
use clap::builder::{PossibleValuesParser, TypedValueParser};
use std::io::Write;
use std::path::{Path, PathBuf};
use walls_build::mesh::{self, MeshOptions, Orientation};
use walls_build::{CheckOptions, DumpOptions, Given, LengthUnit, Units, Wall, dumps};
use walls_diagnostics::render::{self, FileReport};
use walls_diagnostics::terminal::Escaped;
use walls_output::{Outputs, Tool};

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
    /// Replace OUT if it exists (a regular file that is not the mesh, not read-only and
    /// with one name).
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
    // clap asks for INPUT unless --completions, which never reaches here.
    let Some(input) = &args.input else {
        crate::errln!("walls-mesh: error: no mesh named");
        return 2;
    };
    // OUT is looked at before anything is read: a file it may not replace ends the
    // command at once.
    let mut outputs = Outputs::new(Tool::MESH, args.force);
    outputs.reads(input);
    // `-` and /dev/stdout are standard output, which is written to, never replaced.
    let stdout = [Path::new("-"), Path::new("/dev/stdout")];
    let target = match args.output.as_deref().filter(|out| !stdout.contains(out)) {
        Some(out) => match outputs.plan(out) {
            Ok(target) => Some(target),
            Err(e) => return error(e.message(&out.display().to_string(), Tool::MESH)),
        },
        None => None,
    };
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
    // The comment is for people: the mesh's name with its control characters escaped,
    // so that the walls file holds none (S006) that its name brought.
    let comment = format!(
        "Made by walls-mesh from {}: {} as {}, orientation {way}.",
        Escaped(&name),
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
    match target {
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
        Some(target) => match target.write(dumped.text.as_bytes()) {
            Ok(()) if target.exists() => {
                crate::errln!("walls-mesh: replaced {} (--force)", target.path().display());
                0
            }
            Ok(()) => 0,
            Err(e) => error(target.message(&e)),
        },
    }
}

/// `n` things, with the plural when it needs one.
fn count(n: usize, thing: &str) -> String {
    format!("{n} {thing}{}", if n == 1 { "" } else { "s" })
}
