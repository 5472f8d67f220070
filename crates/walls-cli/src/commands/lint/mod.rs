//! `walls-lint`: check walls files and pkdgrav's `.par` files for everything pkdgrav
//! would reject or misread.
//!
//! A file is checked in its language ([`Language`]): a `.par` file (but `ssdraw.par`,
//! ssdraw's own) as pkdgrav's reader and the `--pkdgrav-build` build see it
//! ([`walls_par`]), with its run directory before the job ([`run`]), anything else as a
//! walls file.
//!
//! Exit status: 0 clean, 1 errors found (or warnings, with `--deny-warnings`), 2 usage
//! or I/O error. An I/O error wins: a file that cannot be read (or a folder with no walls
//! file, or a `.par` naming a missing one) makes the status 2 even when other files have
//! findings, and every format reports it. Findings go to standard output in every format
//! (human, json, sarif, github, gitlab), the tool's own errors and warnings to standard
//! error; human findings go to standard error only when standard output carries standard
//! input's fixed text (`--fix -`). Folders are walked as [`walk`] says.
//! `--fix`, `--unsafe-fixes` and `--diff` apply the diagnostics' fixes first (`fix.rs`).
//! Each file is checked with the settings found for it ([`super::settings`]); the flags
//! win over them.

mod fix;
mod run;
mod walk;

pub use fix::fix_text;
pub use walls_ide::MAX_FIX_ROUNDS;

use super::settings::{Resolver, SettingsArgs, absolute_file};
use crate::{ContactModel, all_codes, check_bytes, find_code, input};
use clap::{Parser, ValueEnum};
use rayon::prelude::*;
use std::io::Write;
use std::sync::Arc;
use walls_diagnostics::render::{self, FileReport, ToolInfo, Unreadable};
use walls_diagnostics::{Diagnostic, Severity};
use walls_ide::Fixable;
use walls_model::Options;

