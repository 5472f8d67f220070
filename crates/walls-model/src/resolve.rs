//! Reading a parsed file the way pkdgrav does, front to back, into a [`Scene`].
//!
//! Units scale the values read after them; `defaults` edits the default wall; `wall`
//! appends a copy of the defaults; units and `time` close a wall block. Each value is
//! checked as it is read (ranges, zero vectors, numbers too large for a double), since
//! pkdgrav refuses such a file at that token: the resolver hands it to the value rules
//! (`rules`, by the keyword's range) and stores what they return. Statements whose values
//! the syntax check already rejected are skipped, so a broken file still resolves to what
//! parsed.

use crate::ContactModel;
use crate::rules::{self, Read, negative_osc_freq, number_too_large};
use crate::scene::{
    Place, Scene, Setting, Settings, Source, Units, Value, Vec3, Wall, WallSettings,
};
use std::ops::Range;
use std::sync::Arc;
use walls_diagnostics::Diagnostic;
use walls_keywords::{Keyword, Role, ValueRange, ValueShape};
use walls_syntax::{Statement, SyntaxTree, TokenId, TokenKind};

/// Resolves `tree` into the scene pkdgrav would build, with the diagnostics about single
/// values found on the way.
pub fn resolve(tree: &SyntaxTree, mode: ContactModel) -> (Scene, Vec<Diagnostic>) {
    let (scene, diagnostics, _) = resolve_noting_unread(tree, mode);
    (scene, diagnostics)
}

/// Where the keywords of the property statements that set nothing start, in file order:
/// their values did not read, or overflow once scaled. The block rules count only the
/// statements that set their value (a `radius` after which a broken `radius` stands is not
/// overridden by it).
#[derive(Default)]
pub(crate) struct Unread(Vec<usize>);

impl Unread {
    /// Whether every property statement set its value.
    pub(crate) fn is_empty(&self) -> bool {
        self.0.is_empty()
    }

    /// Whether the statement whose keyword starts at `offset` set nothing.
    pub(crate) fn contains(&self, offset: usize) -> bool {
        self.0.binary_search(&offset).is_ok()
    }
}

/// [`resolve`], with the property statements that set nothing.
pub(crate) fn resolve_noting_unread(
    tree: &SyntaxTree,
    mode: ContactModel,
) -> (Scene, Vec<Diagnostic>, Unread) {
    let mut r = Resolver {
        tree,
        mode,
        units: Units::default(),
        defaults: Settings::default(),
        shared: None,
        scene: Scene::default(),
        target: Target::None,
        out: Vec::new(),
        block_osc_freq: None,
        block_start: 0,
        block_type_unread: false,
        unread: Unread::default(),
        pending_freqs: Vec::new(),
    };
    let walls = tree
        .items()
        .iter()
        .filter(|item| matches!(item, walls_syntax::Item::Block(b) if b.kind == walls_syntax::BlockKind::Wall))
        .count();
    r.scene.walls.reserve_exact(walls);
    for (stmt, block) in tree.statements() {
        r.statement(stmt, block);
    }
    r.close_block();
    r.scene.units = r.units;
    negative_osc_freq::add_fixes(&r.pending_freqs, &r.scene, tree.text(), &mut r.out);
    (r.scene, r.out, r.unread)
}

/// Reads a number token (already validated by the lexer) exactly as `str::parse` does.
/// Short decimals, most of any walls file, take Clinger's fast path: when the digits
/// form an integer m < 2^53 and the power of ten p has |p| ≤ 22, both m and 10^|p| are
/// exact doubles and m·10^p or m/10^|p| is one correctly rounded operation.
fn parse_number(text: &str) -> Option<f64> {
    let b = text.as_bytes();
    let negative = b.first() == Some(&b'-');
    let mut i = usize::from(matches!(b.first(), Some(b'+' | b'-')));
    let mut mantissa: u64 = 0;
    let mut digits = 0;
    let mut exponent: i32 = 0;
    let mut seen_dot = false;
    while let Some(&c) = b.get(i) {
        match c {
            b'0'..=b'9' => {
                digits += 1;
                if digits > 15 {
                    return text.parse().ok();
                }
                mantissa = mantissa * 10 + u64::from(c - b'0');
                exponent -= i32::from(seen_dot);
            }
            b'.' if !seen_dot => seen_dot = true,
            _ => return text.parse().ok(),
        }
        i += 1;
    }
    const POW10: [f64; 23] = [
        1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16,
        1e17, 1e18, 1e19, 1e20, 1e21, 1e22,
    ];
    let m = mantissa as f64;
    let value = if exponent == 0 {
        m
    } else {
        m / POW10[(-exponent) as usize]
    };
    Some(if negative { -value } else { value })
}

