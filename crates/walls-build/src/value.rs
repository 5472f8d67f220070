//! A token's value as a program gives it, checked against the keyword table as it is set,
//! and numbers written so that pkdgrav's C reader (`atof`) reads them back exactly.

use std::fmt;
use walls_keywords::{Keyword, Role, ValueShape, WallType};
use walls_syntax::Suggestion;

/// A value as a program gives it, before it is checked against its keyword: what a
/// Python object, a command-line word or a Rust literal becomes.
#[derive(Debug, Clone, PartialEq)]
pub enum Given {
    /// `true` or `false` (never a number here, whatever C or Python think).
    Bool(bool),
    /// A whole number.
    Int(i64),
    /// A real number.
    Float(f64),
    /// A word: a wall type name, or a mistake.
    Text(String),
    /// A sequence: a vector's components.
    List(Vec<Given>),
}

impl Given {
    /// A value as written on a command line (`--set KEY=VALUE`): a whole number, a real,
    /// three of them separated by commas or spaces (a vector), or a word. A real is read
    /// by the tools' one rule for numbers ([`walls_keywords::number`]): one that is not
    /// finite, overflows or underflows (`1e-400`, which pkdgrav would read as 0) is
    /// refused, with what is wrong (a subnormal is read; the file gets its S110 warning).
    pub fn parse(text: &str) -> Result<Given, String> {
        use walls_keywords::number::{self, Problem};
        let parts: Vec<&str> = text
            .split([',', ' ', '\t'])
            .filter(|p| !p.is_empty())
            .collect();
        let one = |p: &str| {
            if let Ok(i) = p.parse::<i64>() {
                return Ok(Given::Int(i));
            }
            match number::read(p) {
                Ok(x) => Ok(Given::Float(x)),
                Err(Problem::NotANumber) => Ok(Given::Text(p.to_string())),
                Err(why) => Err(format!("`{p}` is {why}")),
            }
        };
        match parts.as_slice() {
            [p] => one(p),
            [] => Ok(Given::Text(String::new())),
            _ => parts
                .into_iter()
                .map(one)
                .collect::<Result<_, _>>()
                .map(Given::List),
        }
    }

    /// The value as a message names it.
    fn describe(&self) -> String {
        match self {
            Given::Bool(b) => format!("the bool `{b}`"),
            Given::Int(i) => format!("the integer `{i}`"),
            Given::Float(x) => format!("the number `{}`", number(*x)),
            Given::Text(t) => format!("the word `{t}`"),
            Given::List(l) => format!(
                "a list of {} value{}",
                l.len(),
                if l.len() == 1 { "" } else { "s" }
            ),
        }
    }
}

impl From<f64> for Given {
    fn from(x: f64) -> Self {
        Given::Float(x)
    }
}

impl From<i64> for Given {
    fn from(i: i64) -> Self {
        Given::Int(i)
    }
}

impl From<i32> for Given {
    fn from(i: i32) -> Self {
        Given::Int(i.into())
    }
}

impl From<bool> for Given {
    fn from(b: bool) -> Self {
        Given::Bool(b)
    }
}

impl From<&str> for Given {
    fn from(t: &str) -> Self {
        Given::Text(t.to_string())
    }
}

impl From<[f64; 3]> for Given {
    fn from(v: [f64; 3]) -> Self {
        Given::List(v.iter().map(|&x| Given::Float(x)).collect())
    }
}

/// A checked value, of its keyword's shape.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Value {
    /// A finite real.
    Number(f64),
    /// An integer.
    Integer(i64),
    /// Three finite reals.
    Vector([f64; 3]),
    /// A wall type.
    Type(WallType),
}

impl fmt::Display for Value {
    /// The value as the walls file writes it.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Value::Number(x) => f.write_str(&number(*x)),
            Value::Integer(i) => write!(f, "{i}"),
            Value::Vector([x, y, z]) => {
                write!(f, "{} {} {}", number(*x), number(*y), number(*z))
            }
            Value::Type(t) => f.write_str(t.name()),
        }
    }
}

/// Why a token or a wall type was refused.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum BuildError {
    /// No keyword has this name.
    UnknownKeyword {
        /// The name given.
        name: String,
        /// A keyword it may be a misspelling of.
        suggestion: Option<&'static str>,
    },
    /// A keyword that has no place here: a unit or `wall` among a wall's tokens, a wall
    /// token among the units.
    Misplaced {
        /// The keyword.
        keyword: &'static str,
        /// What was being set: "a wall" or "the units".
        place: &'static str,
    },
    /// No wall type has this name.
    UnknownType {
        /// The name given.
        name: String,
        /// What it may have meant, ready for a message.
        suggestion: Option<String>,
    },
    /// A value of the wrong kind: a list for a number, a bool for a number, a word for a
    /// vector, a vector of other than 3 numbers.
    WrongShape {
        /// The keyword.
        keyword: &'static str,
        /// What it takes.
        expected: &'static str,
        /// What it was given.
        found: String,
    },
    /// A number with a fractional part for an integer keyword.
    Fractional {
        /// The keyword.
        keyword: &'static str,
        /// The number, as written.
        value: String,
    },
    /// NaN or an infinity.
    NotFinite {
        /// The keyword.
        keyword: &'static str,
        /// The value, as written.
        value: String,
    },
}