/// The command line of `walls-lint`.
#[derive(Parser)]
#[command(
    name = "walls-lint",
    version,
    about = "Check pkdgrav walls files for every mistake pkdgrav would reject or silently misread.",
    after_help = "Exit status: 0 no errors, 1 errors found (or warnings, with --deny-warnings), 2 usage or I/O error (a file that cannot be read gives 2 even when others have errors).\nFindings go to standard output in every format (to standard error beside --fix -'s fixed text); the tool's own errors to standard error.\nA folder is walked (.gitignore respected): its files matching --include (default *.walls), its .par files (pkdgrav's parameter files; not ssdraw.par) and the walls files they name (achWallsFile).\nA .par file is checked as pkdgrav's reader and the --pkdgrav-build build read it, and with its walls file and initial conditions (achInFile, a .ss file) before the job: overlaps, steps per contact, wall speeds, outputs (R codes; the files it names are read only inside the folder named).\nSettings come from the nearest walls.toml, .walls.toml or pyproject.toml [tool.walls] above each file (docs/configuration.md); flags override them."
)]
pub struct LintArgs {
    /// Files or folders to check; `-` reads standard input.
    #[arg(required_unless_present = "explain", value_name = "PATH")]
    pub files: Vec<String>,
    /// In folders, check the files matching this gitignore-style glob (repeatable;
    /// default `*.walls`).
    #[arg(long, value_name = "GLOB", value_parser = glob)]
    pub include: Vec<String>,
    /// In folders, skip the files and folders matching this gitignore-style glob
    /// (repeatable).
    #[arg(long, value_name = "GLOB", value_parser = glob)]
    pub exclude: Vec<String>,
    /// Output format.
    #[arg(long, value_enum, default_value_t = Format::Human)]
    pub format: Format,
    /// The contact model the file is for: hsdem refuses what pkdgrav's hard-sphere code
    /// lacks [default: ssdem].
    #[arg(long, value_enum)]
    pub mode: Option<ContactModel>,
    /// pkdgrav's MAX_NUM_WALLS: warn when the file has more walls [default: 20].
    #[arg(long, value_name = "N")]
    pub max_walls: Option<usize>,
    /// The smallest particle radius (pkdgrav units): enables the SSDEM wall-speed check.
    #[arg(long, value_name = "R", value_parser = positive)]
    pub min_radius: Option<f64>,
    /// The simulation timestep (pkdgrav units): the update step of walls with `step 0`.
    #[arg(long, value_name = "DT", value_parser = positive)]
    pub dt: Option<f64>,
    /// The pkdgrav build `.par` files are checked for: its compile options, space or
    /// comma separated, with or without `USE_` (COLLISIONS and WALLS are always on;
    /// else the settings' `[run] pkdgrav-build`) [default: DEM DEM_FIXED_BALL
    /// DEM_ROTATION_DASHPOT].
    #[arg(long, value_name = "OPTIONS", value_parser = pkdgrav_build)]
    pub pkdgrav_build: Option<walls_par::Build>,
    /// Exit with status 1 on warnings too.
    #[arg(long)]
    pub deny_warnings: bool,
    /// When to colour human output.
    #[arg(long, value_enum, default_value_t = Color::Auto)]
    pub color: Color,
    /// Explain a diagnostic code (`S101` or `unknown-word`) or a keyword (`osc-vec`) and exit.
    #[arg(long, value_name = "CODE", conflicts_with = "files")]
    pub explain: Option<String>,
    /// Apply the safe fixes the diagnostics carry (rewriting the files; standard input's
    /// fixed text goes to standard output), then report what remains.
    #[arg(long)]
    pub fix: bool,
    /// Apply the unsafe fixes too (guesses, such as a spelling suggestion); implies --fix.
    #[arg(long)]
    pub unsafe_fixes: bool,
    /// Write nothing: print a unified diff of what the fixes would change, and exit 1 if
    /// they would change anything; implies --fix.
    #[arg(long, conflicts_with = "format")]
    pub diff: bool,
    /// Print the completion script for SHELL to standard output and exit.
    #[arg(long, value_name = "SHELL", exclusive = true)]
    pub completions: Option<clap_complete::Shell>,
    /// Where the settings come from.
    #[command(flatten)]
    pub settings: SettingsArgs,
}

/// `--format`: where and how diagnostics are reported.
#[allow(missing_docs, reason = "a value's doc comment would show in --help")]
#[derive(Clone, Copy, ValueEnum)]
pub enum Format {
    Human,
    Json,
    Sarif,
    Github,
    Gitlab,
}

/// `--color`: when to colour human output.
#[allow(missing_docs, reason = "a value's doc comment would show in --help")]
#[derive(Clone, Copy, ValueEnum)]
pub enum Color {
    Auto,
    Always,
    Never,
}

/// How a file is checked: as a walls file with its options, or as a pkdgrav `.par` file
/// for a build.
pub(super) enum Language {
    /// A walls file.
    Walls(Options),
    /// A pkdgrav parameter file.
    Par(walls_par::Build),
}

/// A checked file's text and its diagnostics, whichever its language.
pub(super) struct Report {
    /// The text the spans refer to.
    pub text: Arc<str>,
    /// Its diagnostics, sorted by position.
    pub diagnostics: Vec<Diagnostic>,
}

impl Fixable for Report {
    fn text(&self) -> &str {
        &self.text
    }
    fn diagnostics(&self) -> &[Diagnostic] {
        &self.diagnostics
    }
}

impl Language {
    /// The language of the file at `path`: a `.par` file is pkdgrav's (but `ssdraw.par`,
    /// ssdraw's own parameter file, which is no `key = value` file); anything else, and
    /// standard input, a walls file.
    fn of(path: &str, options: Options, build: &walls_par::Build) -> Language {
        if is_pkdgrav_par(std::path::Path::new(path)) {
            Language::Par(build.clone())
        } else {
            Language::Walls(options)
        }
    }

