//! The `walls-lint --format json` object (command-line contract, docs/spec.md §2).
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
//!
//! A file that could not be read comes after the others as
//! `{"path", "error": "why", "diagnostics": []}`.
//!
//! The object is serialized from borrowing structs straight to the writer, one
//! diagnostic at a time, with the keys in the order above.

use super::{FileReport, Region, Unreadable, summarize};
use crate::{Diagnostic, Fix, LineIndex};
use serde::{Serialize, Serializer};
use std::io::{self, Write};

/// Writes the `--format json` object of all `files` and the `unreadable` ones,
/// pretty-printed with the keys in contract order and followed by a newline.
///
/// The JSON goes out in many small writes: pass a buffered writer.
pub fn json(
    out: &mut dyn Write,
    files: &[FileReport],
    unreadable: &[Unreadable],
) -> io::Result<()> {
    let summary = summarize(files);
    let output = Output {
        files: files
            .iter()
            .map(|report| Entry::Read(File { report }))
            .chain(unreadable.iter().map(|u| {
                Entry::Unreadable(NotRead {
                    path: u.path,
                    error: u.error,
                    line: u.line,
                    diagnostics: [],
                })
            }))
            .collect(),
        summary: Counts {
            errors: summary.errors,
            warnings: summary.warnings,
        },
    };
    super::safe_json::write(&mut *out, &output)?;
    writeln!(out)
}

/// The whole output object.
#[derive(Serialize)]
struct Output<'a> {
    files: Vec<Entry<'a>>,
    summary: Counts,
}

/// One entry of `files`.
#[derive(Serialize)]
#[serde(untagged)]
enum Entry<'a> {
    Read(File<'a>),
    Unreadable(NotRead<'a>),
}

/// A file that could not be read.
#[derive(Serialize)]
struct NotRead<'a> {
    path: &'a str,
    error: &'a str,
    #[serde(skip_serializing_if = "Option::is_none")]
    line: Option<usize>,
    diagnostics: [(); 0],
}

/// One file: `{"path", "diagnostics"}`, its items produced one by one while
/// serializing.
struct File<'a> {
    report: &'a FileReport<'a>,
}

impl Serialize for File<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let report = self.report;
        let index = LineIndex::new(report.source);
        FileFields {
            path: report.path,
            diagnostics: Items {
                index: &index,
                report,
            },
        }
        .serialize(serializer)
    }
}

/// The fields of a [`File`], once its line index is built.
#[derive(Serialize)]
struct FileFields<'a> {
    path: &'a str,
    diagnostics: Items<'a>,
}

/// A file's diagnostics as items, produced one by one while serializing.
struct Items<'a> {
    index: &'a LineIndex,
    report: &'a FileReport<'a>,
}

impl Serialize for Items<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let source = self.report.source;
        serializer.collect_seq(
            self.report
                .diagnostics
                .iter()
                .map(|d| item(self.index, source, d)),
        )
    }
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
    /// At a record of a binary file: `{"kind": "particle", "index": 17}` (the line and
    /// column are then 1).
    #[serde(skip_serializing_if = "Option::is_none")]
    record: Option<JsonRecord>,
    #[serde(skip_serializing_if = "Option::is_none")]
    help: Option<&'a str>,
    #[serde(skip_serializing_if = "Option::is_none")]
    fix: Option<JsonFix<'a>>,
}

#[derive(Serialize)]
struct JsonRecord {
    kind: &'static str,
    index: usize,
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
        record: d.record.map(|r| JsonRecord {
            kind: r.kind,
            index: r.index,
        }),
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

    /// The bytes `json` writes for `files`.
    fn write(files: &[FileReport]) -> Vec<u8> {
        let mut out = Vec::new();
        super::json(&mut out, files, &[]).unwrap();
        out
    }

    /// What `json` writes, parsed back.
    fn json(files: &[FileReport]) -> serde_json::Value {
        serde_json::from_slice::<serde_json::Value>(&write(files)).unwrap()
    }

    /// What `json` writes, without the final newline (the snapshot predates it).
    fn json_string(files: &[FileReport]) -> String {
        let text = String::from_utf8(write(files)).unwrap();
        text.strip_suffix('\n')
            .expect("output ends with a newline")
            .to_owned()
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
        let text = json_string(&files);
        assert!(!text.ends_with('\n'), "exactly one final newline");
        let parsed: serde_json::Value = serde_json::from_str(&text).unwrap();
        assert_eq!(parsed, json(&files));

        // No files at all: still the whole object.
        assert_eq!(
            String::from_utf8(write(&[])).unwrap(),
            "{\n  \"files\": [],\n  \"summary\": {\n    \"errors\": 0,\n    \"warnings\": 0\n  }\n}\n"
        );
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
    fn unreadable_files_have_an_error() {
        let diags = diagnostics();
        let u = Unreadable {
            path: "gone.walls",
            error: "cannot read gone.walls: No such file or directory (os error 2)",
            line: None,
        };
        let mut out = Vec::new();
        super::json(&mut out, &[report(&diags)], &[u]).unwrap();
        let v: serde_json::Value = serde_json::from_slice(&out).unwrap();
        assert_eq!(
            v["files"][1],
            serde_json::json!({
                "path": "gone.walls",
                "error": "cannot read gone.walls: No such file or directory (os error 2)",
                "diagnostics": []
            })
        );
        assert_eq!(v["files"][0]["path"], "scene.walls");
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
