//! What an attacker's `.par` gets: a clear finding at its place, never a flood, a panic or
//! a fix that eats text.

use walls_diagnostics::{Applicability, Severity, apply_fixes};
use walls_par::{Build, check};

#[test]
fn a_ten_megabyte_line_is_a_handful_of_findings() {
    let text = format!(
        "achOutName = {}\nnSteps = 5\n",
        "x = 1 ! ".repeat(1_250_000)
    );
    let t = std::time::Instant::now();
    let found = check(&text, &Build::default());
    assert!(t.elapsed().as_secs() < 5);
    // The long line (P002), the `!` of its first read, the first error of its rest:
    // nothing per piece.
    // (The file's start holds the findings about the keys left at their defaults.)
    let end = text.find("\nnSteps").unwrap();
    let on_line: Vec<_> = found
        .iter()
        .filter(|d| d.span != (0..0) && d.span.start < end)
        .collect();
    assert!(on_line.len() <= 3, "{on_line:#?}");
    assert_eq!(
        on_line
            .iter()
            .filter(|d| d.severity == Severity::Error)
            .count(),
        3
    );
}

#[test]
fn fixes_never_eat_the_text_before_an_indented_hash() {
    // The rest of a long line starts with blanks then `#`: no fix may delete the line's
    // first part.
    let text = format!("achOutName = a{}  # comment\n", "b".repeat(111));
    let found = check(&text, &Build::default());
    let fixed = apply_fixes(&text, &found, Applicability::Unsafe);
    assert!(fixed.starts_with("achOutName = a"), "{fixed}");
    // At a line's start the comment moves to the first column.
    let found = check("  # note\n", &Build::default());
    assert_eq!(
        apply_fixes("  # note\n", &found, Applicability::Safe),
        "# note\n"
    );
}

#[test]
fn hostile_values_are_located_findings() {
    for (text, code) in [
        ("dDelta = 1e400\n", "P005"),
        ("dDelta = 1e-400\n", "P005"),
        ("dDelta = nan\n", "P005"),
        ("nSteps = 99999999999\n", "P005"),
        ("nSteps = \u{1b}]52;c;x\u{7}\n", "P001"),
        ("\u{1b}[2J = 1\n", "P001"),
        ("dDelta = 1e-7 \u{202e}s\n", "P004"),
        ("dDelta\u{0} = 1\n", "P001"),
    ] {
        let found = check(text, &Build::default());
        let d = found
            .iter()
            .find(|d| d.code.id == code)
            .unwrap_or_else(|| panic!("{text:?}: {found:#?}"));
        assert!(d.span.end <= text.len() && text.is_char_boundary(d.span.start));
    }
}

proptest::proptest! {
    #[test]
    fn any_text_is_checked_without_a_panic(text in "\\PC{0,400}") {
        for d in check(&text, &Build::default()) {
            proptest::prop_assert!(text.is_char_boundary(d.span.start) && text.is_char_boundary(d.span.end));
            let _ = apply_fixes(&text, std::slice::from_ref(&d), Applicability::Unsafe);
        }
    }
}
