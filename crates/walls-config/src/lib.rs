//! The settings of `walls-lint`, `walls-fmt` and the language server
//! (docs/configuration.md).
//!
//! A settings file is `walls.toml`, `.walls.toml` or a `pyproject.toml` with a
//! `[tool.walls]` table, with a `[lint]` and a `[format]` table. [`find`] looks for one
//! upward from a file's folder: the nearest folder that has one wins, whole (nothing is
//! merged from folders further up), and two of them in one folder are an error. For
//! formatting, [`find_format`] also takes `.walls-fmt.toml`, the older file of formatting
//! options alone; a folder with both it and a `[format]` table is an error naming both.
//! [`load`] reads one file named on the command line (`--config`).
//!
//! Every mistake (unknown key, wrong type, unknown code, bad glob, a value out of range)
//! is a [`SettingsError`] with the file, line and column. Command-line flags win over the
//! file: the callers apply them.
//!
//! Resources: a settings file is read up to [`MAX_FILE_BYTES`], the limit walls files
//! have (a device, a socket or a folder is refused unread, a pipe only read when named);
//! every list is read and applied in linear time ([`Lint::filter`] looks each
//! diagnostic's code up once). What a file costs in memory is about twenty times its
//! size, plus the matcher the `ignore` crate compiles for each glob (some 10 KB each):
//! docs/configuration.md, "Limits".

mod read;

pub use read::{ReadError, read_at_most};

use ignore::gitignore::Gitignore;
use ignore::overrides::OverrideBuilder;
use std::collections::HashMap;
use std::fmt;
use std::path::{Path, PathBuf};
use walls_diagnostics::{Code, Diagnostic, Severity};
use walls_format::FormatOptions;
use walls_keywords::ContactModel;
use walls_model::Options;

/// The names of a settings file, in the order [`find`] looks for them in a folder.
pub const SETTINGS_FILES: [&str; 3] = ["walls.toml", ".walls.toml", "pyproject.toml"];

/// The older file of formatting options alone.
pub const FORMAT_FILE: &str = ".walls-fmt.toml";

/// The largest file the tools read, settings files and walls files alike: spans are
/// stored as 32-bit offsets.
pub const MAX_FILE_BYTES: u64 = u32::MAX as u64;

/// Checks a glob of a settings file or of a flag (`--include`, `--exclude`) as the folder
/// walk and `per-file-ignores` use it (gitignore-style): a `[` without its `]` is a
/// mistake, and so are the globs that gitignore syntax would quietly read as matching
/// nothing: an empty one, a comment (`#…`) and a negation (`!…`), which has no meaning in
/// a list of files to take or to skip. `\#` and `\!` start a name with `#` or `!`.
pub fn check_glob(glob: &str) -> Result<(), String> {
    let invalid = |why: &str| Err(format!("invalid glob `{glob}`: {why}"));
    if glob.trim().is_empty() {
        return invalid("an empty glob matches nothing");
    }
    if glob.starts_with('#') {
        return invalid(
            "a glob cannot start with `#` (a comment in gitignore syntax); write `\\#` for a name that starts with `#`",
        );
    }
    if glob.starts_with('!') {
        return invalid(
            "a glob here cannot be negated; write `\\!` for a name that starts with `!`",
        );
    }
    OverrideBuilder::new("/")
        .add(glob)
        .map(|_| ())
        .map_err(|e| bad_glob(glob, &e))
}

/// The message for a glob the `ignore` crate refused.
fn bad_glob(glob: &str, e: &ignore::Error) -> String {
    format!("invalid glob `{glob}`: {e}")
}

/// A settings file that could not be used.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SettingsError {
    /// The file.
    pub path: PathBuf,
    /// The 1-based line and character column of the mistake, where it has one.
    pub at: Option<(usize, usize)>,
    /// What is wrong.
    pub message: String,
}

impl fmt::Display for SettingsError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.at {
            Some((line, column)) => write!(
                f,
                "{}:{line}:{column}: {}",
                self.path.display(),
                self.message
            ),
            None => write!(f, "{}: {}", self.path.display(), self.message),
        }
    }
}

/// A place in a settings file, for messages about what it says.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Location {
    /// The file.
    pub path: PathBuf,
    /// 1-based line.
    pub line: usize,
    /// 1-based character column.
    pub column: usize,
}

impl fmt::Display for Location {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}:{}", self.path.display(), self.line, self.column)
    }
}

