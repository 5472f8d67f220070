//! The LSP features: each converts LSP positions to byte offsets, asks `walls-ide`, and
//! maps its plain-data answer into LSP values (UTF-16 positions).

use crate::document::Document;
use crate::position::{offset, position, range};
use std::collections::HashMap;
use tower_lsp_server::ls_types::{self as lsp, *};
use walls_diagnostics::Severity;
use walls_format::FormatOptions;
use walls_ide::{ActionKind, Analysis, CompletionKind, HighlightKind, SymbolKind as Kind};

/// The semantic token types, in legend order (`token_type` gives the index).
pub const TOKEN_TYPES: [SemanticTokenType; 5] = [
    SemanticTokenType::KEYWORD,
    SemanticTokenType::PROPERTY,
    SemanticTokenType::ENUM_MEMBER,
    SemanticTokenType::NUMBER,
    SemanticTokenType::COMMENT,
];

/// A highlight's index in [`TOKEN_TYPES`].
fn token_type(kind: HighlightKind) -> u32 {
    match kind {
        HighlightKind::Keyword => 0,
        HighlightKind::Property => 1,
        HighlightKind::WallType => 2,
        HighlightKind::Number => 3,
        HighlightKind::Comment => 4,
    }
}

/// The LSP range of a byte range of the document.
fn lsp_range(a: &Analysis, span: &std::ops::Range<usize>) -> Range {
    range(&a.lines, a.text(), span)
}

/// The byte range of an LSP range of the document.
fn byte_range(a: &Analysis, r: Range) -> std::ops::Range<usize> {
    offset(&a.lines, a.text(), r.start)..offset(&a.lines, a.text(), r.end)
}

/// The document's diagnostics, as the client shows them: first the one naming an
/// unusable settings file, if any.
pub fn diagnostics(uri: &Uri, doc: &Document) -> Vec<lsp::Diagnostic> {
    let checked = doc.analysis.diagnostics().iter();
    doc.settings_problem
        .iter()
        .cloned()
        .chain(checked.map(|d| to_lsp(uri, &doc.analysis, d)))
        .collect()
}

fn to_lsp(uri: &Uri, a: &Analysis, d: &walls_diagnostics::Diagnostic) -> lsp::Diagnostic {
    let mut message = d.message.clone();
    if let Some(help) = &d.help {
        message.push_str("\nhelp: ");
        message.push_str(help);
    }
    lsp::Diagnostic {
        range: lsp_range(a, &d.span),
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
                    location: Location::new(uri.clone(), lsp_range(a, &l.span)),
                    message: l.message.clone(),
                })
                .collect()
        }),
        ..lsp::Diagnostic::default()
    }
}

/// The keyword's documentation, with the value it has where the cursor is.
pub fn hover(doc: &Document, at: Position) -> Option<Hover> {
    let a = &doc.analysis;
    let offset = offset(&a.lines, a.text(), at);
    // A position past the end of its line (or of the text) points at nothing.
    if position(&a.lines, a.text(), offset) != at {
        return None;
    }
    let hover = walls_ide::hover(a, offset)?;
    Some(Hover {
        contents: HoverContents::Markup(MarkupContent {
            kind: MarkupKind::Markdown,
            value: hover.markdown,
        }),
        range: Some(lsp_range(a, &hover.range)),
    })
}

/// The edit that formats the whole document, if it changes anything.
pub fn format(doc: &Document, options: &FormatOptions) -> Option<Vec<TextEdit>> {
    let formatted = walls_ide::format(&doc.analysis, options)?;
    Some(vec![whole(&doc.analysis, formatted)])
}

/// The edit that formats the items a range touches.
pub fn format_range(doc: &Document, r: Range, options: &FormatOptions) -> Option<Vec<TextEdit>> {
    let a = &doc.analysis;
    let edit = walls_ide::format_range(a, byte_range(a, r), options)?;
    Some(vec![TextEdit::new(
        lsp_range(a, &edit.span),
        edit.replacement,
    )])
}

fn whole(a: &Analysis, new_text: String) -> TextEdit {
    TextEdit::new(lsp_range(a, &(0..a.text().len())), new_text)
}

/// A quick fix for every diagnostic in `r` that has one, and "fix all safe problems".
pub fn code_actions(uri: &Uri, doc: &Document, r: Range) -> Vec<CodeActionOrCommand> {
    let a = &doc.analysis;
    walls_ide::code_actions(a, byte_range(a, r))
        .into_iter()
        .map(|action| {
            let edits = action
                .edits
                .into_iter()
                .map(|e| TextEdit::new(lsp_range(a, &e.span), e.replacement))
                .collect();
            let edit = Some(workspace_edit(uri, edits));
            CodeActionOrCommand::CodeAction(match action.kind {
                ActionKind::QuickFix {
                    diagnostic,
                    preferred,
                } => CodeAction {
                    title: action.title,
                    kind: Some(CodeActionKind::QUICKFIX),
                    diagnostics: Some(vec![to_lsp(uri, a, &a.diagnostics()[diagnostic])]),
                    edit,
                    is_preferred: Some(preferred),
                    ..CodeAction::default()
                },
                ActionKind::FixAll => CodeAction {
                    title: action.title,
                    kind: Some(CodeActionKind::SOURCE_FIX_ALL),
                    edit,
                    ..CodeAction::default()
                },
            })
        })
        .collect()
}

