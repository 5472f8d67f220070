//! The `walls-lint --format json` object (command-line contract, SPEC §2).
//!
//! ```text
//! {"files":[{"path":…, "diagnostics":[{"code","severity","message","line","column",
//!   "end_line","end_column","help"?,"fix"?}]}], "summary":{"errors":N,"warnings":N}}
//! ```
//!
//! Lines and columns are 1-based, columns count characters and `end_column` is
//! exclusive. `help` and `fix` are left out when absent; a fix is
//! `{"message", "applicability": "safe"|"unsafe", "edits": [{"line", "column",
//! "end_line", "end_column", "content"}]}`.

use super::{FileReport, Region, summarize};
use crate::{Diagnostic, Fix, LineIndex};
use serde::Serialize;

/// The whole output object.
#[derive(Serialize)]
struct Output<'a> {
    files: Vec<File<'a>>,
    summary: Counts,
}

#[derive(Serialize)]
struct File<'a> {
    path: &'a str,
    diagnostics: Vec<Item<'a>>,
}

#[derive(Serialize)]
struct Item<'a> {
    code: &'static str,
    severity: &'static str,
    message: &'a str,
    line: usize,
    column: usize,
    end_line: usize,
    end_column: usize,
    #[serde(skip_serializing_if = "Option::is_none")]
    help: Option<&'a str>,
    #[serde(skip_serializing_if = "Option::is_none")]
    fix: Option<JsonFix<'a>>,
}

#[derive(Serialize)]
struct JsonFix<'a> {
    message: &'a str,
    applicability: &'static str,
    edits: Vec<JsonEdit<'a>>,
}

#[derive(Serialize)]
struct JsonEdit<'a> {
    line: usize,
    column: usize,
    end_line: usize,
    end_column: usize,
    content: &'a str,
}

#[derive(Serialize)]
struct Counts {
    errors: usize,
    warnings: usize,
}

fn output<'a>(files: &[FileReport<'a>]) -> Output<'a> {
    let summary = summarize(files);
    Output {
        files: files.iter().map(file).collect(),
        summary: Counts {
            errors: summary.errors,
            warnings: summary.warnings,
        },
    }
}

fn file<'a>(report: &FileReport<'a>) -> File<'a> {
    let index = LineIndex::new(report.source);
    File {
        path: report.path,
        diagnostics: report
            .diagnostics
            .iter()
            .map(|d| item(&index, report.source, d))
            .collect(),
    }
}

fn item<'a>(index: &LineIndex, source: &str, d: &'a Diagnostic) -> Item<'a> {
    let r = Region::of(index, source, &d.span);
    Item {
        code: d.code.id,
        severity: d.severity.as_str(),
        message: &d.message,
        line: r.line,
        column: r.column,
        end_line: r.end_line,
        end_column: r.end_column,
        help: d.help.as_deref(),
        fix: d.fix.as_ref().map(|f| fix(index, source, f)),
    }
}

fn fix<'a>(index: &LineIndex, source: &str, f: &'a Fix) -> JsonFix<'a> {
    JsonFix {
        message: &f.message,
        applicability: f.applicability.as_str(),
        edits: f
            .edits
            .iter()
            .map(|e| {
                let r = Region::of(index, source, &e.span);
                JsonEdit {
                    line: r.line,
                    column: r.column,
                    end_line: r.end_line,
                    end_column: r.end_column,
                    content: &e.replacement,
                }
            })
            .collect(),
    }
}

/// The `--format json` object as a value.
///
/// Object keys of a [`serde_json::Value`] come out sorted unless serde_json's
/// `preserve_order` feature is on; use [`json_string`] to print the keys in the
/// order the contract lists them.
pub fn json(files: &[FileReport]) -> serde_json::Value {
    serde_json::to_value(output(files)).expect("plain structs always serialize")
}

/// The `--format json` object, pretty-printed with the keys in contract order
/// (no trailing newline).
pub fn json_string(files: &[FileReport]) -> String {
    serde_json::to_string_pretty(&output(files)).expect("plain structs always serialize")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::test_support::{SOURCE, diagnostics};

    fn report(diags: &[Diagnostic]) -> FileReport<'_> {
        FileReport {
            path: "scene.walls",
            source: SOURCE,
            diagnostics: diags,
        }
    }

    #[test]
    fn snapshot() {
        let diags = diagnostics();
        insta::assert_snapshot!(json_string(&[report(&diags)]));
    }

    #[test]
    fn value_matches_string() {
        let diags = diagnostics();
        let files = [report(&diags)];
        let parsed: serde_json::Value = serde_json::from_str(&json_string(&files)).unwrap();
        assert_eq!(parsed, json(&files));
    }

    #[test]
    fn columns_count_characters_and_optional_keys_are_left_out() {
        let diags = diagnostics();
        let v = json(&[report(&diags)]);
        let d = &v["files"][0]["diagnostics"];
        // `wall` follows `# μ `: 4 characters (5 bytes) before it.
        assert_eq!(d[1]["line"], 1);
        assert_eq!(d[1]["column"], 5);
        assert_eq!(d[1]["end_column"], 9);
        assert_eq!(d[1]["severity"], "info");
        assert!(d[1].get("help").is_none());
        assert!(d[1].get("fix").is_none());
        // Empty span at the end of the last line (no final newline).
        assert_eq!(d[2]["line"], 3);
        assert_eq!(d[2]["column"], 12);
        assert_eq!(d[2]["end_line"], 3);
        assert_eq!(d[2]["end_column"], 12);
        assert_eq!(d[2]["fix"]["applicability"], "safe");
        assert_eq!(d[2]["fix"]["edits"][0]["content"], " 1");
        // Multi-line span.
        assert_eq!(
            (d[3]["line"].clone(), d[3]["end_line"].clone()),
            (2.into(), 3.into())
        );
        assert_eq!(d[0]["code"], "S101");
        assert_eq!(d[0]["help"], "did you mean `color`?");
        assert_eq!(
            v["summary"],
            serde_json::json!({"errors": 2, "warnings": 1})
        );
    }

    #[test]
    fn spans_past_the_end_are_clamped() {
        let diags = vec![Diagnostic::error(
            &crate::render::test_support::UNKNOWN_WORD,
            500..900,
            "far away",
        )];
        let v = json(&[report(&diags)]);
        let d = &v["files"][0]["diagnostics"][0];
        assert_eq!(
            (d["line"].clone(), d["column"].clone()),
            (3.into(), 12.into())
        );
    }
}
