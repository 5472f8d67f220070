//! The LSP features, each a function from an analysed document to LSP values.

use crate::document::Document;
use crate::position::{offset, position, range};
use std::collections::HashMap;
use tower_lsp_server::ls_types::{self as lsp, *};
use walls_diagnostics::{Applicability, Severity, apply_fixes};
use walls_format::FormatOptions;
use walls_keywords::{Keyword, Role};
use walls_model::{Place, Source, Value};
use walls_syntax::{BlockKind, Item, Statement};

/// The document's diagnostics, as the client shows them.
pub fn diagnostics(uri: &Uri, doc: &Document) -> Vec<lsp::Diagnostic> {
    doc.diagnostics
        .iter()
        .map(|d| to_lsp(uri, doc, d))
        .collect()
}

fn to_lsp(uri: &Uri, doc: &Document, d: &walls_diagnostics::Diagnostic) -> lsp::Diagnostic {
    let text = doc.text();
    let mut message = d.message.clone();
    if let Some(help) = &d.help {
        message.push_str("\nhelp: ");
        message.push_str(help);
    }
    lsp::Diagnostic {
        range: range(&doc.index, text, &d.span),
        severity: Some(match d.severity {
            Severity::Error => DiagnosticSeverity::ERROR,
            Severity::Warning => DiagnosticSeverity::WARNING,
            Severity::Info => DiagnosticSeverity::INFORMATION,
        }),
        code: Some(NumberOrString::String(d.code.id.into())),
        source: Some("walls".into()),
        message,
        related_information: (!d.labels.is_empty()).then(|| {
            d.labels
                .iter()
                .map(|l| DiagnosticRelatedInformation {
                    location: Location::new(uri.clone(), range(&doc.index, text, &l.span)),
                    message: l.message.clone(),
                })
                .collect()
        }),
        ..lsp::Diagnostic::default()
    }
}

/// The keyword's documentation, with the value it has where the cursor is.
pub fn hover(doc: &Document, at: Position) -> Option<Hover> {
    let tree = &doc.parse.tree;
    let text = doc.text();
    let offset = offset(&doc.index, text, at);
    // A position past the end of its line (or of the text) points at nothing.
    if position(&doc.index, text, offset) != at {
        return None;
    }
    let stmt = tree.statement_containing(offset)?;
    let keyword = tree.keyword(&stmt)?;
    let span = tree.statement_span(&stmt);
    if offset > span.end {
        return None;
    }
    let mut value = keyword.markdown();
    if let Some(note) = effective_value(doc, &stmt, keyword) {
        value.push('\n');
        value.push_str(&note);
    }
    Some(Hover {
        contents: HoverContents::Markup(MarkupContent {
            kind: MarkupKind::Markdown,
            value,
        }),
        range: Some(range(&doc.index, text, &span)),
    })
}

/// For a property in a wall block: the wall's effective value and where it came from;
/// for one in a `defaults` block, what that means. Nothing for statements outside blocks.
fn effective_value(doc: &Document, stmt: &Statement, keyword: Keyword) -> Option<String> {
    let tree = &doc.parse.tree;
    let block = tree.statements().find(|(s, _)| *s == stmt)?.1?;
    if keyword.role() != Role::Property {
        return None;
    }
    if block.kind == BlockKind::Defaults {
        return Some("Sets the default for the walls created after this block.".into());
    }
    let index = tree
        .items()
        .iter()
        .filter_map(|i| match i {
            Item::Block(b) if b.kind == BlockKind::Wall => Some(b),
            _ => None,
        })
        .position(|b| std::ptr::eq(b, block))?;
    let wall = doc.analysis.scene.walls.get(index)?;
    let setting = wall.setting(keyword)?;
    let values = tree.values(stmt);
    let here = match (values.first(), values.last()) {
        (Some(&a), Some(&b)) => Some(tree.span(a).start..tree.span(b).end),
        _ => None,
    };
    let line = |at: usize| doc.index.line_of(at) + 1;
    let from = match &setting.source {
        Source::Builtin => "the built-in default".to_string(),
        Source::Set {
            derived_from: Some(k),
            values,
            ..
        } => format!(
            "the `{}` on line {} (2/7 of it)",
            k.name(),
            line(values.range().start)
        ),
        Source::Set { values, .. } if Some(values.range()) == here => "this token".to_string(),
        Source::Set {
            place: Place::Wall,
            values,
            ..
        } => format!(
            "the `{}` on line {}, which wins",
            keyword.name(),
            line(values.range().start)
        ),
        Source::Set {
            place: Place::Defaults,
            values,
            ..
        } => format!("`defaults` on line {}", line(values.range().start)),
    };
    let shown = match setting.value {
        Value::Number(x) => format!("{x}"),
        Value::Integer(i) => format!("{i}"),
        Value::Vector(v) => format!("{} {} {}", v.x, v.y, v.z),
        Value::Type(t) => t.name().to_string(),
    };
    // What happened to the number as written: unit scaling, or a percentage.
    let written = match (&setting.source, setting.value) {
        (
            Source::Set {
                values,
                derived_from: None,
                ..
            },
            Value::Number(x),
        ) if Some(values.range()) == here => doc.text()[values.range()]
            .parse::<f64>()
            .ok()
            .filter(|&raw| raw != x),
        _ => None,
    };
    let note = match written {
        Some(raw) if keyword == Keyword::Transparency => {
            format!(" Written as {raw}, a percentage.")
        }
        Some(raw) => format!(" Written as {raw}, scaled by the units in force."),
        None => String::new(),
    };
    Some(format!(
        "In wall {}: **{shown}** (pkdgrav units), from {from}.{note}",
        wall.index
    ))
}

