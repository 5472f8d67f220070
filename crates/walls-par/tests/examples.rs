//! Every `.par` code's explanation is true: its bad example gives the code, its good
//! example nothing at all, read by pkdgrav's default build with walls.

use walls_par::{Build, check, codes};

/// The ```par block after the line `label:`.
fn example<'a>(explanation: &'a str, label: &str) -> &'a str {
    let at = explanation
        .find(&format!("\n{label}:\n```par\n"))
        .unwrap_or_else(|| panic!("no {label} example"));
    let body = &explanation[at + label.len() + 10..];
    &body[..body.find("```").unwrap()]
}

#[test]
fn bad_examples_give_their_code_and_good_ones_nothing() {
    let build = Build::default();
    for code in codes::ALL {
        let good = check(example(code.explanation, "Good"), &build);
        assert!(
            good.is_empty(),
            "{}: the good example gives {good:#?}",
            code.id
        );
        let bad = check(example(code.explanation, "Bad"), &build);
        assert!(
            bad.iter().any(|d| std::ptr::eq(d.code, *code)),
            "{}: the bad example gives {bad:#?}",
            code.id
        );
    }
}
