//! Numbers, one rule everywhere: what a number's text (or a double read from a binary
//! file) means to pkdgrav, whose readers (C's `atof`, XDR) take any of them without a
//! word, and which of them the tools refuse or warn about.
//!
//! Every reader of the tools follows it and reports with its own location (a walls file's
//! span, a file and line, a `.ss` byte, an option's name): walls files (S110, C120),
//! `.par`, particle (CSV, `.ss`) and cohesion files, meshes (STL, OBJ), command-line
//! options and the Python API. The rule:
//!
//! * **not a number** (`abc`, `1.2.3`) and **not finite** (`nan`, `inf`, or such a
//!   value in a binary file): an error;
//! * **overflow**, a number beyond the largest double, about 1.8e308 (`1e999`), which
//!   `atof` reads as infinity: an error;
//! * **underflow**, a number written with a non-zero digit that a double rounds to 0
//!   (`1e-400`), which `atof` reads as 0 (setting only `errno`, which pkdgrav does not
//!   look at): an error;
//! * **subnormal**, a number that is not zero but below the smallest normal double,
//!   about 2.2e-308 (`1e-320`): read as it is, with fewer significant digits, as pkdgrav
//!   reads it: a warning;
//! * anything else, zero written as zero included, is read as it is.
//!
//! [`read`] classifies a number's text, [`check`] a value already read, and
//! [`subnormal`] says whether a value read deserves the warning; [`Problem`]'s and
//! [`Subnormal`]'s texts are the messages every reader gives after "`TEXT` is ". A count
//! derived from numbers (steps of a run) fits up to [`EXACT_COUNT`].

use std::fmt;

/// The smallest normal double, about 2.2e-308: below it (and above 0) a double is
/// subnormal.
pub const SMALLEST_NORMAL: f64 = f64::MIN_POSITIVE;

/// The most a count derived from numbers may be (steps from a time span and a timestep,
/// a `.par` file's step numbers): 2⁵³, below which every whole number is a double, so
/// that a step's time `step · dt` starts from the step exactly. A count beyond it (or
/// beyond a `u64`, or from a quotient that is not finite) does not fit and is refused.
pub const EXACT_COUNT: u64 = 1 << 53;

/// Why a number is refused.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Problem {
    /// The text is not a decimal number.
    NotANumber,
    /// NaN or an infinity, written as such (`nan`, `inf`) or read from a binary file.
    NotFinite,
    /// Beyond the largest double: pkdgrav would read infinity.
    Overflow,
    /// Written with a non-zero digit, but a double rounds it to 0: pkdgrav would read 0.
    Underflow,
}

impl Problem {
    /// What to do instead, for a message's help.
    pub fn help(self) -> &'static str {
        match self {
            Problem::NotANumber | Problem::NotFinite => "write a finite decimal number",
            Problem::Overflow => {
                "C's atof overflows to infinity silently; use units that keep the value below about 1.8e308"
            }
            Problem::Underflow => {
                "C's atof underflows to 0 silently; write 0 if you mean 0, or use units that keep the value above about 2.2e-308"
            }
        }
    }
}

impl fmt::Display for Problem {
    /// What is wrong, to follow "`TEXT` is ".
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Problem::NotANumber => "not a number",
            Problem::NotFinite => "not a finite number",
            Problem::Overflow => "too large for a double: pkdgrav reads it as infinity",
            Problem::Underflow => "too small for a double: pkdgrav reads it as 0",
        })
    }
}

impl std::error::Error for Problem {}

/// A subnormal value: the warning a reader gives about it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Subnormal(pub f64);

impl Subnormal {
    /// What to do instead, for a message's help.
    pub const HELP: &'static str = "use units that keep the value above about 2.2e-308";
}

impl fmt::Display for Subnormal {
    /// What is wrong, to follow "`TEXT` is ".
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "below the smallest normal double: pkdgrav reads it as {:e}, with fewer significant digits",
            self.0
        )
    }
}

/// The value of a number's text as pkdgrav reads it, or why it is refused. A subnormal
/// value is read (see [`subnormal`] for its warning). The text is a decimal number as
/// Rust reads it (an optional sign, digits with an optional `.` and fraction, an
/// optional exponent); `nan` and `inf` are read as words and refused.
pub fn read(text: &str) -> Result<f64, Problem> {
    let x: f64 = text.parse().map_err(|_| Problem::NotANumber)?;
    if x.is_nan() {
        return Err(Problem::NotFinite);
    }
    if x.is_infinite() {
        // `inf`, `infinity` are words; a number with digits is too large.
        return Err(if text.bytes().any(|b| b.is_ascii_digit()) {
            Problem::Overflow
        } else {
            Problem::NotFinite
        });
    }
    if x == 0.0 && !zero_as_written(text) {
        return Err(Problem::Underflow);
    }
    Ok(x)
}

