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

#[test]
fn the_attack_review_s_breaks_stay_fixed() {
    let build = Build::default();
    let codes = |text: &str| -> Vec<&'static str> {
        check(text, &build).iter().map(|d| d.code.id).collect()
    };
    // Hex floats with a binary exponent are read as strtod reads them (8, not 1).
    assert!(!codes("dDelta = 0x1p3\n").contains(&"P004"));
    // A CRLF line of 127 bytes: its `\r` is a blank line to pkdgrav, no long line.
    let line = format!("achOutName = {}\r\n", "o".repeat(114));
    assert_eq!(line.len(), 129);
    assert!(!codes(&line).contains(&"P002"));
    // A rename that would set a key the file sets is not offered.
    let text = "achInFile = p.ss\nnSteps = 100\nnStep = 5\n";
    let found = check(text, &build);
    let d = found.iter().find(|d| d.code.id == "P003").unwrap();
    assert!(
        d.fix.is_none() && d.help.as_deref().unwrap().contains("line 2"),
        "{d:#?}"
    );
    assert_eq!(apply_fixes(text, &found, Applicability::Unsafe), text);
    // The overridden line of a CRLF file goes with its `\r\n`.
    let text = "achInFile = p.ss\r\nnSteps = 1\r\nnSteps = 2\r\n";
    let fixed = apply_fixes(text, &check(text, &build), Applicability::Safe);
    assert_eq!(fixed, "achInFile = p.ss\r\nnSteps = 2\r\n");
    // A NUL byte ends a string value.
    assert!(codes("achOutName = ab\0cd\n").contains(&"P004"));
    // SLIDING_PATCH is no build that reads walls files.
    assert!(Build::parse("DEM SLIDING_PATCH").is_err());
    // Ten thousand unknown keys, each with its "did you mean", quickly.
    let many: String = (0..10_000).map(|i| format!("zz{i} = 1\n")).collect();
    let t = std::time::Instant::now();
    assert_eq!(
        codes(&many).iter().filter(|c| **c == "P003").count(),
        10_000
    );
    // And a hundred thousand duplicates.
    let dups: String = (0..100_000).map(|i| format!("nSteps = {i}\n")).collect();
    assert_eq!(
        codes(&dups).iter().filter(|c| **c == "P006").count(),
        99_999
    );
    assert!(t.elapsed().as_secs() < 20, "{:?}", t.elapsed());
}

#[test]
fn the_review_s_findings_stay_fixed() {
    let build = Build::default();
    let codes = |text: &str| -> Vec<&'static str> {
        check(text, &build).iter().map(|d| d.code.id).collect()
    };
    // A NUL byte ends the line: what follows it, a `!` included, is not read.
    let found = codes("dDelta = 1e-7\0 ! x\n");
    assert!(
        !found.contains(&"P001") && found.contains(&"P004"),
        "{found:?}"
    );
    // A value pkdgrav cannot read makes no start-up row hold (A10 on `nDigits = yes`).
    let found = check("nDigits = yes\n", &build);
    assert!(
        found.iter().all(|d| !d.message.contains("[A10]")),
        "{found:#?}"
    );
    // The rest of a long line that is a comment loses nothing: no P002.
    let line = format!("achOutName = {}#{}\n", "o".repeat(114), "c".repeat(20));
    assert!(!codes(&line).contains(&"P002"));
    // The hard-sphere rows hold only when pkdgrav runs their block (nSmooth ≥ 1).
    let hs = Build::parse("NUMREC").unwrap();
    let rows = |text: &str| -> Vec<String> {
        check(text, &hs).iter().map(|d| d.message.clone()).collect()
    };
    assert!(
        rows("iOverlapOption = -1\n")
            .iter()
            .any(|m| m.contains("[B22]"))
    );
    assert!(
        !rows("iOverlapOption = -1\nnSmooth = 0\n")
            .iter()
            .any(|m| m.contains("[B22]"))
    );
    // Quotes kept where pkdgrav keeps them.
    assert!(codes("achOutName = \"ss\"\n").contains(&"P004"));
    assert!(!codes("achWallsFile = \"w.dat\"\n").contains(&"P004"));
}