fn workspace_edit(uri: &Uri, edits: Vec<TextEdit>) -> WorkspaceEdit {
    WorkspaceEdit {
        changes: Some(HashMap::from([(uri.clone(), edits)])),
        ..WorkspaceEdit::default()
    }
}

/// The outline: each wall ("wall 3: disk") and defaults block with its statements, and
/// the statements outside blocks.
pub fn symbols(doc: &Document) -> Vec<DocumentSymbol> {
    walls_ide::symbols(&doc.analysis)
        .into_iter()
        .map(|s| to_symbol(&doc.analysis, s))
        .collect()
}

#[allow(deprecated)] // `DocumentSymbol::deprecated` must still be given.
fn to_symbol(a: &Analysis, s: walls_ide::Symbol) -> DocumentSymbol {
    let (kind, block) = match s.kind {
        Kind::Wall => (SymbolKind::OBJECT, true),
        Kind::Defaults => (SymbolKind::NAMESPACE, true),
        Kind::Property => (SymbolKind::PROPERTY, false),
        Kind::Statement => (SymbolKind::CONSTANT, false),
    };
    DocumentSymbol {
        name: s.name,
        detail: s.detail,
        kind,
        tags: None,
        deprecated: None,
        range: lsp_range(a, &s.range),
        selection_range: lsp_range(a, &s.selection_range),
        children: block.then(|| s.children.into_iter().map(|c| to_symbol(a, c)).collect()),
    }
}

/// A folding range for every block that spans several lines.
pub fn folding(doc: &Document) -> Vec<FoldingRange> {
    let a = &doc.analysis;
    walls_ide::folding(a)
        .into_iter()
        .filter_map(|span| {
            let start = a.lines.line_of(span.start);
            let end = a.lines.line_of(span.end);
            (end > start).then(|| FoldingRange {
                start_line: start as u32,
                end_line: end as u32,
                kind: Some(FoldingRangeKind::Region),
                ..FoldingRange::default()
            })
        })
        .collect()
}

/// Completions at a position: type names after `type`, nothing in a comment, otherwise
/// keywords, those the wall's type reads first, each a snippet with its default values.
pub fn completion(doc: &Document, at: Position) -> Vec<CompletionItem> {
    let a = &doc.analysis;
    walls_ide::completion(a, offset(&a.lines, a.text(), at))
        .into_iter()
        .map(|item| CompletionItem {
            label: item.label,
            kind: Some(match item.kind {
                CompletionKind::WallType => CompletionItemKind::ENUM_MEMBER,
                CompletionKind::Property => CompletionItemKind::PROPERTY,
                CompletionKind::Keyword => CompletionItemKind::KEYWORD,
            }),
            detail: Some(item.detail),
            documentation: item.documentation.map(|value| {
                Documentation::MarkupContent(MarkupContent {
                    kind: MarkupKind::Markdown,
                    value,
                })
            }),
            sort_text: item.sort_text,
            insert_text_format: item.snippet.is_some().then_some(InsertTextFormat::SNIPPET),
            insert_text: item.snippet,
            ..CompletionItem::default()
        })
        .collect()
}

/// Semantic tokens of the whole document, or of the lines of `only`.
pub fn semantic_tokens(doc: &Document, only: Option<Range>) -> Vec<SemanticToken> {
    let a = &doc.analysis;
    let text = a.text();
    let (first, last) = only.map_or((0, u32::MAX), |r| (r.start.line, r.end.line));
    let mut out = Vec::new();
    let (mut prev_line, mut prev_start) = (0, 0);
    for token in walls_ide::semantic_tokens(a) {
        let start = position(&a.lines, text, token.range.start);
        if start.line < first || start.line > last {
            continue;
        }
        let length = text[token.range].encode_utf16().count() as u32;
        let delta_start = if start.line == prev_line {
            start.character - prev_start
        } else {
            start.character
        };
        out.push(SemanticToken {
            delta_line: start.line - prev_line,
            delta_start,
            length,
            token_type: token_type(token.kind),
            token_modifiers_bitset: 0,
        });
        (prev_line, prev_start) = (start.line, start.character);
    }
    out
}

/// Hints: what a wall inherits from `defaults`, values the unit tokens scale, and the
/// `k_t` a `k_n` sets; only those inside `r`.
pub fn inlay_hints(doc: &Document, r: Range) -> Vec<InlayHint> {
    let a = &doc.analysis;
    walls_ide::inlay_hints(a, byte_range(a, r))
        .into_iter()
        .map(|h| InlayHint {
            position: position(&a.lines, a.text(), h.offset),
            label: InlayHintLabel::String(h.label),
            kind: None,
            text_edits: None,
            tooltip: None,
            padding_left: Some(true),
            padding_right: None,
            data: None,
        })
        // Positions past a line's end fall on its end as offsets: compare as positions.
        .filter(|h| h.position >= r.start && h.position <= r.end)
        .collect()
}

/// Where the value under the cursor comes from: on a property of a wall, the token that
/// set the wall's effective value (its own, or a `defaults` line); on `wall`, every
/// `defaults` value the wall inherits.
pub fn definition(doc: &Document, uri: &Uri, at: Position) -> Vec<Location> {
    let a = &doc.analysis;
    walls_ide::definition(a, offset(&a.lines, a.text(), at))
        .iter()
        .map(|span| Location::new(uri.clone(), lsp_range(a, span)))
        .collect()
}