/// Whether the digits of a number's text before its exponent are all zeros.
fn zero_as_written(text: &str) -> bool {
    let mantissa = text.split(['e', 'E']).next().unwrap_or_default();
    !mantissa.bytes().any(|b| matches!(b, b'1'..=b'9'))
}

/// Whether a number's text can be below 1e-300 in size without being zero as written:
/// only with a negative exponent or with 300 characters or more. A reader that only
/// looks for underflow and subnormals (the walls-file check, which reads every value
/// again later) passes over the others without parsing them.
#[inline]
pub fn may_be_tiny(text: &str) -> bool {
    // A decimal's only `-` after its first byte follows its `e` or `E`.
    let b = text.as_bytes();
    b.len() >= 300
        || b.iter()
            .rposition(|&c| c == b'-')
            .is_some_and(|i| i > 0 && matches!(b[i - 1], b'e' | b'E'))
}

/// A value already read (from a binary file, a program's argument): refused if it is not
/// finite; a subnormal is accepted (see [`subnormal`]).
pub fn check(x: f64) -> Result<f64, Problem> {
    if x.is_finite() {
        Ok(x)
    } else {
        Err(Problem::NotFinite)
    }
}

/// The warning a value read deserves: `Some` when it is subnormal.
pub fn subnormal(x: f64) -> Option<Subnormal> {
    (x != 0.0 && x.abs() < SMALLEST_NORMAL).then_some(Subnormal(x))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn texts_are_classified_as_atof_would_read_them() {
        assert_eq!(read("1.5"), Ok(1.5));
        assert_eq!(read("-0"), Ok(0.0));
        assert_eq!(read("0e-400"), Ok(0.0));
        assert_eq!(read("0.000e-999"), Ok(0.0));
        assert_eq!(read("1e-400"), Err(Problem::Underflow));
        assert_eq!(read("-0.001e-322"), Err(Problem::Underflow));
        assert_eq!(read("1e999"), Err(Problem::Overflow));
        assert_eq!(read("-1.8e308"), Err(Problem::Overflow));
        assert_eq!(read("nan"), Err(Problem::NotFinite));
        assert_eq!(read("-Infinity"), Err(Problem::NotFinite));
        assert_eq!(read("1.2.3"), Err(Problem::NotANumber));
        assert_eq!(read(""), Err(Problem::NotANumber));
        assert_eq!(read("1e-320"), Ok(1e-320));
        // The smallest subnormal, and the largest double.
        assert_eq!(read("4.9e-324"), Ok(5e-324));
        assert_eq!(read("1.7976931348623157e308"), Ok(f64::MAX));
    }

    #[test]
    fn values_are_classified_alike() {
        assert_eq!(check(f64::NAN), Err(Problem::NotFinite));
        assert_eq!(check(f64::NEG_INFINITY), Err(Problem::NotFinite));
        assert_eq!(check(-0.0), Ok(-0.0));
        assert_eq!(subnormal(1e-320), Some(Subnormal(1e-320)));
        assert_eq!(subnormal(-1e-310), Some(Subnormal(-1e-310)));
        assert_eq!(subnormal(SMALLEST_NORMAL), None);
        assert_eq!(subnormal(0.0), None);
        assert_eq!(subnormal(1.0), None);
    }

    #[test]
    fn only_a_tiny_text_needs_parsing_for_tininess() {
        for text in [
            "1e-320",
            "1E-400",
            "-2.5e-310",
            &format!("0.{}1", "0".repeat(330)),
        ] {
            assert!(may_be_tiny(text), "{text}");
        }
        for text in ["1e300", "0.5", "12345", "-0.25", "-1e5", "-1"] {
            assert!(!may_be_tiny(text), "{text}");
            assert!(read(text).is_ok_and(|x| x == 0.0 || x.abs() > 1e-300));
        }
    }

    #[test]
    fn messages_follow_the_text() {
        assert_eq!(
            format!("`1e-400` is {}", Problem::Underflow),
            "`1e-400` is too small for a double: pkdgrav reads it as 0"
        );
        assert_eq!(
            format!("`1e-320` is {}", Subnormal(1e-320)),
            "`1e-320` is below the smallest normal double: pkdgrav reads it as 1e-320, with fewer significant digits"
        );
    }
}
