//! C203 `k-t-before-k-n`: `k_t` is set before `k_n` in one block, so `k_n` overwrites it.
//!
//! Checked block by block, for the three pairs of spring constants.

use crate::check::{Block, Checker};
use walls_diagnostics::{Code, Diagnostic};
use walls_keywords::Keyword;

/// `k_t` is set before `k_n` in one block, so `k_n` overwrites it.
pub static KT_BEFORE_KN: Code = Code {
    id: "C203",
    name: "k-t-before-k-n",
    summary: "`k_t` is set before `k_n` in one block, so `k_n` overwrites it",
    explanation:
        "Setting `k_n` also sets `k_t` to 2/7 of it. A `k_t` written before the `k_n` of the
same block is therefore lost; write it after. The same holds for `k_t_outer`/`k_n_outer`
and `k_t_inner`/`k_n_inner`.

Bad:
```walls
wall type plane
  k_t 3
  k_n 7
```

Good:
```walls
wall type plane
  k_n 7
  k_t 3
```
",
};

/// Reports a tangential spring constant whose last setting in `block` comes before the
/// block's last normal one.
pub(crate) fn check(cx: &mut Checker, block: &Block) {
    let tree = cx.tree;
    for (kt, kn) in [
        (Keyword::KT, Keyword::KN),
        (Keyword::KTOuter, Keyword::KNOuter),
        (Keyword::KTInner, Keyword::KNInner),
    ] {
        let (Some(last_kt), Some(last_kn)) = (block.last_of(kt), block.last_of(kn)) else {
            continue;
        };
        let (kt_span, kn_span) = (tree.span(tree.head(last_kt)), tree.span(tree.head(last_kn)));
        if kt_span.start < kn_span.start {
            cx.push(
                Diagnostic::warning(
                    &KT_BEFORE_KN,
                    kt_span,
                    format!(
                        "`{}` is overwritten by the `{}` after it, which sets it to 2/7 of its value",
                        kt.name(),
                        kn.name()
                    ),
                )
                .with_label(kn_span, format!("this sets `{}` again", kt.name()))
                .with_help(format!("write `{}` after `{}`", kt.name(), kn.name())),
            );
        }
    }
}
