//! M002 `ignored-in-hsdem`: a soft-sphere (SSDEM) token that a hard-sphere (HSDEM) run ignores.
//!
//! Checked token by token in HSDEM, straight from the syntax tree: what a wall's type
//! does with the token does not matter, the hard-sphere code never reads it. `taper` is
//! M001's.

use walls_diagnostics::{Code, Diagnostic};
use walls_keywords::Keyword;
use walls_syntax::{SyntaxTree, TokenKind};

/// A soft-sphere (SSDEM) token that a hard-sphere (HSDEM) run ignores.
pub static IGNORED_IN_HSDEM: Code = Code {
    id: "M002",
    name: "ignored-in-hsdem",
    summary: "a soft-sphere (SSDEM) token that a hard-sphere (HSDEM) run ignores",
    explanation:
        "Spring constants (`k_n`, `k_t` and the two-layer `*_inner`/`*_outer` tokens), friction
(`mu_s`, `mu_r`, `mu_t`, `beta_s`), cohesion and the reactive-wall tokens (`mass`, `cog`,
`rot-vec`, inertia, principal axes, `assembly`) are read only by pkdgrav's soft-sphere
code. In a hard-sphere run they change nothing. Checked with `--mode hsdem`.

Bad (with `--mode hsdem`):
```walls
defaults epsn 0.9 epst 1
wall type plane
  k_n 1e5
```

Good:
```walls
defaults epsn 0.9 epst 1
wall type plane
```
",
};

/// Warns about every soft-sphere-only token of the file.
pub(crate) fn check(tree: &SyntaxTree) -> Vec<Diagnostic> {
    let mut out = Vec::new();
    for &id in tree.significant() {
        if let TokenKind::Keyword(k) = tree.kind(id)
            && k.ssdem_only()
            && k != Keyword::Taper
        {
            out.push(Diagnostic::warning(
                &IGNORED_IN_HSDEM,
                tree.span(id),
                format!(
                    "`{}` is read only by pkdgrav's soft-sphere code; a hard-sphere run ignores it",
                    tree.token_text(id)
                ),
            ));
        }
    }
    out
}