    /// Checks a file's bytes.
    pub(super) fn check_bytes(&self, bytes: Vec<u8>) -> Report {
        match self {
            Language::Walls(options) => check_bytes(bytes, options).into(),
            Language::Par(build) => walls_ide::par::check_par_bytes(bytes, build).into(),
        }
    }

    /// Checks a text (a fixed one).
    pub(super) fn check_text(&self, text: String) -> Report {
        match self {
            Language::Walls(options) => walls_ide::check_text(text, options).into(),
            Language::Par(build) => walls_ide::par::check_par_text(text, build).into(),
        }
    }
}

impl From<crate::Checked> for Report {
    fn from(c: crate::Checked) -> Report {
        Report {
            text: c.text,
            diagnostics: c.diagnostics,
        }
    }
}

impl From<walls_ide::par::ParChecked> for Report {
    fn from(c: walls_ide::par::ParChecked) -> Report {
        Report {
            text: c.text,
            diagnostics: c.diagnostics,
        }
    }
}

/// Whether `path` names a pkdgrav parameter file ([`walls_par::is_par_file`]).
pub(super) fn is_pkdgrav_par(path: &std::path::Path) -> bool {
    (path.file_name())
        .and_then(|n| n.to_str())
        .is_some_and(walls_par::is_par_file)
}

/// One checked file: the text the diagnostics refer to, or the I/O error.
struct Linted {
    name: String,
    outcome: Result<(Arc<str>, Vec<Diagnostic>), String>,
    /// Its warnings fail the check (`--deny-warnings`, or its settings' `deny-warnings`).
    deny_warnings: bool,
    /// The settings' ignores of codes it has errors of: they are reported anyway.
    ignored_errors: Vec<String>,
    /// A `.par` file's run directory, checked before the job ([`run`]): the findings in
    /// its other files and the I/O errors.
    run: Option<run::RunChecked>,
}

impl Linted {
    /// A file's outcome, before its settings say more of it.
    fn new(name: String, outcome: Result<(Arc<str>, Vec<Diagnostic>), String>) -> Linted {
        Linted {
            name,
            outcome,
            deny_warnings: false,
            ignored_errors: Vec::new(),
            run: None,
        }
    }
}

