//! SARIF 2.1.0 logs for code-scanning services (GitHub code scanning and others).
//!
//! One run whose `tool.driver` lists the given rules; one result per diagnostic with
//! its level (`error`, `warning`, `note`), message (help appended after a newline),
//! primary location, related locations for the secondary labels, and the fix as a
//! SARIF `fix` with `artifactChanges`. Regions use 1-based lines and columns counted
//! in Unicode code points (`columnKind: "unicodeCodePoints"`), `endColumn` exclusive.
//!
//! Files that could not be read are `toolExecutionNotifications` (level `error`, with
//! the file's URI) of the run's one invocation, whose `executionSuccessful` is then
//! false; with every file read, the run has no `invocations`.
//!
//! The log is serialized from borrowing structs straight to the writer: results and
//! related locations are produced one at a time while writing, so memory stays flat
//! however many diagnostics there are. Every object's fields are declared in sorted
//! key order, the order the output has always had.

use super::{FileReport, Region, ToolInfo, Unreadable, message_with_help};
use crate::{Code, Diagnostic, Label, LineIndex, Severity};
use serde::Serialize;
use serde::ser::{SerializeSeq, Serializer};
use std::borrow::Cow;
use std::io::{self, Write};
use std::ops::Range;

/// Writes the SARIF 2.1.0 log of all `files`, with `rules` as the driver's rule
/// table, as pretty-printed JSON followed by a newline.
///
/// Results whose code is not among `rules` keep their `ruleId` but have no
/// `ruleIndex`. The JSON goes out in many small writes: pass a buffered writer.
pub fn sarif(
    out: &mut dyn Write,
    files: &[FileReport],
    unreadable: &[Unreadable],
    tool: &ToolInfo,
    rules: &[&'static Code],
) -> io::Result<()> {
    let uris: Vec<String> = files.iter().map(|f| path_to_uri(f.path)).collect();
    let log = Log {
        schema: "https://json.schemastore.org/sarif-2.1.0.json",
        runs: [Run {
            artifacts: uris
                .iter()
                .map(|uri| Artifact {
                    location: ArtifactUri { uri },
                })
                .collect(),
            column_kind: "unicodeCodePoints",
            invocations: (!unreadable.is_empty()).then(|| {
                [Invocation {
                    execution_successful: false,
                    tool_execution_notifications: unreadable
                        .iter()
                        .map(|u| Notification {
                            level: "error",
                            locations: [NotificationLocation {
                                physical_location: NotificationPlace {
                                    artifact_location: ArtifactUri {
                                        uri: path_to_uri(u.path),
                                    },
                                    region: u.line.map(|start_line| LineRegion { start_line }),
                                },
                            }],
                            message: Text::from(u.error),
                        })
                        .collect(),
                }]
            }),
            results: Results {
                files,
                uris: &uris,
                rules,
            },
            tool: Tool {
                driver: Driver {
                    information_uri: tool.information_uri,
                    name: tool.name,
                    rules: rules.iter().map(|c| Rule::of(c)).collect(),
                    version: tool.version,
                },
            },
        }],
        version: "2.1.0",
    };
    super::safe_json::write(&mut *out, &log)?;
    writeln!(out)
}

/// The whole log.
#[derive(Serialize)]
struct Log<'a> {
    #[serde(rename = "$schema")]
    schema: &'static str,
    runs: [Run<'a>; 1],
    version: &'static str,
}

/// The one run.
#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct Run<'a> {
    artifacts: Vec<Artifact<'a>>,
    column_kind: &'static str,
    #[serde(skip_serializing_if = "Option::is_none")]
    invocations: Option<[Invocation<'a>; 1]>,
    results: Results<'a>,
    tool: Tool<'a>,
}

/// The one invocation, listed only to report the files that could not be read.
#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct Invocation<'a> {
    execution_successful: bool,
    tool_execution_notifications: Vec<Notification<'a>>,
}

/// A file that could not be read.
#[derive(Serialize)]
struct Notification<'a> {
    level: &'static str,
    locations: [NotificationLocation; 1],
    message: Text<'a>,
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct NotificationLocation {
    physical_location: NotificationPlace,
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct NotificationPlace {
    artifact_location: ArtifactUri<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    region: Option<LineRegion>,
}

/// A notification's line.
#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct LineRegion {
    start_line: usize,
}

