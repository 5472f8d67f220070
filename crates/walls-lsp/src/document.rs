//! An open document: its version, its analysis and how it was checked, recomputed on each
//! change with the settings found for it then. A pkdgrav `.par` file ([`is_par`]) is a
//! [`ParDocument`]: its check for the build and its lines.

use crate::settings::Check;
use tower_lsp_server::ls_types::Diagnostic;
use walls_ide::par::ParChecked;
use walls_ide::{Analysis, Lines};

/// One open walls file, analysed.
pub struct Document {
    /// The client's version of the text.
    pub version: i32,
    /// The text checked (tree, scene, sorted diagnostics less the ignored ones) and its
    /// lines.
    pub analysis: Analysis,
    /// The diagnostic naming its settings file, if that file is unusable.
    pub settings_problem: Option<Diagnostic>,
    /// How it was checked, to check the texts its fixes make.
    pub check: Check,
}

impl Document {
    /// Parses, resolves and checks `text` as `check` says.
    pub fn new(version: i32, text: String, check: Check) -> Self {
        Document {
            version,
            analysis: check.run(text),
            settings_problem: check.problem(),
            check,
        }
    }

    /// The text.
    pub fn text(&self) -> &str {
        self.analysis.text()
    }
}

/// Whether the document at `uri` is a pkdgrav parameter file, by its path's last part
/// ([`walls_par::is_par_file`], as `walls-lint` decides).
pub fn is_par(uri: &tower_lsp_server::ls_types::Uri) -> bool {
    let path = uri.path().as_str();
    walls_par::is_par_file(path.rsplit('/').next().unwrap_or(path))
}

/// One open `.par` file, checked.
pub struct ParDocument {
    /// The client's version of the text.
    pub version: i32,
    /// The check (text and sorted diagnostics less the ignored ones).
    pub checked: ParChecked,
    /// Where each line of the text starts.
    pub lines: Lines,
    /// The diagnostic naming its settings file, if that file is unusable.
    pub settings_problem: Option<Diagnostic>,
    /// How it was checked: its build.
    pub check: Check,
}

impl ParDocument {
    /// Checks `text` as `check` says.
    pub fn new(version: i32, text: String, check: Check) -> Self {
        let checked = check.checked_par(text);
        ParDocument {
            version,
            lines: Lines::new(&checked.text),
            checked,
            settings_problem: check.problem(),
            check,
        }
    }

    /// The text.
    pub fn text(&self) -> &str {
        &self.checked.text
    }
}
