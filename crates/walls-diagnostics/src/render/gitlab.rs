//! GitLab Code Quality reports: the `codequality` artifact of a GitLab CI job.
//!
//! ```text
//! [{"description", "check_name", "fingerprint", "severity",
//!   "location": {"path", "lines": {"begin", "end"}}}, …]
//! ```
//!
//! One issue per diagnostic: `check_name` is its code (`S101`), `description` its message
//! (help appended after a newline), `severity` `critical` for an error, `major` for a
//! warning and `info` for an info, and `location` its 1-based first and last lines. A
//! file that could not be read is a `blocker` issue named `unreadable-file` at line 1.
//! Paths are written with `/` and without a leading `./`, as GitLab compares them with
//! the paths of the repository.
//!
//! GitLab keeps one issue per fingerprint and compares a merge request's issues with its
//! target branch's by fingerprint, so a fingerprint must be unique in a report and must
//! not change when unrelated lines are added or removed above the issue. It is the
//! SHA-256 of the path, the code, the text the diagnostic covers and the number of
//! earlier diagnostics of that file with the same code and text; never a line number.
//! For a file that could not be read, the error message stands for the text.
//! An empty span (something missing, such as a value at the end of a line) covers no
//! text, so the text before it on its line, at most [`CONTEXT`] bytes, stands for it.

use super::{FileReport, Region, Unreadable, clamp_span, message_with_help};
use crate::{Diagnostic, LineIndex, Severity};
use serde::Serialize;
use serde::ser::{SerializeSeq, Serializer};
use sha2::{Digest, Sha256};
use std::borrow::Cow;
use std::collections::HashMap;
use std::io::{self, Write};

/// The most bytes before an empty span that stand for it in the fingerprint.
const CONTEXT: usize = 64;

/// The `check_name` of a file that could not be read.
const UNREADABLE: &str = "unreadable-file";

/// Writes the Code Quality report of all `files` and the `unreadable` ones: a
/// pretty-printed JSON array followed by a newline.
///
/// The JSON goes out in many small writes: pass a buffered writer.
pub fn gitlab(
    out: &mut dyn Write,
    files: &[FileReport],
    unreadable: &[Unreadable],
) -> io::Result<()> {
    super::safe_json::write(&mut *out, &Issues { files, unreadable })?;
    writeln!(out)
}

/// Every issue of a report, produced one by one while serializing.
struct Issues<'a> {
    files: &'a [FileReport<'a>],
    unreadable: &'a [Unreadable<'a>],
}

impl Serialize for Issues<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut seq = serializer.serialize_seq(None)?;
        // How many issues each path has had so far with each check and text; a path
        // given twice (standard input, say) goes on counting.
        let mut seen: HashMap<String, HashMap<(&str, Cow<str>), usize>> = HashMap::new();
        for file in self.files {
            let path = report_path(file.path);
            let index = LineIndex::new(file.source);
            let seen = seen.entry(path.to_string()).or_default();
            for d in file.diagnostics {
                // At a record of a binary file, the record stands for the text.
                let text = match d.record {
                    Some(r) => Cow::Owned(r.to_string()),
                    None => Cow::Borrowed(covered_text(file.source, d)),
                };
                let issue = issue(&index, file.source, &path, d, &text, 0);
                let occurrence = seen.entry((d.code.id, text)).or_default();
                let fingerprint = fingerprint(&path, d.code.id, &issue.text, *occurrence);
                seq.serialize_element(&Issue {
                    fingerprint,
                    ..issue.issue
                })?;
                *occurrence += 1;
            }
        }
        for u in self.unreadable {
            let path = report_path(u.path);
            let occurrence = seen
                .entry(path.to_string())
                .or_default()
                .entry((UNREADABLE, Cow::Borrowed(u.error)))
                .or_default();
            seq.serialize_element(&Issue {
                description: Cow::Borrowed(u.error),
                check_name: UNREADABLE,
                fingerprint: fingerprint(&path, UNREADABLE, u.error, *occurrence),
                severity: "blocker",
                location: Location {
                    path: &path,
                    lines: Lines {
                        begin: u.line.unwrap_or(1),
                        end: u.line.unwrap_or(1),
                    },
                },
            })?;
            *occurrence += 1;
        }
        seq.end()
    }
}

