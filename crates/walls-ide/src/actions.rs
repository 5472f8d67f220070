//! Code actions: a quick fix for each diagnostic with a fix, and "fix all safe
//! problems".

use crate::{Fixable, fix_rounds};
use std::ops::Range;
use walls_diagnostics::{Applicability, Edit};

/// What a code action does.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ActionKind {
    /// Applies the fix of one diagnostic.
    QuickFix {
        /// The diagnostic's index in the checked text's diagnostics.
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
/// edit of the text, however many fixes, made of the same rounds as `walls-lint --fix`'s
/// ([`fix_rounds`]), each new text checked by `check`. `checked` is a walls file's
/// [`crate::Checked`] or a `.par` file's [`crate::par::ParChecked`].
pub fn code_actions<C: Fixable>(
    checked: &C,
    range: Range<usize>,
    max_quick_fixes: usize,
    check: &dyn Fn(String) -> C,
) -> Vec<Action> {
    let text = checked.text();
    let diagnostics = checked.diagnostics();
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
    if let Some((fixed, count)) = fix_rounds(checked, Applicability::Safe, check) {
        actions.push(Action {
            title: format!("Fix all safe problems ({count})"),
            kind: ActionKind::FixAll,
            edits: vec![Edit {
                span: 0..text.len(),
                replacement: fixed.text().to_string(),
            }],
        });
    }
    actions
}
