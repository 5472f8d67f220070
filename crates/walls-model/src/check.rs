//! The checker: runs the rules about blocks, walls and files (docs/spec.md §1 "Checks
//! users expect" and the wall-type and contact-model rules), on top of the value rules
//! the resolver applies as it reads.
//!
//! Each rule lives in its own file under `rules/`; this module fixes the order they run
//! in (which orders diagnostics that share a span) and gives them a [`Checker`] to report
//! through.

use crate::resolve::Unread;
use crate::rules::{
    arithmetic_overflow, assembly_without_mass, axes_not_orthogonal, degenerate_triangle,
    hole_not_inside, hsdem_particle_value::AtNinetyNine, ignored_by_type, k_t_before_k_n,
    lone_oscillation, mass_without_assembly::NoAssembly, no_walls, not_in_hsdem,
    osc_vec_not_following_orient, reactive_spinning, reactive_type, rectangle_not_rectangular,
    repeated_token, sticky_wall_order::StickyOrder, taper_on_ring, too_many_walls, unused_default,
    wall_too_fast,
};
use crate::scene::{Scene, Wall};
use crate::{ContactModel, Options};
use std::collections::HashSet;
use std::ops::Range;
use walls_diagnostics::{Diagnostic, Edit};
use walls_keywords::{Keyword, Role};
use walls_syntax::{Block as SyntaxBlock, Item, Statement, SyntaxTree};

/// Runs the block and wall rules.
pub(crate) fn check(
    tree: &SyntaxTree,
    scene: &Scene,
    unread: &Unread,
    options: &Options,
) -> Vec<Diagnostic> {
    let mut c = Checker {
        tree,
        options,
        unread,
        out: Vec::new(),
        seen: HashSet::new(),
    };
    c.blocks();
    c.walls(scene);
    unused_default::check(&mut c, scene);
    no_walls::check(&mut c, scene);
    too_many_walls::check(&mut c, scene);
    c.out
}

/// What the block, wall and file rules see and report through.
pub(crate) struct Checker<'a> {
    /// The file.
    pub(crate) tree: &'a SyntaxTree,
    /// The run the file is for.
    pub(crate) options: &'a Options,
    /// The property statements that set nothing.
    unread: &'a Unread,
    out: Vec<Diagnostic>,
    /// Code, span and (for codes about several keywords) keyword of what was reported,
    /// so a `defaults` line shared by many walls is reported once.
    seen: HashSet<(&'static str, usize, usize, Option<Keyword>)>,
}

/// One block's property statements by keyword, in source order within a keyword.
pub(crate) struct Block<'t> {
    /// The statements, sorted by keyword (stably).
    pub(crate) keyed: Vec<(Keyword, &'t Statement)>,
}

impl<'t> Block<'t> {
    /// The block's last statement of keyword `k`.
    pub(crate) fn last_of(&self, k: Keyword) -> Option<&'t Statement> {
        self.keyed
            .iter()
            .rev()
            .find(|(key, _)| *key == k)
            .map(|&(_, s)| s)
    }
}

impl<'a> Checker<'a> {
    /// Reports `d` unless the same code was reported at the same span already.
    pub(crate) fn push(&mut self, d: Diagnostic) {
        self.push_about(d, None);
    }

    /// Reports `d` unless the same code was reported at the same span (about the same
    /// keyword) already.
    pub(crate) fn push_about(&mut self, d: Diagnostic, keyword: Option<Keyword>) {
        if self
            .seen
            .insert((d.code.id, d.span.start, d.span.end, keyword))
        {
            self.out.push(d);
        }
    }

    /// Repeated tokens and `k_t` before `k_n`, block by block, among the statements
    /// that set their value.
    fn blocks(&mut self) {
        let unread = self.unread;
        let tree = self.tree;
        // One buffer serves every block.
        let mut block = Block { keyed: Vec::new() };
        for item in tree.items() {
            let Item::Block(b) = item else { continue };
            block.keyed.clear();
            block.keyed.extend(tree.body(b).iter().filter_map(|s| {
                tree.keyword(s)
                    .filter(|k| k.role() == Role::Property)
                    .filter(|_| {
                        unread.is_empty() || !unread.contains(tree.span(tree.head(s)).start)
                    })
                    .map(|k| (k, s))
            }));
            block.keyed.sort_by_key(|&(k, _)| k);
            repeated_token::check(self, &block);
            k_t_before_k_n::check(self, &block);
        }
    }

    /// The wall rules, wall by wall, then the ones gathered over all walls.
    fn walls(&mut self, scene: &Scene) {
        let mut sticky = StickyOrder::default();
        let mut at_99 = AtNinetyNine::default();
        let mut no_assembly = NoAssembly::default();
        for wall in &scene.walls {
            // A wall whose type did not read is judged by no type: the rules that depend
            // on it are silent (the syntax error is the finding), so that no fix touches
            // the wall on the type's account.
            let t = wall.known_type();
            if let Some(t) = t {
                ignored_by_type::check(self, wall, t);
                arithmetic_overflow::check(self, wall, t);
                degenerate_triangle::check(self, wall, t);
                rectangle_not_rectangular::check(self, wall, t);
                hole_not_inside::check(self, wall, t);
                taper_on_ring::check(self, wall, t);
            }
            lone_oscillation::check(self, wall);
            if let Some(t) = t {
                osc_vec_not_following_orient::check(self, wall, t);
                wall_too_fast::check(self, wall, t);
            }
            if self.options.mode == ContactModel::Ssdem {
                // The reactive rules look at reactive walls only (but the first, at the
                // walls that are not): decide once.
                if wall.is_reactive() {
                    if let Some(t) = t {
                        reactive_type::check(self, wall, t);
                    }
                    reactive_spinning::check(self, wall);
                    no_assembly.note(wall);
                    axes_not_orthogonal::check(self, wall);
                } else {
                    assembly_without_mass::check(self, wall);
                }
            } else {
                if let Some(t) = t {
                    not_in_hsdem::check(self, wall, t);
                }
                at_99.note(wall);
            }
            sticky.check(self, wall);
        }
        at_99.report(self);
        no_assembly.report(self, scene);
    }