/// Checks the files `args` name and reports on them; the exit status.
pub fn run(args: &LintArgs) -> i32 {
    if let Some(query) = &args.explain {
        return explain(query);
    }
    let resolver = match Resolver::new(&args.settings) {
        Ok(resolver) => resolver,
        Err(e) => {
            crate::errln!("walls-lint: error: {e}");
            return 2;
        }
    };
    let globs = |folder: &str| {
        let lint = &resolver.settings(folder).map_err(|e| e.to_string())?.lint;
        let pick = |flag: &Vec<String>, set: &Vec<String>| {
            if flag.is_empty() { set } else { flag }.clone()
        };
        Ok((
            pick(&args.include, &lint.include),
            pick(&args.exclude, &lint.exclude),
        ))
    };
    let targets = match walk::expand(&args.files, globs) {
        Ok(targets) => targets,
        Err(e) => {
            crate::errln!("walls-lint: error: {e}");
            return 2;
        }
    };
    let fixing = fix::Fixing::asked(args);
    if let Some(clash) = fixing.and_then(|f| f.output_clash(args.format, &targets.files)) {
        crate::errln!("walls-lint: error: {clash}");
        return 2;
    }
    let (checked, fixes): (Vec<Linted>, Vec<fix::FileFixes>) = targets
        .files
        .par_iter()
        .map(|p| {
            lint(
                p,
                targets.walked.get(p).map(|r| r.as_path()),
                args,
                &resolver,
                fixing,
            )
        })
        .unzip();
    let (checked, run_errors) = with_runs(checked);
    for c in &checked {
        for e in &c.ignored_errors {
            crate::errln!("walls-lint: warning: {e}");
        }
    }

    let mut unreadable: Vec<Unreadable> = Vec::new();
    for c in &checked {
        if let Err(e) = &c.outcome {
            unreadable.push(Unreadable {
                path: &c.name,
                error: e,
                line: None,
            });
        }
    }
    for (path, error, line) in &run_errors {
        unreadable.push(Unreadable {
            path,
            error,
            line: *line,
        });
    }
    for e in &targets.errors {
        unreadable.push(Unreadable {
            path: &e.path,
            error: &e.message,
            line: e.line,
        });
    }
    for (c, f) in checked.iter().zip(&fixes) {
        if let Some(e) = &f.not_written {
            unreadable.push(Unreadable {
                path: &c.name,
                error: e,
                line: None,
            });
        }
    }
    // A broken settings file is every file's error: said once.
    let mut said = std::collections::HashSet::new();
    for u in &unreadable {
        if said.insert(u.error) {
            crate::errln!("walls-lint: error: {}", u.error);
        }
    }
    let io_failed = !unreadable.is_empty();
    let reports: Vec<FileReport> = checked
        .iter()
        .filter_map(|c| {
            let (text, diagnostics) = c.outcome.as_ref().ok()?;
            Some(FileReport {
                path: &c.name,
                source: text,
                diagnostics,
            })
        })
        .collect();
    let summary = render::summarize(&reports);
    let denied = checked.iter().any(|c| {
        c.deny_warnings
            && c.outcome.as_ref().is_ok_and(|(_, diagnostics)| {
                diagnostics.iter().any(|d| d.severity == Severity::Warning)
            })
    });
    let fixed = fixes.iter().map(|f| f.fixed).sum();
    let diff = fixing.is_some_and(|f| f.diff);
    let written = fix::write_outputs(&fixes).and_then(|()| {
        if diff {
            fix::write_diff_summary(&fixes)
        } else {
            // Standard output carries standard input's fixed text when there is one: the
            // findings go beside it, to standard error, so the text stays the file's.
            let stdout_taken = fixes.iter().any(|f| f.output.is_some());
            write_reports(
                args,
                &reports,
                &unreadable,
                fixing.map(|_| fixed),
                stdout_taken,
            )
        }
    });
    if let Err(e) = written {
        if e.kind() != std::io::ErrorKind::BrokenPipe {
            crate::errln!("walls-lint: error: cannot write output: {e}");
        }
        return 2;
    }
    // The process ends here: freeing every tree and diagnostic first would only cost time.
    std::mem::forget(checked);
    if io_failed {
        2
    } else if diff {
        i32::from(fixed > 0)
    } else if summary.errors > 0 || denied {
        1
    } else {
        0
    }
}

