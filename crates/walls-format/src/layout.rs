//! Laying out a parsed file: statements, comments and blank lines into lines.
//!
//! The tree is walked once, statement by statement, with a cursor over the tokens. The
//! trivia before a statement gives its leading comments (each on its own line) and the
//! blank lines the author left; a comment on the same line after a statement is its
//! trailing comment; comments inside a statement (between a keyword and values written
//! on later lines) follow it. Each top-level item is laid out as lines, then written.

use crate::{FormatOptions, Formatted};
use walls_keywords::Keyword;
use walls_syntax::{Item, Statement, SyntaxTree, TokenKind};

/// A statement ready to be written, with the comments around it.
struct Piece<'t> {
    /// Comments on their own lines before it, each with whether a blank line preceded it.
    leading: Vec<(bool, &'t str)>,
    /// Whether a blank line preceded the statement itself (after its leading comments).
    blank_before: bool,
    /// Keyword and values, canonical.
    words: String,
    /// Comments inside and after it, in source order.
    comments: Vec<&'t str>,
    keyword: Option<Keyword>,
}

/// One output line.
enum Line<'t> {
    Blank,
    Comment(usize, &'t str),
    Statement(usize, String, Option<&'t str>),
}

struct Layout<'t> {
    tree: &'t SyntaxTree,
    options: &'t FormatOptions,
    /// The next token not yet laid out.
    cursor: usize,
    /// Comments inside the last statement beyond the one its line keeps: they go on
    /// their own lines before what follows, where reading the output puts them too.
    carried: Vec<&'t str>,
    out: String,
}

/// Formats the whole tree.
pub(crate) fn format(tree: &SyntaxTree, options: &FormatOptions) -> Formatted {
    let mut l = Layout {
        tree,
        options,
        cursor: 0,
        carried: Vec::new(),
        out: String::with_capacity(tree.text().len() + tree.text().len() / 8),
    };
    let mut pieces = Vec::with_capacity(tree.items().len());
    let mut src_start = 0;
    let mut out_start = 0;
    let mut previous_block_lines: Option<usize> = None;
    let items = tree.items();
    for (i, item) in items.iter().enumerate() {
        let statements: Vec<&Statement> = match item {
            Item::Block(b) => std::iter::once(&b.head).chain(tree.body(b)).collect(),
            Item::Statement(s) | Item::Stray(s) => vec![s],
        };
        // Statements after a block's head are indented; a lone statement is not.
        let body_start = match item {
            Item::Block(_) => 1,
            _ => usize::MAX,
        };
        let mut parsed: Vec<Piece> = statements.iter().map(|s| l.piece(s)).collect();
        if i + 1 == items.len() {
            // Comments after the last statement belong to the last item.
            let (tail, _) = l.gap(tree.tokens().len());
            parsed.push(Piece {
                leading: tail,
                blank_before: false,
                words: String::new(),
                comments: Vec::new(),
                keyword: None,
            });
        }
        let lines = l.lines(parsed, body_start);
        let statement_lines = lines
            .iter()
            .filter(|line| matches!(line, Line::Statement(..)))
            .count();
        let is_block = matches!(item, Item::Block(_));
        // A blank line between walls when either spans several lines.
        let separate =
            is_block && previous_block_lines.is_some_and(|prev| prev > 1 || statement_lines > 1);
        l.write(lines, separate, i == 0);
        previous_block_lines = is_block.then_some(statement_lines);
        let src_end = if i + 1 == items.len() {
            tree.text().len()
        } else {
            l.line_end()
        };
        // Comments carried into the next item bind the two into one piece, so that a
        // range formatted alone never splits a comment from where it is written.
        if l.carried.is_empty() {
            pieces.push((src_start..src_end, out_start..l.out.len()));
            src_start = src_end;
            out_start = l.out.len();
        }
    }
    if items.is_empty() {
        let (comments, _) = l.gap(tree.tokens().len());
        let lines = comments
            .into_iter()
            .flat_map(|(blank, c)| blank_then(blank, Line::Comment(0, c)))
            .collect();
        l.write(lines, false, true);
        pieces.push((0..tree.text().len(), 0..l.out.len()));
    }
    Formatted {
        text: l.out,
        pieces,
    }
}

