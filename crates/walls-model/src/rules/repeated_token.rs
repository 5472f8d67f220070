//! C202 `repeated-token`: a token is set twice in one block.
//!
//! Checked block by block; the fix is safe.

use crate::check::{Block, Checker};
use walls_diagnostics::{Applicability, Code, Diagnostic};
use walls_syntax::Statement;

/// A token is set twice in one block.
pub static REPEATED_TOKEN: Code = Code {
    id: "C202",
    name: "repeated-token",
    summary: "a token is set twice in one block",
    explanation:
        "The last value wins, so the earlier one has no effect. Only statements whose values read
count: a later `radius` without a value overrides nothing. The fix (safe) removes the earlier
one.

Bad:
```walls
wall type disk
  radius 1
  radius 2
```

Good:
```walls
wall type disk
  radius 2
```
",
};

/// Reports every property statement of `block` that a later one of the same keyword
/// overrides, in source order.
pub(crate) fn check(cx: &mut Checker, block: &Block) {
    let tree = cx.tree;
    let keyed = &block.keyed;
    let mut repeated: Vec<(&Statement, &Statement)> = keyed
        .windows(2)
        .filter(|w| w[0].0 == w[1].0)
        .map(|w| {
            (
                w[0].1,
                block.last_of(w[0].0).expect("the keyword is in the block"),
            )
        })
        .collect();
    repeated.sort_by_key(|(s, _)| tree.span(tree.head(s)).start);
    for (earlier, last) in repeated {
        let head = tree.head(earlier);
        let name = tree.token_text(head);
        let mut d = Diagnostic::warning(
            &REPEATED_TOKEN,
            tree.span(head),
            format!("`{name}` is set again later in this block, so this value has no effect"),
        )
        .with_label(tree.span(tree.head(last)), "the last one wins");
        if let Some(edits) = cx.delete_all(std::iter::once(earlier)) {
            d = d.with_fix(Applicability::Safe, format!("remove this `{name}`"), edits);
        }
        cx.push(d);
    }
}
