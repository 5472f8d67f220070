//! The editor features as data: each `data/<feature>/NAME.walls` is a file, with a `$0`
//! marking the cursor for the features that take one, and `NAME.snap` beside it is the
//! feature's answer, its byte ranges shown as 1-based `line:column` with the text they
//! cover. `data/suppress/` shows the diagnostics left by suppression comments and the
//! file after their safe fixes.

use std::fmt::Write as _;
use std::ops::Range;
use std::path::Path;
use walls_diagnostics::LineIndex;
use walls_ide::{Analysis, Symbol};
use walls_model::Options;
use walls_test_support::snapshot_beside;

/// The file's text without its `$0`, analysed, and where the `$0` was.
fn load(path: &Path) -> (Analysis, Option<usize>) {
    let written = std::fs::read_to_string(path).unwrap();
    let cursor = written.find("$0");
    let text = written.replacen("$0", "", 1);
    (Analysis::of_text(text, &Options::default()), cursor)
}

fn cursor(path: &Path, cursor: Option<usize>) -> usize {
    cursor.unwrap_or_else(|| panic!("{} has no $0", path.display()))
}

/// A byte range as `line:column-line:column "covered text"`.
fn at(a: &Analysis, span: &Range<usize>) -> String {
    let text = a.text();
    let index = LineIndex::new(text);
    let (s, e) = (
        index.line_col(text, span.start),
        index.line_col(text, span.end),
    );
    format!(
        "{}:{}-{}:{} {:?}",
        s.line,
        s.column,
        e.line,
        e.column,
        &text[span.clone()]
    )
}

#[test]
fn hover() {
    insta::glob!("data/hover/*.walls", |path| {
        let (a, c) = load(path);
        let out = match walls_ide::hover(&a, cursor(path, c)) {
            Some(h) => format!("{}\n\n{}\n", at(&a, &h.range), h.markdown),
            None => "no hover\n".into(),
        };
        snapshot_beside(path, &out);
    });
}

#[test]
fn completion() {
    insta::glob!("data/completion/*.walls", |path| {
        let (a, c) = load(path);
        let mut out = String::new();
        for item in walls_ide::completion(&a, cursor(path, c)) {
            write!(out, "{} ({:?}): {}", item.label, item.kind, item.detail).unwrap();
            if let Some(sort) = &item.sort_text {
                write!(out, " sort {sort:?}").unwrap();
            }
            if let Some(snippet) = &item.snippet {
                write!(out, " inserts {snippet:?}").unwrap();
            }
            if item.documentation.is_some() {
                out.push_str(" documented");
            }
            out.push('\n');
        }
        snapshot_beside(path, &out);
    });
}

#[test]
fn inlay_hints() {
    insta::glob!("data/inlay_hints/*.walls", |path| {
        let (a, _) = load(path);
        let mut out = String::new();
        for h in walls_ide::inlay_hints(&a, 0..a.text().len()) {
            writeln!(out, "{} {}", at(&a, &(h.offset..h.offset)), h.label).unwrap();
        }
        snapshot_beside(path, &out);
    });
}

#[test]
fn definition() {
    insta::glob!("data/definition/*.walls", |path| {
        let (a, c) = load(path);
        let mut out = String::new();
        for span in walls_ide::definition(&a, cursor(path, c)) {
            writeln!(out, "{}", at(&a, &span)).unwrap();
        }
        snapshot_beside(path, &out);
    });
}

#[test]
fn symbols() {
    fn write(out: &mut String, a: &Analysis, s: &Symbol, depth: usize) {
        writeln!(
            out,
            "{}{} ({:?}) {}{} at {}",
            "  ".repeat(depth),
            s.name,
            s.kind,
            at(a, &s.range),
            s.detail
                .as_ref()
                .map_or(String::new(), |d| format!(" [{d}]")),
            at(a, &s.selection_range)
        )
        .unwrap();
        for c in &s.children {
            write(out, a, c, depth + 1);
        }
    }
    insta::glob!("data/symbols/*.walls", |path| {
        let (a, _) = load(path);
        let mut out = String::new();
        for s in walls_ide::symbols(&a) {
            write(&mut out, &a, &s, 0);
        }
        snapshot_beside(path, &out);
    });
}

#[test]
fn folding() {
    insta::glob!("data/folding/*.walls", |path| {
        let (a, _) = load(path);
        let mut out = String::new();
        for span in walls_ide::folding(&a) {
            writeln!(out, "{}", at(&a, &span)).unwrap();
        }
        snapshot_beside(path, &out);
    });
}

#[test]
fn semantic_tokens() {
    insta::glob!("data/semantic_tokens/*.walls", |path| {
        let (a, _) = load(path);
        let mut out = String::new();
        for t in walls_ide::semantic_tokens(&a) {
            writeln!(out, "{} {:?}", at(&a, &t.range), t.kind).unwrap();
        }
        snapshot_beside(path, &out);
    });
}

#[test]
fn code_actions() {
    insta::glob!("data/code_actions/*.walls", |path| {
        let (a, c) = load(path);
        let c = cursor(path, c);
        let mut out = String::new();
        for action in walls_ide::code_actions(&a, c..c) {
            writeln!(out, "{} ({:?})", action.title, action.kind).unwrap();
            for e in &action.edits {
                writeln!(out, "  {} -> {:?}", at(&a, &e.span), e.replacement).unwrap();
            }
        }
        snapshot_beside(path, &out);
    });
}

#[test]
fn explanations() {
    let code = walls_ide::explain("unknown-word").unwrap();
    assert!(code.starts_with("S101 (unknown-word): "), "{code}");
    assert_eq!(walls_ide::explain("s101"), Some(code));
    assert!(
        walls_ide::explain("radius")
            .unwrap()
            .starts_with("**radius**")
    );
    assert_eq!(walls_ide::explain("no-such-thing"), None);
}

#[test]
fn suppress() {
    insta::glob!("data/suppress/*.walls", |path| {
        let (a, _) = load(path);
        let mut out = String::new();
        for d in a.diagnostics() {
            writeln!(
                out,
                "{} {} {}: {}",
                d.code.id,
                d.severity.as_str(),
                at(&a, &d.span),
                d.message
            )
            .unwrap();
            if let Some(fix) = &d.fix {
                writeln!(
                    out,
                    "  fix ({}): {}",
                    fix.applicability.as_str(),
                    fix.message
                )
                .unwrap();
            }
        }
        let fixed = walls_diagnostics::apply_fixes(
            a.text(),
            a.diagnostics(),
            walls_diagnostics::Applicability::Safe,
        );
        write!(out, "\nafter the safe fixes:\n{fixed}").unwrap();
        snapshot_beside(path, &out);
    });
}