impl BuildError {
    /// Whether the value was of the wrong kind altogether (Python's `TypeError`), rather
    /// than a wrong name or number (a `ValueError`).
    pub fn is_type_error(&self) -> bool {
        matches!(self, BuildError::WrongShape { .. })
    }
}

impl fmt::Display for BuildError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            BuildError::UnknownKeyword { name, suggestion } => {
                write!(f, "unknown keyword `{name}`")?;
                match suggestion {
                    Some(s) => write!(f, ": did you mean `{s}`?"),
                    None => Ok(()),
                }
            }
            BuildError::Misplaced { keyword, place } if *place == UNITS => write!(
                f,
                "`{keyword}` is not a unit: the units are lengthunit, massunit and timeunit"
            ),
            BuildError::Misplaced { keyword, place } => write!(
                f,
                "`{keyword}` cannot be set in {place}: give the units to dumps, and each wall as a wall of its own"
            ),
            BuildError::UnknownType { name, suggestion } => {
                write!(f, "unknown wall type `{name}`")?;
                match suggestion {
                    Some(s) => write!(f, ": did you mean {s}?"),
                    None => write!(
                        f,
                        " (the types are {})",
                        WallType::ALL
                            .iter()
                            .map(|t| t.name())
                            .collect::<Vec<_>>()
                            .join(", ")
                    ),
                }
            }
            BuildError::WrongShape {
                keyword,
                expected,
                found,
            } => write!(f, "`{keyword}` takes {expected}, found {found}"),
            BuildError::Fractional { keyword, value } => write!(
                f,
                "`{keyword}` takes an integer, found `{value}` (pkdgrav would read it with atoi, dropping the fraction)"
            ),
            BuildError::NotFinite { keyword, value } => {
                write!(f, "`{keyword}` takes a finite number, found `{value}`")
            }
        }
    }
}

impl std::error::Error for BuildError {}

/// The place name of the units in [`BuildError::Misplaced`].
pub(crate) const UNITS: &str = "the units";
/// The place name of a wall (or the defaults) in [`BuildError::Misplaced`].
pub(crate) const WALL: &str = "a wall";

/// The keyword named `name`, in any case, with `_` standing for `-` (`osc_ampl` is
/// `osc-ampl`: Python's keyword arguments cannot hold a `-`).
pub(crate) fn keyword_named(name: &str) -> Result<Keyword, BuildError> {
    walls_keywords::keyword(name)
        .or_else(|| walls_keywords::keyword(&name.replace('_', "-")))
        .ok_or_else(|| BuildError::UnknownKeyword {
            name: name.to_string(),
            suggestion: walls_syntax::keyword_like(name),
        })
}

/// The wall type named `name` (any spelling the reader accepts, any case).
pub fn wall_type_named(name: &str) -> Result<WallType, BuildError> {
    walls_keywords::wall_type(name).ok_or_else(|| BuildError::UnknownType {
        name: name.to_string(),
        suggestion: match walls_syntax::type_like(name) {
            Suggestion::One(t) => Some(format!("`{t}`")),
            Suggestion::Several(names) => Some(format!("one of {}", names.join(", "))),
            Suggestion::None => None,
        },
    })
}

/// The value named `name` (any case) in a table of names.
pub(crate) fn named<T: Copy>(table: &[(&str, T)], name: &str) -> Option<T> {
    table
        .iter()
        .find(|(n, _)| n.eq_ignore_ascii_case(name))
        .map(|&(_, t)| t)
}

/// Checks `given` as the value of the keyword `name` in `place` ([`WALL`] takes the
/// wall properties, [`UNITS`] the three unit tokens).
pub(crate) fn check(
    name: &str,
    given: Given,
    place: &'static str,
) -> Result<(Keyword, Value), BuildError> {
    let keyword = keyword_named(name)?;
    let fits = match place {
        UNITS => matches!(
            keyword,
            Keyword::LengthUnit | Keyword::MassUnit | Keyword::TimeUnit
        ),
        _ => keyword.role() == Role::Property,
    };
    if !fits {
        return Err(BuildError::Misplaced {
            keyword: keyword.name(),
            place,
        });
    }
    let value = value_of(keyword, given)?;
    Ok((keyword, value))
}

