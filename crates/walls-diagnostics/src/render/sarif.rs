//! SARIF 2.1.0 logs for code-scanning services (GitHub code scanning and others).
//!
//! One run whose `tool.driver` lists the given rules; one result per diagnostic with
//! its level (`error`, `warning`, `note`), message (help appended after a newline),
//! primary location, related locations for the secondary labels, and the fix as a
//! SARIF `fix` with `artifactChanges`. Regions use 1-based lines and columns counted
//! in Unicode code points (`columnKind: "unicodeCodePoints"`), `endColumn` exclusive.

use super::{FileReport, Region, ToolInfo, message_with_help};
use crate::{Code, Diagnostic, LineIndex, Severity};
use serde_json::{Value, json};

/// The SARIF 2.1.0 log of all `files`, with `rules` as the driver's rule table.
///
/// Results whose code is not among `rules` keep their `ruleId` but have no
/// `ruleIndex`.
pub fn sarif(files: &[FileReport], tool: &ToolInfo, rules: &[&'static Code]) -> Value {
    let rule_table: Vec<Value> = rules.iter().map(|c| rule(c)).collect();
    let artifacts: Vec<Value> = files
        .iter()
        .map(|f| json!({ "location": { "uri": path_to_uri(f.path) } }))
        .collect();
    let mut results = Vec::new();
    for (artifact, file) in files.iter().enumerate() {
        let index = LineIndex::new(file.source);
        let uri = path_to_uri(file.path);
        let ctx = Ctx {
            index: &index,
            source: file.source,
            uri: &uri,
            artifact,
        };
        results.extend(file.diagnostics.iter().map(|d| result(&ctx, d, rules)));
    }
    let mut driver = json!({
        "name": tool.name,
        "version": tool.version,
        "rules": rule_table,
    });
    if let Some(uri) = tool.information_uri {
        driver["informationUri"] = json!(uri);
    }
    json!({
        "$schema": "https://json.schemastore.org/sarif-2.1.0.json",
        "version": "2.1.0",
        "runs": [{
            "tool": { "driver": driver },
            "columnKind": "unicodeCodePoints",
            "artifacts": artifacts,
            "results": results,
        }]
    })
}

/// What every location of one file needs.
struct Ctx<'a> {
    index: &'a LineIndex,
    source: &'a str,
    uri: &'a str,
    artifact: usize,
}

impl Ctx<'_> {
    fn artifact_location(&self) -> Value {
        json!({ "uri": self.uri, "index": self.artifact })
    }

    fn region(&self, span: &std::ops::Range<usize>) -> Value {
        let r = Region::of(self.index, self.source, span);
        json!({
            "startLine": r.line,
            "startColumn": r.column,
            "endLine": r.end_line,
            "endColumn": r.end_column,
        })
    }

    fn physical_location(&self, span: &std::ops::Range<usize>) -> Value {
        json!({
            "artifactLocation": self.artifact_location(),
            "region": self.region(span),
        })
    }
}

fn rule(code: &Code) -> Value {
    json!({
        "id": code.id,
        "name": code.name,
        "shortDescription": { "text": code.summary },
        "fullDescription": { "text": code.explanation },
        "help": { "text": code.explanation },
    })
}

fn result(ctx: &Ctx, d: &Diagnostic, rules: &[&'static Code]) -> Value {
    let level = match d.severity {
        Severity::Error => "error",
        Severity::Warning => "warning",
        Severity::Info => "note",
    };
    let mut result = json!({
        "ruleId": d.code.id,
        "level": level,
        "message": { "text": message_with_help(d) },
        "locations": [{ "physicalLocation": ctx.physical_location(&d.span) }],
    });
    if let Some(i) = rules.iter().position(|c| c.id == d.code.id) {
        result["ruleIndex"] = json!(i);
    }
    if !d.labels.is_empty() {
        result["relatedLocations"] = d
            .labels
            .iter()
            .enumerate()
            .map(|(i, l)| {
                json!({
                    "id": i,
                    "physicalLocation": ctx.physical_location(&l.span),
                    "message": { "text": l.message },
                })
            })
            .collect();
    }
    if let Some(fix) = &d.fix {
        let replacements: Vec<Value> = fix
            .edits
            .iter()
            .map(|e| {
                json!({
                    "deletedRegion": ctx.region(&e.span),
                    "insertedContent": { "text": e.replacement },
                })
            })
            .collect();
        result["fixes"] = json!([{
            "description": { "text": fix.message },
            "artifactChanges": [{
                "artifactLocation": ctx.artifact_location(),
                "replacements": replacements,
            }],
            "properties": { "applicability": fix.applicability.as_str() },
        }]);
    }
    result
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

    const TOOL: ToolInfo = ToolInfo {
        name: "walls-lint",
        version: "0.1.0",
        information_uri: Some("https://example.invalid/walls"),
    };

    fn log() -> Value {
        let diags = diagnostics();
        let file = FileReport {
            path: "dir/scene.walls",
            source: SOURCE,
            diagnostics: &diags,
        };
        sarif(&[file], &TOOL, &[&UNKNOWN_WORD, &MISSING_VALUE])
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
