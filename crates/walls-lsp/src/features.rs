//! The LSP features: each converts LSP positions to byte offsets, asks `walls-ide`, and
//! maps its plain-data answer into LSP values (UTF-16 positions).
//!
//! Every answer has a bound, whatever the document: a list answer has at most the
//! entries of its `MAX_…` constant below (tower-lsp turns each answer into a
//! `serde_json::Value` before writing it, some 0.2 to 7 KB an entry, so that an outline
//! of 100,000 walls with their statements took 2.9 GB), and the answers that carry text
//! (formatting, "fix all") carry one edit of about the document's size. The bounds and
//! what each costs are in docs/editors.md ("Limits").

use crate::document::{Document, ParDocument};
use crate::position::{offset, position, range};
use std::collections::HashMap;
use tower_lsp_server::ls_types::{self as lsp, *};
use walls_diagnostics::Severity;
use walls_format::FormatOptions;
use walls_ide::{ActionKind, Analysis, CompletionKind, HighlightKind, Lines, SymbolKind as Kind};

/// The most entries of an outline: `walls-ide` shapes it to fit (the blocks without their
/// statements, else runs of blocks).
pub const MAX_SYMBOLS: usize = 2_000;
/// The most diagnostics published for a document, errors first; one more says how many
/// are left out.
pub const MAX_DIAGNOSTICS: usize = 1_000;
/// The most semantic tokens of one answer: past them, the editor's grammar colours.
pub const MAX_TOKENS: usize = 50_000;
/// The most folding ranges of one answer (VS Code's own default limit).
pub const MAX_FOLDS: usize = 5_000;
/// The most inlay hints of one answer.
pub const MAX_HINTS: usize = 1_000;
/// The most quick fixes of one answer (with "fix all", which is one edit).
pub const MAX_QUICK_FIXES: usize = 100;

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
/// unusable settings file, if any; then at most [`MAX_DIAGNOSTICS`] of the check's, and
/// one saying how many more there are.
pub fn diagnostics(uri: &Uri, doc: &Document) -> Vec<lsp::Diagnostic> {
    let a = &doc.analysis;
    shown_diagnostics(
        uri,
        (&a.lines, a.text()),
        a.diagnostics(),
        doc.settings_problem.as_ref(),
    )
}

/// [`diagnostics`] of a `.par` document.
pub fn par_diagnostics(uri: &Uri, doc: &ParDocument) -> Vec<lsp::Diagnostic> {
    shown_diagnostics(
        uri,
        (&doc.lines, doc.text()),
        &doc.checked.diagnostics,
        doc.settings_problem.as_ref(),
    )
}

/// The diagnostics `all` of the text `(lines, text)` as the client shows them, after
/// `settings_problem`.
fn shown_diagnostics(
    uri: &Uri,
    (lines, text): (&Lines, &str),
    all: &[walls_diagnostics::Diagnostic],
    settings_problem: Option<&lsp::Diagnostic>,
) -> Vec<lsp::Diagnostic> {
    let shown = published(all, MAX_DIAGNOSTICS);
    let mut out: Vec<lsp::Diagnostic> = settings_problem.into_iter().cloned().collect();
    out.extend(shown.iter().map(|&i| to_lsp(uri, (lines, text), &all[i])));
    let left_out = all.len() - shown.len();
    if left_out > 0 {
        // At the first one left out, where the editor's list stops being whole.
        let first = (0..all.len())
            .find(|i| shown.binary_search(i).is_err())
            .map_or(0..0, |i| all[i].span.clone());
        out.push(lsp::Diagnostic {
            range: range(lines, text, &first),
            severity: Some(DiagnosticSeverity::INFORMATION),
            source: Some("walls".into()),
            message: format!(
                "{left_out} more diagnostics are not shown: the editor gets {MAX_DIAGNOSTICS} of \
                 this file's {}, errors first; `walls-lint` lists them all",
                all.len()
            ),
            ..lsp::Diagnostic::default()
        });
    }
    out
}

/// The indices of the diagnostics of `all` (in order of position) that are published:
/// all of them when they are at most `max`, else the first errors up to `max`, then the
/// first warnings, then the first infos, each kept in order of position.
fn published(all: &[walls_diagnostics::Diagnostic], max: usize) -> Vec<usize> {
    if all.len() <= max {
        return (0..all.len()).collect();
    }
    let rank = |s: Severity| match s {
        Severity::Error => 0,
        Severity::Warning => 1,
        Severity::Info => 2,
    };
    let mut count = [0usize; 3];
    for d in all {
        count[rank(d.severity)] += 1;
    }
    let mut room = max;
    let quota = count.map(|c| {
        let q = c.min(room);
        room -= q;
        q
    });
    let mut taken = [0usize; 3];
    (0..all.len())
        .filter(|&i| {
            let r = rank(all[i].severity);
            taken[r] += 1;
            taken[r] <= quota[r]
        })
        .collect()
}

