//! Every diagnostic code is documented with examples that are true: the bad example
//! produces the code and the good example produces no diagnostic at all. The same text
//! is `docs/diagnostics.md`, kept in step here (`UPDATE_DOCS=1` rewrites it).

use std::collections::HashSet;
use std::path::Path;
use walls_cli::{all_codes, find_code, lint_bytes};
use walls_model::Mode;

/// The ```walls block after the line starting with `label`, and whether that line asks
/// for `--mode hsdem`.
fn example(explanation: &str, label: &str) -> Option<(String, Mode)> {
    let start = explanation.find(&format!("\n{label}"))?;
    let rest = &explanation[start + 1..];
    let line = rest.lines().next()?;
    let mode = if line.contains("--mode hsdem") {
        Mode::Hsdem
    } else {
        Mode::Ssdem
    };
    let after = rest.strip_prefix(line)?.trim_start_matches('\n');
    let body = after.strip_prefix("```walls\n")?;
    Some((body[..body.find("```")?].to_string(), mode))
}

#[test]
fn examples_in_explanations_are_true() {
    let mut without_bad_block = Vec::new();
    for code in all_codes() {
        let bad = example(code.explanation, "Bad");
        // The good example is checked in the bad one's mode, so it shows the way out.
        let mode = bad.as_ref().map_or(Mode::Ssdem, |b| b.1);
        let (good, _) = example(code.explanation, "Good")
            .unwrap_or_else(|| panic!("{} has no good example", code.id));
        let (_, diagnostics) = lint_bytes(good.as_bytes(), mode);
        assert!(
            diagnostics.is_empty(),
            "{}: good example gives {diagnostics:#?}",
            code.id
        );
        match bad {
            Some((bad, mode)) => {
                let (_, diagnostics) = lint_bytes(bad.as_bytes(), mode);
                assert!(
                    diagnostics.iter().any(|d| std::ptr::eq(d.code, code)),
                    "{}: bad example gives {diagnostics:#?}",
                    code.id
                );
            }
            None => without_bad_block.push(code.id),
        }
    }
    // These cannot be shown as a text block; the data-driven tests cover them.
    assert_eq!(without_bad_block, ["S001", "S002", "S003"]);
}

#[test]
fn codes_are_unique_and_found_by_id_or_name() {
    let mut seen = HashSet::new();
    for code in all_codes() {
        assert!(
            seen.insert(code.id) && seen.insert(code.name),
            "{} repeats",
            code.id
        );
        assert!(std::ptr::eq(
            find_code(&code.id.to_lowercase()).unwrap(),
            code
        ));
        assert!(std::ptr::eq(find_code(code.name).unwrap(), code));
    }
}

#[test]
fn docs_list_every_code() {
    let mut doc = String::from(
        "# Diagnostic codes\n\n<!-- Generated from the code registry by `UPDATE_DOCS=1 cargo test -p walls-cli --test codes`; do not edit. -->\n\n\
         `walls-lint --explain CODE` prints the same text. `S` codes are syntax (what pkdgrav refuses to read), \
         `M` codes depend on the contact model (`--mode`).\n\n| code | name | summary |\n|---|---|---|\n",
    );
    for c in all_codes() {
        doc.push_str(&format!(
            "| [{}](#{}) | `{}` | {} |\n",
            c.id,
            c.id.to_lowercase(),
            c.name,
            c.summary
        ));
    }
    for c in all_codes() {
        doc.push_str(&format!(
            "\n## {}\n\n`{}`: {}.\n\n{}",
            c.id, c.name, c.summary, c.explanation
        ));
    }
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../docs/diagnostics.md");
    if std::env::var_os("UPDATE_DOCS").is_some() {
        std::fs::write(&path, &doc).unwrap();
    }
    let on_disk = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        on_disk == doc,
        "docs/diagnostics.md is stale: run UPDATE_DOCS=1 cargo test -p walls-cli --test codes"
    );
}
