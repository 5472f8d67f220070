//! Shared pieces of the walls command-line tools: reading inputs (files or standard
//! input) and the registry of diagnostic codes that `--explain` and SARIF read.

pub mod input;

use std::sync::Arc;
use walls_diagnostics::{Code, Diagnostic};
use walls_model::Mode;

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

/// Everything `walls-lint` checks in one file: decodes the bytes, parses, runs the
/// model checks. Returns the text the diagnostics' spans refer to (the valid prefix, for
/// bytes that are not UTF-8) and the diagnostics sorted by position.
pub fn lint_bytes(bytes: &[u8], mode: Mode) -> (Arc<str>, Vec<Diagnostic>) {
    match walls_syntax::decode(bytes) {
        Ok(text) => {
            let parsed = walls_syntax::parse(text);
            let mut diagnostics = parsed.diagnostics;
            diagnostics.extend(walls_model::check_mode(&parsed.tree, mode));
            diagnostics.sort_by_key(|d| (d.span.start, d.span.end));
            (parsed.tree.shared_text().clone(), diagnostics)
        }
        Err((prefix, diagnostic)) => (prefix.into(), vec![*diagnostic]),
    }
}
