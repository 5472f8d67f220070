//! Syntax diagnostics: pkdgrav's refusals that can be seen from the tokens and the tree.
//!
//! Each mistake gets one diagnostic with the exact span of the offending text: a broken
//! statement is reported once and the values after the mistake are absorbed into it, so
//! nothing cascades. See [`crate::codes`] for the documented codes.

use crate::codes;
use crate::lexer::TokenKind;
use crate::suggest;
use crate::tree::{Item, Statement, SyntaxTree, TokenId};
use std::collections::HashMap;
use std::ops::Range;
use walls_diagnostics::{Applicability, Diagnostic, Edit, MAX_LABELS, terminal};
use walls_keywords::{Keyword, Role, ValueShape};

/// pkdgrav reads lines into a 4096-byte buffer: at most 4095 bytes before the newline.
pub const MAX_LINE_BYTES: usize = 4095;

/// The most control-character warnings (S006) one file gets: the last of them says how
/// many runs follow, so that a file of a million escapes is not a million warnings.
pub const MAX_CONTROL_RUNS: usize = 1000;

/// Finds every syntax mistake in `tree`, sorted by position.
pub(crate) fn validate(tree: &SyntaxTree) -> Vec<Diagnostic> {
    let mut v = Validator {
        tree,
        out: Vec::new(),
        suggestions: HashMap::new(),
    };
    v.file_rules();
    v.items();
    v.out.sort_by_key(|d| (d.span.start, d.span.end));
    v.out
}

struct Validator<'t> {
    tree: &'t SyntaxTree,
    out: Vec<Diagnostic>,
    /// "Did you mean" answers by word: generated files repeat the same mistake.
    suggestions: HashMap<&'t str, Option<&'static str>>,
}

