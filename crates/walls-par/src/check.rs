//! The one check of a `.par` file for a build: its lines read as pkdgrav reads them
//! ([`crate::syntax`]), each entry's key looked up in the build's registrations and its
//! value read for the key's type ([`crate::value`]), then the rules: one per code, in
//! `rules/`, and the start-up checks' table ([`crate::startup`]).

use crate::keys::{self, Key};
use crate::options::Build;
use crate::rules;
use crate::syntax::{self, Kind, Line};
use crate::value::{self, Reading, Unreadable, Value};
use std::collections::HashMap;
use std::ops::Range;
use walls_diagnostics::{Diagnostic, Severity};

/// One `key = value` entry of the file that the build registers, read.
#[derive(Debug, Clone)]
pub struct Entry {
    /// The key's registration.
    pub key: &'static Key,
    /// The key's bytes.
    pub key_span: Range<usize>,
    /// The bytes of the value pkdgrav reads.
    pub value_span: Range<usize>,
    /// The whole line's bytes, its line break included (for a fix that deletes it).
    pub line_span: Range<usize>,
    /// The line's number.
    pub line: usize,
    /// What pkdgrav reads; `None` when it cannot (a syntax error, reported).
    pub value: Option<Value>,
}

/// The file as pkdgrav reads it for one build: its lines and the entries it registers,
/// by key (the last line of a key wins, as in pkdgrav).
#[derive(Debug)]
pub struct File<'a> {
    /// The text.
    pub text: &'a str,
    /// The build.
    pub build: &'a Build,
    /// Its lines.
    pub lines: Vec<Line>,
    /// The registered entries, in file order.
    pub entries: Vec<Entry>,
    /// The index in `entries` of each key's last entry.
    last: HashMap<&'static str, usize>,
    /// The keys a command line sets over the file (pkdgrav's flags win over it): their
    /// values are not the file's to judge.
    overridden: Vec<&'a str>,
}

