//! An open document: its version and its analysis, recomputed on each change.

use walls_ide::Analysis;
use walls_model::Options;

/// One open walls file, analysed.
pub struct Document {
    /// The client's version of the text.
    pub version: i32,
    /// The text checked (tree, scene, sorted diagnostics) and its lines.
    pub analysis: Analysis,
}

impl Document {
    /// Parses, resolves and checks `text`.
    pub fn new(version: i32, text: String, options: &Options) -> Self {
        Document {
            version,
            analysis: Analysis::of_text(text, options),
        }
    }

    /// The text.
    pub fn text(&self) -> &str {
        self.analysis.text()
    }
}
