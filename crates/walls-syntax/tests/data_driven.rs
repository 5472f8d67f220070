//! Tests as data: every `.walls` file under `tests/data/ok` and `tests/data/err` is
//! parsed, and its tree and diagnostics are compared with the `.snap` file beside it.
//! Files under `ok/` must produce no diagnostic; files under `err/` must produce some.
//! Update the snapshots with `INSTA_UPDATE=always cargo test -p walls-syntax` and review
//! them with `git diff`.

use std::fmt::Write as _;
use walls_diagnostics::{Applicability, apply_fixes};
use walls_syntax::{Item, SyntaxTree, parse};
use walls_test_support::{render, snapshot_beside};

#[test]
fn ok_files_parse_cleanly() {
    insta::glob!("data/ok/*.walls", |path| {
        let text = std::fs::read_to_string(path).unwrap();
        let parsed = parse(text.as_str());
        assert_eq!(parsed.tree.to_string(), text, "lossless");
        assert!(
            parsed.diagnostics.is_empty(),
            "{}: {:#?}",
            path.display(),
            parsed.diagnostics
        );
        snapshot_beside(path, &tree_outline(&parsed.tree));
    });
}

#[test]
fn err_files_report_every_mistake() {
    insta::glob!("data/err/*.walls", |path| {
        let text = std::fs::read_to_string(path).unwrap();
        let parsed = parse(text.as_str());
        assert_eq!(parsed.tree.to_string(), text, "lossless");
        assert!(
            !parsed.diagnostics.is_empty(),
            "{} has no error",
            path.display()
        );
        let mut out = render(&text, &parsed.diagnostics);
        // Applying the safe fixes must remove the diagnostics they were offered for.
        let fixed = apply_fixes(&text, &parsed.diagnostics, Applicability::Safe);
        if fixed != text {
            let after = parse(fixed.as_str());
            writeln!(out, "--- after safe fixes ---\n{fixed}--- leaves ---").unwrap();
            out.push_str(&render(&fixed, &after.diagnostics));
        }
        snapshot_beside(path, &out);
    });
}

/// One line per statement: its block role, keyword and values as written.
fn tree_outline(tree: &SyntaxTree) -> String {
    let mut out = String::new();
    let line = |out: &mut String, indent: &str, tag: &str, s: &walls_syntax::Statement| {
        let words: Vec<&str> = std::iter::once(tree.head(s))
            .chain(tree.values(s).iter().copied())
            .map(|t| tree.token_text(t))
            .collect();
        writeln!(out, "{indent}{tag} {}", words.join(" ")).unwrap();
    };
    for item in tree.items() {
        match item {
            Item::Block(b) => {
                line(
                    &mut out,
                    "",
                    &format!("{:?}", b.kind).to_lowercase(),
                    &b.head,
                );
                for s in tree.body(b) {
                    line(&mut out, "  ", "-", s);
                }
            }
            Item::Statement(s) => line(&mut out, "", "statement", s),
            Item::Stray(s) => line(&mut out, "", "stray", s),
        }
    }
    out
}
