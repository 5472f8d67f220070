//! Building fixes: numbers written back as text, for the rules' fixes and messages.

use crate::scene::Vec3;
use walls_diagnostics::Edit;

/// A real as the shortest decimal text that reads back as the same double: plain
/// notation for ordinary magnitudes (`1`, `0.25`), exponent notation for very large or
/// small ones (`6.68458e-14`).
pub(crate) fn number(x: f64) -> String {
    let x = if x == 0.0 { 0.0 } else { x }; // no "-0"
    if x == 0.0 || (1e-5..1e16).contains(&x.abs()) {
        format!("{x}")
    } else {
        format!("{x:?}")
    }
}

/// A computed real rounded to 12 significant digits, so that float noise from the
/// arithmetic (`0.5499999999999999`) does not reach the file.
pub(crate) fn rounded(x: f64) -> String {
    number(format!("{x:.11e}").parse().unwrap_or(x))
}

/// A computed vector, each component [`rounded`].
pub(crate) fn vector(v: &Vec3) -> String {
    format!("{} {} {}", rounded(v.x), rounded(v.y), rounded(v.z))
}

/// Whether each number of `words` reads as 0 or a normal double: a value a fix adds must
/// not be one pkdgrav reads with fewer digits (S110).
pub(crate) fn normal_numbers(words: &str) -> bool {
    words
        .split(' ')
        .filter_map(|w| w.parse::<f64>().ok())
        .all(|x| x == 0.0 || x.is_normal())
}

/// An edit adding `words` (which start with a space) right after byte `at`, before a
/// comment glued there (which then stays glued to nothing new: a space follows `words`).
pub(crate) fn append(text: &str, at: usize, words: String) -> Edit {
    let glued = text[at..].starts_with(['#', '!']);
    Edit {
        span: at..at,
        replacement: if glued { words + " " } else { words },
    }
}

/// The text of a number with its sign flipped, exactly (`0.1` → `-0.1`, `-2` → `2`).
pub(crate) fn negated(text: &str) -> String {
    match text.as_bytes().first() {
        Some(b'-') => text[1..].to_string(),
        Some(b'+') => format!("-{}", &text[1..]),
        _ => format!("-{text}"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_read_back_exactly() {
        for x in [
            0.0,
            -0.0,
            1.0,
            0.1,
            -2.5e-7,
            1e21,
            123456.789,
            f64::MIN_POSITIVE,
        ] {
            assert_eq!(
                number(x).parse::<f64>().unwrap(),
                if x == 0.0 { 0.0 } else { x }
            );
        }
        assert_eq!(number(-0.0), "0");
        assert_eq!(number(2.0), "2");
        assert_eq!(number(6.68458e-14), "6.68458e-14");
        assert_eq!(rounded(0.5499999999999999), "0.55");
        assert_eq!(vector(&Vec3::new(1.0, -0.0, 1e-20)), "1 0 1e-20");
        assert_eq!(negated("-.5"), ".5");
        assert_eq!(negated("+3E+2"), "-3E+2");
        assert_eq!(negated("0.1"), "-0.1");
    }
}
