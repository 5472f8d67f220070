//! A wall (or the defaults block) as a program builds it: its type and its tokens, each
//! checked as it is set; and the unit tokens of a file.

use crate::value::{self, BuildError, Given, UNITS, Value, WALL};
use walls_keywords::{Keyword, WallType, pkdgrav_units};

/// A wall: its type and its tokens in the order they were set. Also the `defaults`
/// block, whose tokens every later wall starts from.
///
/// Each token is checked against the keyword table as it is set ([`Wall::set`]): its
/// name, the shape of its value, integers, finiteness. What depends on the whole file
/// (ranges, perpendicular rectangle sides, tokens a type ignores) is checked when the
/// file is written ([`crate::dumps`]).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Wall {
    /// `type` first when set, then every other token once, in the order last set.
    tokens: Vec<(Keyword, Value)>,
}

impl Wall {
    /// A wall with no tokens: the type and values of the defaults in force (a plane
    /// unless the defaults say otherwise).
    pub fn new() -> Wall {
        Wall::default()
    }

    /// A wall of the type named `type_name` (any spelling pkdgrav reads: `disc` is a disk).
    pub fn of_type(type_name: &str) -> Result<Wall, BuildError> {
        let mut wall = Wall::new();
        wall.set("type", Given::Text(type_name.to_string()))?;
        Ok(wall)
    }

    /// Sets the token `name` (any case; `_` may stand for `-`, as in `osc_ampl`) to
    /// `value`, replacing an earlier value of it; `type` takes a wall type name. A value
    /// that does not fit leaves the wall as it was.
    pub fn set(&mut self, name: &str, value: impl Into<Given>) -> Result<&mut Wall, BuildError> {
        let (keyword, value) = value::check(name, value.into(), WALL)?;
        self.put(keyword, value);
        Ok(self)
    }

    /// [`Wall::set`], by value, for chains: `Wall::of_type("disk")?.with("radius", 0.5)?`.
    pub fn with(mut self, name: &str, value: impl Into<Given>) -> Result<Wall, BuildError> {
        self.set(name, value)?;
        Ok(self)
    }

    /// A triangle from its reference vertex and the vectors to the other two.
    pub(crate) fn polygon(t: WallType, origin: [f64; 3], v1: [f64; 3], v2: [f64; 3]) -> Wall {
        Wall {
            tokens: vec![
                (Keyword::Type, Value::Type(t)),
                (Keyword::Origin, Value::Vector(origin)),
                (Keyword::Vertex1, Value::Vector(v1)),
                (Keyword::Vertex2, Value::Vector(v2)),
            ],
        }
    }

    fn put(&mut self, keyword: Keyword, value: Value) {
        self.tokens.retain(|(k, _)| *k != keyword);
        if keyword == Keyword::Type {
            self.tokens.insert(0, (keyword, value));
        } else {
            self.tokens.push((keyword, value));
        }
    }

    /// The wall's type name, if it sets one.
    pub fn wall_type(&self) -> Option<&'static str> {
        self.tokens.iter().find_map(|(_, v)| match v {
            Value::Type(t) => Some(t.name()),
            _ => None,
        })
    }

    /// The value of the token `name` (spelled as for [`Wall::set`]), if set.
    pub fn get(&self, name: &str) -> Option<Value> {
        let keyword = value::keyword_named(name).ok()?;
        self.tokens
            .iter()
            .find(|(k, _)| *k == keyword)
            .map(|&(_, v)| v)
    }

    /// The tokens as the file writes them: canonical names and values, `type` first.
    pub fn tokens(&self) -> impl Iterator<Item = (&'static str, Value)> + '_ {
        self.tokens.iter().map(|&(k, v)| (k.name(), v))
    }

    /// Whether no token is set.
    pub fn is_empty(&self) -> bool {
        self.tokens.is_empty()
    }
}

/// The unit tokens a file starts with: `lengthunit`, `massunit` and `timeunit`, the
/// size of the file's unit in pkdgrav's (docs/units.md).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Units {
    tokens: Vec<(Keyword, f64)>,
}