/// The formatting options for a document: from the `.walls-fmt.toml` above its file, as
/// `walls-fmt` would find them (defaults for other URIs or a broken configuration).
fn format_options(uri: &Uri) -> FormatOptions {
    let path = uri
        .as_str()
        .strip_prefix("file://")
        .map(|p| std::path::PathBuf::from(percent_decode(p)));
    path.as_deref()
        .and_then(std::path::Path::parent)
        .and_then(|dir| walls_format::discover(dir).ok())
        .map(|(options, _)| options)
        .unwrap_or_default()
}

/// `%xx` escapes of a URI path decoded (UTF-8 assumed; anything else kept as written).
fn percent_decode(s: &str) -> String {
    let b = s.as_bytes();
    let mut out = Vec::with_capacity(b.len());
    let mut i = 0;
    while i < b.len() {
        let hex = |c: u8| (c as char).to_digit(16);
        match (
            b[i],
            b.get(i + 1).copied().and_then(hex),
            b.get(i + 2).copied().and_then(hex),
        ) {
            (b'%', Some(h), Some(l)) => {
                out.push((h * 16 + l) as u8);
                i += 3;
            }
            (c, _, _) => {
                out.push(c);
                i += 1;
            }
        }
    }
    String::from_utf8(out).unwrap_or_else(|_| s.to_string())
}

/// The edit that formats the whole document, if it changes anything.
pub fn format(uri: &Uri, doc: &Document) -> Option<Vec<TextEdit>> {
    let formatted = walls_format::format(&doc.parse, &format_options(uri)).ok()?;
    (formatted.text != doc.text()).then(|| vec![whole(doc, formatted.text)])
}

/// The edit that formats the items a range touches.
pub fn format_range(uri: &Uri, doc: &Document, r: Range) -> Option<Vec<TextEdit>> {
    let text = doc.text();
    let span = offset(&doc.index, text, r.start)..offset(&doc.index, text, r.end);
    let edit = walls_format::format_range(&doc.parse, span, &format_options(uri)).ok()??;
    Some(vec![TextEdit::new(
        range(&doc.index, text, &edit.span),
        edit.replacement,
    )])
}

fn whole(doc: &Document, new_text: String) -> TextEdit {
    TextEdit::new(
        range(&doc.index, doc.text(), &(0..doc.text().len())),
        new_text,
    )
}