/// What the property tokens currently edit.
#[derive(Clone, Copy, PartialEq)]
enum Target {
    None,
    Defaults,
    Wall(usize),
}

/// A statement's values as read.
#[derive(Clone, Copy)]
enum Raw {
    Number(f64),
    Integer(i64),
    Vector([f64; 3]),
    Type(walls_keywords::WallType),
}

struct Resolver<'t> {
    tree: &'t SyntaxTree,
    mode: ContactModel,
    units: Units,
    defaults: Settings,
    /// The defaults as the walls share them, made when the first wall after a change
    /// needs them.
    shared: Option<Arc<Settings>>,
    scene: Scene,
    target: Target,
    out: Vec<Diagnostic>,
    /// A negative `osc-freq` set in the open block, with the units in force there:
    /// reported when the block closes, its fix made once every wall is read.
    block_osc_freq: Option<(Range<usize>, Units)>,
    /// Where the open block's keyword starts.
    block_start: usize,
    /// A type written in the open block did not read.
    block_type_unread: bool,
    /// The property statements that set nothing.
    unread: Unread,
    /// The negative frequencies reported, whose fixes are made once every wall is read.
    pending_freqs: Vec<negative_osc_freq::Pending>,
}

impl Resolver<'_> {
    /// The defaults in force, shared by the walls created under them.
    fn shared_defaults(&mut self) -> Arc<Settings> {
        self.shared
            .get_or_insert_with(|| Arc::new(self.defaults.clone()))
            .clone()
    }
}

impl<'t> Resolver<'t> {
    fn statement(&mut self, stmt: &Statement, block: Option<&walls_syntax::Block>) {
        let Some(keyword) = self.tree.keyword(stmt) else {
            return;
        };
        match keyword {
            Keyword::Wall => {
                self.close_block();
                self.block_start = self.tree.span(self.tree.head(stmt)).start;
                let index = self.scene.walls.len();
                let inherited = self.shared_defaults();
                let head = self.tree.statement_span(stmt);
                let end = block
                    .and_then(|b| self.tree.body(b).last())
                    .map_or(head.end, |last| self.tree.statement_span(last).end);
                self.scene.walls.push(Wall {
                    index,
                    span: self.tree.span(self.tree.head(stmt)),
                    block: crate::Span::from(head.start..end),
                    settings: WallSettings::new(inherited),
                    units: self.units,
                });
                self.target = Target::Wall(index);
                self.block_type_unread = false;
                self.note_unread_type(keyword, self.tree.values(stmt), None);
                return;
            }
            Keyword::Defaults => {
                self.close_block();
                self.block_start = self.tree.span(self.tree.head(stmt)).start;
                self.target = Target::Defaults;
                self.block_type_unread = false;
                self.note_unread_type(keyword, self.tree.values(stmt), None);
                return;
            }
            _ => {}
        }
        if keyword.role() == Role::General && self.target != Target::Defaults {
            self.close_block();
            self.target = Target::None;
        }
        let values = self.tree.values(stmt);
        let raw = self.read(keyword, values);
        self.note_unread_type(keyword, values, raw);
        let Some(raw) = raw else {
            self.set_nothing(keyword, stmt);
            return;
        };
        let values = self.values_span(stmt);
        if keyword.role() == Role::General {
            self.general(keyword, raw, values);
        } else if self.target != Target::None {
            self.property(keyword, raw, stmt, values);
        }
    }

    /// Notes a property statement that set nothing.
    fn set_nothing(&mut self, keyword: Keyword, stmt: &Statement) {
        if keyword.role() == Role::Property {
            let start = self.tree.span(self.tree.head(stmt)).start;
            self.unread.0.push(start);
        }
    }

