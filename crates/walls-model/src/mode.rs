//! The contact model a file is checked for, and what pkdgrav's hard-sphere code lacks.

use crate::codes;
use walls_diagnostics::Diagnostic;
use walls_keywords::Keyword;
use walls_syntax::{SyntaxTree, TokenKind};

/// pkdgrav's two particle–wall contact models.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Mode {
    /// Soft-sphere DEM: springs and dashpots (the default).
    #[default]
    Ssdem,
    /// Hard-sphere DEM: instantaneous collisions.
    Hsdem,
}

/// Reports the wall types and tokens a hard-sphere run refuses (errors) or ignores
/// (warnings). Nothing is reported for SSDEM.
pub fn check_mode(tree: &SyntaxTree, mode: Mode) -> Vec<Diagnostic> {
    if mode == Mode::Ssdem {
        return Vec::new();
    }
    let mut out = Vec::new();
    for &id in tree.significant() {
        let span = tree.span(id);
        let text = tree.token_text(id);
        match tree.kind(id) {
            TokenKind::TypeName(t) if t.ssdem_only() => out.push(
                Diagnostic::error(
                    &codes::NOT_IN_HSDEM,
                    span,
                    format!("pkdgrav's hard-sphere code has no {} walls", t.name()),
                )
                .with_help("run with SSDEM, or build the shape from rectangles, disks and cylinders"),
            ),
            TokenKind::Keyword(Keyword::Taper) => out.push(
                Diagnostic::error(
                    &codes::NOT_IN_HSDEM,
                    span,
                    "pkdgrav's hard-sphere code does not implement `taper`",
                )
                .with_help("remove `taper`, or run with SSDEM"),
            ),
            TokenKind::Keyword(k) if k.ssdem_only() => out.push(
                Diagnostic::warning(
                    &codes::IGNORED_IN_HSDEM,
                    span,
                    format!("`{text}` is read only by pkdgrav's soft-sphere code; a hard-sphere run ignores it"),
                ),
            ),
            _ => {}
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use walls_diagnostics::Severity;

    #[test]
    fn hsdem_refuses_triangle_shell_taper_and_warns_on_springs() {
        let text = "wall type triangle\nwall type SHELL\nwall type cylinder-finite taper 0.5\n  k_n 1\n  mass 2\nwall type plane\n";
        let tree = walls_syntax::parse(text).tree;
        assert!(check_mode(&tree, Mode::Ssdem).is_empty());
        let found: Vec<(&str, Severity, &str)> = check_mode(&tree, Mode::Hsdem)
            .iter()
            .map(|d| (d.code.id, d.severity, &text[d.span.clone()]))
            .collect();
        assert_eq!(
            found,
            [
                ("M001", Severity::Error, "triangle"),
                ("M001", Severity::Error, "SHELL"),
                ("M001", Severity::Error, "taper"),
                ("M002", Severity::Warning, "k_n"),
                ("M002", Severity::Warning, "mass"),
            ]
        );
    }
}
