//! Reading one settings file: `walls.toml`, `.walls.toml`, `pyproject.toml`'s
//! `[tool.walls]` or `.walls-fmt.toml`, every mistake located by line and column.

use crate::{Ignore, Lint, Location, PerFile, Settings, SettingsError};
use ignore::gitignore::GitignoreBuilder;
use ignore::overrides::OverrideBuilder;
use serde::Deserialize;
use std::collections::BTreeMap;
use std::ops::Range;
use std::path::Path;
use toml::Spanned;
use walls_format::{FormatOptions, FormatTable};
use walls_keywords::ContactModel;

/// The tables of `walls.toml` (and of `[tool.walls]`).
#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct WallsTables {
    lint: Option<LintTable>,
    format: Option<FormatTable>,
}

/// `pyproject.toml`: only `[tool.walls]` is ours.
#[derive(Deserialize)]
struct PyProject {
    tool: Option<PyTools>,
}

#[derive(Deserialize)]
struct PyTools {
    walls: Option<WallsTables>,
}

/// The `[lint]` table as written.
#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields, rename_all = "kebab-case")]
struct LintTable {
    mode: Option<Mode>,
    max_walls: Option<usize>,
    min_radius: Option<Spanned<f64>>,
    dt: Option<Spanned<f64>>,
    deny_warnings: Option<bool>,
    #[serde(default)]
    ignore: Vec<Spanned<String>>,
    #[serde(default)]
    per_file_ignores: BTreeMap<Spanned<String>, Vec<Spanned<String>>>,
    #[serde(default)]
    include: Vec<Spanned<String>>,
    #[serde(default)]
    exclude: Vec<Spanned<String>>,
}

/// `mode`, spelled as `--mode` is.
#[derive(Deserialize, Clone, Copy)]
#[serde(rename_all = "lowercase")]
enum Mode {
    Ssdem,
    Hsdem,
}

/// What kind of file a path is, by its name.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(crate) enum Kind {
    /// `walls.toml`, `.walls.toml`, or any other name given to `--config`.
    Walls,
    /// `pyproject.toml`: its `[tool.walls]`.
    PyProject,
    /// `.walls-fmt.toml`: formatting options at the top level.
    Format,
}

impl Kind {
    /// The kind of the file at `path`, by its name.
    pub(crate) fn of(path: &Path) -> Kind {
        match path.file_name().and_then(|n| n.to_str()) {
            Some("pyproject.toml") => Kind::PyProject,
            Some(crate::FORMAT_FILE) => Kind::Format,
            _ => Kind::Walls,
        }
    }
}

/// Reads the settings file at `path`. `None` for a `pyproject.toml` without
/// `[tool.walls]` (it does not count as settings).
pub(crate) fn read(path: &Path) -> Result<Option<Settings>, SettingsError> {
    let text = std::fs::read_to_string(path).map_err(|e| SettingsError {
        path: path.to_path_buf(),
        at: None,
        message: format!("cannot read: {e}"),
    })?;
    let file = File { path, text: &text };
    let tables = match Kind::of(path) {
        Kind::Walls => file.parse::<WallsTables>()?,
        Kind::PyProject => match file.parse::<PyProject>()?.tool.and_then(|t| t.walls) {
            Some(tables) => tables,
            None => return Ok(None),
        },
        Kind::Format => WallsTables {
            lint: None,
            format: Some(file.parse::<FormatTable>()?),
        },
    };
    let lint = match tables.lint {
        Some(table) => file.lint(table)?,
        None => Lint::default(),
    };
    let format = match tables.format {
        Some(table) => Some(file.format(&table)?),
        None => None,
    };
    Ok(Some(Settings {
        path: Some(path.to_path_buf()),
        lint,
        format,
    }))
}

/// A settings file being read: its path and text, to locate mistakes.
struct File<'a> {
    path: &'a Path,
    text: &'a str,
}

