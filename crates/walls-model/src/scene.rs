//! The resolved scene: every wall with the effective value of every token.
//!
//! A wall stores only what was set for it (the `defaults` in force when it was created,
//! then its own tokens); anything else is the keyword's built-in default. Every value is
//! in pkdgrav units (scaled by the units in force when it was read) and remembers where
//! it came from, so diagnostics and hovers can point there.

use nalgebra::Vector3;
use smallvec::SmallVec;
use std::ops::Range;
use std::sync::Arc;
use walls_keywords::{Builtin, Keyword, WallType};

/// A 3-vector of reals.
pub type Vec3 = Vector3<f64>;

/// An effective value, in pkdgrav units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Value {
    /// A real.
    Number(f64),
    /// An integer (`color`, `cohesion_model`, `assembly`).
    Integer(i64),
    /// A vector; `orient` and `osc-vec` are normalised (unless zero).
    Vector(Vec3),
    /// A wall type.
    Type(WallType),
}

impl Value {
    /// The value of `k` before anything sets it (`None` for keywords without a value).
    #[inline]
    pub fn builtin(k: Keyword) -> Option<Value> {
        Value::from_builtin(k.builtin())
    }

    #[inline]
    fn from_builtin(b: Builtin) -> Option<Value> {
        match b {
            Builtin::None => None,
            Builtin::Number(x) => Some(Value::Number(x)),
            Builtin::Integer(i) => Some(Value::Integer(i)),
            Builtin::Vector(v) => Some(Value::Vector(Vec3::from(v))),
            Builtin::Type(t) => Some(Value::Type(t)),
        }
    }
}

/// The unit vector along `v`, or `None` for the zero vector. Scales by the largest
/// component first, so vectors whose length overflows a double (1e308 1e308 0) still
/// have a direction.
#[inline]
pub fn direction(v: &Vec3) -> Option<Vec3> {
    // The common case in one square root; tiny and huge vectors take the scaled path.
    let n2 = v.norm_squared();
    if n2.is_normal() && n2 < f64::MAX {
        return Some(v / n2.sqrt());
    }
    let largest = v.amax();
    if largest == 0.0 || !largest.is_finite() {
        return None;
    }
    (v / largest).try_normalize(0.0)
}

/// A byte range of the source, stored in 32 bits a side (a wall keeps several).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Span {
    start: u32,
    end: u32,
}

impl Span {
    /// The byte range.
    pub fn range(self) -> Range<usize> {
        self.start as usize..self.end as usize
    }
}

impl From<Range<usize>> for Span {
    fn from(r: Range<usize>) -> Self {
        // Texts are under 4 GiB (walls-syntax stores 32-bit offsets too).
        Span {
            start: r.start as u32,
            end: r.end as u32,
        }
    }
}

/// Where a token that set a value stands.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Place {
    /// In a `defaults` block.
    Defaults,
    /// In the wall's own block.
    Wall,
}

/// Where an effective value came from.
#[derive(Debug, Clone, PartialEq)]
pub enum Source {
    /// Nothing set it: the keyword's built-in default.
    Builtin,
    /// A token set it.
    Set {
        /// In a `defaults` block or the wall's own block.
        place: Place,
        /// The values of the token that set it (for a `k_t` derived from `k_n`: the
        /// `k_n`'s). Its keyword is the token before them.
        values: Span,
        /// Set as a consequence of another keyword: `k_t` is 2/7 of a `k_n` set later.
        derived_from: Option<Keyword>,
    },
}

impl Source {
    /// The span to point at for this value: the values of the token that set it.
    pub fn span(&self) -> Option<Range<usize>> {
        match self {
            Source::Builtin => None,
            Source::Set { values, .. } => Some(values.range()),
        }
    }
}

/// An effective value with its source.
#[derive(Debug, Clone, PartialEq)]
pub struct Setting {
    /// The value, in pkdgrav units.
    pub value: Value,
    /// Where it came from.
    pub source: Source,
}

/// A set of values: the defaults, or what a wall overrides. A wall usually sets a few
/// tokens, kept inline: a file of 100,000 walls makes no allocation per wall.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Settings {
    entries: SmallVec<[(Keyword, Setting); 4]>,
    /// A type was written that did not read (see [`Wall::known_type`]).
    type_unread: bool,
}

