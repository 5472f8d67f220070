//! Help for mistakes: "did you mean" suggestions, and what pkdgrav's C number readers
//! (`atof`, `atoi`) would silently make of a malformed value.

use walls_keywords::{Keyword, WallType};

/// The keyword closest to `word`, if one is close enough to be a likely misspelling.
pub fn keyword_like(word: &str) -> Option<&'static str> {
    closest(word, Keyword::ALL.iter().map(|k| k.name()))
}

/// What to suggest for a word that should have been a wall type.
#[derive(Debug, PartialEq, Eq)]
pub enum Suggestion {
    /// One likely name.
    One(&'static str),
    /// Several names the word abbreviates (`cylinder`), quoted for a message.
    Several(Vec<String>),
    /// Nothing close.
    None,
}

/// The wall type `word` most likely meant: a close misspelling, or the names it is a
/// prefix of.
pub fn type_like(word: &str) -> Suggestion {
    let names = || WallType::ALL.iter().map(|t| t.name());
    if let Some(name) = closest(word, names()) {
        return Suggestion::One(name);
    }
    let lower = word.to_ascii_lowercase();
    let prefixed: Vec<String> = names()
        .filter(|n| lower.len() >= 3 && n.starts_with(&lower))
        .map(|n| format!("`{n}`"))
        .collect();
    match prefixed.len() {
        0 => Suggestion::None,
        _ => Suggestion::Several(prefixed),
    }
}

fn closest(word: &str, names: impl Iterator<Item = &'static str>) -> Option<&'static str> {
    let lower = word.to_ascii_lowercase();
    // `_` and `-` are easily swapped: compare with both made alike first.
    let alike = |s: &str| s.replace('_', "-");
    let budget = (lower.chars().count() / 3).clamp(1, 3);
    names
        .map(|name| {
            let d = if alike(name) == alike(&lower) {
                0
            } else {
                strsim::damerau_levenshtein(name, &lower)
            };
            (d, name)
        })
        .filter(|&(d, _)| d <= budget)
        .min_by_key(|&(d, _)| d)
        .map(|(_, name)| name)
}

/// The number C's `atof` reads from the start of `word`, described for a message.
pub(crate) fn atof_reading(word: &str) -> String {
    let unsigned = word.trim_start_matches(['+', '-']);
    let lower = unsigned.to_ascii_lowercase();
    if lower.starts_with("nan") {
        return "NaN".into();
    }
    if lower.starts_with("inf") {
        return "infinity".into();
    }
    if lower.starts_with("0x") {
        return "a hexadecimal number".into();
    }
    let len = decimal_prefix(word.as_bytes());
    match word.get(..len) {
        Some(p) if len > 0 && p.bytes().any(|b| b.is_ascii_digit()) => p.to_string(),
        _ => "0".into(),
    }
}

/// The integer C's `atoi` reads from the start of `word`.
pub(crate) fn atoi_reading(word: &str) -> String {
    let b = word.as_bytes();
    let sign = usize::from(matches!(b.first(), Some(b'+' | b'-')));
    let digits = b[sign..].iter().take_while(|c| c.is_ascii_digit()).count();
    if digits == 0 {
        "0".into()
    } else {
        word[..sign + digits].to_string()
    }
}

/// Whether `word` is an integer as `atoi` would read all of it.
pub(crate) fn is_integer(word: &str) -> bool {
    atoi_reading(word).len() == word.len()
}

/// Whether a word looks like an attempt at a number (so "invalid number" is the right
/// complaint rather than "unknown word").
pub(crate) fn looks_numeric(word: &str) -> bool {
    let unsigned = word.trim_start_matches(['+', '-']);
    let lower = unsigned.to_ascii_lowercase();
    unsigned.starts_with(|c: char| c.is_ascii_digit() || c == '.')
        || lower.starts_with("nan")
        || lower.starts_with("inf")
        || unsigned.is_empty()
}

/// Length of the longest prefix of `b` that is a decimal real per docs/spec.md §1.
fn decimal_prefix(b: &[u8]) -> usize {
    let mut i = usize::from(matches!(b.first(), Some(b'+' | b'-')));
    let int = b[i..].iter().take_while(|c| c.is_ascii_digit()).count();
    i += int;
    let mut frac = 0;
    if b.get(i) == Some(&b'.') {
        frac = b[i + 1..].iter().take_while(|c| c.is_ascii_digit()).count();
        if int + frac > 0 {
            i += 1 + frac;
        }
    }
    if int + frac == 0 {
        return 0;
    }
    if matches!(b.get(i), Some(b'e' | b'E')) {
        let mut j = i + 1;
        if matches!(b.get(j), Some(b'+' | b'-')) {
            j += 1;
        }
        let exp = b[j..].iter().take_while(|c| c.is_ascii_digit()).count();
        if exp > 0 {
            i = j + exp;
        }
    }
    i
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn atof_reads_like_c() {
        assert_eq!(atof_reading("1.2.3"), "1.2");
        assert_eq!(atof_reading("abc"), "0");
        assert_eq!(atof_reading("1e"), "1");
        assert_eq!(atof_reading("1e+"), "1");
        assert_eq!(atof_reading("-.5x"), "-.5");
        assert_eq!(atof_reading("."), "0");
        assert_eq!(atof_reading("-nan"), "NaN");
        assert_eq!(atof_reading("INF"), "infinity");
        assert_eq!(atof_reading("0x1p3"), "a hexadecimal number");
        assert_eq!(atoi_reading("12.5"), "12");
        assert_eq!(atoi_reading("-3"), "-3");
        assert_eq!(atoi_reading("x"), "0");
        assert!(is_integer("+7") && !is_integer("1e2"));
    }

    #[test]
    fn suggestions_find_misspellings_only() {
        assert_eq!(keyword_like("raduis"), Some("radius"));
        assert_eq!(keyword_like("OSC_AMPL"), Some("osc-ampl"));
        assert_eq!(keyword_like("kn"), Some("k_n"));
        assert_eq!(keyword_like("hello"), None);
        assert_eq!(
            type_like("cylinder-finit"),
            Suggestion::One("cylinder-finite")
        );
        assert_eq!(type_like("sphere"), Suggestion::None);
        assert_eq!(
            type_like("Cylinder"),
            Suggestion::Several(vec![
                "`cylinder-infinite`".into(),
                "`cylinder-finite`".into()
            ])
        );
    }
}