impl<'t> Validator<'t> {
    fn text(&self, id: TokenId) -> &'t str {
        self.tree.token_text(id)
    }

    /// The keyword a word is probably a misspelling of, remembered per word.
    fn keyword_like(&mut self, word: &'t str) -> Option<&'static str> {
        *self
            .suggestions
            .entry(word)
            .or_insert_with(|| suggest::keyword_like(word))
    }

    fn span(&self, id: TokenId) -> Range<usize> {
        self.tree.span(id)
    }

    fn file_rules(&mut self) {
        let text = self.tree.text();
        if !text.is_empty() && !text.ends_with('\n') {
            let end = text.len();
            self.out.push(
                Diagnostic::error(
                    &codes::MISSING_FINAL_NEWLINE,
                    end..end,
                    "the last line does not end with a newline",
                )
                .with_help("pkdgrav aborts on a last line without a newline")
                .with_fix(
                    Applicability::Safe,
                    "add a newline at the end of the file",
                    vec![Edit {
                        span: end..end,
                        replacement: "\n".into(),
                    }],
                ),
            );
        }
        // One pass over the tokens: newlines end lines, glued comments are flagged.
        let mut line_start = 0;
        for (i, t) in self.tree.tokens().iter().enumerate() {
            match t.kind {
                TokenKind::Newline => {
                    let id = TokenId(i as u32);
                    self.line_length(line_start, t.start as usize);
                    line_start = self.span(id).end;
                }
                TokenKind::GluedComment => self.glued_comment(TokenId(i as u32)),
                TokenKind::Whitespace => {
                    let id = TokenId(i as u32);
                    if self.text(id).starts_with('\u{feff}') {
                        self.byte_order_mark(id);
                    }
                }
                _ => {}
            }
        }
        self.line_length(line_start, text.len());
        self.control_characters();
    }

    /// Control characters and bidirectional controls ([`terminal`]): one warning for each
    /// run of them within a token, at most [`MAX_CONTROL_RUNS`].
    fn control_characters(&mut self) {
        let text = self.tree.text();
        let starts = self.tree.tokens().starts();
        let mut from = 0;
        let mut reported = 0;
        while let Some((start, c)) = terminal::find(text, from) {
            let token = starts.partition_point(|&s| s as usize <= start) - 1;
            let token_end = starts.get(token + 1).map_or(text.len(), |&s| s as usize);
            let mut end = start + c.len_utf8();
            while let Some(c) = terminal::at_offset(text, end).filter(|_| end < token_end) {
                end += c.len_utf8();
            }
            let kind = self.tree.tokens().kinds()[token];
            let mut d = control_run(text, start..end, kind);
            from = end;
            reported += 1;
            if reported == MAX_CONTROL_RUNS {
                let more = terminal::runs(&text[from..]).count();
                if more > 0 {
                    d.message.push_str(&format!(
                        " (and at least {more} more runs of such characters after it, not reported one by one)"
                    ));
                }
                self.out.push(d);
                return;
            }
            self.out.push(d);
        }
    }

    /// A byte-order mark, which pkdgrav reads as part of the word after it.
    fn byte_order_mark(&mut self, id: TokenId) {
        let span = self.span(id);
        let message = if span.start == 0 {
            "the file starts with a UTF-8 byte-order mark, which pkdgrav reads as part of the first word"
        } else {
            "a UTF-8 byte-order mark, which pkdgrav reads as part of a word"
        };
        self.out.push(
            Diagnostic::error(&codes::BYTE_ORDER_MARK, span.clone(), message)
                .with_help("save the file as UTF-8 without a byte-order mark")
                .with_fix(
                    Applicability::Safe,
                    "remove the byte-order mark",
                    vec![Edit {
                        span,
                        replacement: String::new(),
                    }],
                ),
        );
    }

    /// pkdgrav's line buffer holds `MAX_LINE_BYTES` before the newline.
    fn line_length(&mut self, start: usize, end: usize) {
        let len = end - start;
        if len <= MAX_LINE_BYTES {
            return;
        }
        let text = self.tree.text();
        let mut cut = start + MAX_LINE_BYTES;
        while !text.is_char_boundary(cut) {
            cut -= 1;
        }
        self.out.push(
            Diagnostic::error(
                &codes::LINE_TOO_LONG,
                cut..end,
                format!("line is {len} bytes long; pkdgrav reads at most {MAX_LINE_BYTES}"),
            )
            .with_help("put each statement on a line of its own"),
        );
    }

    fn glued_comment(&mut self, id: TokenId) {
        let span = self.span(id);
        let word = TokenId(id.0 - 1);
        let glued = format!("{}{}", self.text(word), &self.text(id)[..1]);
        self.out.push(
            Diagnostic::error(
                &codes::GLUED_COMMENT,
                span.clone(),
                format!("comment glued to `{}`", self.text(word)),
            )
            .with_label(self.span(word), "pkdgrav reads this and the comment as one word")
            .with_help(format!(
                "pkdgrav starts a comment only at the beginning of a word, so it reads `{glued}…` as part of the word"
            ))
            .with_fix(
                Applicability::Safe,
                "insert a space before the comment",
                vec![Edit {
                    span: span.start..span.start,
                    replacement: " ".into(),
                }],
            ),
        );
    }

    fn items(&mut self) {
        let tree = self.tree;
        // The general statement that closed the last wall block, if any.
        let mut closed_by: Option<TokenId> = None;
        let mut orphans: Vec<&Statement> = Vec::new();
        for item in tree.items() {
            match item {
                Item::Statement(s)
                    if tree.keyword(s).map(Keyword::role) == Some(Role::Property) =>
                {
                    orphans.push(s);
                    self.statement(s);
                    continue;
                }
                _ => {}
            }
            self.orphans(&orphans, closed_by);
            orphans.clear();
            match item {
                Item::Block(b) => {
                    closed_by = None;
                    self.statement(&b.head);
                    for s in tree.body(b) {
                        self.statement(s);
                    }
                    if b.kind == crate::tree::BlockKind::Wall {
                        closed_by = Some(tree.head(&b.head));
                    }
                }
                Item::Statement(s) => {
                    // A general token: it closes a wall block that was open.
                    if closed_by.is_some_and(|t| tree.kind(t) == TokenKind::Keyword(Keyword::Wall))
                    {
                        closed_by = Some(tree.head(s));
                    }
                    self.statement(s);
                }
                Item::Stray(s) => {
                    self.extras(tree.values(s), None);
                }
            }
        }
        self.orphans(&orphans, closed_by);
    }

    /// One diagnostic for a run of wall tokens outside any block.
    fn orphans(&mut self, run: &[&Statement], closed_by: Option<TokenId>) {
        let Some(first) = run.first() else { return };
        let head = self.tree.head(first);
        let name = self.text(head).to_string();
        let message = match run.len() {
            1 => format!("`{name}` is outside any wall or defaults block"),
            n => format!(
                "`{name}` and {} more wall tokens are outside any wall or defaults block",
                n - 1
            ),
        };
        let mut d = Diagnostic::error(&codes::OUTSIDE_BLOCK, self.span(head), message);
        for s in run[1..].iter().take(MAX_LABELS) {
            let h = self.tree.head(s);
            d = d.with_label(self.span(h), "also outside a block");
        }
        d = match closed_by.filter(|&t| self.tree.kind(t) != TokenKind::Keyword(Keyword::Wall)) {
            Some(closer) => {
                let closer_name = self.text(closer).to_string();
                d.with_label(self.span(closer), format!("`{closer_name}` closed the wall block here"))
                    .with_help(format!(
                        "`lengthunit`, `massunit`, `timeunit` and `time` end a wall block: move `{closer_name}` above the `wall` line, or start a block with `wall` or `defaults`"
                    ))
            }
            None => d.with_help("start a block with `wall` (or `defaults`) before it"),
        };
        self.out.push(d);
    }

    /// Checks a keyword's values against its shape and line.
    fn statement(&mut self, stmt: &Statement) {
        let tree = self.tree;
        let Some(keyword) = tree.keyword(stmt) else {
            return;
        };
        let head = tree.head(stmt);
        let values = tree.values(stmt);
        let shape = keyword.shape();
        let mut filled = 0;
        while filled < values.len() && filled < shape.arity() {
            let tok = values[filled];
            if shape != ValueShape::TypeName && self.misspelled_keyword(tok) {
                break;
            }
            self.slot(keyword, shape, tok, filled);
            filled += 1;
        }
        if filled < shape.arity() {
            let last = values[..filled].last().copied().unwrap_or(head);
            let next = values
                .get(filled)
                .copied()
                .or_else(|| tree.sig.get(stmt.sig.end as usize).copied());
            self.missing(keyword, head, last, next, filled);
        }
        self.same_line(keyword, head, &values[..filled]);
        self.extras(&values[filled..], Some((keyword, head)));
    }

    /// Whether a word in a value position is more likely a misspelled keyword than a
    /// malformed value (so the statement before it is short, not wrong).
    fn misspelled_keyword(&mut self, tok: TokenId) -> bool {
        let text = self.text(tok);
        self.tree.kind(tok) == TokenKind::Word
            && !suggest::looks_numeric(text)
            && self.keyword_like(text).is_some()
    }

    /// A real number that is not zero as written but reads as 0 (an error), or as a
    /// subnormal (a warning): the rule of [`walls_keywords::number`]. Overflow is judged
    /// once the value is scaled by its unit (C120).
    fn underflow(&mut self, tok: TokenId) {
        use walls_keywords::number::{self, Problem};
        let text = self.text(tok);
        if !number::may_be_tiny(text) {
            return;
        }
        let d = match number::read(text) {
            Err(Problem::Underflow) => Diagnostic::error(
                &codes::NUMBER_UNDERFLOW,
                self.span(tok),
                format!("`{text}` is {}", Problem::Underflow),
            )
            .with_help(Problem::Underflow.help()),
            Ok(x) => match number::subnormal(x) {
                Some(tiny) => Diagnostic::warning(
                    &codes::NUMBER_UNDERFLOW,
                    self.span(tok),
                    format!("`{text}` is {tiny}"),
                )
                .with_help(number::Subnormal::HELP),
                None => return,
            },
            Err(_) => return,
        };
        self.out.push(d);
    }

    /// Whether `tok` is a good value for a slot of `shape`.
    fn fits(&self, shape: ValueShape, tok: TokenId) -> bool {
        match (shape, self.tree.kind(tok)) {
            (ValueShape::Number | ValueShape::Vector, TokenKind::Number) => true,
            (ValueShape::Integer, TokenKind::Number) => suggest::is_integer(self.text(tok)),
            (ValueShape::TypeName, TokenKind::TypeName(_)) => true,
            _ => false,
        }
    }

    fn slot(&mut self, keyword: Keyword, shape: ValueShape, tok: TokenId, index: usize) {
        if matches!(shape, ValueShape::Number | ValueShape::Vector)
            && self.tree.kind(tok) == TokenKind::Number
        {
            self.underflow(tok);
        }
        if self.fits(shape, tok) {
            return;
        }
        let kind = self.tree.kind(tok);
        let text = self.text(tok).to_string();
        let name = keyword.name();
        let span = self.span(tok);
        let what = match shape {
            ValueShape::Vector => format!("the {} number of `{name}`", ordinal(index)),
            _ => format!("a number for `{name}`"),
        };
        let d = match shape {
            ValueShape::None => return,
            ValueShape::Number | ValueShape::Vector => match kind {
                TokenKind::Number => return,
                _ => Diagnostic::error(
                    &codes::INVALID_NUMBER,
                    span,
                    format!("expected {what}, found {}", describe(kind, &text)),
                )
                .with_help(format!(
                    "pkdgrav would silently read `{text}` as {}",
                    suggest::atof_reading(&text)
                )),
            },
            ValueShape::Integer => match kind {
                TokenKind::Number if suggest::is_integer(&text) => return,
                _ => Diagnostic::error(
                    &codes::EXPECTED_INTEGER,
                    span,
                    format!("`{name}` takes an integer, found {}", describe(kind, &text)),
                )
                .with_help(format!(
                    "pkdgrav reads `{name}` with atoi and would silently read `{text}` as {}",
                    suggest::atoi_reading(&text)
                )),
            },
            ValueShape::TypeName => match kind {
                TokenKind::TypeName(_) => return,
                _ => {
                    let message = match kind {
                        TokenKind::Word => format!("unknown wall type `{text}`"),
                        _ => format!(
                            "expected a wall type name after `type`, found {}",
                            describe(kind, &text)
                        ),
                    };
                    let d = Diagnostic::error(&codes::UNKNOWN_WALL_TYPE, span.clone(), message);
                    match suggest::type_like(&text) {
                        // A guess at the type: help, not a fix (a fix keeps the meaning, and a
                        // type decides what every other token of the wall means).
                        suggest::Suggestion::One(t) => d.with_help(format!("did you mean `{t}`?")),
                        suggest::Suggestion::Several(names) => {
                            d.with_help(format!("did you mean {}?", names.join(" or ")))
                        }
                        suggest::Suggestion::None => d.with_help(
                            "the wall types are plane, triangle, rectangle, disk (or disc), cylinder-infinite, cylinder-finite and shell",
                        ),
                    }
                }
            },
        };
        self.out.push(d);
    }

    fn missing(
        &mut self,
        keyword: Keyword,
        head: TokenId,
        last: TokenId,
        next: Option<TokenId>,
        filled: usize,
    ) {
        let shape = keyword.shape();
        let name = keyword.name();
        let found_here = next.filter(|&n| !self.newline_between(last, n));
        let (span, found) = match found_here {
            Some(n) => (self.span(n), describe(self.tree.kind(n), self.text(n))),
            None => {
                let end = self.span(last).end;
                let found = if next.is_none() {
                    "the end of the file"
                } else {
                    "the end of the line"
                };
                (end..end, found.to_string())
            }
        };
        let message = match shape {
            ValueShape::Vector => format!(
                "`{name}` takes 3 numbers but has {filled}: expected the {} number here, found {found}",
                ordinal(filled)
            ),
            _ => format!("`{name}` takes {}, found {found}", shape.describe()),
        };
        let d = Diagnostic::error(&codes::MISSING_VALUE, span, message).with_label(
            self.span(head),
            format!("`{name}` takes {}", shape.describe()),
        );
        self.out.push(d);
    }

    /// pkdgrav reads a token's values from the token's own line.
    fn same_line(&mut self, keyword: Keyword, head: TokenId, values: &[TokenId]) {
        let Some(first_off) = (0..values.len()).find(|&i| {
            let prev = if i == 0 { head } else { values[i - 1] };
            self.newline_between(prev, values[i])
        }) else {
            return;
        };
        let span = self.span(values[first_off]).start..self.span(values[values.len() - 1]).end;
        let mut d = Diagnostic::error(
            &codes::VALUE_ON_OTHER_LINE,
            span,
            format!(
                "value of `{}` on a later line than `{}`",
                keyword.name(),
                keyword.name()
            ),
        )
        .with_label(
            self.span(head),
            "pkdgrav reads the values from this line only",
        );
        let mut edits = Vec::new();
        let mut has_comment = false;
        for (i, &v) in values.iter().enumerate() {
            let prev = if i == 0 { head } else { values[i - 1] };
            if self.newline_between(prev, v) {
                let gap = self.span(prev).end..self.span(v).start;
                has_comment |= (prev.0 + 1..v.0).any(|t| {
                    matches!(
                        self.tree.kind(TokenId(t)),
                        TokenKind::Comment | TokenKind::GluedComment
                    )
                });
                edits.push(Edit {
                    span: gap,
                    replacement: " ".into(),
                });
            }
        }
        d = if has_comment {
            d.with_help("move the values onto the keyword's line, and the comment after them")
        } else {
            d.with_fix(
                Applicability::Safe,
                format!("join the values onto the line of `{}`", keyword.name()),
                edits,
            )
        };
        self.out.push(d);
    }

    /// Values that no keyword takes: one diagnostic per mistake.
    fn extras(&mut self, tokens: &[TokenId], after: Option<(Keyword, TokenId)>) {
        let mut j = 0;
        while j < tokens.len() {
            let tok = tokens[j];
            let kind = self.tree.kind(tok);
            let text = self.text(tok).to_string();
            let numeric = |v: &Self, t: TokenId| match v.tree.kind(t) {
                TokenKind::Number => true,
                TokenKind::Word => suggest::looks_numeric(v.text(t)),
                _ => false,
            };
            if numeric(self, tok) {
                let run = tokens[j..]
                    .iter()
                    .take_while(|&&t| numeric(self, t))
                    .count();
                let last = tokens[j + run - 1];
                let span = self.span(tok).start..self.span(last).end;
                let message = match after {
                    Some((k, _)) if k.shape() == ValueShape::None => {
                        format!("`{}` takes no value", k.name())
                    }
                    Some((k, _)) => format!(
                        "unexpected value after `{}`, which takes {}",
                        k.name(),
                        k.shape().describe()
                    ),
                    None => "value before any keyword".to_string(),
                };
                let mut d = Diagnostic::error(&codes::UNEXPECTED_VALUE, span, message);
                if let Some((k, head)) = after {
                    d = d.with_label(
                        self.span(head),
                        format!("`{}` takes {}", k.name(), k.shape().describe()),
                    );
                }
                self.out.push(d);
                j += run;
                continue;
            }
            let span = self.span(tok);
            if let TokenKind::TypeName(t) = kind {
                self.out.push(
                    Diagnostic::error(
                        &codes::TYPE_NAME_WITHOUT_TYPE,
                        span.clone(),
                        format!("wall type `{text}` without `type` before it"),
                    )
                    .with_help(format!(
                        "a type name is the value of `type`: write `type {}`",
                        t.name()
                    )),
                );
                j += 1;
                continue;
            }
            let mut d = Diagnostic::error(
                &codes::UNKNOWN_WORD,
                span.clone(),
                format!("unknown word `{text}`"),
            );
            let suggestion = self.keyword_like(self.text(tok));
            // A guess at the keyword: help, not a fix (the statement it would make is
            // judged by every rule, and may change other walls' values).
            d = match suggestion {
                Some(k) => d.with_help(format!("did you mean `{k}`?")),
                None => {
                    d.with_help("see `walls-lint --explain S101` for the keywords of the language")
                }
            };
            self.out.push(d);
            // The values after an unknown word are its own (a type name, if it looks
            // like `type`; numbers otherwise): no more complaints about them.
            j += 1;
            let takes_type = suggestion
                .and_then(walls_keywords::keyword)
                .map(Keyword::shape)
                == Some(ValueShape::TypeName);
            j += tokens[j..]
                .iter()
                .take_while(|&&t| match self.tree.kind(t) {
                    TokenKind::TypeName(_) => takes_type,
                    _ => !takes_type && numeric(self, t),
                })
                .count();
        }
    }

    /// Whether a newline stands between two tokens.
    fn newline_between(&self, a: TokenId, b: TokenId) -> bool {
        self.tree.tokens().kinds()[a.0 as usize + 1..b.0 as usize].contains(&TokenKind::Newline)
    }
}

