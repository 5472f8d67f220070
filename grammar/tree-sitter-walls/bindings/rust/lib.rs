//! The tree-sitter grammar of walls files, for editors: `LANGUAGE` for a parser, and
//! the highlight and fold queries.

use tree_sitter_language::LanguageFn;

unsafe extern "C" {
    fn tree_sitter_walls() -> *const ();
}

/// The walls language, for `tree_sitter::Parser::set_language`.
pub const LANGUAGE: LanguageFn = unsafe { LanguageFn::from_raw(tree_sitter_walls) };

/// The highlight query.
pub const HIGHLIGHTS_QUERY: &str = include_str!("../../queries/highlights.scm");

/// The fold query.
pub const FOLDS_QUERY: &str = include_str!("../../queries/folds.scm");