    /// Notes a type written in the open block that did not read (`raw` is what the
    /// statement read): a `type` whose value is not a type name, or a type name that is
    /// not the value of a `type` (`wall shell`, or one after a misspelled `type`). The wall
    /// (or the walls the defaults make) is then judged by no type.
    fn note_unread_type(&mut self, keyword: Keyword, values: &[TokenId], raw: Option<Raw>) {
        // What read is a number or a type name that is the statement's value: only the
        // values after it, or those of a statement that did not read, can be a stray one.
        let read = raw.map_or(0, |_| keyword.shape().arity());
        if read >= values.len() && raw.is_some() {
            return;
        }
        let unread = (keyword == Keyword::Type && raw.is_none())
            || values[read.min(values.len())..]
                .iter()
                .any(|&v| matches!(self.tree.kind(v), TokenKind::TypeName(_)));
        if !unread {
            return;
        }
        self.block_type_unread = true;
        match self.target {
            Target::Wall(i) => self.scene.walls[i].settings.set_type_unread(),
            Target::Defaults => {
                self.shared = None;
                self.defaults.set_type_unread(true);
            }
            Target::None => {}
        }
    }

    /// The values of a statement if they fit its keyword (the syntax check reports the
    /// ones that do not).
    fn read(&self, keyword: Keyword, values: &[TokenId]) -> Option<Raw> {
        let shape = keyword.shape();
        if values.len() < shape.arity() {
            return None;
        }
        let number = |i: usize| -> Option<f64> {
            let id = values[i];
            (self.tree.kind(id) == TokenKind::Number)
                .then(|| parse_number(self.tree.token_text(id)))
                .flatten()
        };
        match shape {
            ValueShape::None => None,
            ValueShape::Number => number(0).map(Raw::Number),
            ValueShape::Vector => Some(Raw::Vector([number(0)?, number(1)?, number(2)?])),
            ValueShape::Integer => {
                let text = self.tree.token_text(values[0]);
                let digits = text.trim_start_matches('+');
                (self.tree.kind(values[0]) == TokenKind::Number
                    && digits
                        .trim_start_matches('-')
                        .bytes()
                        .all(|b| b.is_ascii_digit()))
                .then(|| {
                    // Too many digits for 64 bits: keep the sign, so range checks fire.
                    digits.parse::<i64>().unwrap_or(if digits.starts_with('-') {
                        i64::MIN
                    } else {
                        i64::MAX
                    })
                })
                .map(Raw::Integer)
            }
            ValueShape::TypeName => match self.tree.kind(values[0]) {
                TokenKind::TypeName(t) => Some(Raw::Type(t)),
                _ => None,
            },
        }
    }

    fn values_span(&self, stmt: &Statement) -> Range<usize> {
        let values = self.tree.values(stmt);
        let arity = self
            .tree
            .keyword(stmt)
            .map_or(values.len(), |k| k.shape().arity().min(values.len()));
        match (values.first(), values.get(arity.max(1) - 1)) {
            (Some(&a), Some(&b)) => self.tree.span(a).start..self.tree.span(b).end,
            _ => self.tree.statement_span(stmt),
        }
    }