/// Checks one file with its settings, the flags winning over them; with `fixing`, applies
/// its fixes first (`fix.rs`). A `.par` file's run directory is checked too ([`run`]):
/// inside `walked`, the folder whose walk found it, or its own folder when named. Diagnostics of ignored codes are dropped after every check,
/// so their fixes are never applied either.
fn lint(
    path: &str,
    walked: Option<&std::path::Path>,
    args: &LintArgs,
    resolver: &Resolver,
    fixing: Option<fix::Fixing>,
) -> (Linted, fix::FileFixes) {
    let settings = match resolver.settings(path) {
        Ok(settings) => settings,
        Err(e) => {
            let linted = Linted::new(input::display_name(path), Err(e.to_string()));
            return (linted, fix::FileFixes::default());
        }
    };
    let set = &settings.lint;
    let defaults = Options::default();
    let options = Options {
        mode: args.mode.or(set.mode).unwrap_or(defaults.mode),
        max_walls: args
            .max_walls
            .or(set.max_walls)
            .unwrap_or(defaults.max_walls),
        min_radius: args.min_radius.or(set.min_radius),
        dt: args.dt.or(set.dt),
    };
    let build = (args.pkdgrav_build.as_ref())
        .or(settings.run.pkdgrav_build.as_ref())
        .cloned()
        .unwrap_or_default();
    let language = Language::of(path, options, &build);
    let file = absolute_file(path);
    let keep = |diagnostics: &mut Vec<Diagnostic>| {
        set.filter(file.as_deref(), diagnostics);
    };
    let (mut linted, fixes) = match fixing {
        Some(fixing) => fix::lint(path, &language, &keep, fixing),
        None => {
            let read = input::read(path);
            let outcome = read.bytes.map(|bytes| {
                let mut checked = language.check_bytes(bytes);
                keep(&mut checked.diagnostics);
                (checked.text, checked.diagnostics)
            });
            (Linted::new(read.name, outcome), fix::FileFixes::default())
        }
    };
    // A `.par` file's run directory is checked before the job.
    if let (Language::Par(build), Ok((text, diagnostics))) = (&language, &mut linted.outcome) {
        let mut found = run::check(path, walked, text, build);
        diagnostics.append(&mut found.par);
        keep(diagnostics);
        diagnostics.sort_by_key(|d| (d.span.start, d.span.end));
        for f in &mut found.files {
            let file = absolute_file(&f.name);
            set.filter(file.as_deref(), &mut f.diagnostics);
        }
        linted.run = Some(found);
    }
    // The errors of ignored codes are kept; filtering again names the settings that
    // asked for them to be ignored.
    if let Ok((_, diagnostics)) = &mut linted.outcome {
        for i in set.filter(file.as_deref(), diagnostics) {
            linted.ignored_errors.push(format!(
                "{}: `{}` is ignored, but errors cannot be: its errors in {} are reported",
                i.at, i.code.id, linted.name
            ));
        }
    }
    linted.deny_warnings = args.deny_warnings || set.deny_warnings.unwrap_or(false);
    (linted, fixes)
}

/// A run directory's I/O error: the `.par`, the error, the `.par`'s line.
type RunError = (String, String, Option<usize>);

/// The checked files with the findings of the `.par` files' run directories added to the
/// reports of the files they are in (a file not checked itself gets a report of its
/// own), and the run directories' I/O errors: (the `.par`, the error, its line).
fn with_runs(mut checked: Vec<Linted>) -> (Vec<Linted>, Vec<RunError>) {
    let mut errors = Vec::new();
    let mut files = Vec::new();
    for c in &mut checked {
        if let Some(found) = c.run.take() {
            for (error, line) in found.errors {
                errors.push((c.name.clone(), error, line));
            }
            files.extend(found.files);
        }
    }
    // Each checked file by its real path, once (a tree of many run directories stays
    // linear).
    let mut index: std::collections::HashMap<std::path::PathBuf, usize> = if files.is_empty() {
        Default::default()
    } else {
        (checked.iter().enumerate())
            .filter_map(|(i, c)| Some((std::fs::canonicalize(&c.name).ok()?, i)))
            .collect()
    };
    for f in files {
        let same = index.get(&f.real).copied();
        match same.map(|i| &mut checked[i].outcome) {
            Some(Ok((_, diagnostics))) => {
                diagnostics.extend(f.diagnostics);
                diagnostics.sort_by_key(|d| (d.span.start, d.span.end));
                // Two `.par` files of one run directory find the same things in it.
                diagnostics.dedup();
            }
            Some(Err(_)) => {}
            None => {
                index.insert(f.real, checked.len());
                checked.push(Linted::new(f.name, Ok((f.text, f.diagnostics))));
            }
        }
    }
    (checked, errors)
}

/// `--pkdgrav-build`'s value: pkdgrav's compile options.
fn pkdgrav_build(s: &str) -> Result<walls_par::Build, String> {
    walls_par::Build::parse(s).map_err(|e| e.to_string())
}

