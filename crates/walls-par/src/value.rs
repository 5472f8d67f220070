//! A `.par` value as pkdgrav reads it for its key's type (docs/pkdgrav-physics.md §14):
//! integers and switches as C's `%d` (a leading whole number: `0.5` is 0, `1e6` is 1),
//! doubles as `%lf` (a leading number, the rest ignored), strings to the first `#` with
//! trailing blanks removed, quotes kept (but the four file names' one leading and one
//! trailing `"`).

use crate::keys::Kind;

/// What pkdgrav reads from a value's text.
#[derive(Debug, Clone, PartialEq)]
pub enum Value {
    /// An integer or a switch.
    Int(i64),
    /// A double.
    Double(f64),
    /// A string.
    Str(String),
}

impl Value {
    /// The value as a number (a string has none).
    pub fn real(&self) -> Option<f64> {
        match *self {
            Value::Int(x) => Some(x as f64),
            Value::Double(x) => Some(x),
            Value::Str(_) => None,
        }
    }
}

/// A value read, with what pkdgrav passed over: the bytes after the number that are
/// not a comment (`e5` of `1e5` for an integer), ignored without a word.
#[derive(Debug, Clone, PartialEq)]
pub struct Reading {
    /// The value.
    pub value: Value,
    /// The length of the text pkdgrav read as the value, from the value's start.
    pub read: usize,
    /// The text it ignored that is not a comment (empty for none).
    pub ignored: String,
}

/// Why a value cannot be read.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Unreadable {
    /// No number where the key's type needs one: pkdgrav stops with a syntax error.
    NotANumber,
    /// An integer beyond a C `int`: `%d` gives some other number.
    BeyondInt,
}

/// The keys whose string value loses one leading and one trailing `"` (§14): the walls,
/// cohesion, uniform-gravity and special-particles file names.
pub const UNQUOTED: [&str; 4] = [
    "achWallsFile",
    "achCohesionFile",
    "achUnifGravFile",
    "achSpecialFile",
];

/// The value `text` (from the value's first byte to the end of the read) of `key`, of
/// type `kind`, as pkdgrav reads it.
pub fn read(key: &str, kind: Kind, text: &str) -> Result<Reading, Unreadable> {
    match kind {
        Kind::Str => {
            let end = text.find('#').unwrap_or(text.len());
            let s = text[..end].trim_end_matches([' ', '\t', '\r', '\x0b', '\x0c']);
            let s = if UNQUOTED.contains(&key) {
                let s = s.strip_prefix('"').unwrap_or(s);
                s.strip_suffix('"').unwrap_or(s)
            } else {
                s
            };
            Ok(Reading {
                value: Value::Str(s.to_string()),
                read: end,
                ignored: String::new(),
            })
        }
        Kind::Int | Kind::Bool => {
            let b = text.as_bytes();
            let sign = usize::from(matches!(b.first(), Some(b'-' | b'+')));
            let digits = b[sign..].iter().take_while(|c| c.is_ascii_digit()).count();
            if digits == 0 {
                return Err(Unreadable::NotANumber);
            }
            let read = sign + digits;
            let x: i64 = text[..read].parse().map_err(|_| Unreadable::BeyondInt)?;
            if i32::try_from(x).is_err() {
                return Err(Unreadable::BeyondInt);
            }
            Ok(Reading {
                value: Value::Int(x),
                read,
                ignored: ignored(&text[read..]),
            })
        }
        Kind::Double => {
            let read = float_prefix(text).ok_or(Unreadable::NotANumber)?;
            let x = parse_c_double(&text[..read]);
            Ok(Reading {
                value: Value::Double(x),
                read,
                ignored: ignored(&text[read..]),
            })
        }
    }
}

/// The text after a number that is not a comment or blanks.
fn ignored(rest: &str) -> String {
    let rest = rest.trim_start_matches([' ', '\t', '\r', '\x0b', '\x0c']);
    if rest.starts_with('#') {
        String::new()
    } else {
        rest.trim_end().to_string()
    }
}

/// The length of the longest prefix of `text` that C's `strtod` reads as a number: an
/// optional sign, then `inf`, `infinity` or `nan` (any case), or digits with an
/// optional `.` and fraction (at least one digit) and an optional exponent (read only
/// with digits after it), or a hexadecimal number.
fn float_prefix(text: &str) -> Option<usize> {
    let b = text.as_bytes();
    let sign = usize::from(matches!(b.first(), Some(b'-' | b'+')));
    let rest = &text[sign..];
    let lower = rest.to_ascii_lowercase();
    for word in ["infinity", "inf", "nan"] {
        if lower.starts_with(word) {
            return Some(sign + word.len());
        }
    }
    if lower.starts_with("0x") {
        // Hex digits with at most one `.`.
        let mut dot = false;
        let hex = rest[2..]
            .bytes()
            .take_while(|&c| {
                let first_dot = c == b'.' && !dot;
                dot |= c == b'.';
                c.is_ascii_hexdigit() || first_dot
            })
            .count();
        if hex == 0 {
            return None;
        }
        // A binary exponent, read only with digits after it.
        let mut at = sign + 2 + hex;
        if matches!(b.get(at), Some(b'p' | b'P')) {
            let s = usize::from(matches!(b.get(at + 1), Some(b'-' | b'+')));
            let e = b[(at + 1 + s).min(b.len())..]
                .iter()
                .take_while(|c| c.is_ascii_digit())
                .count();
            if e > 0 {
                at += 1 + s + e;
            }
        }
        return Some(at);
    }
    let digits = |from: usize| b[from..].iter().take_while(|c| c.is_ascii_digit()).count();
    let mut at = sign;
    let whole = digits(at);
    at += whole;
    let mut fraction = 0;
    if b.get(at) == Some(&b'.') {
        fraction = digits(at + 1);
        at += 1 + fraction;
    }
    if whole + fraction == 0 {
        return None;
    }
    if matches!(b.get(at), Some(b'e' | b'E')) {
        let s = usize::from(matches!(b.get(at + 1), Some(b'-' | b'+')));
        let e = digits(at + 1 + s);
        if e > 0 {
            at += 1 + s + e;
        }
    }
    Some(at)
}