fn blank_then(blank: bool, line: Line<'_>) -> Vec<Line<'_>> {
    if blank {
        vec![Line::Blank, line]
    } else {
        vec![line]
    }
}

impl<'t> Layout<'t> {
    fn kind(&self, i: usize) -> TokenKind {
        self.tree.tokens().kinds()[i]
    }

    fn text(&self, i: usize) -> &'t str {
        self.tree.token_text(walls_syntax::TokenId(i as u32))
    }

    /// The comments on their own lines from the cursor up to token `end`, each with
    /// whether a blank line came before it, and whether a blank line comes after the
    /// last of them (before token `end`).
    fn gap(&mut self, end: usize) -> (Vec<(bool, &'t str)>, bool) {
        let mut comments: Vec<(bool, &'t str)> =
            self.carried.drain(..).map(|c| (false, c)).collect();
        let mut newlines = 0;
        for i in self.cursor..end {
            match self.kind(i) {
                TokenKind::Newline => newlines += 1,
                TokenKind::Comment | TokenKind::GluedComment => {
                    comments.push((newlines >= 2, self.text(i)));
                    newlines = 0;
                }
                _ => {}
            }
        }
        self.cursor = end;
        (comments, newlines >= 2)
    }

    /// Reads one statement and the comments around it, moving the cursor past its
    /// trailing comment.
    fn piece(&mut self, stmt: &Statement) -> Piece<'t> {
        let tokens = self.tree.statement_tokens(stmt);
        let head = tokens[0].0 as usize;
        let last = tokens[tokens.len() - 1].0 as usize;
        let (leading, blank_before) = self.gap(head);
        let mut words = String::new();
        let mut comments = Vec::new();
        for i in head..=last {
            match self.kind(i) {
                TokenKind::Keyword(_) | TokenKind::TypeName(_) => {
                    if !words.is_empty() {
                        words.push(' ');
                    }
                    words.push_str(&self.text(i).to_ascii_lowercase());
                }
                TokenKind::Number | TokenKind::Word => {
                    words.push(' ');
                    words.push_str(self.text(i));
                }
                TokenKind::Comment | TokenKind::GluedComment => comments.push(self.text(i)),
                _ => {}
            }
        }
        // A comment later on the same line trails the statement.
        let mut i = last + 1;
        while i < self.tree.tokens().len()
            && matches!(self.kind(i), TokenKind::Whitespace | TokenKind::Separator)
        {
            i += 1;
        }
        self.cursor = last + 1;
        if i < self.tree.tokens().len()
            && matches!(self.kind(i), TokenKind::Comment | TokenKind::GluedComment)
        {
            comments.push(self.text(i));
            self.cursor = i + 1;
        }
        // The statement's line keeps one comment; the others follow on their own lines.
        if comments.len() > 1 {
            self.carried = comments.split_off(1);
        }
        Piece {
            leading,
            blank_before,
            words,
            comments,
            keyword: self.tree.keyword(stmt),
        }
    }

    /// The lines of one item; pieces from `body_start` on are indented.
    fn lines(&self, mut pieces: Vec<Piece<'t>>, body_start: usize) -> Vec<Line<'t>> {
        // `wall type x`: a wall's type goes on its first line, and so does the first
        // statement of `defaults` (`defaults epsn 0.9`), when nothing stands between.
        let joins = |head: &Piece, next: &Piece| match head.keyword {
            Some(Keyword::Wall) => next.keyword == Some(Keyword::Type),
            Some(Keyword::Defaults) => !next.words.is_empty(),
            _ => false,
        };
        if body_start == 1
            && pieces.len() > 1
            && joins(&pieces[0], &pieces[1])
            && pieces[0].comments.is_empty()
            && pieces[1].leading.is_empty()
            && !(pieces[1].blank_before && self.options.keep_blank_lines)
        {
            let ty = pieces.remove(1);
            pieces[0].words.push(' ');
            pieces[0].words.push_str(&ty.words);
            pieces[0].comments = ty.comments;
        }
        let keep = self.options.keep_blank_lines;
        let mut lines = Vec::new();
        for (n, p) in pieces.into_iter().enumerate() {
            let indent = if n >= body_start && !p.words.is_empty() {
                self.options.indent_width
            } else {
                0
            };
            for (blank, c) in p.leading {
                if blank && keep {
                    lines.push(Line::Blank);
                }
                lines.push(Line::Comment(indent, c));
            }
            if p.words.is_empty() {
                continue;
            }
            if p.blank_before && keep {
                lines.push(Line::Blank);
            }
            lines.push(Line::Statement(
                indent,
                p.words,
                p.comments.into_iter().next(),
            ));
        }
        lines
    }

    /// Writes an item's lines: no blank line at the top of the file or twice in a row;
    /// a blank line first when `separate`.
    fn write(&mut self, lines: Vec<Line<'t>>, separate: bool, first: bool) {
        let widths: Vec<usize> = lines
            .iter()
            .map(|line| match line {
                Line::Statement(indent, words, _) => indent + words.len(),
                _ => 0,
            })
            .collect();
        let mut blank_pending = separate && !first;
        for (n, line) in lines.iter().enumerate() {
            match line {
                Line::Blank => {
                    blank_pending = !(first && self.out.is_empty());
                    continue;
                }
                _ if blank_pending => {
                    self.out.push('\n');
                    blank_pending = false;
                }
                _ => {}
            }
            match line {
                Line::Blank => {}
                Line::Comment(indent, c) => {
                    push_indent(&mut self.out, *indent);
                    self.out.push_str(c);
                }
                Line::Statement(indent, words, comment) => {
                    push_indent(&mut self.out, *indent);
                    self.out.push_str(words);
                    if let Some(c) = comment {
                        let column = if self.options.align_trailing_comments {
                            run_width(&lines, &widths, n)
                        } else {
                            widths[n]
                        };
                        push_indent(&mut self.out, column - widths[n] + 1);
                        self.out.push_str(c);
                    }
                }
            }
            self.out.push('\n');
        }
    }

    /// Where the line holding the cursor's last token ends (past its newline). The
    /// cursor stays: the newline still counts towards the blank lines that follow.
    fn line_end(&self) -> usize {
        let tokens = self.tree.tokens();
        let mut i = self.cursor;
        while i < tokens.len()
            && matches!(self.kind(i), TokenKind::Whitespace | TokenKind::Separator)
        {
            i += 1;
        }
        if i < tokens.len() && self.kind(i) == TokenKind::Newline {
            i += 1;
        }
        tokens
            .starts()
            .get(i)
            .map_or(self.tree.text().len(), |&s| s as usize)
    }
}

/// The widest statement with a comment in the run of statement lines around line `n`.
fn run_width(lines: &[Line<'_>], widths: &[usize], n: usize) -> usize {
    let in_run = |k: usize| matches!(lines[k], Line::Statement(_, _, Some(_)));
    let mut start = n;
    while start > 0 && in_run(start - 1) {
        start -= 1;
    }
    let mut end = n;
    while end + 1 < lines.len() && in_run(end + 1) {
        end += 1;
    }
    widths[start..=end]
        .iter()
        .copied()
        .max()
        .unwrap_or(widths[n])
}

fn push_indent(out: &mut String, n: usize) {
    out.extend(std::iter::repeat_n(' ', n));
}
