//! Suppression comments: `# walls-lint: ignore C201 M003` and
//! `# walls-lint: ignore-file C201`, honoured by the one check of a file.
//!
//! A comment whose text, after its `#` or `!` and any spaces, starts with `walls-lint:`
//! is a directive. `ignore CODE…` silences the listed codes' diagnostics that start on
//! the comment's line; a comment standing alone on its line applies instead to the next
//! line that has tokens (comments and blank lines between are skipped). `ignore-file
//! CODE…` silences them in the whole file. Codes are ids (`C201`), separated by spaces or
//! commas; a `#` after them starts a free reason. Errors are never silenced.
//!
//! The directives are checked too: an unknown code is `L001`, a directive that is not
//! understood or names no code is `L002`, a code that silences nothing is `L003` (with a
//! safe fix that removes it, or the whole comment when nothing else in it is used), and a
//! code that would silence an error is `L004`. `L` diagnostics are never silenced by
//! comments (the settings' `ignore` can turn their warnings off).

use std::ops::Range;
use walls_diagnostics::{Applicability, Code, Diagnostic, Edit, Severity};
use walls_syntax::{SyntaxTree, TokenKind};

/// What starts a directive, after the comment's `#` or `!` and spaces.
const PREFIX: &str = "walls-lint:";

/// A code in a suppression is not a diagnostic code.
pub static UNKNOWN_CODE: Code = Code {
    id: "L001",
    name: "unknown-suppressed-code",
    summary: "a suppression comment names a code that does not exist",
    explanation: "A `# walls-lint: ignore` comment lists diagnostic ids such as `C201`; an \
id that no diagnostic has silences nothing, and usually is a typo. `walls-lint --explain` \
and docs/diagnostics.md list every code.

Bad:
```walls
wall type plane
  radius 2  # walls-lint: ignore C299
```

Good:
```walls
wall type plane
  radius 2  # walls-lint: ignore C201
```
",
};

/// A suppression comment that is not understood, or names no code.
pub static MALFORMED_SUPPRESSION: Code = Code {
    id: "L002",
    name: "malformed-suppression",
    summary: "a suppression comment is not understood, or names no code",
    explanation: "After `walls-lint:` a comment says `ignore` (this line, or the next line \
with tokens when the comment stands alone) or `ignore-file` (the whole file), then the \
codes it silences: `# walls-lint: ignore C201 M003`. A comment that says something else \
silences nothing. A bare `ignore` without codes is refused: a blanket suppression would \
also hide every later finding on that line, including the ones nobody has seen yet.

Bad:
```walls
wall type plane
  radius 2  # walls-lint: ignore
```

Good:
```walls
wall type plane
  radius 2  # walls-lint: ignore C201
```
",
};

/// A code in a suppression silences nothing.
pub static UNUSED_SUPPRESSION: Code = Code {
    id: "L003",
    name: "unused-suppression",
    summary: "a suppression comment silences nothing",
    explanation: "The code a `# walls-lint: ignore` comment names is not reported where the \
comment applies (on its line, the next line with tokens, or anywhere in the file for \
`ignore-file`), so the comment only hides a future finding nobody has seen. This happens \
when the mistake was corrected and the comment stayed. The fix (safe) removes the code, \
or the whole comment when it silences nothing else.

Bad:
```walls
wall type disk
  radius 2  # walls-lint: ignore C201
```

Good:
```walls
wall type disk
  radius 2
```
",
};

/// A suppression that would silence an error.
pub static ERROR_NOT_SILENCED: Code = Code {
    id: "L004",
    name: "error-not-silenced",
    summary: "a suppression comment tries to silence an error",
    explanation: "Errors are what pkdgrav rejects or misreads, so no comment or setting \
hides them: the error is still reported, and this warning points at the code in the \
comment. Correct the file instead.

Bad:
```walls
wall type plane
  origin 0 0  # walls-lint: ignore S103
```

Good:
```walls
wall type plane
  origin 0 0 0
```
",
};

/// The suppression codes, in code order.
pub static ALL: &[&Code] = &[
    &UNKNOWN_CODE,
    &MALFORMED_SUPPRESSION,
    &UNUSED_SUPPRESSION,
    &ERROR_NOT_SILENCED,
];

/// One directive of the file.
struct Directive {
    /// The comment's byte range.
    comment: Range<usize>,
    /// Where the suppressed diagnostics start: a line (inclusive of its end), or the
    /// whole file.
    scope: Range<usize>,
    /// The codes named, known or not.
    codes: Vec<Entry>,
    /// The whole comment may be removed (it stands alone on its line, or trails a
    /// statement): the range to delete to remove it cleanly.
    removal: Range<usize>,
}