/// The double C's `strtod` makes of a number `float_prefix` found: Rust's reading, which
/// rounds as it does, for decimals and the words; a hexadecimal number's value.
fn parse_c_double(text: &str) -> f64 {
    let (negative, body) = match text.as_bytes().first() {
        Some(b'-') => (true, &text[1..]),
        Some(b'+') => (false, &text[1..]),
        _ => (false, text),
    };
    let x = if body.len() > 2 && body[..2].eq_ignore_ascii_case("0x") {
        let (mantissa, exponent) = body[2..]
            .split_once(['p', 'P'])
            .unwrap_or((&body[2..], "0"));
        let exponent: i32 = exponent.parse().unwrap_or(i32::MAX);
        let (whole, fraction) = mantissa.split_once('.').unwrap_or((mantissa, ""));
        let mut x = 0.0;
        for c in whole.chars() {
            x = x * 16.0 + f64::from(c.to_digit(16).unwrap_or(0));
        }
        let mut scale = 1.0 / 16.0;
        for c in fraction.chars() {
            x += f64::from(c.to_digit(16).unwrap_or(0)) * scale;
            scale /= 16.0;
        }
        // Scaled in two halves, so that 2^-1074 (a power whose reciprocal no double
        // holds) is reached.
        let e = exponent.clamp(-2200, 2200);
        x * 2f64.powi(e / 2) * 2f64.powi(e - e / 2)
    } else if body.to_ascii_lowercase().starts_with("nan") {
        f64::NAN
    } else {
        body.parse::<f64>().unwrap_or(f64::NAN)
    };
    if negative { -x } else { x }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn int(text: &str) -> (i64, String) {
        let r = read("nSteps", Kind::Int, text).unwrap();
        (r.value.real().unwrap() as i64, r.ignored)
    }

    fn double(text: &str) -> (f64, String) {
        let r = read("dDelta", Kind::Double, text).unwrap();
        (r.value.real().unwrap(), r.ignored)
    }

    #[test]
    fn integers_are_read_as_percent_d() {
        assert_eq!(int("100 # steps"), (100, String::new()));
        assert_eq!(int("1e5"), (1, "e5".into()));
        assert_eq!(int("0.5"), (0, ".5".into()));
        assert_eq!(int("-3x"), (-3, "x".into()));
        assert_eq!(
            read("nSteps", Kind::Int, "yes"),
            Err(Unreadable::NotANumber)
        );
        assert_eq!(read("nSteps", Kind::Int, ".5"), Err(Unreadable::NotANumber));
        assert_eq!(
            read("nSteps", Kind::Int, "3000000000"),
            Err(Unreadable::BeyondInt)
        );
    }

    #[test]
    fn doubles_are_read_as_percent_lf() {
        assert_eq!(double("1e-5 # s"), (1e-5, String::new()));
        assert_eq!(double("1e-5 s"), (1e-5, "s".into()));
        assert_eq!(double("2.e"), (2.0, "e".into()));
        assert_eq!(double(".5"), (0.5, String::new()));
        assert_eq!(double("0x1.8p"), (1.5, "p".into()));
        assert_eq!(double("0x1p3"), (8.0, String::new()));
        assert_eq!(double("-0x1p-3 # s"), (-0.125, String::new()));
        assert_eq!(double("0x1p-1074").0, f64::from_bits(1));
        assert_eq!(double("0x1.8.8"), (1.5, ".8".into()));
        assert!(double("1e400").0.is_infinite());
        assert!(double("-inf").0.is_infinite());
        assert!(double("nan").0.is_nan());
        assert_eq!(double("1e-400").0, 0.0);
        assert_eq!(
            read("dDelta", Kind::Double, "e5"),
            Err(Unreadable::NotANumber)
        );
    }

    #[test]
    fn strings_run_to_a_hash_and_file_names_lose_their_quotes() {
        let s = |key: &str, text: &str| match read(key, Kind::Str, text).unwrap().value {
            Value::Str(s) => s,
            _ => unreachable!(),
        };
        assert_eq!(s("achOutName", "\"ss\"  # name"), "\"ss\"");
        assert_eq!(s("achWallsFile", "\"walls.dat\"  # w"), "walls.dat");
        assert_eq!(s("achWallsFile", "\"\"a\"\""), "\"a\"");
    }
}
