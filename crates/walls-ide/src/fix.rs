//! Fixing a file: the fixes of one level applied round after round, the text checked
//! again after each (docs/diagnostics.md, "Fixing"), written once for `walls-lint --fix`
//! and the editor's "fix all".
//!
//! A round applies every fix of the level whose edits do not overlap an edit already
//! taken; rounds go on until one applies nothing, at most [`MAX_ROUNDS`], so that the fixes
//! an overlap held back, or that a fix made possible, are applied too.

use crate::Checked;
use crate::par::ParChecked;
use walls_diagnostics::{Applicability, Diagnostic, apply_fixes_counted};

/// A checked text whose diagnostics' fixes can be applied: a walls file's [`Checked`] or a
/// `.par` file's [`ParChecked`].
pub trait Fixable {
    /// The text the diagnostics' spans refer to.
    fn text(&self) -> &str;
    /// Its diagnostics.
    fn diagnostics(&self) -> &[Diagnostic];
}

impl Fixable for Checked {
    fn text(&self) -> &str {
        &self.text
    }
    fn diagnostics(&self) -> &[Diagnostic] {
        &self.diagnostics
    }
}

impl Fixable for ParChecked {
    fn text(&self) -> &str {
        &self.text
    }
    fn diagnostics(&self) -> &[Diagnostic] {
        &self.diagnostics
    }
}

/// The most rounds of fixes on one file.
pub const MAX_ROUNDS: usize = 10;

/// The check of `first`'s text with the fixes of `level` applied, round after round, each
/// new text checked by `check`, and how many fixes were applied; `None` if there was
/// nothing to apply.
pub fn fix_rounds<C: Fixable>(
    first: &C,
    level: Applicability,
    check: &dyn Fn(String) -> C,
) -> Option<(C, usize)> {
    let mut fixed: Option<C> = None;
    let mut count = 0;
    for _ in 0..MAX_ROUNDS {
        let current = fixed.as_ref().unwrap_or(first);
        let (text, applied) = apply_fixes_counted(current.text(), current.diagnostics(), level);
        if applied == 0 || text == current.text() {
            break;
        }
        count += applied;
        fixed = Some(check(text));
    }
    fixed.map(|checked| (checked, count))
}
