//! Code actions: a quick fix for each diagnostic with a fix, and "fix all safe
//! problems".

use crate::Analysis;
use std::ops::Range;
use walls_diagnostics::{Applicability, Edit, apply_fixes};

/// What a code action does.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ActionKind {
    /// Applies the fix of one diagnostic.
    QuickFix {
        /// The diagnostic's index in [`Analysis::diagnostics`].
        diagnostic: usize,
        /// Whether the fix is safe to apply unasked.
        preferred: bool,
    },
    /// Applies every safe fix of the file.
    FixAll,
}

/// A code action: a title and the edits it makes.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Action {
    /// What it says in the menu.
    pub title: String,
    /// What it does.
    pub kind: ActionKind,
    /// The edits, as byte ranges of the text and their replacements.
    pub edits: Vec<Edit>,
}

/// A quick fix for each diagnostic touching `range` that has one (the first
/// `max_quick_fixes` of them), then "Fix all safe problems (N)" if any fix is safe: one
/// edit of the text, however many fixes.
pub fn code_actions(
    analysis: &Analysis,
    range: Range<usize>,
    max_quick_fixes: usize,
) -> Vec<Action> {
    let text = analysis.text();
    let diagnostics = analysis.diagnostics();
    let mut actions = Vec::new();
    for (i, d) in diagnostics.iter().enumerate() {
        let Some(fix) = &d.fix else { continue };
        if d.span.end < range.start || range.end < d.span.start {
            continue;
        }
        if actions.len() == max_quick_fixes {
            break;
        }
        actions.push(Action {
            title: format!("{} ({})", fix.message, d.code.id),
            kind: ActionKind::QuickFix {
                diagnostic: i,
                preferred: fix.applicability == Applicability::Safe,
            },
            edits: fix.edits.clone(),
        });
    }
    let safe = diagnostics
        .iter()
        .filter(|d| {
            d.fix
                .as_ref()
                .is_some_and(|f| f.applicability == Applicability::Safe)
        })
        .count();
    if safe > 0 {
        let fixed = apply_fixes(text, diagnostics, Applicability::Safe);
        actions.push(Action {
            title: format!("Fix all safe problems ({safe})"),
            kind: ActionKind::FixAll,
            edits: vec![Edit {
                span: 0..text.len(),
                replacement: fixed,
            }],
        });
    }
    actions
}