impl Settings {
    /// The setting for `k`, if something set it.
    #[inline]
    pub fn get(&self, k: Keyword) -> Option<&Setting> {
        self.entries
            .iter()
            .find(|(key, _)| *key == k)
            .map(|(_, s)| s)
    }

    /// Sets `k`, replacing an earlier setting.
    pub fn set(&mut self, k: Keyword, setting: Setting) {
        match self.entries.iter_mut().find(|(key, _)| *key == k) {
            Some(entry) => entry.1 = setting,
            None => self.entries.push((k, setting)),
        }
    }

    /// Every setting, in the order first set.
    pub fn iter(&self) -> impl Iterator<Item = &(Keyword, Setting)> {
        self.entries.iter()
    }

    /// Whether a type written for these settings did not read.
    pub fn type_unread(&self) -> bool {
        self.type_unread
    }

    /// Says whether a type written for these settings did not read.
    pub(crate) fn set_type_unread(&mut self, unread: bool) {
        self.type_unread = unread;
    }
}

/// What was set for a wall: the `defaults` in force when it was created, shared with
/// the other walls created under them (a file of 100,000 walls with a `defaults` block
/// keeps that block once, not 100,000 times), then its own tokens.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct WallSettings {
    inherited: Arc<Settings>,
    own: Settings,
}

impl WallSettings {
    /// A wall's settings starting from `inherited`.
    pub fn new(inherited: Arc<Settings>) -> Self {
        WallSettings {
            inherited,
            own: Settings::default(),
        }
    }

    /// The setting for `k`: the wall's own, else the inherited default's.
    #[inline]
    pub fn get(&self, k: Keyword) -> Option<&Setting> {
        self.own.get(k).or_else(|| self.inherited.get(k))
    }

    /// Sets `k` for this wall, over what it inherited.
    pub fn set(&mut self, k: Keyword, setting: Setting) {
        self.own.set(k, setting);
    }

    /// The setting for `k` the wall takes from its `defaults`, whatever it sets itself.
    pub fn inherited(&self, k: Keyword) -> Option<&Setting> {
        self.inherited.get(k)
    }

    /// Notes that a type written in the wall's block did not read: the wall's type is
    /// unknown, whatever else its block or its defaults say.
    pub(crate) fn set_type_unread(&mut self) {
        self.own.set_type_unread(true);
    }

    /// Whether the wall's type is unknown: a type written in its block did not read, or
    /// its block sets no type and it inherits defaults whose type did not read.
    pub fn type_unread(&self) -> bool {
        self.own.type_unread()
            || (self.own.get(Keyword::Type).is_none() && self.inherited.type_unread())
    }

    /// Every setting: the inherited ones in their order (each as the wall overrides it),
    /// then the wall's own new ones in the order they were set, as if the defaults had
    /// been copied into the wall and then overwritten.
    pub fn iter(&self) -> impl Iterator<Item = &(Keyword, Setting)> {
        let inherited = self.inherited.iter().map(|entry| {
            self.own
                .iter()
                .find(|(k, _)| *k == entry.0)
                .unwrap_or(entry)
        });
        let new = self
            .own
            .iter()
            .filter(|(k, _)| self.inherited.get(*k).is_none());
        inherited.chain(new)
    }
}

/// One wall, as pkdgrav builds it.
#[derive(Debug, Clone, PartialEq)]
pub struct Wall {
    /// Its index among the walls (pkdgrav's wall id), from 0.
    pub index: usize,
    /// The `wall` keyword.
    pub span: Range<usize>,
    /// Its block, from the `wall` keyword to the end of the block's last statement: the
    /// source map from the tree to the walls (walls are in file order, so the wall at an
    /// offset is a binary search).
    pub block: Span,
    /// What was set for it: the defaults in force at `wall`, then its own tokens.
    pub settings: WallSettings,
    /// The units in force at `wall` (and through its block, which a unit token closes):
    /// what its values were scaled by.
    pub units: Units,
}

