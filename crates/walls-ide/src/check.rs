//! The whole check of one file: decode, parse, resolve the scene, run the checker and
//! sort every diagnostic, written once for the linter, the scene printer, the language
//! server and the charts.

use crate::lines::Lines;
use std::sync::Arc;
use walls_diagnostics::{Diagnostic, Severity};
use walls_model::{Options, Scene};
use walls_syntax::{Parse, SyntaxTree};

/// A file as the tools see it: its text, its parse, its scene, and every diagnostic.
#[derive(Debug, Clone)]
pub struct Checked {
    /// The text the spans refer to (the valid prefix, for bytes that are not UTF-8).
    pub text: Arc<str>,
    /// The lossless tree of the text and its syntax diagnostics (kept for the formatter,
    /// which refuses some of them; [`Checked::diagnostics`] holds them too).
    pub parse: Parse,
    /// The walls resolved from what parsed (empty for bytes that are not UTF-8).
    pub scene: Scene,
    /// Syntax and model diagnostics, sorted by position (for bytes that are not UTF-8,
    /// only the encoding error).
    pub diagnostics: Vec<Diagnostic>,
}

/// Everything `walls-lint` checks in a text: parses, resolves the scene, runs the
/// checker, and sorts the syntax and model diagnostics together by position.
pub fn check_text(text: impl Into<Arc<str>>, options: &Options) -> Checked {
    let parse = walls_syntax::parse(text);
    let analysis = walls_model::analyze(&parse.tree, options);
    let mut diagnostics = parse.diagnostics.clone();
    diagnostics.extend(analysis.diagnostics);
    // Stable: a syntax diagnostic stays before a model one at the same span.
    diagnostics.sort_by_key(|d| (d.span.start, d.span.end));
    Checked {
        text: parse.tree.shared_text().clone(),
        parse,
        scene: analysis.scene,
        diagnostics,
    }
}

/// [`check_text`] of bytes: decodes them first. Takes the bytes so that they are freed
/// once the text is made from them, before the tree grows. Bytes that are not UTF-8
/// give only the encoding error, with the parse of the valid prefix and no scene.
pub fn check_bytes(bytes: Vec<u8>, options: &Options) -> Checked {
    match walls_syntax::decode(bytes) {
        Ok(text) => check_text(text, options),
        Err((prefix, diagnostic)) => {
            let parse = walls_syntax::parse(prefix);
            Checked {
                text: parse.tree.shared_text().clone(),
                parse,
                scene: Scene::default(),
                diagnostics: vec![*diagnostic],
            }
        }
    }
}

impl Checked {
    /// The diagnostics of error severity, in order: what stops a run or a scene.
    pub fn errors(&self) -> Vec<Diagnostic> {
        self.diagnostics
            .iter()
            .filter(|d| d.severity == Severity::Error)
            .cloned()
            .collect()
    }
}

/// A checked file ready for the editor features: the check and where its lines start.
#[derive(Debug, Clone)]
pub struct Analysis {
    /// The check.
    pub checked: Checked,
    /// Where each line of the text starts.
    pub lines: Lines,
}

impl Analysis {
    /// Indexes the lines of a checked file.
    pub fn new(checked: Checked) -> Self {
        let lines = Lines::new(&checked.text);
        Analysis { checked, lines }
    }

    /// Checks `text` ([`check_text`]) and indexes its lines.
    pub fn of_text(text: impl Into<Arc<str>>, options: &Options) -> Self {
        Analysis::new(check_text(text, options))
    }

    /// The text.
    pub fn text(&self) -> &str {
        &self.checked.text
    }

    /// The syntax tree.
    pub fn tree(&self) -> &SyntaxTree {
        &self.checked.parse.tree
    }

    /// The resolved scene.
    pub fn scene(&self) -> &Scene {
        &self.checked.scene
    }

    /// Syntax and model diagnostics, sorted by position.
    pub fn diagnostics(&self) -> &[Diagnostic] {
        &self.checked.diagnostics
    }
}