impl<'a> File<'a> {
    /// Reads `text` for `build`, reporting in `out` what reading finds (syntax errors,
    /// unknown keys, values pkdgrav reads otherwise than written or cannot use).
    pub fn read(text: &'a str, build: &'a Build, out: &mut Vec<Diagnostic>) -> File<'a> {
        let lines = syntax::lines(text);
        let mut entries = Vec::new();
        let mut last = HashMap::new();
        for line in &lines {
            rules::line_too_long::check(text, line, out);
            // The line with its break (`\n` or `\r\n`), for a fix that deletes it.
            let line_span = line.span.start
                ..text[line.span.end..]
                    .find('\n')
                    .map_or(text.len(), |k| line.span.end + k + 1);
            // The rest of a long line is read as lines of their own (`rest`): of their
            // errors only the first is reported (pkdgrav stops there; a 10 MB line is
            // one finding, not eighty thousand), what they set is kept.
            let mut rest = Vec::new();
            for (k, piece) in line.reads.iter().enumerate() {
                let out: &mut Vec<Diagnostic> = if k == 0 { &mut *out } else { &mut rest };
                match &piece.kind {
                    Kind::Blank | Kind::Comment => {}
                    Kind::Error { problem, at } => {
                        rules::par_syntax::at_line(text, *problem, at.clone(), out);
                    }
                    Kind::Entry { key, value } => {
                        let name = &text[key.clone()];
                        let Some(registration) = keys::registered(name, build) else {
                            rules::unknown_key::check(name, key.clone(), build, out);
                            continue;
                        };
                        let reading = value::read(name, registration.kind, &text[value.clone()]);
                        let read_value = match reading {
                            Ok(Reading {
                                value: v,
                                read,
                                ignored,
                            }) => {
                                // What a NUL byte cut off the line is lost too.
                                let cut = &text[value.end..piece.span.end];
                                let ignored = if ignored.is_empty() && cut.starts_with('\0') {
                                    cut.to_string()
                                } else {
                                    ignored
                                };
                                let read_span = value.start..value.start + read;
                                rules::read_as::check(
                                    registration,
                                    &text[read_span.clone()],
                                    &v,
                                    &ignored,
                                    value.clone(),
                                    out,
                                );
                                rules::not_finite::check_value(
                                    registration,
                                    &v,
                                    &text[read_span.clone()],
                                    read_span,
                                    out,
                                );
                                Some(v)
                            }
                            Err(Unreadable::NotANumber) => {
                                rules::par_syntax::not_a_number(
                                    registration,
                                    value.clone(),
                                    text,
                                    out,
                                );
                                None
                            }
                            Err(Unreadable::BeyondInt) => {
                                rules::not_finite::beyond_int(
                                    registration,
                                    value.clone(),
                                    text,
                                    out,
                                );
                                None
                            }
                        };
                        last.insert(registration.name, entries.len());
                        entries.push(Entry {
                            key: registration,
                            key_span: key.clone(),
                            value_span: value.clone(),
                            line_span: line_span.clone(),
                            line: line.number,
                            value: read_value,
                        });
                    }
                }
            }
            let first_error = rest.iter().position(|d| d.severity == Severity::Error);
            out.extend(rest.into_iter().enumerate().filter_map(|(k, d)| {
                (d.severity != Severity::Error || Some(k) == first_error).then_some(d)
            }));
        }
        File {
            text,
            build,
            lines,
            entries,
            last,
            overridden: Vec::new(),
        }
    }

    /// The entry of `key` that wins (its last), if the file gives it.
    pub fn given(&self, key: &str) -> Option<&Entry> {
        self.last.get(key).map(|&i| &self.entries[i])
    }

    /// Whether `entry` is the one of its key that wins.
    pub fn wins(&self, entry: &Entry) -> bool {
        self.given(entry.key.name)
            .is_some_and(|e| e.key_span == entry.key_span)
    }

    /// The number pkdgrav runs with for `key`: the file's, else the default (`None` for
    /// a string, a value pkdgrav cannot read, or a key the build does not register).
    pub fn real(&self, key: &str) -> Option<f64> {
        if self.overridden.contains(&key) {
            return None;
        }
        match self.given(key) {
            Some(e) => e.value.as_ref()?.real(),
            None => keys::registered(key, self.build)?.default_value(),
        }
    }

    /// The string pkdgrav runs with for `key` (empty when the file leaves it out).
    pub fn string(&self, key: &str) -> Option<String> {
        if self.overridden.contains(&key) {
            return None;
        }
        match self.given(key) {
            Some(e) => match e.value.as_ref()? {
                Value::Str(s) => Some(s.clone()),
                _ => None,
            },
            None => keys::registered(key, self.build).map(|_| String::new()),
        }
    }
}

/// The findings for the `.par` text `text` read by a pkdgrav of `build`, sorted by place.
pub fn check(text: &str, build: &Build) -> Vec<Diagnostic> {
    check_overridden(text, build, &[])
}

/// [`check`], for a run whose command line sets the keys `overridden` over the file's
/// (`walls-sim run --particles` sets `achInFile`): what the file says of them, or leaves
/// out, is not judged.
pub fn check_overridden(text: &str, build: &Build, overridden: &[&str]) -> Vec<Diagnostic> {
    let mut out = Vec::new();
    let mut file = File::read(text, build, &mut out);
    file.overridden = overridden.to_vec();
    // What the file writes for a key the command line sets is not judged either.
    let set_elsewhere = |d: &Diagnostic| {
        std::ptr::eq(d.code, &crate::codes::NOT_FINITE)
            || std::ptr::eq(d.code, &crate::codes::READ_AS)
    };
    if !overridden.is_empty() {
        let spans: Vec<_> = (file.entries.iter())
            .filter(|e| overridden.contains(&e.key.name))
            .map(|e| e.value_span.clone())
            .collect();
        out.retain(|d| {
            !(set_elsewhere(d)
                && spans
                    .iter()
                    .any(|s| s.start <= d.span.start && d.span.end <= s.end))
        });
    }
    rules::unknown_key::no_rename_to_a_key_given(&file, &mut out);
    rules::duplicate_key::check(&file, &mut out);
    let stopped = rules::startup::check(&file, &mut out);
    rules::not_modelled::check(&file, &stopped, &mut out);
    out.sort_by(|a, b| {
        (a.span.start, a.span.end, a.code.id).cmp(&(b.span.start, b.span.end, b.code.id))
    });
    out
}