/// One entry of `artifacts`, per file in order.
#[derive(Serialize)]
struct Artifact<'a> {
    location: ArtifactUri<&'a str>,
}

/// An artifact location without an index (in the `artifacts` table itself, and for
/// files that could not be read).
#[derive(Serialize)]
struct ArtifactUri<U> {
    uri: U,
}

#[derive(Serialize)]
struct Tool<'a> {
    driver: Driver<'a>,
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct Driver<'a> {
    #[serde(skip_serializing_if = "Option::is_none")]
    information_uri: Option<&'a str>,
    name: &'a str,
    rules: Vec<Rule>,
    version: &'a str,
}

/// One entry of the driver's rule table.
#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct Rule {
    full_description: Text<'static>,
    help: Text<'static>,
    id: &'static str,
    name: &'static str,
    short_description: Text<'static>,
}

impl Rule {
    fn of(code: &'static Code) -> Self {
        Rule {
            full_description: Text::from(code.explanation),
            help: Text::from(code.explanation),
            id: code.id,
            name: code.name,
            short_description: Text::from(code.summary),
        }
    }
}

/// A SARIF message or multiformat string: `{"text": …}`.
#[derive(Serialize)]
struct Text<'a> {
    text: Cow<'a, str>,
}

impl<'a> From<&'a str> for Text<'a> {
    fn from(text: &'a str) -> Self {
        Text {
            text: Cow::Borrowed(text),
        }
    }
}

/// All results of all files, produced one by one while serializing.
struct Results<'a> {
    files: &'a [FileReport<'a>],
    uris: &'a [String],
    rules: &'a [&'static Code],
}

impl Serialize for Results<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut seq = serializer.serialize_seq(None)?;
        for (artifact, (file, uri)) in self.files.iter().zip(self.uris).enumerate() {
            let index = LineIndex::new(file.source);
            let ctx = Ctx {
                index: &index,
                source: file.source,
                uri,
                artifact,
            };
            for d in file.diagnostics {
                seq.serialize_element(&result(&ctx, d, self.rules))?;
            }
        }
        seq.end()
    }
}

/// What every location of one file needs.
struct Ctx<'a> {
    index: &'a LineIndex,
    source: &'a str,
    uri: &'a str,
    artifact: usize,
}

impl<'a> Ctx<'a> {
    fn artifact_location(&self) -> ArtifactLocation<'a> {
        ArtifactLocation {
            index: self.artifact,
            uri: self.uri,
        }
    }

    fn region(&self, span: &Range<usize>) -> SarifRegion {
        let r = Region::of(self.index, self.source, span);
        SarifRegion::Lines {
            end_column: r.end_column,
            end_line: r.end_line,
            start_column: r.column,
            start_line: r.line,
        }
    }

    /// The location of `span`: lines and columns, or, for a diagnostic at a record of a
    /// binary file (`bytes`), the span's bytes as they are.
    fn physical_location(&self, span: &Range<usize>, bytes: bool) -> PhysicalLocation<'a> {
        PhysicalLocation {
            artifact_location: self.artifact_location(),
            region: if bytes {
                SarifRegion::Bytes {
                    byte_offset: span.start,
                    byte_length: span.end.saturating_sub(span.start),
                }
            } else {
                self.region(span)
            },
        }
    }
}

/// A file reference in a location: its URI and index in `artifacts`.
#[derive(Serialize)]
struct ArtifactLocation<'a> {
    index: usize,
    uri: &'a str,
}

/// 1-based lines and code-point columns, `endColumn` exclusive; or, in a binary file
/// (a record of a `.ss` file), a byte offset and length.
#[derive(Serialize)]
#[serde(untagged)]
enum SarifRegion {
    #[serde(rename_all = "camelCase")]
    Lines {
        end_column: usize,
        end_line: usize,
        start_column: usize,
        start_line: usize,
    },
    #[serde(rename_all = "camelCase")]
    Bytes {
        byte_length: usize,
        byte_offset: usize,
    },
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct PhysicalLocation<'a> {
    artifact_location: ArtifactLocation<'a>,
    region: SarifRegion,
}

/// An entry of a result's `locations`; at a record of a binary file, the record as a
/// logical location too (`particle 17`).
#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct Location<'a> {
    #[serde(skip_serializing_if = "Option::is_none")]
    logical_locations: Option<[LogicalLocation; 1]>,
    physical_location: PhysicalLocation<'a>,
}