/// The warning for the run of hazards at `span` of `text`, in a token of `kind`.
fn control_run(text: &str, span: Range<usize>, kind: TokenKind) -> Diagnostic {
    /// Characters of a run the message shows.
    const SHOWN: usize = 8;
    let run = &text[span.clone()];
    let count = run.chars().count();
    let bidi = |c: char| matches!(c, '\u{202a}'..='\u{202e}' | '\u{2066}'..='\u{2069}');
    let separator = |c: char| matches!(c, '\u{2028}' | '\u{2029}');
    let (noun, effect) = if run.chars().all(bidi) {
        (
            "bidirectional control",
            "editors and reviews show a line with bidirectional controls in another order than pkdgrav reads it",
        )
    } else if run.chars().all(separator) {
        (
            "line separator",
            "editors show a line separator as a line break where pkdgrav sees none",
        )
    } else {
        (
            "control character",
            "a terminal acts on control characters instead of showing them: `ESC ] 52` sets the clipboard, a carriage return writes over the line",
        )
    };
    let end = run.char_indices().nth(SHOWN).map_or(run.len(), |(i, _)| i);
    let shown = format!(
        "{}{}",
        terminal::escape(&run[..end]),
        if end < run.len() { "…" } else { "" }
    );
    let (place, reading) = match kind {
        TokenKind::Comment | TokenKind::GluedComment => {
            ("in a comment", "pkdgrav ignores them in a comment")
        }
        TokenKind::Whitespace => ("between words", "pkdgrav reads them as a space"),
        _ => ("in a word", "pkdgrav reads them as part of the word"),
    };
    let message = match count {
        1 => format!("{noun} `{shown}` {place}"),
        n => format!("{n} {noun}s `{shown}` {place}"),
    };
    let d = Diagnostic::warning(&codes::CONTROL_CHARACTER, span.clone(), message)
        .with_help(format!("{effect}; {reading}"));
    if kind == TokenKind::Whitespace {
        d.with_fix(
            Applicability::Safe,
            "replace with a space",
            vec![Edit {
                span,
                replacement: " ".into(),
            }],
        )
    } else {
        d
    }
}