/// A glob for `--include` and `--exclude`, checked as the settings file's are.
fn glob(s: &str) -> Result<String, String> {
    walls_config::check_glob(s).map(|()| s.to_string())
}

/// A strictly positive real, for `--min-radius` and `--dt`, read by the tools' one rule
/// for numbers (`1e-400`, which a double rounds to 0, is refused as such).
fn positive(s: &str) -> Result<f64, String> {
    match walls_keywords::number::read(s) {
        Ok(x) if x > 0.0 => Ok(x),
        Ok(_) => Err(format!("`{s}` is not a positive number")),
        Err(why) => Err(format!("`{s}` is {why}")),
    }
}

/// Writes the report in the format `args` ask for, on standard output (as ruff, flake8
/// and shellcheck do: `walls-lint f > report.txt` keeps it), or for human output on
/// standard error when `stdout_taken` (standard input's fixed text is on standard output).
/// Human output ends with a summary, which says how many fixes were applied when `fixed`
/// gives their number.
fn write_reports(
    args: &LintArgs,
    reports: &[FileReport],
    unreadable: &[Unreadable],
    fixed: Option<usize>,
    stdout_taken: bool,
) -> std::io::Result<()> {
    match args.format {
        Format::Human => {
            let color = match args.color {
                Color::Always => true,
                Color::Never => false,
                Color::Auto if stdout_taken => crate::console::color_stderr(),
                Color::Auto => crate::console::color_stdout(),
            };
            // ariadne writes a character at a time: a buffer in front of either stream.
            let stream: Box<dyn Write> = if stdout_taken {
                Box::new(std::io::stderr().lock())
            } else {
                Box::new(std::io::stdout().lock())
            };
            let mut out = std::io::BufWriter::new(stream);
            for r in reports {
                render::human(&mut out, r, color)?;
            }
            let s = render::summarize(reports);
            if s.errors + s.warnings + s.infos > 0 || reports.len() > 1 || fixed > Some(0) {
                write!(
                    out,
                    "{} error{}, {} warning{} in {} file{}",
                    s.errors,
                    plural(s.errors),
                    s.warnings,
                    plural(s.warnings),
                    reports.len(),
                    plural(reports.len())
                )?;
                match fixed {
                    Some(n) => writeln!(out, "; {n} fixed")?,
                    None => writeln!(out)?,
                }
            }
            out.flush()
        }
        Format::Json => {
            let mut out = std::io::BufWriter::new(std::io::stdout().lock());
            render::json(&mut out, reports, unreadable)?;
            out.flush()
        }
        Format::Sarif => {
            let tool = ToolInfo {
                name: "walls-lint",
                version: env!("CARGO_PKG_VERSION"),
                information_uri: None,
            };
            let rules: Vec<_> = all_codes().collect();
            let mut out = std::io::BufWriter::new(std::io::stdout().lock());
            render::sarif(&mut out, reports, unreadable, &tool, &rules)?;
            out.flush()
        }
        Format::Github => {
            let mut out = std::io::BufWriter::new(std::io::stdout().lock());
            render::github(&mut out, reports, unreadable)?;
            out.flush()
        }
        Format::Gitlab => {
            let mut out = std::io::BufWriter::new(std::io::stdout().lock());
            render::gitlab(&mut out, reports, unreadable)?;
            out.flush()
        }
    }
}

fn explain(query: &str) -> i32 {
    if let Some(code) = find_code(query) {
        crate::outln!("{}", walls_ide::explain_code(code));
        return 0;
    }
    if let Some(keyword) = walls_keywords::keyword(query) {
        crate::out!("{}", keyword.markdown());
        return 0;
    }
    let known: Vec<&str> = all_codes().map(|c| c.id).collect();
    crate::errln!(
        "walls-lint: error: `{query}` is neither a diagnostic code ({}) nor a keyword of the language",
        known.join(", ")
    );
    2
}

fn plural(n: usize) -> &'static str {
    if n == 1 { "" } else { "s" }
}