/// The settings a file is checked and formatted with.
#[derive(Debug, Clone, Default)]
pub struct Settings {
    /// The settings file, or `None` when none was found (the defaults).
    pub path: Option<PathBuf>,
    /// The `[lint]` table (empty when the file has none).
    pub lint: Lint,
    /// The `[format]` table's options, if the file has one.
    pub format: Option<FormatOptions>,
    /// The `[run]` table (empty when the file has none).
    pub run: Run,
}

/// The `[run]` table: what a run directory is run by.
#[derive(Debug, Clone, Default)]
pub struct Run {
    /// `pkdgrav-build`: the pkdgrav build `.par` files are checked for (its compile
    /// options, as `--pkdgrav-build` takes them; docs/par-files.md).
    pub pkdgrav_build: Option<walls_par::Build>,
}

/// The `[lint]` table: each value, if the file sets it.
#[derive(Debug, Clone, Default)]
pub struct Lint {
    /// `mode`: the contact model.
    pub mode: Option<ContactModel>,
    /// `max-walls`: pkdgrav's MAX_NUM_WALLS.
    pub max_walls: Option<usize>,
    /// `min-radius`: the smallest particle radius.
    pub min_radius: Option<f64>,
    /// `dt`: the simulation timestep.
    pub dt: Option<f64>,
    /// `deny-warnings`: exit 1 on warnings too.
    pub deny_warnings: Option<bool>,
    /// `ignore`: codes whose warnings and infos are not reported.
    pub ignore: Vec<Ignore>,
    /// `per-file-ignores`: more codes for the files matching a glob.
    pub per_file_ignores: Vec<PerFile>,
    /// `include`: the files of a folder to check (gitignore-style globs).
    pub include: Vec<String>,
    /// `exclude`: the files and folders of a folder to skip.
    pub exclude: Vec<String>,
}

/// A code to ignore, and where the settings say so.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Ignore {
    /// The code.
    pub code: &'static Code,
    /// Where the settings file names it.
    pub at: Location,
}

/// The codes to ignore in the files a glob matches.
#[derive(Debug, Clone)]
pub struct PerFile {
    /// The glob as written.
    pub glob: String,
    /// The glob, gitignore-style, relative to the settings file's folder.
    matcher: Gitignore,
    /// The codes.
    pub codes: Vec<Ignore>,
}

impl Lint {
    /// The checker's options: `base` (the defaults, or an editor's settings) with each
    /// value this table sets in its place. Command-line flags win over the table: the
    /// linter applies them to the result.
    pub fn options(&self, base: &Options) -> Options {
        Options {
            mode: self.mode.unwrap_or(base.mode),
            max_walls: self.max_walls.unwrap_or(base.max_walls),
            min_radius: self.min_radius.or(base.min_radius),
            dt: self.dt.or(base.dt),
        }
    }

    /// The ignores that apply to the file at `file` (an absolute path; `None` for
    /// standard input, which only `ignore` applies to).
    pub fn ignores_for<'a>(&'a self, file: Option<&'a Path>) -> impl Iterator<Item = &'a Ignore> {
        let per_file = self.per_file_ignores.iter().filter(move |p| {
            file.is_some_and(|f| {
                f.starts_with(p.matcher.path())
                    && p.matcher.matched_path_or_any_parents(f, false).is_ignore()
            })
        });
        self.ignore
            .iter()
            .chain(per_file.flat_map(|p| p.codes.iter()))
    }

    /// Removes from `diagnostics` the warnings and infos whose code is ignored for
    /// `file`. Errors are never removed: the ignores that met one are returned (each
    /// once), for the caller to say so. Linear in the ignores and the diagnostics: the
    /// first ignore of each code (in the order [`Lint::ignores_for`] gives) is found once.
    pub fn filter<'a>(
        &'a self,
        file: Option<&'a Path>,
        diagnostics: &mut Vec<Diagnostic>,
    ) -> Vec<&'a Ignore> {
        let mut ignores: HashMap<&str, &Ignore> = HashMap::new();
        for i in self.ignores_for(file) {
            ignores.entry(i.code.id).or_insert(i);
        }
        if ignores.is_empty() {
            return Vec::new();
        }
        let mut met_errors: Vec<&Ignore> = Vec::new();
        diagnostics.retain(|d| {
            let Some(&ignore) = ignores.get(d.code.id) else {
                return true;
            };
            if d.severity == Severity::Error {
                if !met_errors.iter().any(|m| std::ptr::eq(*m, ignore)) {
                    met_errors.push(ignore);
                }
                return true;
            }
            false
        });
        met_errors
    }
}

