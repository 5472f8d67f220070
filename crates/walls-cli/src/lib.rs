//! Shared pieces of the walls command-line tools: reading inputs (files or standard
//! input), the whole check of one file, the `--mode` argument, and the registry of
//! diagnostic codes that `--explain` and SARIF read.

pub mod commands;
pub mod input;

/// `--mode`: the contact model a file is for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum ModeArg {
    /// Soft-sphere DEM (the default).
    Ssdem,
    /// Hard-sphere DEM.
    Hsdem,
}

impl From<ModeArg> for walls_model::Mode {
    fn from(mode: ModeArg) -> Self {
        match mode {
            ModeArg::Ssdem => walls_model::Mode::Ssdem,
            ModeArg::Hsdem => walls_model::Mode::Hsdem,
        }
    }
}

use std::sync::Arc;
use walls_diagnostics::{Code, Diagnostic};
use walls_model::Options;

/// Every diagnostic code the tools can emit, in code order.
pub fn all_codes() -> impl Iterator<Item = &'static Code> {
    walls_syntax::codes::ALL
        .iter()
        .chain(walls_model::codes::ALL)
        .copied()
}

/// Finds a code by its id (`S101`, any case) or its name (`unknown-word`).
pub fn find_code(query: &str) -> Option<&'static Code> {
    all_codes().find(|c| c.id.eq_ignore_ascii_case(query) || c.name.eq_ignore_ascii_case(query))
}

/// A file as the tools see it: its text, its scene, and every diagnostic.
pub struct Checked {
    /// The text the spans refer to (the valid prefix, for bytes that are not UTF-8).
    pub text: Arc<str>,
    /// The walls resolved from what parsed (empty for bytes that are not UTF-8).
    pub scene: walls_model::Scene,
    /// Syntax and model diagnostics, sorted by position.
    pub diagnostics: Vec<Diagnostic>,
}

/// Everything `walls-lint` checks in one file: decodes the bytes, parses, resolves the
/// scene and runs the checker. Takes the bytes so that they are freed once the text is
/// made from them, before the tree grows.
pub fn check_bytes(bytes: Vec<u8>, options: &Options) -> Checked {
    match walls_syntax::decode(bytes) {
        Ok(text) => {
            let parsed = walls_syntax::parse(text);
            let analysis = walls_model::analyze(&parsed.tree, options);
            let mut diagnostics = parsed.diagnostics;
            diagnostics.extend(analysis.diagnostics);
            diagnostics.sort_by_key(|d| (d.span.start, d.span.end));
            Checked {
                text: parsed.tree.shared_text().clone(),
                scene: analysis.scene,
                diagnostics,
            }
        }
        Err((prefix, diagnostic)) => Checked {
            text: prefix.into(),
            scene: walls_model::Scene::default(),
            diagnostics: vec![*diagnostic],
        },
    }
}