    /// The value rules' view of a statement's values.
    fn read_at(&self, keyword: Keyword, values: Range<usize>) -> Read<'t> {
        let tree = self.tree;
        Read {
            keyword,
            // Messages quote the value as written, not as scaled.
            written: &tree.text()[values.clone()],
            span: values,
            mode: self.mode,
        }
    }

    fn general(&mut self, keyword: Keyword, raw: Raw, values: Range<usize>) {
        let Raw::Number(x) = raw else { return };
        let at = self.read_at(keyword, values);
        if !rules::check_general(&at, x, &mut self.out) {
            return;
        }
        match keyword {
            Keyword::LengthUnit => self.units.length = x,
            Keyword::MassUnit => self.units.mass = x,
            Keyword::TimeUnit => self.units.time = x,
            Keyword::Time => self.scene.time = Some(x * self.units.time),
            _ => {}
        }
    }

    fn property(&mut self, keyword: Keyword, raw: Raw, stmt: &Statement, values: Range<usize>) {
        let dim = keyword.dimension();
        let scale = dim.factor(self.units.length, self.units.mass, self.units.time);
        let value = match raw {
            Raw::Number(x) => Value::Number(x * scale),
            Raw::Integer(i) => Value::Integer(i),
            Raw::Vector(v) => Value::Vector(Vec3::from(v) * scale),
            Raw::Type(t) => Value::Type(t),
        };
        let at = self.read_at(keyword, values.clone());
        if !number_too_large::check(&at, value, &mut self.out) {
            self.set_nothing(keyword, stmt);
            return;
        }
        let value = rules::check_property(&at, value, &mut self.out);
        let place = match self.target {
            Target::Defaults => Place::Defaults,
            _ => Place::Wall,
        };
        let keyword_span = self.tree.span(self.tree.head(stmt));
        let setting = Setting {
            value,
            source: Source::Set {
                place,
                values: values.clone().into(),
                derived_from: None,
            },
        };
        if keyword.value_range() == ValueRange::NonNegativeFrequency {
            self.block_osc_freq =
                negative_osc_freq::is_negative(value).then(|| (values.clone(), self.units));
        }
        // Setting a normal spring constant sets the tangential one to 2/7 of it.
        let derived = match keyword {
            Keyword::KN => Some(Keyword::KT),
            Keyword::KNOuter => Some(Keyword::KTOuter),
            Keyword::KNInner => Some(Keyword::KTInner),
            _ => None,
        };
        let derived = derived.map(|kt| {
            let Value::Number(kn) = value else {
                unreachable!("spring constants are numbers")
            };
            let v = if kn == -1.0 { -1.0 } else { 2.0 / 7.0 * kn };
            (
                kt,
                Setting {
                    value: Value::Number(v),
                    source: Source::Set {
                        place,
                        values: values.clone().into(),
                        derived_from: Some(keyword),
                    },
                },
            )
        });
        if place == Place::Defaults {
            self.scene.defaults.push((keyword, keyword_span));
        }
        match self.target {
            Target::Wall(i) => {
                let target = &mut self.scene.walls[i].settings;
                target.set(keyword, setting);
                if let Some((kt, s)) = derived {
                    target.set(kt, s);
                }
            }
            _ => {
                // The defaults change: walls created from now on share a new copy.
                self.shared = None;
                if keyword == Keyword::Type {
                    // A type that reads makes the defaults' type known, unless another
                    // written in this block did not read.
                    self.defaults.set_type_unread(self.block_type_unread);
                }
                self.defaults.set(keyword, setting);
                if let Some((kt, s)) = derived {
                    self.defaults.set(kt, s);
                }
            }
        }
    }

    /// Ends the open block: reports a negative `osc-freq` set in it, and keeps what its
    /// fix needs: the block's final amplitude and phase.
    fn close_block(&mut self) {
        let Some((freq, units)) = self.block_osc_freq.take() else {
            return;
        };
        let settings = match self.target {
            Target::Wall(i) => Some(&self.scene.walls[i].settings),
            _ => None,
        };
        let end = |k: Keyword| {
            settings
                .map_or_else(|| self.defaults.get(k), |s| s.get(k))
                .cloned()
                .unwrap_or_else(|| Setting {
                    value: match k.builtin() {
                        walls_keywords::Builtin::Number(x) => Value::Number(x),
                        _ => Value::Number(0.0),
                    },
                    source: Source::Builtin,
                })
        };
        let pending = negative_osc_freq::Pending {
            at: self.out.len(),
            in_wall: matches!(self.target, Target::Wall(_)),
            block_start: self.block_start,
            first_after: self.scene.walls.len(),
            units,
            ampl: end(Keyword::OscAmpl),
            phase: end(Keyword::OscPhase),
            freq,
        };
        self.out.push(negative_osc_freq::at_block_end(
            self.tree.text(),
            &pending.freq,
        ));
        self.pending_freqs.push(pending);
    }
}

#[cfg(test)]
mod tests {
    use super::parse_number;

    #[test]
    fn fast_numbers_equal_std_parse() {
        for text in [
            "0",
            "-0",
            "1",
            "+3",
            "5.",
            ".5",
            "-0.5",
            "0.1234",
            "123456789012345",
            "1234567890123456",
            "0.000000000000000000000001",
            "1.99102e-07",
            "+3E+2",
            "6.68458e-14",
            "99",
            "-1",
            "0.30000000000000004",
            "9007199254740993",
        ] {
            let expected: f64 = text.parse().unwrap();
            let got = parse_number(text).unwrap();
            assert_eq!(got.to_bits(), expected.to_bits(), "{text}");
        }
    }
}