/// One code of a directive and what it did.
struct Entry {
    /// The code's word in the comment.
    span: Range<usize>,
    /// The code, if it is one.
    code: Option<&'static Code>,
    /// It silenced at least one warning or info.
    used: bool,
    /// The errors it would have silenced (the first one's span is shown).
    errors: Vec<Range<usize>>,
}

/// Applies the suppression comments of `tree` to `diagnostics` (sorted by position):
/// removes the silenced ones and adds the `L` diagnostics about the comments, keeping the
/// order by position.
pub(crate) fn apply(tree: &SyntaxTree, diagnostics: &mut Vec<Diagnostic>) {
    let text = tree.text();
    // Almost every file has no directive: one fast search decides.
    if !text.contains(PREFIX) {
        return;
    }
    let mut found = Vec::new();
    let mut directives = Vec::new();
    let kinds = tree.tokens().kinds();
    for (i, &kind) in kinds.iter().enumerate() {
        if kind == TokenKind::Comment
            && let Some(d) = directive(tree, i, &mut found)
        {
            directives.push(d);
        }
    }
    let mut silenced = vec![false; diagnostics.len()];
    for d in &mut directives {
        let first = diagnostics.partition_point(|x| x.span.start < d.scope.start);
        let last = diagnostics.partition_point(|x| x.span.start <= d.scope.end);
        for (i, diagnostic) in diagnostics.iter().enumerate().take(last).skip(first) {
            for entry in &mut d.codes {
                // The `L` diagnostics are made after this: comments cannot silence them.
                if !entry.code.is_some_and(|c| std::ptr::eq(c, diagnostic.code)) {
                    continue;
                }
                if diagnostic.severity == Severity::Error {
                    entry.errors.push(diagnostic.span.clone());
                } else {
                    entry.used = true;
                    silenced[i] = true;
                }
            }
        }
    }
    let mut kept: Vec<Diagnostic> = std::mem::take(diagnostics)
        .into_iter()
        .zip(silenced)
        .filter_map(|(d, s)| (!s).then_some(d))
        .collect();
    for d in &directives {
        report(d, &mut found);
    }
    kept.extend(found);
    kept.sort_by_key(|d| (d.span.start, d.span.end));
    *diagnostics = kept;
}

/// The directive in comment token `i`, if it is one; malformed ones are reported in
/// `found` and give `None`.
fn directive(tree: &SyntaxTree, i: usize, found: &mut Vec<Diagnostic>) -> Option<Directive> {
    let text = tree.text();
    let comment = span_of(tree, i);
    let body = &text[comment.clone()];
    let after_mark = &body[1..];
    let rest = after_mark.trim_start();
    let rest = rest.strip_prefix(PREFIX)?;
    let at = comment.end - rest.len();
    let words = words(&text[at..comment.end], at);
    let Some((verb, verb_span)) = words.first().cloned() else {
        found.push(malformed(
            comment.clone(),
            "`walls-lint:` is followed by nothing: write `ignore` or `ignore-file` and the codes to silence",
        ));
        return None;
    };
    let file_wide = match verb {
        "ignore" => false,
        "ignore-file" => true,
        other => {
            found.push(malformed(
                verb_span,
                format!("`{other}` is not a directive: write `ignore` or `ignore-file` and the codes to silence"),
            ));
            return None;
        }
    };
    let mut codes = Vec::new();
    for (word, span) in words.into_iter().skip(1) {
        if word.starts_with('#') {
            break;
        }
        match crate::find_code(word) {
            Some(code) if code.id == word => codes.push(Entry {
                span,
                code: Some(code),
                used: false,
                errors: Vec::new(),
            }),
            Some(code) => {
                found.push(
                    malformed(
                        span,
                        format!(
                            "`{word}` is not a code's id: suppressions name ids, such as `{}`",
                            code.id
                        ),
                    )
                    .with_help(format!("`{}` is the id of `{}`", code.id, code.name)),
                );
                return None;
            }
            None if looks_like_code(word) => {
                found.push(
                    Diagnostic::warning(
                        &UNKNOWN_CODE,
                        span.clone(),
                        format!("`{word}` is not a diagnostic code"),
                    )
                    .with_help(
                        "`walls-lint --explain CODE` and docs/diagnostics.md list the codes",
                    ),
                );
                codes.push(Entry {
                    span,
                    code: None,
                    used: false,
                    errors: Vec::new(),
                });
            }
            None => {
                found.push(malformed(
                    span,
                    format!("`{word}` is not a diagnostic code: list codes such as `C201`, then `#` before a reason"),
                ));
                return None;
            }
        }
    }
    if codes.is_empty() {
        found.push(malformed(
            comment,
            format!(
                "`{verb}` names no code: a blanket suppression would hide every finding; list the codes to silence"
            ),
        ));
        return None;
    }
    let kinds = tree.tokens().kinds();
    let line = line_of(text, comment.start);
    let trailing = kinds[..i]
        .iter()
        .rev()
        .take_while(|&&k| k != TokenKind::Newline)
        .any(|k| !k.is_trivia());
    let scope = if file_wide {
        0..text.len()
    } else if trailing {
        line.clone()
    } else {
        match (i + 1..kinds.len()).find(|&j| !kinds[j].is_trivia()) {
            Some(j) => line_of(text, span_of(tree, j).start),
            // Nothing follows: it silences nothing (and is reported as unused).
            None => text.len() + 1..text.len() + 1,
        }
    };
    let removal = if trailing {
        let start = kinds[..i]
            .iter()
            .rposition(|&k| k != TokenKind::Whitespace)
            .map_or(0, |j| span_of(tree, j).end);
        start..comment.end
    } else {
        line_removal(text, line)
    };
    Some(Directive {
        comment,
        scope,
        codes,
        removal,
    })
}