impl Units {
    /// No unit tokens: every value is in pkdgrav's units.
    pub fn new() -> Units {
        Units::default()
    }

    /// Sets `lengthunit`, `massunit` or `timeunit`. Whether it is positive is checked
    /// with the file.
    pub fn set(&mut self, name: &str, value: impl Into<Given>) -> Result<&mut Units, BuildError> {
        let (keyword, value) = value::check(name, value.into(), UNITS)?;
        let Value::Number(x) = value else {
            unreachable!("the unit tokens take numbers");
        };
        self.tokens.retain(|(k, _)| *k != keyword);
        self.tokens.push((keyword, x));
        Ok(self)
    }

    /// A file whose lengths are in `unit`.
    pub fn length(unit: LengthUnit) -> Units {
        Units {
            tokens: vec![(Keyword::LengthUnit, unit.in_au())],
        }
    }

    /// The tokens in the order set.
    pub fn tokens(&self) -> impl Iterator<Item = (&'static str, f64)> + '_ {
        self.tokens.iter().map(|&(k, x)| (k.name(), x))
    }
}

/// A unit of length a mesh may be in, written as the `lengthunit` that makes its numbers
/// that unit (docs/meshes.md).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LengthUnit {
    /// Millimetres.
    Mm,
    /// Centimetres.
    Cm,
    /// Metres.
    M,
    /// Kilometres.
    Km,
    /// Astronomical units, pkdgrav's own.
    Au,
}

impl LengthUnit {
    /// Every unit, with its name.
    pub const ALL: &'static [(&'static str, LengthUnit)] = &[
        ("mm", LengthUnit::Mm),
        ("cm", LengthUnit::Cm),
        ("m", LengthUnit::M),
        ("km", LengthUnit::Km),
        ("au", LengthUnit::Au),
    ];

    /// The unit named `name` (`mm`, `cm`, `m`, `km`, `au`, any case).
    pub fn named(name: &str) -> Option<LengthUnit> {
        value::named(LengthUnit::ALL, name)
    }

    /// The unit's size in astronomical units: its `lengthunit`, with the toolkit's AU
    /// (`walls_keywords::pkdgrav_units::AU_M`, docs/units.md).
    pub fn in_au(self) -> f64 {
        let cm = match self {
            LengthUnit::Mm => 0.1,
            LengthUnit::Cm => 1.0,
            LengthUnit::M => 100.0,
            LengthUnit::Km => 1e5,
            LengthUnit::Au => return 1.0,
        };
        cm / (pkdgrav_units::AU_M * 100.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tokens_keep_the_order_last_set_with_the_type_first() {
        let mut wall = Wall::new();
        wall.set("k_t", 1.0).unwrap();
        wall.set("radius", 2.0).unwrap();
        wall.set("TYPE", "disc").unwrap();
        wall.set("k_t", 3.0).unwrap();
        let names: Vec<_> = wall.tokens().map(|(n, _)| n).collect();
        assert_eq!(names, ["type", "radius", "k_t"]);
        assert_eq!(wall.wall_type(), Some("disk"));
        assert_eq!(wall.get("K_T"), Some(Value::Number(3.0)));
    }

    #[test]
    fn a_refused_value_leaves_the_wall_as_it_was() {
        let mut wall = Wall::of_type("triangle").unwrap();
        wall.set("color", 3).unwrap();
        assert!(wall.set("color", 3.5).is_err());
        assert_eq!(wall.get("color"), Some(Value::Integer(3)));
    }

    #[test]
    fn length_units_are_their_size_in_au() {
        assert_eq!(LengthUnit::Cm.in_au(), 6.684587122268446e-14);
        assert_eq!(LengthUnit::named("KM"), Some(LengthUnit::Km));
        assert_eq!(LengthUnit::Au.in_au(), 1.0);
        assert_eq!(LengthUnit::named("inch"), None);
    }
}