impl File<'_> {
    /// The error at byte `span.start` of the file.
    fn error(&self, span: Option<Range<usize>>, message: impl Into<String>) -> SettingsError {
        SettingsError {
            path: self.path.to_path_buf(),
            at: span.map(|s| line_column(self.text, s.start)),
            message: message.into(),
        }
    }

    /// Where byte `offset` is, for messages.
    fn location(&self, offset: usize) -> Location {
        let (line, column) = line_column(self.text, offset);
        Location {
            path: self.path.to_path_buf(),
            line,
            column,
        }
    }

    fn parse<T: serde::de::DeserializeOwned>(&self) -> Result<T, SettingsError> {
        toml::from_str(self.text).map_err(|e| self.error(e.span(), e.message().trim_end()))
    }

    fn format(&self, table: &FormatTable) -> Result<FormatOptions, SettingsError> {
        table
            .options()
            .map_err(|(span, message)| self.error(Some(span), message))
    }

    fn lint(&self, table: LintTable) -> Result<Lint, SettingsError> {
        let dir = crate::absolute(self.path.parent().unwrap_or(Path::new("")));
        let dir = dir.as_path();
        let positive = |x: Option<Spanned<f64>>, key: &str| -> Result<_, SettingsError> {
            match x {
                Some(v) if !(*v.get_ref() > 0.0 && v.get_ref().is_finite()) => Err(self.error(
                    Some(v.span()),
                    format!("{key} must be a positive number, not {}", v.get_ref()),
                )),
                v => Ok(v.map(Spanned::into_inner)),
            }
        };
        let per_file_ignores = table
            .per_file_ignores
            .into_iter()
            .map(|(glob, codes)| {
                let mut builder = GitignoreBuilder::new(dir);
                builder
                    .add_line(None, glob.get_ref())
                    .map_err(|e| self.error(Some(glob.span()), bad_glob(glob.get_ref(), &e)))?;
                let matcher = builder
                    .build()
                    .map_err(|e| self.error(Some(glob.span()), bad_glob(glob.get_ref(), &e)))?;
                Ok(PerFile {
                    glob: glob.into_inner(),
                    matcher,
                    codes: self.codes(codes)?,
                })
            })
            .collect::<Result<_, SettingsError>>()?;
        Ok(Lint {
            mode: table.mode.map(|m| match m {
                Mode::Ssdem => ContactModel::Ssdem,
                Mode::Hsdem => ContactModel::Hsdem,
            }),
            max_walls: table.max_walls,
            min_radius: positive(table.min_radius, "min-radius")?,
            dt: positive(table.dt, "dt")?,
            deny_warnings: table.deny_warnings,
            ignore: self.codes(table.ignore)?,
            per_file_ignores,
            include: self.globs(dir, table.include)?,
            exclude: self.globs(dir, table.exclude)?,
        })
    }

    /// The codes of an `ignore` list, by id or name.
    fn codes(&self, codes: Vec<Spanned<String>>) -> Result<Vec<Ignore>, SettingsError> {
        codes
            .into_iter()
            .map(|c| match walls_ide::find_code(c.get_ref()) {
                Some(code) => Ok(Ignore {
                    code,
                    at: self.location(c.span().start),
                }),
                None => Err(self.error(
                    Some(c.span()),
                    format!(
                        "`{}` is not a diagnostic code (walls-lint --explain CODE, docs/diagnostics.md)",
                        c.get_ref()
                    ),
                )),
            })
            .collect()
    }

    /// The globs of `include` or `exclude`, checked as the folder walk will use them.
    fn globs(&self, dir: &Path, globs: Vec<Spanned<String>>) -> Result<Vec<String>, SettingsError> {
        let mut builder = OverrideBuilder::new(dir);
        for g in &globs {
            builder
                .add(g.get_ref())
                .map_err(|e| self.error(Some(g.span()), bad_glob(g.get_ref(), &e)))?;
        }
        Ok(globs.into_iter().map(Spanned::into_inner).collect())
    }
}

fn bad_glob(glob: &str, e: &ignore::Error) -> String {
    format!("invalid glob `{glob}`: {e}")
}

/// The 1-based line and character column of byte `offset` of `text`.
fn line_column(text: &str, offset: usize) -> (usize, usize) {
    let offset = offset.min(text.len());
    let before = &text[..offset];
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, column)
}
