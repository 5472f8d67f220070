//! Reading one settings file: `walls.toml`, `.walls.toml`, `pyproject.toml`'s
//! `[tool.walls]` or `.walls-fmt.toml`, every mistake located by line and column.
//!
//! A settings file is read whole, up to [`MAX_FILE_BYTES`](crate::MAX_FILE_BYTES) (the
//! limit walls files have), the limit enforced while reading: a regular file's size is
//! looked at before anything is read, and a pipe stops being read one byte past the
//! limit. A device, a socket or a folder is refused before it is opened; a pipe is read
//! only when named (`--config <(…)`), never when found in a folder, where nothing would
//! write to it. Every glob is checked as the folder walk and the matching will use it
//! ([`crate::check_glob`]), and every location is found through one index of the
//! text's lines, so that a list of any length is read in linear time.

use crate::{Ignore, Lint, Location, MAX_FILE_BYTES, PerFile, Run, Settings, SettingsError};
use ignore::gitignore::GitignoreBuilder;
use serde::Deserialize;
use std::collections::BTreeMap;
use std::io::Read;
use std::ops::Range;
use std::path::Path;
use toml::Spanned;
use walls_diagnostics::LineIndex;
use walls_format::{FormatOptions, FormatTable};
use walls_keywords::ContactModel;

/// The tables of `walls.toml` (and of `[tool.walls]`).
#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct WallsTables {
    lint: Option<LintTable>,
    format: Option<FormatTable>,
    run: Option<RunTable>,
}

/// The `[run]` table as written.
#[derive(Deserialize, Default)]
#[serde(deny_unknown_fields, rename_all = "kebab-case")]
struct RunTable {
    pkdgrav_build: Option<Spanned<String>>,
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

/// How a settings file came to be read: named on the command line, or found in a folder.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(crate) enum Origin {
    /// `--config PATH`: a pipe is read too.
    Named,
    /// Found upward from a folder: only a regular file is read.
    Found,
}

/// Why [`read_at_most`] gave up.
#[derive(Debug)]
pub enum ReadError {
    /// The input has more than this many bytes.
    TooLarge(u64),
    /// Reading failed.
    Io(std::io::Error),
}

impl std::fmt::Display for ReadError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ReadError::TooLarge(limit) => {
                write!(f, "larger than {limit} bytes, the most the tools read")
            }
            ReadError::Io(e) => e.fmt(f),
        }
    }
}

/// The pieces [`read_at_most`] reads a long input in.
const PIECE: usize = 64 << 20;

/// Reads all of `reader`, up to `limit` bytes: more is an error, found after reading one
/// byte past the limit. Never more than `limit + 1` bytes are held: an input longer than
/// a piece of 64 MiB is read in pieces (a growing buffer would hold its old and its new
/// copy at once: an endless pipe took 8.4 GB to refuse at 4 GB), joined once at the end
/// when it is within the limit. Every reader of the tools' files uses it, with
/// [`MAX_FILE_BYTES`].
pub fn read_at_most(reader: impl Read, limit: u64) -> Result<Vec<u8>, ReadError> {
    read_in_pieces(reader, limit, PIECE)
}

/// [`read_at_most`], in pieces of `piece` bytes.
fn read_in_pieces(reader: impl Read, limit: u64, piece: usize) -> Result<Vec<u8>, ReadError> {
    let mut reader = reader.take(limit.saturating_add(1));
    let mut pieces: Vec<Vec<u8>> = Vec::new();
    let mut total = 0u64;
    loop {
        // The first piece grows as it needs (a small input is one small buffer); the
        // others are one piece each.
        let mut next = match pieces.is_empty() {
            true => Vec::new(),
            false => Vec::with_capacity(piece),
        };
        let n = (&mut reader)
            .take(piece as u64)
            .read_to_end(&mut next)
            .map_err(ReadError::Io)?;
        total += n as u64;
        if total > limit {
            return Err(ReadError::TooLarge(limit));
        }
        if n > 0 {
            pieces.push(next);
        }
        if n < piece {
            break;
        }
    }
    if pieces.len() <= 1 {
        return Ok(pieces.pop().unwrap_or_default());
    }
    let mut bytes = Vec::with_capacity(total as usize);
    for p in pieces {
        bytes.extend_from_slice(&p);
    }
    Ok(bytes)
}

/// What the file at `path` is, when it is not something a settings file can be: a
/// folder, a device, a socket, or (when found rather than named) a pipe.
fn refused_kind(meta: &std::fs::Metadata, origin: Origin) -> Option<&'static str> {
    let kind = meta.file_type();
    if kind.is_dir() {
        return Some("a folder");
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if kind.is_char_device() {
            return Some("a character device");
        }
        if kind.is_block_device() {
            return Some("a block device");
        }
        if kind.is_socket() {
            return Some("a socket");
        }
        if kind.is_fifo() && origin == Origin::Found {
            return Some("a fifo");
        }
    }
    (!kind.is_file() && origin == Origin::Found).then_some("not a regular file")
}