/// The `L` diagnostics of one directive's codes: unused ones (with their fix) and
/// attempts to silence an error.
fn report(d: &Directive, found: &mut Vec<Diagnostic>) {
    let unused = |e: &Entry| e.code.is_some() && !e.used && e.errors.is_empty();
    let all_unused = d.codes.iter().all(unused);
    for (k, entry) in d.codes.iter().enumerate() {
        let Some(code) = entry.code else { continue };
        if let Some(error) = entry.errors.first() {
            found.push(
                Diagnostic::warning(
                    &ERROR_NOT_SILENCED,
                    entry.span.clone(),
                    format!(
                        "`{}` is an error here, and errors cannot be silenced",
                        code.id
                    ),
                )
                .with_label(error.clone(), "this error is still reported")
                .with_help("correct the file: pkdgrav rejects or misreads what an error reports"),
            );
        } else if unused(entry) {
            let (message, span) = if all_unused {
                ("remove the suppression comment", d.removal.clone())
            } else if k == 0 {
                // The first code: up to the next one, so `ignore C201, M003` keeps `ignore M003`.
                (
                    "remove the unused code",
                    entry.span.start..d.codes[1].span.start,
                )
            } else {
                (
                    "remove the unused code",
                    d.codes[k - 1].span.end..entry.span.end,
                )
            };
            found.push(
                Diagnostic::warning(
                    &UNUSED_SUPPRESSION,
                    entry.span.clone(),
                    format!("`{}` is not reported where this comment applies", code.id),
                )
                .with_label(d.comment.clone(), "the suppression")
                .with_fix(
                    Applicability::Safe,
                    message,
                    vec![Edit {
                        span,
                        replacement: String::new(),
                    }],
                ),
            );
        }
    }
}

/// A warning `L002` at `span`.
fn malformed(span: Range<usize>, message: impl Into<String>) -> Diagnostic {
    Diagnostic::warning(&MALFORMED_SUPPRESSION, span, message)
}

/// Whether `word` has the shape of a code id: capital letters, then digits.
fn looks_like_code(word: &str) -> bool {
    let digits = word.trim_start_matches(|c: char| c.is_ascii_uppercase());
    digits.len() < word.len() && !digits.is_empty() && digits.bytes().all(|b| b.is_ascii_digit())
}

/// The words of `s` (split at spaces and commas) with their byte ranges, `s` starting
/// at byte `offset`.
fn words(s: &str, offset: usize) -> Vec<(&str, Range<usize>)> {
    let mut out = Vec::new();
    let mut start = None;
    for (i, c) in s.char_indices().chain(std::iter::once((s.len(), ' '))) {
        let separator = c.is_whitespace() || c == ',';
        match (start, separator) {
            (None, false) => start = Some(i),
            (Some(b), true) => {
                out.push((&s[b..i], offset + b..offset + i));
                start = None;
            }
            _ => {}
        }
    }
    out
}

/// Byte range of token `i`.
fn span_of(tree: &SyntaxTree, i: usize) -> Range<usize> {
    tree.span(walls_syntax::TokenId(i as u32))
}

/// The line holding byte `offset`: from its first byte to its `\n` (or the end of the
/// text), both included, so that an empty span at the line's end is on it.
fn line_of(text: &str, offset: usize) -> Range<usize> {
    let start = text[..offset].rfind('\n').map_or(0, |n| n + 1);
    let end = text[offset..].find('\n').map_or(text.len(), |n| offset + n);
    start..end
}