impl Wall {
    /// The effective setting of `k` (built-in default if nothing set it). `None` only
    /// for keywords that take no value.
    #[inline]
    pub fn setting(&self, k: Keyword) -> Option<Setting> {
        self.settings.get(k).cloned().or_else(|| {
            Value::from_builtin(k.builtin()).map(|value| Setting {
                value,
                source: Source::Builtin,
            })
        })
    }

    /// The effective value of `k`.
    #[inline]
    pub fn value(&self, k: Keyword) -> Option<Value> {
        self.settings
            .get(k)
            .map(|s| s.value)
            .or_else(|| Value::from_builtin(k.builtin()))
    }

    /// The effective real value of a number-valued keyword (0 for others).
    #[inline]
    pub fn number(&self, k: Keyword) -> f64 {
        match self.value(k) {
            Some(Value::Number(x)) => x,
            Some(Value::Integer(i)) => i as f64,
            _ => 0.0,
        }
    }

    /// The effective integer value of an integer-valued keyword (0 for others).
    #[inline]
    pub fn integer(&self, k: Keyword) -> i64 {
        match self.value(k) {
            Some(Value::Integer(i)) => i,
            _ => 0,
        }
    }

    /// The effective vector value of a vector-valued keyword (zero for others).
    #[inline]
    pub fn vector(&self, k: Keyword) -> Vec3 {
        match self.value(k) {
            Some(Value::Vector(v)) => v,
            _ => Vec3::zeros(),
        }
    }

    /// The wall's type, if it is known: `None` when a type written for the wall (in its
    /// block, or in the `defaults` it inherits its type from) did not read: a `type`
    /// without a type name after it, or a type name that is not the value of a `type`
    /// (`wall shell`). Such a wall is judged by no type: the checks that depend on the
    /// type are silent on it, and the syntax error is the finding.
    #[inline]
    pub fn known_type(&self) -> Option<WallType> {
        (!self.settings.type_unread()).then(|| self.wall_type())
    }

    /// The wall's type as pkdgrav's reader leaves it: the last `type` that read, plane
    /// if none did (see [`Wall::known_type`] for the checks).
    #[inline]
    pub fn wall_type(&self) -> WallType {
        match self.value(Keyword::Type) {
            Some(Value::Type(t)) => t,
            _ => WallType::Plane,
        }
    }

    /// The unit normal: `orient`, or for triangles and rectangles vertex1 × vertex2
    /// normalised (zero when degenerate).
    pub fn normal(&self) -> Vec3 {
        match self.wall_type() {
            WallType::Triangle | WallType::Rectangle => {
                let edges = direction(&self.vector(Keyword::Vertex1))
                    .zip(direction(&self.vector(Keyword::Vertex2)));
                edges
                    .and_then(|(a, b)| direction(&a.cross(&b)))
                    .unwrap_or_else(Vec3::zeros)
            }
            _ => self.vector(Keyword::Orient),
        }
    }

    /// Whether the wall has a finite mass and so reacts to particles.
    #[inline]
    pub fn is_reactive(&self) -> bool {
        self.number(Keyword::Mass) > 0.0
    }
}

/// The walls of a file, in order.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Scene {
    /// Every wall, in file order.
    pub walls: Vec<Wall>,
    /// Every property set in a `defaults` block, in file order, with its keyword's span.
    pub defaults: Vec<(Keyword, Range<usize>)>,
    /// The units in force at the end of the file.
    pub units: Units,
    /// The file's `time` (the last one written) in pkdgrav units, times the `timeunit`
    /// in force where it is written; `None` without one.
    pub time: Option<f64>,
}

/// `lengthunit`, `massunit` and `timeunit` as the file set them (docs/spec.md §1): how
/// many pkdgrav units one of the file's units is. All 1 until set.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Units {
    /// pkdgrav lengths per file length.
    pub length: f64,
    /// pkdgrav masses per file mass.
    pub mass: f64,
    /// pkdgrav times per file time.
    pub time: f64,
}

impl Default for Units {
    fn default() -> Self {
        Units {
            length: 1.0,
            mass: 1.0,
            time: 1.0,
        }
    }
}

impl Units {
    /// Whether the file set any unit (to something other than 1).
    pub fn are_set(&self) -> bool {
        *self != Units::default()
    }
}