/// The nearest settings file upward from folder `dir` (which is made absolute), read;
/// the defaults when there is none up to the filesystem's root.
pub fn find(dir: &Path) -> Result<Settings, SettingsError> {
    let dir = absolute(dir);
    for d in dir.ancestors() {
        if let Some(settings) = settings_in(d)? {
            return Ok(settings);
        }
    }
    Ok(Settings::default())
}

/// The formatting options for a file in folder `dir`: those of the nearest folder
/// upward with a settings file or a `.walls-fmt.toml` (the defaults for a settings file
/// without `[format]`), with the file they come from.
pub fn find_format(dir: &Path) -> Result<(FormatOptions, Option<PathBuf>), SettingsError> {
    let dir = absolute(dir);
    for d in dir.ancestors() {
        let settings = settings_in(d)?;
        let old = shown(&d.join(FORMAT_FILE));
        let old = old.exists().then_some(old);
        match (settings, old) {
            (Some(s), Some(old)) if s.format.is_some() => {
                let path = s.path.unwrap_or_default();
                return Err(SettingsError {
                    message: format!(
                        "both this file and {} set the formatting options: keep one (move them to the [format] table)",
                        path.display()
                    ),
                    path: old,
                    at: None,
                });
            }
            (_, Some(old)) => return format_of(load_as(&old, read::Origin::Found)?),
            (Some(s), None) => return format_of(s),
            (None, None) => {}
        }
    }
    Ok((FormatOptions::default(), None))
}

/// The options a settings file's `[format]` gives (the defaults without one), with its path.
fn format_of(s: Settings) -> Result<(FormatOptions, Option<PathBuf>), SettingsError> {
    Ok((s.format.unwrap_or_default(), s.path))
}

/// Reads the settings file at `path`, named on the command line: a `pyproject.toml` is
/// read for its `[tool.walls]` (an error if it has none), a `.walls-fmt.toml` for
/// formatting options, any other name as a `walls.toml`.
pub fn load(path: &Path) -> Result<Settings, SettingsError> {
    load_as(path, read::Origin::Named)
}

/// Reads the settings file at `path`, named or found; an error if it has no settings.
fn load_as(path: &Path, origin: read::Origin) -> Result<Settings, SettingsError> {
    read::read(path, origin)?.ok_or_else(|| SettingsError {
        path: path.to_path_buf(),
        at: None,
        message: "has no [tool.walls] table".into(),
    })
}

/// The settings file of folder `dir`, if it has one; two are an error.
fn settings_in(dir: &Path) -> Result<Option<Settings>, SettingsError> {
    let mut found: Option<Settings> = None;
    for name in SETTINGS_FILES {
        let path = shown(&dir.join(name));
        // Something by that name that is no regular file is an error, not skipped.
        if !path.exists() {
            continue;
        }
        let Some(settings) = read::read(&path, read::Origin::Found)? else {
            continue;
        };
        if let Some(first) = &found {
            return Err(SettingsError {
                message: format!(
                    "both this file and {} are settings files of the same folder: keep one",
                    path.display()
                ),
                path: first.path.clone().unwrap_or_default(),
                at: None,
            });
        }
        found = Some(settings);
    }
    Ok(found)
}

/// `path` (absolute) as messages show it: relative to the current folder when it is
/// inside it, else whole.
fn shown(path: &Path) -> PathBuf {
    std::env::current_dir()
        .ok()
        .map(|cwd| absolute(&cwd))
        .and_then(|cwd| path.strip_prefix(cwd).ok().map(Path::to_path_buf))
        .unwrap_or_else(|| path.to_path_buf())
}

/// `dir` as an absolute path without `.` or `..` (symbolic links resolved where it
/// exists), so that every ancestor is looked at and per-file globs match.
pub fn absolute(dir: &Path) -> PathBuf {
    let dir = if dir.as_os_str().is_empty() {
        Path::new(".")
    } else {
        dir
    };
    std::fs::canonicalize(dir)
        .or_else(|_| std::path::absolute(dir))
        .unwrap_or_else(|_| dir.to_path_buf())
}

#[cfg(test)]
mod tests;
