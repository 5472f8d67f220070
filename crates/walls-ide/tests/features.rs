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
        for h in walls_ide::inlay_hints(&a, 0..a.text().len(), usize::MAX) {
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
        for s in walls_ide::symbols(&a, usize::MAX) {
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
        for t in walls_ide::semantic_tokens(&a, 0..usize::MAX) {
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
        let check = |text: String| walls_ide::check_text(text, &Options::default());
        for action in walls_ide::code_actions(&a.checked, c..c, usize::MAX, &check) {
            writeln!(out, "{} ({:?})", action.title, action.kind).unwrap();
            for e in &action.edits {
                writeln!(out, "  {} -> {:?}", at(&a, &e.span), e.replacement).unwrap();
            }
        }
        snapshot_beside(path, &out);
    });
}

/// `n` disks after a `lengthunit`, each with its radius.
fn disks(n: usize) -> Analysis {
    let mut text = String::from("lengthunit 2\n");
    for _ in 0..n {
        text.push_str("wall type disk\n  radius 1\n");
    }
    Analysis::of_text(text, &Options::default())
}

/// An outline as `name (kind): children`, one entry a line.
fn outline(a: &Analysis, max: usize) -> Vec<String> {
    walls_ide::symbols(a, max)
        .iter()
        .map(|s| {
            format!(
                "{} ({:?}) {}: {}",
                s.name,
                s.kind,
                at(a, &s.selection_range),
                s.children.len()
            )
        })
        .collect()
}

#[test]
fn an_outline_has_at_most_the_entries_asked_for() {
    let a = disks(25);
    // 26 entries at the top, 50 statements in blocks.
    let full = outline(&a, 76);
    assert_eq!(full.len(), 26);
    assert_eq!(full[1], "wall 0: disk (Wall) 2:1-2:5 \"wall\": 2");
    // The top level alone.
    let flat = outline(&a, 75);
    assert_eq!(flat.len(), 26);
    assert_eq!(flat[1], "wall 0: disk (Wall) 2:1-2:5 \"wall\": 0");
    // Runs of ten, then of a hundred.
    assert_eq!(
        outline(&a, 3),
        [
            "walls 0–8 (Group) 1:1-1:11 \"lengthunit\": 0",
            "walls 9–18 (Group) 20:1-20:5 \"wall\": 0",
            "walls 19–24 (Group) 40:1-40:5 \"wall\": 0",
        ]
    );
    let one = walls_ide::symbols(&a, 2);
    assert_eq!(one.len(), 1);
    assert_eq!(one[0].name, "walls 0–24");
    assert_eq!(one[0].range, 0..a.text().len() - 1);
    // A run with no wall is named by its first entry.
    let units = Analysis::of_text("lengthunit 2\n".repeat(30), &Options::default());
    assert_eq!(walls_ide::symbols(&units, 5)[0].name, "lengthunit …");
    // A hundred thousand walls: a thousand groups of a hundred, never more.
    let many = disks(100_000);
    let groups = walls_ide::symbols(&many, 2000);
    assert_eq!(groups.len(), 1001);
    assert_eq!(groups[999].name, "walls 99899–99998");
    assert_eq!(groups[1000].name, "wall 99999");
}

#[test]
fn a_statement_detail_is_cut() {
    let numbers = "1.5 ".repeat(1000);
    let a = Analysis::of_text(
        format!("wall type plane\n  origin {numbers}\n"),
        &Options::default(),
    );
    let symbols = walls_ide::symbols(&a, 100);
    let detail = symbols[0].children[1].detail.as_deref().unwrap();
    assert!(detail.ends_with(" …"), "{detail}");
    assert!(detail.len() <= walls_ide::MAX_DETAIL + 8, "{detail}");
}

#[test]
fn hints_and_tokens_are_bounded() {
    let text = format!("defaults\n  color 3\n{}", "wall type disk\n".repeat(100));
    let a = Analysis::of_text(text, &Options::default());
    let all = walls_ide::inlay_hints(&a, 0..a.text().len(), usize::MAX);
    assert_eq!(all.len(), 100);
    assert_eq!(walls_ide::inlay_hints(&a, 0..a.text().len(), 7), all[..7]);
    // Tokens starting in a byte range: those of the 3rd wall's line.
    let line = a.lines.line_start(4).unwrap()..a.lines.line_start(5).unwrap();
    let tokens: Vec<_> = walls_ide::semantic_tokens(&a, line)
        .map(|t| &a.text()[t.range])
        .collect();
    assert_eq!(tokens, ["wall", "type", "disk"]);
    assert_eq!(
        walls_ide::semantic_tokens(&a, 0..usize::MAX).count(),
        3 + 300
    );
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