/// `given` as a value of `keyword`'s shape.
fn value_of(keyword: Keyword, given: Given) -> Result<Value, BuildError> {
    let name = keyword.name();
    let wrong = |given: &Given| BuildError::WrongShape {
        keyword: name,
        expected: keyword.shape().describe(),
        found: given.describe(),
    };
    match keyword.shape() {
        ValueShape::TypeName => match given {
            Given::Text(t) => wall_type_named(&t).map(Value::Type),
            other => Err(wrong(&other)),
        },
        ValueShape::Number => real(name, &given)
            .ok_or_else(|| wrong(&given))?
            .map(Value::Number),
        ValueShape::Integer => match given {
            Given::Int(i) => Ok(Value::Integer(i)),
            Given::Float(x) if !x.is_finite() => Err(BuildError::NotFinite {
                keyword: name,
                value: number(x),
            }),
            // A whole real (NumPy's 3.0) is the integer; the cast saturates, and the
            // checker reports a value out of the keyword's range.
            Given::Float(x) if x.fract() == 0.0 => Ok(Value::Integer(x as i64)),
            Given::Float(x) => Err(BuildError::Fractional {
                keyword: name,
                value: number(x),
            }),
            other => Err(wrong(&other)),
        },
        ValueShape::Vector => match &given {
            Given::List(items) if items.len() == 3 => {
                let mut v = [0.0; 3];
                for (slot, item) in v.iter_mut().zip(items) {
                    *slot = real(name, item).ok_or_else(|| BuildError::WrongShape {
                        keyword: name,
                        expected: keyword.shape().describe(),
                        found: format!("a list holding {}", item.describe()),
                    })??;
                }
                Ok(Value::Vector(v))
            }
            other => Err(wrong(other)),
        },
        // Only the block keywords take no value, and `check` has refused them.
        ValueShape::None => Err(wrong(&given)),
    }
}

/// A real from a number (`None` for anything else: a bool is not a number here), or the
/// error for a value that is not finite.
fn real(keyword: &'static str, given: &Given) -> Option<Result<f64, BuildError>> {
    let x = match *given {
        Given::Float(x) => x,
        Given::Int(i) => i as f64,
        _ => return None,
    };
    // The tools' one rule for a value already read (a subnormal gets the file's S110).
    Some(
        walls_keywords::number::check(x).map_err(|_| BuildError::NotFinite {
            keyword,
            value: number(x),
        }),
    )
}

/// `x` as the shortest decimal that reads back as exactly `x` (Rust's float formatting
/// is shortest round-trip, and C's `atof` rounds correctly): plain from 1e-5 up to 1e16
/// (`0.30000000000000004`, `5`), with an exponent outside (`6.68e-14`, `1e-300`, `2e20`)
/// so that no number needs hundreds of digits.
pub fn number(x: f64) -> String {
    let a = x.abs();
    if a == 0.0 || (1e-5..1e16).contains(&a) || !x.is_finite() {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_shortest_and_plain_or_with_an_exponent() {
        assert_eq!(number(0.1 + 0.2), "0.30000000000000004");
        assert_eq!(number(5.0), "5");
        assert_eq!(number(-0.0), "-0");
        assert_eq!(number(1e-300), "1e-300");
        assert_eq!(number(6.68e-14), "6.68e-14");
        assert_eq!(number(-2.5e20), "-2.5e20");
        assert_eq!(number(123456.75), "123456.75");
        assert_eq!(number(1e-5), "0.00001");
        assert_eq!(number(9.9e-6), "9.9e-6");
        assert_eq!(number(f64::MIN_POSITIVE / 4.0), "5.562684646268003e-309");
    }

    #[test]
    fn command_line_values_parse_as_numbers_vectors_or_words() {
        assert_eq!(Given::parse("3"), Ok(Given::Int(3)));
        assert_eq!(Given::parse("0.5"), Ok(Given::Float(0.5)));
        assert_eq!(
            Given::parse("1,0, -2.5"),
            Ok(Given::List(vec![
                Given::Int(1),
                Given::Int(0),
                Given::Float(-2.5)
            ]))
        );
        assert_eq!(Given::parse("disk"), Ok(Given::Text("disk".into())));
        // The one rule for numbers: `1e-400` was 0 (`--set epsn=1e-400` made a sticky
        // wall), `inf` a word.
        assert_eq!(
            Given::parse("1e-400"),
            Err("`1e-400` is too small for a double: pkdgrav reads it as 0".into())
        );
        assert_eq!(
            Given::parse("0,0,1e999"),
            Err("`1e999` is too large for a double: pkdgrav reads it as infinity".into())
        );
        assert_eq!(
            Given::parse("inf"),
            Err("`inf` is not a finite number".into())
        );
        assert_eq!(Given::parse("1e-320"), Ok(Given::Float(1e-320)));
    }
}
