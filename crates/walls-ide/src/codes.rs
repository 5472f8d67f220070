//! The registry of diagnostic codes: every code the tools can emit, found by id or
//! name, and explained as `walls-lint --explain` and the language server show them.

use walls_diagnostics::Code;

/// Every diagnostic code the tools can emit, in code order.
pub fn all_codes() -> impl Iterator<Item = &'static Code> {
    walls_syntax::codes::ALL
        .iter()
        .chain(walls_model::codes::ALL)
        .chain(crate::suppress::ALL)
        .chain(walls_par::codes::ALL)
        .chain(walls_par::run_codes::ALL)
        .copied()
}

/// Finds a code by its id (`S101`, any case) or its name (`unknown-word`).
pub fn find_code(query: &str) -> Option<&'static Code> {
    all_codes().find(|c| c.id.eq_ignore_ascii_case(query) || c.name.eq_ignore_ascii_case(query))
}

/// A code's explanation in Markdown: `ID (name): summary`, a blank line, then why it
/// matters with a bad and a good example.
pub fn explain_code(code: &Code) -> String {
    format!(
        "{} ({}): {}\n\n{}",
        code.id, code.name, code.summary, code.explanation
    )
}

/// What `query` means, in Markdown: the explanation of the code it names (by id or
/// name), else the documentation of the keyword it spells; `None` for anything else.
pub fn explain(query: &str) -> Option<String> {
    find_code(query)
        .map(explain_code)
        .or_else(|| walls_keywords::keyword(query).map(|k| k.markdown()))
}