/// A record of a binary file, named: `{"name": "particle 17", "kind": "element"}`.
#[derive(Serialize)]
struct LogicalLocation {
    kind: &'static str,
    name: String,
}

/// One result: a diagnostic.
#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct SarifResult<'a> {
    #[serde(skip_serializing_if = "Option::is_none")]
    fixes: Option<[SarifFix<'a>; 1]>,
    level: &'static str,
    locations: [Location<'a>; 1],
    message: Text<'a>,
    #[serde(skip_serializing_if = "Option::is_none")]
    related_locations: Option<RelatedLocations<'a>>,
    rule_id: &'static str,
    #[serde(skip_serializing_if = "Option::is_none")]
    rule_index: Option<usize>,
}

/// A diagnostic's secondary labels, produced one by one while serializing.
struct RelatedLocations<'a> {
    ctx: &'a Ctx<'a>,
    labels: &'a [Label],
    /// The diagnostic is at a record of a binary file: its labels' spans are bytes.
    bytes: bool,
}

impl Serialize for RelatedLocations<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.collect_seq(
            self.labels
                .iter()
                .enumerate()
                .map(|(id, l)| RelatedLocation {
                    id,
                    message: Text::from(l.message.as_str()),
                    physical_location: self.ctx.physical_location(&l.span, self.bytes),
                }),
        )
    }
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct RelatedLocation<'a> {
    id: usize,
    message: Text<'a>,
    physical_location: PhysicalLocation<'a>,
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct SarifFix<'a> {
    artifact_changes: [ArtifactChange<'a>; 1],
    description: Text<'a>,
    properties: FixProperties,
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct ArtifactChange<'a> {
    artifact_location: ArtifactLocation<'a>,
    replacements: Vec<Replacement<'a>>,
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct Replacement<'a> {
    deleted_region: SarifRegion,
    inserted_content: Text<'a>,
}

/// The fix's property bag: whether it may be applied unasked.
#[derive(Serialize)]
struct FixProperties {
    applicability: &'static str,
}