fn to_lsp(
    uri: &Uri,
    (lines, text): (&Lines, &str),
    d: &walls_diagnostics::Diagnostic,
) -> lsp::Diagnostic {
    let mut message = d.message.clone();
    if let Some(help) = &d.help {
        message.push_str("\nhelp: ");
        message.push_str(help);
    }
    lsp::Diagnostic {
        range: range(lines, text, &d.span),
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
                    location: Location::new(uri.clone(), range(lines, text, &l.span)),
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

/// A quick fix for each diagnostic in `r` that has one (at most [`MAX_QUICK_FIXES`]),
/// and "fix all safe problems".
pub fn code_actions(uri: &Uri, doc: &Document, r: Range) -> Vec<CodeActionOrCommand> {
    let a = &doc.analysis;
    let actions = walls_ide::code_actions(&a.checked, byte_range(a, r), MAX_QUICK_FIXES, &|text| {
        doc.check.checked(text)
    });
    to_lsp_actions(uri, (&a.lines, a.text()), a.diagnostics(), actions)
}

/// [`code_actions`] of a `.par` document.
pub fn par_code_actions(uri: &Uri, doc: &ParDocument, r: Range) -> Vec<CodeActionOrCommand> {
    let (lines, text) = (&doc.lines, doc.text());
    let bytes = offset(lines, text, r.start)..offset(lines, text, r.end);
    let actions = walls_ide::code_actions(&doc.checked, bytes, MAX_QUICK_FIXES, &|text| {
        doc.check.checked_par(text)
    });
    to_lsp_actions(uri, (lines, text), &doc.checked.diagnostics, actions)
}

/// `actions` on the text `(lines, text)` whose diagnostics are `diagnostics`, as LSP's.
fn to_lsp_actions(
    uri: &Uri,
    (lines, text): (&Lines, &str),
    diagnostics: &[walls_diagnostics::Diagnostic],
    actions: Vec<walls_ide::Action>,
) -> Vec<CodeActionOrCommand> {
    actions
        .into_iter()
        .map(|action| {
            let edits = action
                .edits
                .into_iter()
                .map(|e| TextEdit::new(range(lines, text, &e.span), e.replacement))
                .collect();
            let edit = Some(workspace_edit(uri, edits));
            CodeActionOrCommand::CodeAction(match action.kind {
                ActionKind::QuickFix {
                    diagnostic,
                    preferred,
                } => CodeAction {
                    title: action.title,
                    kind: Some(CodeActionKind::QUICKFIX),
                    diagnostics: Some(vec![to_lsp(uri, (lines, text), &diagnostics[diagnostic])]),
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
/// the statements outside blocks, in at most [`MAX_SYMBOLS`] entries (walls-ide's
/// `symbols` says how a longer outline is shaped).
pub fn symbols(doc: &Document) -> Vec<DocumentSymbol> {
    walls_ide::symbols(&doc.analysis, MAX_SYMBOLS)
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
        Kind::Group => (SymbolKind::ARRAY, false),
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

/// A folding range for every block that spans several lines (the first
/// [`MAX_FOLDS`]).
pub fn folding(doc: &Document) -> Vec<FoldingRange> {
    let a = &doc.analysis;
    walls_ide::folding(a)
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
        .take(MAX_FOLDS)
        .collect()
}

/// Completions at a position: type names after `type`, nothing in a comment, otherwise
/// keywords, those the wall's type reads first, each a snippet with its default values.
pub fn completion(doc: &Document, at: Position) -> Vec<CompletionItem> {
    let a = &doc.analysis;
    walls_ide::completion(a, offset(&a.lines, a.text(), at))
        .into_iter()
        .map(completion_item)
        .collect()
}

/// A completion as LSP's.
fn completion_item(item: walls_ide::CompletionItem) -> CompletionItem {
    CompletionItem {
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
    }
}

/// The `.par` key's documentation where the cursor is ([`walls_ide::par::par_hover`]).
pub fn par_hover(doc: &ParDocument, at: Position) -> Option<Hover> {
    let (lines, text) = (&doc.lines, doc.text());
    let offset = offset(lines, text, at);
    if position(lines, text, offset) != at {
        return None;
    }
    let hover = walls_ide::par::par_hover(text, offset, doc.check.build())?;
    Some(Hover {
        contents: HoverContents::Markup(MarkupContent {
            kind: MarkupKind::Markdown,
            value: hover.markdown,
        }),
        range: Some(range(lines, text, &hover.range)),
    })
}

/// The `.par` keys the build registers, for the word being typed
/// ([`walls_ide::par::par_completion`]).
pub fn par_completion(doc: &ParDocument, at: Position) -> Vec<CompletionItem> {
    let (lines, text) = (&doc.lines, doc.text());
    walls_ide::par::par_completion(text, offset(lines, text, at), doc.check.build())
        .into_iter()
        .map(completion_item)
        .collect()
}

/// Semantic tokens of the whole document, or of the lines of `only`: the first
/// [`MAX_TOKENS`] of them.
pub fn semantic_tokens(doc: &Document, only: Option<Range>) -> Vec<SemanticToken> {
    let a = &doc.analysis;
    let text = a.text();
    let (first, last) = only.map_or((0, u32::MAX), |r| (r.start.line, r.end.line));
    let line_start = |line: u32| a.lines.line_start(line as usize).unwrap_or(usize::MAX);
    let bytes = line_start(first)..line_start(last.saturating_add(1));
    let mut out = Vec::new();
    let (mut prev_line, mut prev_start) = (0, 0);
    for token in walls_ide::semantic_tokens(a, bytes).take(MAX_TOKENS) {
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
/// `k_t` a `k_n` sets; only those inside `r`, the first [`MAX_HINTS`].
pub fn inlay_hints(doc: &Document, r: Range) -> Vec<InlayHint> {
    let a = &doc.analysis;
    walls_ide::inlay_hints(a, byte_range(a, r), MAX_HINTS)
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