    /// Where the wall sets `k`, if it or its defaults do.
    pub(crate) fn span_of(&self, wall: &Wall, k: Keyword) -> Option<Range<usize>> {
        wall.setting(k).and_then(|s| s.source.span())
    }

    /// Where a triangle's or rectangle's shape is set: its vertex2, else its vertex1,
    /// else its `wall`.
    pub(crate) fn vertices_span(&self, wall: &Wall) -> Range<usize> {
        self.span_of(wall, Keyword::Vertex2)
            .or_else(|| self.span_of(wall, Keyword::Vertex1))
            .unwrap_or_else(|| wall.span.clone())
    }

    /// Where a reactive wall's mass is set, else its `wall`.
    pub(crate) fn mass_span(&self, wall: &Wall) -> Range<usize> {
        self.span_of(wall, Keyword::Mass)
            .unwrap_or_else(|| wall.span.clone())
    }

    /// Whether a property statement set its value (its values read, and stayed finite).
    pub(crate) fn sets(&self, stmt: &Statement) -> bool {
        !self
            .unread
            .contains(self.tree.span(self.tree.head(stmt)).start)
    }

    /// The block that holds byte `offset`.
    pub(crate) fn block_at(&self, offset: usize) -> Option<&'a SyntaxBlock> {
        let items = self.tree.items();
        let start = |item: &Item| {
            let stmt = match item {
                Item::Block(b) => &b.head,
                Item::Statement(s) | Item::Stray(s) => s,
            };
            self.tree.statement_span(stmt).start
        };
        let at = items.partition_point(|item| start(item) <= offset);
        match items.get(at.checked_sub(1)?)? {
            Item::Block(b) => Some(b),
            _ => None,
        }
    }

    /// The edits removing every statement of `statements` (in source order), those that
    /// touch merged into one; `None` if one cannot be removed ([`Checker::delete`]) or
    /// there is none.
    pub(crate) fn delete_all<'s>(
        &self,
        statements: impl Iterator<Item = &'s Statement>,
    ) -> Option<Vec<Edit>> {
        let mut edits: Vec<Edit> = Vec::new();
        for stmt in statements {
            let edit = self.delete(stmt)?;
            match edits.last_mut() {
                Some(last) if edit.span.start <= last.span.end => {
                    last.span.end = last.span.end.max(edit.span.end);
                    last.replacement = edit.replacement;
                }
                _ => edits.push(edit),
            }
        }
        (!edits.is_empty()).then_some(edits)
    }

    /// An edit removing a statement: its whole line when nothing else is on it, else the
    /// statement and the blank before it. Comments are never removed. `None` for a
    /// statement with more values than its keyword takes: those are mistakes of their own
    /// (an unknown word, a stray number), which a fix does not delete unseen.
    pub(crate) fn delete(&self, stmt: &Statement) -> Option<Edit> {
        let extra = match self.tree.keyword(stmt) {
            Some(k) => self.tree.values(stmt).len() > k.shape().arity(),
            None => true,
        };
        if extra {
            return None;
        }
        let text = self.tree.text();
        let span = self.tree.statement_span(stmt);
        let line_start = text[..span.start].rfind('\n').map_or(0, |i| i + 1);
        let line_end = text[span.end..]
            .find('\n')
            .map_or(text.len(), |i| span.end + i + 1);
        let before = &text[line_start..span.start];
        let after = &text[span.end..line_end];
        let blank = |s: &str| {
            s.chars()
                .all(|c| matches!(c, ' ' | '\t' | ',' | '=' | '\r' | '\n'))
        };
        if blank(before) && blank(after) {
            return Some(Edit {
                span: line_start..line_end,
                replacement: String::new(),
            });
        }
        // A suppression comment on the statement's line would apply to the next line
        // once the statement is gone (crate walls-ide, `suppress.rs`): it goes too.
        let directive = after
            .trim_start_matches([' ', '\t', ',', '='])
            .get(1..)
            .is_some_and(|c| c.trim_start().starts_with("walls-lint:"));
        if blank(before) && directive {
            return Some(Edit {
                span: line_start..line_end,
                replacement: String::new(),
            });
        }
        if blank(before) {
            // A comment follows on the line: keep the indentation and the comment.
            let gap = after.len() - after.trim_start_matches([' ', '\t', ',', '=']).len();
            return Some(Edit {
                span: span.start..span.end + gap,
                replacement: String::new(),
            });
        }
        let start =
            span.start - before.len() + before.trim_end_matches([' ', '\t', ',', '=']).len();
        // A comment glued to the statement stays a comment, not glued to the word before.
        let glued = after.starts_with(['#', '!']);
        Some(Edit {
            span: start..span.end,
            replacement: if glued { " " } else { "" }.into(),
        })
    }
}