/// A quick fix for every diagnostic in `r` that has one, and "fix all safe problems".
pub fn code_actions(uri: &Uri, doc: &Document, r: Range) -> Vec<CodeActionOrCommand> {
    let text = doc.text();
    let span = offset(&doc.index, text, r.start)..offset(&doc.index, text, r.end);
    let mut actions = Vec::new();
    for d in &doc.diagnostics {
        let Some(fix) = &d.fix else { continue };
        if d.span.end < span.start || span.end < d.span.start {
            continue;
        }
        let edits = fix
            .edits
            .iter()
            .map(|e| TextEdit::new(range(&doc.index, text, &e.span), e.replacement.clone()))
            .collect();
        actions.push(CodeActionOrCommand::CodeAction(CodeAction {
            title: format!("{} ({})", fix.message, d.code.id),
            kind: Some(CodeActionKind::QUICKFIX),
            diagnostics: Some(vec![to_lsp(uri, doc, d)]),
            edit: Some(workspace_edit(uri, edits)),
            is_preferred: Some(fix.applicability == Applicability::Safe),
            ..CodeAction::default()
        }));
    }
    let safe = doc
        .diagnostics
        .iter()
        .filter(|d| {
            d.fix
                .as_ref()
                .is_some_and(|f| f.applicability == Applicability::Safe)
        })
        .count();
    if safe > 0 {
        let fixed = apply_fixes(text, &doc.diagnostics, Applicability::Safe);
        actions.push(CodeActionOrCommand::CodeAction(CodeAction {
            title: format!("Fix all safe problems ({safe})"),
            kind: Some(CodeActionKind::SOURCE_FIX_ALL),
            edit: Some(workspace_edit(uri, vec![whole(doc, fixed)])),
            ..CodeAction::default()
        }));
    }
    actions
}

fn workspace_edit(uri: &Uri, edits: Vec<TextEdit>) -> WorkspaceEdit {
    WorkspaceEdit {
        changes: Some(HashMap::from([(uri.clone(), edits)])),
        ..WorkspaceEdit::default()
    }
}

/// The outline: each wall ("wall 3: disk") and defaults block with its statements, and
/// the statements outside blocks.
#[allow(deprecated)] // `DocumentSymbol::deprecated` must still be given.
pub fn symbols(doc: &Document) -> Vec<DocumentSymbol> {
    let tree = &doc.parse.tree;
    let text = doc.text();
    let symbol =
        |name: String, detail: Option<String>, kind, stmt: &walls_syntax::Statement, children| {
            let head = tree.span(tree.head(stmt));
            DocumentSymbol {
                name,
                detail,
                kind,
                tags: None,
                deprecated: None,
                range: range(&doc.index, text, &tree.statement_span(stmt)),
                selection_range: range(&doc.index, text, &head),
                children,
            }
        };
    let values = |stmt: &walls_syntax::Statement| {
        let v: Vec<&str> = tree
            .values(stmt)
            .iter()
            .map(|&t| tree.token_text(t))
            .collect();
        (!v.is_empty()).then(|| v.join(" "))
    };
    let mut walls = doc.analysis.scene.walls.iter();
    let mut out = Vec::new();
    for item in tree.items() {
        match item {
            Item::Block(b) => {
                let children: Vec<DocumentSymbol> = tree
                    .body(b)
                    .iter()
                    .filter_map(|s| {
                        let k = tree.keyword(s)?;
                        Some(symbol(
                            k.name().into(),
                            values(s),
                            SymbolKind::PROPERTY,
                            s,
                            None,
                        ))
                    })
                    .collect();
                let (name, kind) = match b.kind {
                    BlockKind::Wall => {
                        let w = walls.next();
                        let name = w.map_or("wall".into(), |w| {
                            format!("wall {}: {}", w.index, w.wall_type().name())
                        });
                        (name, SymbolKind::OBJECT)
                    }
                    BlockKind::Defaults => ("defaults".into(), SymbolKind::NAMESPACE),
                };
                let mut s = symbol(name, None, kind, &b.head, Some(children));
                if let Some(last) = tree.body(b).last() {
                    let end = tree.statement_span(last).end;
                    s.range = range(&doc.index, text, &(tree.statement_span(&b.head).start..end));
                }
                out.push(s);
            }
            Item::Statement(s) => {
                if let Some(k) = tree.keyword(s) {
                    out.push(symbol(
                        k.name().into(),
                        values(s),
                        SymbolKind::CONSTANT,
                        s,
                        None,
                    ));
                }
            }
            Item::Stray(_) => {}
        }
    }
    out
}

/// A folding range for every block that spans several lines.
pub fn folding(doc: &Document) -> Vec<FoldingRange> {
    let tree = &doc.parse.tree;
    tree.items()
        .iter()
        .filter_map(|item| {
            let Item::Block(b) = item else { return None };
            let last = tree.body(b).last()?;
            let start = doc.index.line_of(tree.statement_span(&b.head).start);
            let end = doc.index.line_of(tree.statement_span(last).end);
            (end > start).then(|| FoldingRange {
                start_line: start as u32,
                end_line: end as u32,
                kind: Some(FoldingRangeKind::Region),
                ..FoldingRange::default()
            })
        })
        .collect()
}
