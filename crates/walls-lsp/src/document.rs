//! An open document: its text, tree, scene and diagnostics, recomputed on each change.

use crate::position::Lines;
use walls_diagnostics::Diagnostic;
use walls_model::{Analysis, Options};
use walls_syntax::Parse;

/// One open walls file, analysed.
pub struct Document {
    /// The client's version of the text.
    pub version: i32,
    /// The parse (lossless tree and syntax diagnostics).
    pub parse: Parse,
    /// The resolved scene and model diagnostics.
    pub analysis: Analysis,
    /// Lines of the text, as LSP counts them, for positions.
    pub index: Lines,
    /// Syntax and model diagnostics, sorted by position.
    pub diagnostics: Vec<Diagnostic>,
}

impl Document {
    /// Parses, resolves and checks `text`.
    pub fn new(version: i32, text: String, options: &Options) -> Self {
        let parse = walls_syntax::parse(text);
        let analysis = walls_model::analyze(&parse.tree, options);
        let mut diagnostics = parse.diagnostics.clone();
        diagnostics.extend(analysis.diagnostics.iter().cloned());
        diagnostics.sort_by_key(|d| (d.span.start, d.span.end));
        let index = Lines::new(parse.tree.text());
        Document {
            version,
            parse,
            analysis,
            index,
            diagnostics,
        }
    }

    /// The text.
    pub fn text(&self) -> &str {
        self.parse.tree.text()
    }
}