fn describe(kind: TokenKind, text: &str) -> String {
    match kind {
        TokenKind::Keyword(_) => format!("keyword `{text}`"),
        TokenKind::TypeName(_) => format!("type name `{text}`"),
        TokenKind::Number => format!("number `{text}`"),
        _ => format!("`{text}`"),
    }
}

fn ordinal(i: usize) -> &'static str {
    ["1st", "2nd", "3rd"].get(i).copied().unwrap_or("next")
}

#[cfg(test)]
mod tests {
    use super::MAX_CONTROL_RUNS;

    #[test]
    fn control_characters_past_the_limit_are_counted_not_reported() {
        let text = "# \u{1b}\n".repeat(MAX_CONTROL_RUNS + 500);
        let found: Vec<_> = crate::parse(text.as_str())
            .diagnostics
            .into_iter()
            .filter(|d| d.code.id == "S006")
            .collect();
        assert_eq!(found.len(), MAX_CONTROL_RUNS);
        let last = &found[MAX_CONTROL_RUNS - 1];
        assert_eq!(last.span.start, 4 * (MAX_CONTROL_RUNS - 1) + 2);
        assert_eq!(
            last.message,
            "control character `\\x1b` in a comment (and at least 500 more runs of such \
             characters after it, not reported one by one)"
        );
        assert!(
            crate::codes::CONTROL_CHARACTER
                .explanation
                .contains(&format!(
                    "at most 1,{:03} in a file",
                    MAX_CONTROL_RUNS - 1000
                )),
            "S006's explanation gives the limit"
        );
        let exactly = "# \u{1b}\n".repeat(MAX_CONTROL_RUNS);
        let last = crate::parse(exactly.as_str()).diagnostics.pop().unwrap();
        assert_eq!(last.message, "control character `\\x1b` in a comment");
    }
}
