//! The settings file of each document (docs/configuration.md), found again for every
//! check so that a saved change to it is seen: from the folder of a `file:` document,
//! from the workspace folder for any other (an unsaved, untitled one). Its `[lint]`
//! values win over the editor's settings and its ignores hide warnings as `walls-lint`'s
//! do; a settings file that cannot be used becomes one diagnostic naming it.

use std::path::{Path, PathBuf};
use tower_lsp_server::ls_types::{self as lsp, *};
use walls_config::{Lint, SettingsError};
use walls_format::FormatOptions;
use walls_ide::par::ParChecked;
use walls_ide::{Analysis, Checked};
use walls_model::Options;

/// Where a document's settings are looked for.
struct Place {
    /// The folder the search starts from (`None`: no settings file at all).
    dir: Option<PathBuf>,
    /// The document's file, absolute as per-file globs match it (`None` unless `file:`).
    file: Option<PathBuf>,
}

impl Place {
    /// The place of the document at `uri`, with `folder` the workspace folder.
    fn of(uri: &Uri, folder: Option<&Path>) -> Place {
        match file_path(uri) {
            Some(path) => {
                let dir = walls_config::absolute(path.parent().unwrap_or(Path::new("/")));
                Place {
                    file: path.file_name().map(|name| dir.join(name)),
                    dir: Some(dir),
                }
            }
            None => Place {
                dir: folder.map(Path::to_path_buf),
                file: None,
            },
        }
    }
}

/// The path of a `file:` URI (`None` for any other scheme).
pub fn file_path(uri: &Uri) -> Option<PathBuf> {
    if !uri.scheme().as_str().eq_ignore_ascii_case("file") {
        return None;
    }
    uri.to_file_path().map(|p| p.into_owned())
}

/// How one document is checked: the options, and the ignores of its settings file.
pub struct Check {
    /// The editor's options, with the values of the settings' `[lint]` in their place.
    options: Options,
    /// The `[lint]` table (empty without a usable settings file).
    lint: Lint,
    /// The document's file, for `per-file-ignores`.
    file: Option<PathBuf>,
    /// The settings file that could not be used, if any.
    broken: Option<SettingsError>,
    /// The pkdgrav build `.par` files are checked for (the settings' `[run]
    /// pkdgrav-build`, else the default).
    build: walls_par::Build,
}

impl Check {
    /// The check of the document at `uri`, with the settings file found for it over the
    /// editor's options; the editor's options alone if that file is unusable.
    pub fn find(uri: &Uri, folder: Option<&Path>, editor: &Options) -> Check {
        let place = Place::of(uri, folder);
        let found = place.dir.as_deref().map(walls_config::find).transpose();
        let (lint, build, broken) = match found {
            Ok(Some(settings)) => (
                settings.lint,
                settings.run.pkdgrav_build.unwrap_or_default(),
                None,
            ),
            Ok(None) => (Lint::default(), walls_par::Build::default(), None),
            Err(e) => (Lint::default(), walls_par::Build::default(), Some(e)),
        };
        Check {
            options: lint.options(editor),
            lint,
            file: place.file,
            broken,
            build,
        }
    }

    /// Checks the `.par` text `text` for the build, less the warnings and infos the
    /// settings ignore (errors stay).
    pub fn checked_par(&self, text: String) -> ParChecked {
        let mut checked = walls_ide::par::check_par_text(text, &self.build);
        self.lint
            .filter(self.file.as_deref(), &mut checked.diagnostics);
        checked
    }

    /// The build `.par` files are checked for.
    pub fn build(&self) -> &walls_par::Build {
        &self.build
    }

    /// Checks `text`, less the warnings and infos the settings ignore (errors stay).
    pub fn checked(&self, text: String) -> Checked {
        let mut checked = walls_ide::check_text(text, &self.options);
        self.lint
            .filter(self.file.as_deref(), &mut checked.diagnostics);
        checked
    }

    /// [`Check::checked`], with the lines indexed for the editor's features.
    pub fn run(&self, text: String) -> Analysis {
        Analysis::new(self.checked(text))
    }

    /// The diagnostic that names the unusable settings file, if there is one: at the
    /// start of the document, pointing to the mistake in the settings file.
    pub fn problem(&self) -> Option<lsp::Diagnostic> {
        let e = self.broken.as_ref()?;
        let path = walls_config::absolute(&e.path);
        let at = e.at.map_or(Position::default(), |(line, column)| {
            position_in(&path, line, column)
        });
        let location = Uri::from_file_path(&path).map(|uri| DiagnosticRelatedInformation {
            location: Location::new(uri, Range::new(at, at)),
            message: e.message.clone(),
        });
        Some(lsp::Diagnostic {
            range: Range::default(),
            severity: Some(DiagnosticSeverity::ERROR),
            source: Some("walls".into()),
            message: format!("{e}\nthis file is checked with the editor's settings instead"),
            related_information: location.map(|l| vec![l]),
            ..lsp::Diagnostic::default()
        })
    }
}

/// The LSP position (UTF-16) of 1-based `line` and character `column` of the file at
/// `path`; characters are counted as UTF-16 units if the file cannot be read again (or
/// is no longer a regular file within the limit: a pipe is never waited on).
fn position_in(path: &Path, line: usize, column: usize) -> Position {
    let characters = column.saturating_sub(1);
    let text = std::fs::metadata(path)
        .ok()
        .filter(|m| m.is_file())
        .and_then(|_| std::fs::File::open(path).ok())
        .and_then(|f| walls_config::read_at_most(f, walls_config::MAX_FILE_BYTES).ok())
        .and_then(|bytes| String::from_utf8(bytes).ok())
        .unwrap_or_default();
    let units = text
        .lines()
        .nth(line.saturating_sub(1))
        .map_or(characters, |l| {
            l.chars().take(characters).map(char::len_utf16).sum()
        });
    Position::new(
        u32::try_from(line.saturating_sub(1)).unwrap_or(u32::MAX),
        u32::try_from(units).unwrap_or(u32::MAX),
    )
}

/// The formatting options for the document at `uri`, as `walls-fmt` finds them from
/// its place (the defaults where there is no settings file), or why that file is unusable.
pub fn format_options(uri: &Uri, folder: Option<&Path>) -> Result<FormatOptions, SettingsError> {
    match Place::of(uri, folder).dir {
        Some(dir) => walls_config::find_format(&dir).map(|(options, _)| options),
        None => Ok(FormatOptions::default()),
    }
}