/// One issue.
#[derive(Serialize)]
struct Issue<'a> {
    description: Cow<'a, str>,
    check_name: &'a str,
    fingerprint: String,
    severity: &'static str,
    location: Location<'a>,
}

/// Where an issue is: the path and its first and last lines (1-based, inclusive).
#[derive(Serialize)]
struct Location<'a> {
    path: &'a str,
    lines: Lines,
}

#[derive(Serialize)]
struct Lines {
    begin: usize,
    end: usize,
}

/// An issue with the text its fingerprint is of.
struct Found<'a> {
    issue: Issue<'a>,
    text: String,
}

/// The issue of `d`; at a record of a binary file, its description begins with the
/// record (`particle 17: …`) and its lines are 1.
fn issue<'a>(
    index: &LineIndex,
    source: &str,
    path: &'a str,
    d: &'a Diagnostic,
    text: &str,
    occurrence: usize,
) -> Found<'a> {
    let r = Region::of(index, source, &d.span);
    let description = match d.record {
        Some(record) => Cow::Owned(format!("{record}: {}", message_with_help(d))),
        None => message_with_help(d),
    };
    let issue = Issue {
        description,
        check_name: d.code.id,
        fingerprint: fingerprint(path, d.code.id, text, occurrence),
        severity: match d.severity {
            Severity::Error => "critical",
            Severity::Warning => "major",
            Severity::Info => "info",
        },
        location: Location {
            path,
            lines: Lines {
                begin: r.line,
                end: r.end_line,
            },
        },
    };
    Found {
        issue,
        text: text.to_string(),
    }
}

/// The text `d` covers; for an empty span, the text before it on its line (at most
/// [`CONTEXT`] bytes, from a character boundary).
fn covered_text<'s>(source: &'s str, d: &Diagnostic) -> &'s str {
    let span = clamp_span(source, &d.span);
    if !span.is_empty() {
        return &source[span];
    }
    let line = &source[..span.start];
    let line = line.rfind('\n').map_or(line, |nl| &line[nl + 1..]);
    let mut from = line.len().saturating_sub(CONTEXT);
    while !line.is_char_boundary(from) {
        from += 1;
    }
    &line[from..]
}

/// The path as GitLab's repository paths are written: `/` between folders and no
/// leading `./`.
fn report_path(path: &str) -> Cow<'_, str> {
    let path = if path.contains('\\') {
        Cow::Owned(path.replace('\\', "/"))
    } else {
        Cow::Borrowed(path)
    };
    let mut rest = &*path;
    while let Some(after) = rest.strip_prefix("./") {
        rest = after;
    }
    let skip = path.len() - rest.len();
    match path {
        Cow::Borrowed(p) => Cow::Borrowed(&p[skip..]),
        Cow::Owned(p) => Cow::Owned(p[skip..].to_owned()),
    }
}