/// The text of the settings file at `path`, read within the limit.
fn read_text(path: &Path, origin: Origin) -> Result<String, SettingsError> {
    let error = |message: String| SettingsError {
        path: path.to_path_buf(),
        at: None,
        message,
    };
    let meta = std::fs::metadata(path).map_err(|e| error(format!("cannot read: {e}")))?;
    if let Some(kind) = refused_kind(&meta, origin) {
        let why = match (kind, origin) {
            ("a folder", _) => "",
            (_, Origin::Named) => " (a settings file is a regular file or a pipe)",
            (_, Origin::Found) => " (a settings file found in a folder is a regular file)",
        };
        return Err(error(format!("is {kind}, not a settings file{why}")));
    }
    if meta.is_file() && meta.len() > MAX_FILE_BYTES {
        return Err(error(format!(
            "is {} bytes, larger than {MAX_FILE_BYTES} bytes, the most the tools read",
            meta.len()
        )));
    }
    let file = std::fs::File::open(path).map_err(|e| error(format!("cannot read: {e}")))?;
    let bytes =
        read_at_most(file, MAX_FILE_BYTES).map_err(|e| error(format!("cannot read: {e}")))?;
    String::from_utf8(bytes).map_err(|e| {
        let valid = e.utf8_error().valid_up_to();
        let bytes = e.as_bytes();
        let prefix = std::str::from_utf8(&bytes[..valid]).unwrap_or_default();
        SettingsError {
            at: Some(line_column(&LineIndex::new(prefix), prefix, valid)),
            ..error(format!("is not UTF-8 text (byte {:#04x})", bytes[valid]))
        }
    })
}

/// Reads the settings file at `path`. `None` for a `pyproject.toml` without
/// `[tool.walls]` (it does not count as settings).
pub(crate) fn read(path: &Path, origin: Origin) -> Result<Option<Settings>, SettingsError> {
    let text = read_text(path, origin)?;
    let file = File {
        path,
        lines: LineIndex::new(&text),
        text: &text,
    };
    let tables = match Kind::of(path) {
        Kind::Walls => file.parse::<WallsTables>()?,
        Kind::PyProject => match file.parse::<PyProject>()?.tool.and_then(|t| t.walls) {
            Some(tables) => tables,
            None => return Ok(None),
        },
        Kind::Format => WallsTables {
            lint: None,
            format: Some(file.parse::<FormatTable>()?),
            run: None,
        },
    };
    let run = match tables.run.and_then(|t| t.pkdgrav_build) {
        Some(build) => Run {
            pkdgrav_build: Some(
                walls_par::Build::parse(build.get_ref())
                    .map_err(|e| file.error(Some(build.span()), format!("pkdgrav-build: {e}")))?,
            ),
        },
        None => Run::default(),
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
        run,
    }))
}

/// A settings file being read: its path, text and lines, to locate mistakes.
struct File<'a> {
    path: &'a Path,
    text: &'a str,
    lines: LineIndex,
}

impl File<'_> {
    /// The error at byte `span.start` of the file.
    fn error(&self, span: Option<Range<usize>>, message: impl Into<String>) -> SettingsError {
        SettingsError {
            path: self.path.to_path_buf(),
            at: span.map(|s| line_column(&self.lines, self.text, s.start)),
            message: message.into(),
        }
    }

    /// Where byte `offset` is, for messages.
    fn location(&self, offset: usize) -> Location {
        let (line, column) = line_column(&self.lines, self.text, offset);
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
                let bad = |e: String| self.error(Some(glob.span()), e);
                crate::check_glob(glob.get_ref()).map_err(bad)?;
                let mut builder = GitignoreBuilder::new(dir);
                // As `include` reads them: a `[` with no `]` is a mistake, not a `[`.
                builder.allow_unclosed_class(false);
                builder
                    .add_line(None, glob.get_ref())
                    .map_err(|e| bad(crate::bad_glob(glob.get_ref(), &e)))?;
                let matcher = builder
                    .build()
                    .map_err(|e| bad(crate::bad_glob(glob.get_ref(), &e)))?;
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
            include: self.globs(table.include)?,
            exclude: self.globs(table.exclude)?,
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
    fn globs(&self, globs: Vec<Spanned<String>>) -> Result<Vec<String>, SettingsError> {
        globs
            .into_iter()
            .map(|g| match crate::check_glob(g.get_ref()) {
                Ok(()) => Ok(g.into_inner()),
                Err(e) => Err(self.error(Some(g.span()), e)),
            })
            .collect()
    }
}

/// The 1-based line and character column of byte `offset` of `text`, whose lines are
/// `lines`.
fn line_column(lines: &LineIndex, text: &str, offset: usize) -> (usize, usize) {
    let at = lines.line_col(text, offset);
    (at.line, at.column)
}

#[cfg(test)]
mod pieces {
    use super::{ReadError, read_in_pieces};

    #[test]
    fn an_input_in_pieces_is_joined_whole_or_refused_one_byte_past_the_limit() {
        let input: Vec<u8> = (0..=255).cycle().take(1000).collect();
        for piece in [1, 7, 10, 999, 1000, 4096] {
            assert_eq!(
                read_in_pieces(&input[..], 1000, piece).unwrap(),
                input,
                "{piece}"
            );
            let e = read_in_pieces(&input[..], 999, piece).unwrap_err();
            assert!(matches!(e, ReadError::TooLarge(999)), "{piece}: {e}");
        }
        assert_eq!(read_in_pieces(&b""[..], 0, 10).unwrap(), b"");
        // An endless input is read to one byte past the limit, then refused.
        let e = read_in_pieces(std::io::repeat(0), 95, 10).unwrap_err();
        assert!(matches!(e, ReadError::TooLarge(95)));
    }
}