fn result<'a>(ctx: &'a Ctx<'a>, d: &'a Diagnostic, rules: &[&'static Code]) -> SarifResult<'a> {
    let level = match d.severity {
        Severity::Error => "error",
        Severity::Warning => "warning",
        Severity::Info => "note",
    };
    let fixes = d.fix.as_ref().map(|fix| {
        [SarifFix {
            artifact_changes: [ArtifactChange {
                artifact_location: ctx.artifact_location(),
                replacements: fix
                    .edits
                    .iter()
                    .map(|e| Replacement {
                        deleted_region: ctx.region(&e.span),
                        inserted_content: Text::from(e.replacement.as_str()),
                    })
                    .collect(),
            }],
            description: Text::from(fix.message.as_str()),
            properties: FixProperties {
                applicability: fix.applicability.as_str(),
            },
        }]
    });
    SarifResult {
        fixes,
        level,
        locations: [Location {
            logical_locations: d.record.map(|r| {
                [LogicalLocation {
                    kind: "element",
                    name: r.to_string(),
                }]
            }),
            physical_location: ctx.physical_location(&d.span, d.record.is_some()),
        }],
        message: Text {
            text: message_with_help(d),
        },
        related_locations: (!d.labels.is_empty()).then_some(RelatedLocations {
            ctx,
            labels: &d.labels,
            bytes: d.record.is_some(),
        }),
        rule_id: d.code.id,
        // A handful of rules: a scan is cheaper than building a map.
        rule_index: rules.iter().position(|c| c.id == d.code.id),
    }
}

/// A file path as a URI reference: `\` becomes `/`, a Windows drive path becomes a
/// `file:///` URI, and bytes outside the unreserved and path characters are
/// percent-encoded (including `:`, so a relative path never reads as a scheme).
fn path_to_uri(path: &str) -> String {
    let path = path.replace('\\', "/");
    let b = path.as_bytes();
    let drive = b.len() >= 3 && b[0].is_ascii_alphabetic() && b[1] == b':' && b[2] == b'/';
    let (mut out, rest) = if drive {
        (format!("file:///{}:", &path[..1]), &path[2..])
    } else {
        (String::new(), path.as_str())
    };
    for &byte in rest.as_bytes() {
        let keep = byte.is_ascii_alphanumeric() || b"-._~/!$&'()*+,;=@".contains(&byte);
        if keep {
            out.push(byte as char);
        } else {
            out.push_str(&format!("%{byte:02X}"));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::test_support::{MISSING_VALUE, SHAPE, SOURCE, UNKNOWN_WORD, diagnostics};
    use serde_json::{Value, json};

    const TOOL: ToolInfo = ToolInfo {
        name: "walls-lint",
        version: "0.1.0",
        information_uri: Some("https://example.invalid/walls"),
    };

    /// The bytes `sarif` writes for `files`.
    fn write(files: &[FileReport], tool: &ToolInfo, rules: &[&'static Code]) -> Vec<u8> {
        let mut out = Vec::new();
        sarif(&mut out, files, &[], tool, rules).unwrap();
        out
    }

    fn log_bytes() -> Vec<u8> {
        let diags = diagnostics();
        let file = FileReport {
            path: "dir/scene.walls",
            source: SOURCE,
            diagnostics: &diags,
        };
        write(&[file], &TOOL, &[&UNKNOWN_WORD, &MISSING_VALUE])
    }

    fn log() -> Value {
        serde_json::from_slice::<Value>(&log_bytes()).unwrap()
    }

    /// The text a `serde_json::Value` of the same log pretty-prints to (keys sorted),
    /// plus the final newline: the streamed output must be exactly that.
    fn as_value_would_print(bytes: &[u8]) -> String {
        let v: Value = serde_json::from_slice(bytes).unwrap();
        serde_json::to_string_pretty(&v).unwrap() + "\n"
    }

    #[test]
    fn unreadable_files_are_tool_execution_notifications() {
        let u = Unreadable {
            path: "dir/gone one.walls",
            error: "cannot read dir/gone one.walls: No such file or directory (os error 2)",
            line: None,
        };
        let mut out = Vec::new();
        sarif(&mut out, &[], &[u], &TOOL, &[]).unwrap();
        let v: Value = serde_json::from_slice(&out).unwrap();
        assert_eq!(
            v["runs"][0]["invocations"],
            json!([{
                "executionSuccessful": false,
                "toolExecutionNotifications": [{
                    "level": "error",
                    "locations": [{"physicalLocation": {"artifactLocation": {"uri": "dir/gone%20one.walls"}}}],
                    "message": {"text": "cannot read dir/gone one.walls: No such file or directory (os error 2)"}
                }]
            }])
        );
        assert_eq!(
            String::from_utf8(out.clone()).unwrap(),
            as_value_would_print(&out)
        );
        assert!(log()["runs"][0].get("invocations").is_none());
    }

    #[test]
    fn same_text_as_a_value_tree() {
        let bytes = log_bytes();
        assert!(bytes.ends_with(b"}\n"));
        assert_eq!(
            String::from_utf8(bytes.clone()).unwrap(),
            as_value_would_print(&bytes)
        );

        // No files, no rules, no documentation address: empty arrays, no informationUri.
        let tool = ToolInfo {
            information_uri: None,
            ..TOOL
        };
        let bytes = write(&[], &tool, &[]);
        assert_eq!(
            String::from_utf8(bytes.clone()).unwrap(),
            as_value_would_print(&bytes)
        );
        let v: Value = serde_json::from_slice(&bytes).unwrap();
        let run = &v["runs"][0];
        assert!(run["tool"]["driver"].get("informationUri").is_none());
        assert_eq!(run["tool"]["driver"]["rules"], json!([]));
        assert_eq!(run["artifacts"], json!([]));
        assert_eq!(run["results"], json!([]));

        // A file without diagnostics next to one with them: indices follow the files.
        let diags = diagnostics();
        let files = [
            FileReport {
                path: "clean.walls",
                source: "",
                diagnostics: &[],
            },
            FileReport {
                path: "b.walls",
                source: SOURCE,
                diagnostics: &diags,
            },
        ];
        let bytes = write(&files, &tool, &[&SHAPE]);
        assert_eq!(
            String::from_utf8(bytes.clone()).unwrap(),
            as_value_would_print(&bytes)
        );
        let v: Value = serde_json::from_slice(&bytes).unwrap();
        let run = &v["runs"][0];
        assert_eq!(run["artifacts"][1]["location"]["uri"], "b.walls");
        let loc = &run["results"][0]["locations"][0]["physicalLocation"]["artifactLocation"];
        assert_eq!(*loc, json!({"index": 1, "uri": "b.walls"}));
        assert_eq!(run["results"][1]["ruleIndex"], 0);
        assert!(run["results"][0].get("ruleIndex").is_none());
    }

    #[test]
    fn header_and_driver() {
        let v = log();
        assert_eq!(
            v["$schema"],
            "https://json.schemastore.org/sarif-2.1.0.json"
        );
        assert_eq!(v["version"], "2.1.0");
        assert_eq!(v["runs"].as_array().unwrap().len(), 1);
        let run = &v["runs"][0];
        assert_eq!(run["columnKind"], "unicodeCodePoints");
        let driver = &run["tool"]["driver"];
        assert_eq!(driver["name"], "walls-lint");
        assert_eq!(driver["version"], "0.1.0");
        assert_eq!(driver["informationUri"], "https://example.invalid/walls");
        let rules = driver["rules"].as_array().unwrap();
        assert_eq!(rules.len(), 2);
        assert_eq!(rules[0]["id"], "S101");
        assert_eq!(rules[0]["name"], "unknown-word");
        assert_eq!(rules[0]["shortDescription"]["text"], UNKNOWN_WORD.summary);
        assert_eq!(
            rules[0]["fullDescription"]["text"],
            UNKNOWN_WORD.explanation
        );
        assert_eq!(rules[0]["help"]["text"], UNKNOWN_WORD.explanation);
        assert_eq!(run["artifacts"][0]["location"]["uri"], "dir/scene.walls");
    }

    #[test]
    fn results() {
        let v = log();
        let results = v["runs"][0]["results"].as_array().unwrap();
        assert_eq!(results.len(), 4);
        let levels: Vec<&str> = results
            .iter()
            .map(|r| r["level"].as_str().unwrap())
            .collect();
        assert_eq!(levels, ["error", "note", "error", "warning"]);

        let r = &results[0];
        assert_eq!(r["ruleId"], "S101");
        assert_eq!(r["ruleIndex"], 0);
        assert_eq!(
            r["message"]["text"],
            "unknown word `colr`\ndid you mean `color`?"
        );
        let loc = &r["locations"][0]["physicalLocation"];
        assert_eq!(loc["artifactLocation"]["uri"], "dir/scene.walls");
        assert_eq!(
            loc["region"],
            json!({"startLine": 2, "startColumn": 20, "endLine": 2, "endColumn": 24})
        );
        assert_eq!(r["relatedLocations"][0]["message"]["text"], "in this plane");
        assert_eq!(
            r["relatedLocations"][0]["physicalLocation"]["region"]["startColumn"],
            1
        );
        let fix = &r["fixes"][0];
        assert_eq!(fix["description"]["text"], "replace with `color`");
        let rep = &fix["artifactChanges"][0]["replacements"][0];
        assert_eq!(rep["deletedRegion"]["startColumn"], 20);
        assert_eq!(rep["deletedRegion"]["endColumn"], 24);
        assert_eq!(rep["insertedContent"]["text"], "color");
        assert_eq!(
            fix["artifactChanges"][0]["artifactLocation"]["uri"],
            "dir/scene.walls"
        );

        // Info → note; columns in code points after `μ`; its code is not a listed rule.
        let r = &results[1];
        assert_eq!(r["ruleId"], SHAPE.id);
        assert!(r.get("ruleIndex").is_none());
        assert_eq!(
            r["locations"][0]["physicalLocation"]["region"]["startColumn"],
            5
        );
        assert!(r.get("fixes").is_none());
        assert!(r.get("relatedLocations").is_none());

        // Empty region at the end of the file: an insertion point.
        let region = &results[2]["locations"][0]["physicalLocation"]["region"];
        assert_eq!(region["startColumn"], region["endColumn"]);
        assert_eq!(results[2]["ruleIndex"], 1);
    }

    #[test]
    fn uris() {
        assert_eq!(path_to_uri("a/b c.walls"), "a/b%20c.walls");
        assert_eq!(path_to_uri("dir\\x:y.walls"), "dir/x%3Ay.walls");
        assert_eq!(path_to_uri("C:\\w\\μ.walls"), "file:///C:/w/%CE%BC.walls");
        assert_eq!(path_to_uri("/abs/50%.walls"), "/abs/50%25.walls");
    }
}