/// What to delete to remove the comment line `line` (as [`line_of`] gives it) and leave
/// a well-formatted file: the line with its newline, and a blank line after it when one
/// is before it too (or it is the first line), so that no two blank lines meet.
fn line_removal(text: &str, line: Range<usize>) -> Range<usize> {
    let blank = |r: Range<usize>| text[r].trim().is_empty();
    let mut range = line.start..(line.end + 1).min(text.len());
    let blank_before = line.start == 0 || blank(line_of(text, line.start - 1));
    if blank_before {
        if range.end < text.len() {
            let next = line_of(text, range.end);
            if blank(next.clone()) {
                range.end = (next.end + 1).min(text.len());
            }
        } else if line.start > 0 {
            // The last line, after a blank one: the blank line goes too.
            range.start = line_of(text, line.start - 1).start;
        }
    }
    range
}

#[cfg(test)]
mod tests {
    use crate::check_text;
    use walls_diagnostics::{Applicability, apply_fixes};
    use walls_model::Options;

    /// `code@line:message` of every diagnostic of `text`.
    fn report(text: &str) -> Vec<String> {
        let checked = check_text(text, &Options::default());
        checked
            .diagnostics
            .iter()
            .map(|d| {
                let line = text[..d.span.start].matches('\n').count() + 1;
                format!("{}@{line}: {}", d.code.id, d.message)
            })
            .collect()
    }

    #[test]
    fn a_trailing_comment_silences_its_line_and_a_lone_one_the_next_line_with_tokens() {
        let text = "wall type plane\n  radius 2  # walls-lint: ignore C201\n\
                    wall type plane\n  # walls-lint: ignore C201\n\n  # why\n  radius 2\n\
                    wall type plane\n  radius 2\n";
        assert_eq!(report(text), ["C201@9: a plane wall ignores `radius`"]);
    }

    #[test]
    fn ignore_file_silences_everywhere_and_errors_are_never_silenced() {
        let text =
            "# walls-lint: ignore-file C201 S103\nwall type plane\n  radius 2\n  origin 0 0\n";
        assert_eq!(
            report(text),
            [
                "L004@1: `S103` is an error here, and errors cannot be silenced",
                "S103@4: `origin` takes 3 numbers but has 2: expected the 3rd number here, found the end of the file",
            ]
        );
    }

    #[test]
    fn the_comments_themselves_are_checked() {
        let text = "wall type plane # walls-lint: ignore\n\
                    wall type plane # walls-lint: silence C201\n\
                    wall type plane # walls-lint: ignore C999 C201\n\
                    wall type plane # walls-lint: ignore unknown-word\n\
                    wall type plane # walls-lint: ignore C201 because\n\
                    wall type plane # walls-lint: ignore C202 # a reason\n";
        assert_eq!(
            report(text),
            [
                "L002@1: `ignore` names no code: a blanket suppression would hide every finding; list the codes to silence",
                "L002@2: `silence` is not a directive: write `ignore` or `ignore-file` and the codes to silence",
                "L001@3: `C999` is not a diagnostic code",
                "L003@3: `C201` is not reported where this comment applies",
                "L002@4: `unknown-word` is not a code's id: suppressions name ids, such as `S101`",
                "L002@5: `because` is not a diagnostic code: list codes such as `C201`, then `#` before a reason",
                "L003@6: `C202` is not reported where this comment applies",
            ]
        );
    }

    /// The text after the safe fixes, which must be what the formatter writes.
    fn fixed(text: &str) -> String {
        let checked = check_text(text, &Options::default());
        let fixed = apply_fixes(text, &checked.diagnostics, Applicability::Safe);
        let parsed = walls_syntax::parse(fixed.as_str());
        let formatted = walls_format::format(&parsed, &Default::default())
            .unwrap()
            .text;
        assert_eq!(fixed, formatted, "the fix of {text:?} is not formatted");
        fixed
    }

    #[test]
    fn unused_codes_and_comments_are_removed_leaving_a_formatted_file() {
        assert_eq!(
            fixed("wall type disk\n  radius 2 # walls-lint: ignore C201\n"),
            "wall type disk\n  radius 2\n"
        );
        assert_eq!(
            fixed("wall type plane\n  radius 2 # walls-lint: ignore C202, C201 M001\n"),
            "wall type plane\n  radius 2 # walls-lint: ignore C201\n"
        );
        assert_eq!(
            fixed("# walls-lint: ignore-file C201\n\nwall type disk\n"),
            "wall type disk\n"
        );
        assert_eq!(
            fixed("wall type disk\n\n# walls-lint: ignore C201\n\nwall type disk\n"),
            "wall type disk\n\nwall type disk\n"
        );
        assert_eq!(
            fixed("wall type disk\n  # walls-lint: ignore C201\n  radius 1\n"),
            "wall type disk\n  radius 1\n"
        );
        assert_eq!(
            fixed("wall type disk\n\n# walls-lint: ignore C201\n"),
            "wall type disk\n"
        );
    }
}