/// The lower-case hexadecimal SHA-256 of the path, the check, the text and the
/// occurrence, each preceded by its length so that no two inputs run together.
fn fingerprint(path: &str, check: &str, text: &str, occurrence: usize) -> String {
    let mut hasher = Sha256::new();
    let occurrence = (occurrence as u64).to_le_bytes();
    for part in [
        path.as_bytes(),
        check.as_bytes(),
        text.as_bytes(),
        &occurrence,
    ] {
        hasher.update((part.len() as u64).to_le_bytes());
        hasher.update(part);
    }
    const HEX: &[u8; 16] = b"0123456789abcdef";
    let mut hex = String::with_capacity(64);
    for b in hasher.finalize() {
        hex.push(char::from(HEX[usize::from(b >> 4)]));
        hex.push(char::from(HEX[usize::from(b & 0xf)]));
    }
    hex
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::test_support::{MISSING_VALUE, SHAPE, SOURCE, UNKNOWN_WORD, diagnostics};
    use serde_json::{Value, json};

    /// The text `gitlab` writes for one file.
    fn write(path: &str, source: &str, diags: &[Diagnostic]) -> String {
        let mut out = Vec::new();
        let file = FileReport {
            path,
            source,
            diagnostics: diags,
        };
        gitlab(&mut out, &[file], &[]).unwrap();
        String::from_utf8(out).unwrap()
    }

    fn issues(text: &str) -> Vec<Value> {
        serde_json::from_str(text).unwrap()
    }

    #[test]
    fn snapshot() {
        insta::assert_snapshot!(write("./dir/scene.walls", SOURCE, &diagnostics()));
    }

    #[test]
    fn fields_severities_and_lines() {
        let text = write("dir\\scene.walls", SOURCE, &diagnostics());
        assert!(text.ends_with("]\n"), "{text}");
        let issues = issues(&text);
        let seen: Vec<Value> = issues
            .iter()
            .map(|i| json!([i["check_name"], i["severity"], i["location"]["lines"]]))
            .collect();
        assert_eq!(
            seen,
            [
                json!(["S101", "critical", {"begin": 2, "end": 2}]),
                json!(["C201", "info", {"begin": 1, "end": 1}]),
                json!(["S102", "critical", {"begin": 3, "end": 3}]),
                json!(["C201", "major", {"begin": 2, "end": 3}]),
            ]
        );
        assert_eq!(
            issues[0]["description"],
            "unknown word `colr`\ndid you mean `color`?"
        );
        for i in &issues {
            assert_eq!(i["location"]["path"], "dir/scene.walls");
            let fingerprint = i["fingerprint"].as_str().unwrap();
            assert_eq!(fingerprint.len(), 64);
            assert!(fingerprint.bytes().all(|b| b.is_ascii_hexdigit()));
        }
    }

    #[test]
    fn no_files_is_an_empty_array() {
        let mut out = Vec::new();
        gitlab(&mut out, &[], &[]).unwrap();
        assert_eq!(String::from_utf8(out).unwrap(), "[]\n");
    }

    #[test]
    fn unreadable_files_are_blockers() {
        let u = Unreadable {
            path: "./gone.walls",
            error: "cannot read ./gone.walls: No such file or directory (os error 2)",
            line: None,
        };
        let mut out = Vec::new();
        gitlab(&mut out, &[], &[u]).unwrap();
        let issues = issues(std::str::from_utf8(&out).unwrap());
        assert_eq!(
            issues,
            [json!({
                "description": "cannot read ./gone.walls: No such file or directory (os error 2)",
                "check_name": "unreadable-file",
                "fingerprint": fingerprint("gone.walls", "unreadable-file", u.error, 0),
                "severity": "blocker",
                "location": {"path": "gone.walls", "lines": {"begin": 1, "end": 1}}
            })]
        );
    }

    #[test]
    fn a_path_twice_keeps_its_fingerprints_apart() {
        let errors = ["cannot read a: denied", "cannot read a: denied", "a: other"];
        let unreadable: Vec<Unreadable> = errors
            .iter()
            .map(|error| Unreadable {
                path: "a",
                error,
                line: None,
            })
            .collect();
        let diags = [Diagnostic::error(&UNKNOWN_WORD, 0..1, "x")];
        let file = FileReport {
            path: "-",
            source: "x",
            diagnostics: &diags,
        };
        let mut out = Vec::new();
        gitlab(&mut out, &[file, file], &unreadable).unwrap();
        let issues = issues(std::str::from_utf8(&out).unwrap());
        let fingerprints: std::collections::HashSet<&str> = issues
            .iter()
            .map(|i| i["fingerprint"].as_str().unwrap())
            .collect();
        assert_eq!(fingerprints.len(), 5);
    }

    /// Two unknown words on lines 2 and 4 and a missing value at the end of line 3.
    fn two_typos(source: &str) -> Vec<Diagnostic> {
        let mut at = source.match_indices("colr").map(|(i, _)| i);
        let missing = source.find("radius").unwrap() + "radius".len();
        let first = at.next().unwrap();
        let second = at.next().unwrap();
        vec![
            Diagnostic::error(&UNKNOWN_WORD, first..first + 4, "unknown word `colr`"),
            Diagnostic::error(&MISSING_VALUE, missing..missing, "missing value"),
            Diagnostic::error(&UNKNOWN_WORD, second..second + 4, "unknown word `colr`"),
        ]
    }

    fn fingerprints(path: &str, source: &str) -> Vec<Value> {
        issues(&write(path, source, &two_typos(source)))
            .into_iter()
            .map(|i| i["fingerprint"].clone())
            .collect()
    }

    const TYPOS: &str = "wall\n colr 1\ndisk radius\n colr 2\n";

    #[test]
    fn fingerprints_survive_moved_lines_and_tell_identical_text_apart() {
        let before = fingerprints("a.walls", TYPOS);
        // Comments and blank lines above each issue: every line number changes.
        let after = fingerprints(
            "a.walls",
            "# new\n\nwall\n\n colr 1\n# x\ndisk radius\n\n\n colr 2\n",
        );
        assert_eq!(before, after);
        // The same code on the same text: told apart by their order.
        assert_ne!(before[0], before[2]);
        // Another file, other fingerprints.
        let other = fingerprints("b.walls", TYPOS);
        assert!(before.iter().zip(&other).all(|(a, b)| a != b));
    }

    #[test]
    fn fingerprints_change_with_the_covered_text() {
        let a = fingerprints("a.walls", TYPOS);
        // The missing value now follows `cylinder radius`: its context differs.
        let b = fingerprints("a.walls", "wall\n colr 1\ncylinder radius\n colr 2\n");
        assert_eq!(a[0], b[0]);
        assert_ne!(a[1], b[1]);
        assert_eq!(a[2], b[2]);
    }

    #[test]
    fn empty_spans_use_a_bounded_context() {
        // 207 bytes: the last 64 would start inside a `μ`, so the context starts after it.
        let long = format!("{}radius!", "μ".repeat(100));
        let end = long.len();
        let d = Diagnostic::error(&MISSING_VALUE, end..end, "missing");
        assert_eq!(
            covered_text(&long, &d),
            format!("{}radius!", "μ".repeat(28))
        );
        let d = Diagnostic::new(&SHAPE, Severity::Info, 0..0, "at the start");
        assert_eq!(covered_text("x\n", &d), "");
        let d = Diagnostic::error(&MISSING_VALUE, 5..5, "after a newline");
        assert_eq!(covered_text("ab\ncd\n", &d), "cd");
        let d = Diagnostic::error(&MISSING_VALUE, 900..900, "past the end");
        assert_eq!(covered_text("ab\ncd", &d), "cd");
        let d = Diagnostic::error(&MISSING_VALUE, 3..5, "a span");
        assert_eq!(covered_text("ab\ncd", &d), "cd");
    }

    #[test]
    fn paths() {
        assert_eq!(report_path("./././a/b.walls"), "a/b.walls");
        assert_eq!(report_path(".\\w\\a.walls"), "w/a.walls");
        assert_eq!(report_path("../a.walls"), "../a.walls");
        assert_eq!(report_path("-"), "-");
    }

    #[test]
    fn fingerprint_parts_do_not_run_together() {
        assert_ne!(fingerprint("ab", "c", "", 0), fingerprint("a", "bc", "", 0));
        assert_ne!(
            fingerprint("a.walls", "S101", "colr", 0),
            fingerprint("a.walls", "S101", "colr", 1)
        );
        // A known value: the fingerprint of a report is the same on every machine.
        assert_eq!(
            fingerprint("a.walls", "S101", "colr", 0),
            "be635b388d10393979374edb396e99f1cfe0279149782fec7c01d958f057eb57"
        );
    }
}
