//! Reading a parsed file the way pkdgrav does, front to back, into a [`Scene`].
//!
//! Units scale the values read after them; `defaults` edits the default wall; `wall`
//! appends a copy of the defaults; units and `time` close a wall block. Each value is
//! checked as it is read (ranges, zero vectors, numbers too large for a double), since
//! pkdgrav refuses such a file at that token. Statements whose values the syntax check
//! already rejected are skipped, so a broken file still resolves to what parsed.

use crate::Mode;
use crate::codes;
use crate::fix;
use crate::scene::{Place, Scene, Setting, Settings, Source, Value, Vec3, Wall, WallSettings};
use std::ops::Range;
use std::sync::Arc;
use walls_diagnostics::{Applicability, Diagnostic, Edit, Severity};
use walls_keywords::{Dimension, Keyword, Role, ValueShape};
use walls_syntax::{Statement, SyntaxTree, TokenKind};

/// A principal axis may differ from unit length by this much.
pub const AXIS_LENGTH_TOLERANCE: f64 = 0.001;

/// Resolves `tree` into the scene pkdgrav would build, with the diagnostics about single
/// values found on the way.
pub fn resolve(tree: &SyntaxTree, mode: Mode) -> (Scene, Vec<Diagnostic>) {
    let mut r = Resolver {
        tree,
        mode,
        units: Units {
            length: 1.0,
            mass: 1.0,
            time: 1.0,
        },
        defaults: Settings::default(),
        shared: None,
        scene: Scene::default(),
        target: Target::None,
        out: Vec::new(),
        block_osc_freq: None,
        block_start: 0,
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
    (r.scene, r.out)
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

#[derive(Clone, Copy)]
struct Units {
    length: f64,
    mass: f64,
    time: f64,
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
    mode: Mode,
    units: Units,
    defaults: Settings,
    /// The defaults as the walls share them, made when the first wall after a change
    /// needs them.
    shared: Option<Arc<Settings>>,
    scene: Scene,
    target: Target,
    out: Vec<Diagnostic>,
    /// A negative `osc-freq` set in the open block: reported when the block closes,
    /// with a fix computed from the block's final amplitude and phase.
    block_osc_freq: Option<(Range<usize>, f64)>,
    /// Where the open block's keyword starts.
    block_start: usize,
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
                });
                self.target = Target::Wall(index);
                return;
            }
            Keyword::Defaults => {
                self.close_block();
                self.block_start = self.tree.span(self.tree.head(stmt)).start;
                self.target = Target::Defaults;
                return;
            }
            _ => {}
        }
        if keyword.role() == Role::General && self.target != Target::Defaults {
            self.close_block();
            self.target = Target::None;
        }
        let Some(raw) = self.read(keyword, stmt) else {
            return;
        };
        let values = self.values_span(stmt);
        if keyword.role() == Role::General {
            self.general(keyword, raw, values);
        } else if self.target != Target::None {
            self.property(keyword, raw, stmt, values);
        }
    }

    /// The values of a statement if they fit its keyword (the syntax check reports the
    /// ones that do not).
    fn read(&self, keyword: Keyword, stmt: &Statement) -> Option<Raw> {
        let values = self.tree.values(stmt);
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

    fn general(&mut self, keyword: Keyword, raw: Raw, values: Range<usize>) {
        let Raw::Number(x) = raw else { return };
        let name = keyword.name();
        match keyword {
            Keyword::Time => {
                if x < 0.0 {
                    self.push(Diagnostic::error(
                        &codes::NEGATIVE_TIME,
                        values,
                        format!("`time` is {x}; it must not be negative"),
                    ));
                } else if x != 0.0 {
                    self.push(
                        Diagnostic::new(
                            &codes::TIME_IGNORED,
                            Severity::Info,
                            values,
                            "pkdgrav ignores `time`",
                        )
                        .with_help("to place moving walls at a time, set the time in the particle (ss) file"),
                    );
                }
            }
            _ if !x.is_finite() || x <= 0.0 => self.push(Diagnostic::error(
                &codes::UNIT_NOT_POSITIVE,
                values,
                format!("`{name}` must be positive, not {x}; the unit in force is kept"),
            )),
            Keyword::LengthUnit => self.units.length = x,
            Keyword::MassUnit => self.units.mass = x,
            Keyword::TimeUnit => self.units.time = x,
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
        if !self.finite(keyword, value, &values, dim) {
            return;
        }
        let value = self.check_value(keyword, value, &values);
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
        if keyword == Keyword::OscFreq {
            self.block_osc_freq = matches!(value, Value::Number(w) if w < 0.0)
                .then(|| (values.clone(), self.units.length));
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
                self.defaults.set(keyword, setting);
                if let Some((kt, s)) = derived {
                    self.defaults.set(kt, s);
                }
            }
        }
    }

    /// Scaled values must stay finite doubles: `1e999`, or a huge value times a unit.
    fn finite(
        &mut self,
        keyword: Keyword,
        value: Value,
        values: &Range<usize>,
        dim: Dimension,
    ) -> bool {
        let finite = match value {
            Value::Number(x) => x.is_finite(),
            Value::Vector(v) => v.iter().all(|x| x.is_finite()),
            _ => true,
        };
        if !finite {
            self.push(
                Diagnostic::error(
                    &codes::NUMBER_TOO_LARGE,
                    values.clone(),
                    format!(
                        "`{}` is too large for a double once scaled ({})",
                        keyword.name(),
                        dim.describe()
                    ),
                )
                .with_help(
                    "the value is ignored; write it in units that keep it below about 1.8e308",
                ),
            );
        }
        finite
    }

    /// Range rules of single values (SPEC §1 table); returns the value to store
    /// (normalised vectors, transparency as a fraction).
    fn check_value(&mut self, keyword: Keyword, value: Value, values: &Range<usize>) -> Value {
        let span = values.clone();
        let name = keyword.name();
        // Messages quote the value as written, not as scaled.
        let tree = self.tree;
        let written = &tree.text()[values.clone()];
        match (keyword, value) {
            (Keyword::Orient | Keyword::OscVec, Value::Vector(v)) => {
                match crate::scene::direction(&v) {
                    Some(n) => return Value::Vector(n),
                    None => self.zero_vector(keyword, span),
                }
            }
            (Keyword::Vertex1 | Keyword::Vertex2, Value::Vector(v)) if v.norm() == 0.0 => {
                self.zero_vector(keyword, span)
            }
            (
                Keyword::Step | Keyword::Radius | Keyword::HoleRadius | Keyword::Length | Keyword::Mass,
                Value::Number(x),
            ) if x < 0.0 => self.push(Diagnostic::error(
                &codes::NEGATIVE_VALUE,
                span,
                format!("`{name}` is {written}; it must not be negative"),
            )),
            (Keyword::Taper, Value::Number(x)) if !(0.0..=1.0).contains(&x) => self.push(
                Diagnostic::error(&codes::TAPER_RANGE, span, format!("`taper` is {written}; it must be between 0 and 1"))
                    .with_help("0 is a plain cylinder, 1 narrows it to a point at the +orient end"),
            ),
            (Keyword::OpenAngle, Value::Number(x)) if !(0.0..=180.0).contains(&x) => self.push(
                Diagnostic::error(
                    &codes::OPEN_ANGLE_RANGE,
                    span,
                    format!("`open-angle` is {written}; it must be between 0 and 180 degrees"),
                ),
            ),
            (Keyword::OscPhase, Value::Number(x)) if !(0.0..=1.0).contains(&x) => self.push(
                Diagnostic::error(
                    &codes::OSC_PHASE_RANGE,
                    span,
                    format!("`osc-phase` is {written}; it is a fraction of a cycle, between 0 and 1"),
                )
                .with_help(format!("the same phase within one cycle is {}", fix::number(x.rem_euclid(1.0)))),
            ),
            (Keyword::Epsn, Value::Number(x)) if x != 99.0 && x > 1.0 => self.push(
                Diagnostic::error(&codes::EPSN_RANGE, span, format!("`epsn` is {written}; it must be at most 1, or 99"))
                    .with_help("99 means the particle's value; 1 is elastic, 0 sticks, negative removes the particle"),
            ),
            (Keyword::Epst, Value::Number(x)) => {
                let (lo, model) = match self.mode {
                    Mode::Hsdem => (-1.0, "HSDEM"),
                    Mode::Ssdem => (0.0, "SSDEM"),
                };
                if x != 99.0 && !(lo..=1.0).contains(&x) {
                    self.push(
                        Diagnostic::error(
                            &codes::EPST_RANGE,
                            span,
                            format!("`epst` is {written}; in {model} it must be between {lo} and 1, or 99"),
                        )
                        .with_help("99 means the particle's value"),
                    );
                }
            }
            (Keyword::Color, Value::Integer(c)) if !(0..=255).contains(&c) => self.push(Diagnostic::error(
                &codes::COLOR_RANGE,
                span,
                format!("`color` is {written}; it must be between 0 and 255"),
            )),
            (Keyword::Transparency, Value::Number(x)) => {
                if !(0.0..=100.0).contains(&x) {
                    self.push(Diagnostic::error(
                        &codes::TRANSPARENCY_RANGE,
                        span,
                        format!("`transparency` is {written}; it must be between 0 and 1, or a percentage up to 100"),
                    ));
                } else if x > 1.0 {
                    return Value::Number(x / 100.0);
                }
            }
            (
                Keyword::KN
                | Keyword::KT
                | Keyword::MuS
                | Keyword::MuR
                | Keyword::MuT
                | Keyword::BetaS
                | Keyword::CohesiveCoeff
                | Keyword::InnerOverlapBoundary
                | Keyword::KNOuter
                | Keyword::KTOuter
                | Keyword::KNInner
                | Keyword::KTInner,
                Value::Number(x),
            ) if x != -1.0 && x < 0.0 => self.push(
                Diagnostic::error(
                    &codes::MATERIAL_RANGE,
                    span,
                    format!("`{name}` is {written}; it must be −1 (the particle's value) or at least 0"),
                ),
            ),
            (Keyword::CohesionModel, Value::Integer(m)) if !(-1..=1).contains(&m) => self.push(
                Diagnostic::error(
                    &codes::COHESION_MODEL,
                    span,
                    format!("`cohesion_model` is {written}; it must be −1 (particle's), 0 (contact) or 1 (bridge)"),
                ),
            ),
            (Keyword::Assembly, Value::Integer(a)) if !(0..=1).contains(&a) => {
                let message = if a == -1 {
                    "`assembly -1` cannot be written: pkdgrav reads only 0 or 1".to_string()
                } else {
                    format!("`assembly` is {written}; pkdgrav allows 2 assemblies, numbered 0 and 1")
                };
                self.push(
                    Diagnostic::error(&codes::INVALID_ASSEMBLY, span, message)
                        .with_help("a wall that is in no assembly simply leaves `assembly` out"),
                );
            }
            (Keyword::PxjVec | Keyword::PyjVec | Keyword::PzjVec, Value::Vector(v))
                if (v.norm() - 1.0).abs() > AXIS_LENGTH_TOLERANCE =>
            {
                let mut d = Diagnostic::error(
                    &codes::AXIS_NOT_UNIT,
                    span.clone(),
                    format!("principal axis `{name}` has length {:.6}; it must be 1 ± {AXIS_LENGTH_TOLERANCE}", v.norm()),
                );
                if let Some(n) = crate::scene::direction(&v) {
                    d = d.with_fix(
                        Applicability::Unsafe,
                        "normalise the axis",
                        vec![Edit {
                            span,
                            replacement: fix::vector(&n),
                        }],
                    );
                }
                self.push(d);
            }
            (Keyword::IxjVec | Keyword::IyjVec | Keyword::IzjVec, Value::Vector(v)) => {
                let row = match keyword {
                    Keyword::IxjVec => 0,
                    Keyword::IyjVec => 1,
                    _ => 2,
                };
                if (0..3).any(|j| j != row && v[j] != 0.0) {
                    self.push(
                        Diagnostic::warning(
                            &codes::INERTIA_OFF_DIAGONAL,
                            span,
                            format!("`{name}` has off-diagonal terms; pkdgrav uses only the diagonal"),
                        )
                        .with_help("give the inertia in the principal frame (pxj-vec, pyj-vec, pzj-vec) so it is diagonal"),
                    );
                }
            }
            _ => {}
        }
        value
    }

    fn zero_vector(&mut self, keyword: Keyword, span: Range<usize>) {
        self.push(Diagnostic::error(
            &codes::ZERO_VECTOR,
            span,
            format!(
                "`{}` is the zero vector; it must have a direction",
                keyword.name()
            ),
        ));
    }

    /// Ends the open block: reports a negative `osc-freq` set in it, with a fix from the
    /// block's final amplitude and phase.
    fn close_block(&mut self) {
        let Some((values, length_unit)) = self.block_osc_freq.take() else {
            return;
        };
        let get = |k: Keyword| match self.target {
            Target::Wall(i) => self.scene.walls[i].settings.get(k),
            _ => self.defaults.get(k),
        };
        let lookup = |k: Keyword| {
            get(k).cloned().unwrap_or_else(|| Setting {
                value: match k.builtin() {
                    walls_keywords::Builtin::Number(x) => Value::Number(x),
                    _ => Value::Number(0.0),
                },
                source: Source::Builtin,
            })
        };
        let d = fix::negative_osc_freq(
            self.tree.text(),
            self.block_start,
            length_unit,
            &values,
            &lookup(Keyword::OscAmpl),
            &lookup(Keyword::OscPhase),
        );
        self.push(d);
    }

    fn push(&mut self, d: Diagnostic) {
        self.out.push(d);
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
