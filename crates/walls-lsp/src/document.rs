//! An open document: its version, its analysis and how it was checked, recomputed on each
//! change with the settings found for it then.

use crate::settings::Check;
use tower_lsp_server::ls_types::Diagnostic;
use walls_ide::Analysis;

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
