//! Building fixes: numbers written back as text, and the exact rewrite of a negative
//! oscillation frequency.

use crate::codes;
use crate::scene::{Setting, Source, Value, Vec3};
use std::ops::Range;
use walls_diagnostics::{Applicability, Diagnostic, Edit};

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

/// The text of a number with its sign flipped, exactly (`0.1` → `-0.1`, `-2` → `2`).
fn negated(text: &str) -> String {
    match text.as_bytes().first() {
        Some(b'-') => text[1..].to_string(),
        Some(b'+') => format!("-{}", &text[1..]),
        _ => format!("-{text}"),
    }
}

/// The error for a negative `osc-freq` in the block that starts at `block_start`, with
/// the exact rewrite A·sin(−ωt + 2πφ) = (−A)·sin(ωt + 2π(1−φ)): frequency |ω|,
/// amplitude −A, phase (1−φ) mod 1. Values set in the same block are edited in place;
/// inherited ones are appended after the frequency (later tokens win). `length_unit`
/// is the unit in force at the frequency, for writing an inherited amplitude.
pub(crate) fn negative_osc_freq(
    text: &str,
    block_start: usize,
    length_unit: f64,
    freq_values: &Range<usize>,
    ampl: &Setting,
    phase: &Setting,
) -> Diagnostic {
    let freq_text = &text[freq_values.clone()];
    let mut edits = vec![Edit {
        span: freq_values.clone(),
        replacement: negated(freq_text),
    }];
    let mut appended = String::new();
    let (Value::Number(a), Value::Number(phi)) = (ampl.value, phase.value) else {
        unreachable!("osc-ampl and osc-phase are numbers")
    };
    let in_block = |s: &Setting| match &s.source {
        Source::Set { values, .. } if values.range().start >= block_start => Some(values.range()),
        _ => None,
    };
    if a != 0.0 {
        match in_block(ampl) {
            Some(span) => edits.push(Edit {
                replacement: negated(&text[span.clone()]),
                span,
            }),
            None => appended.push_str(&format!(" osc-ampl {}", number(-a / length_unit))),
        }
    }
    let new_phi = (1.0 - phi).rem_euclid(1.0);
    if new_phi != phi {
        match in_block(phase) {
            Some(span) => edits.push(Edit {
                span,
                replacement: number(new_phi),
            }),
            None => appended.push_str(&format!(" osc-phase {}", number(new_phi))),
        }
    }
    if !appended.is_empty() {
        edits.push(Edit {
            span: freq_values.end..freq_values.end,
            replacement: appended,
        });
    }
    edits.sort_by_key(|e| e.span.start);
    Diagnostic::error(
        &codes::NEGATIVE_OSC_FREQ,
        freq_values.clone(),
        format!("`osc-freq` is {freq_text}; pkdgrav rejects a negative frequency"),
    )
    .with_help(
        "A·sin(−ωt + 2πφ) = (−A)·sin(ωt + 2π(1−φ)): write the frequency |ω|, the amplitude −A and the phase (1−φ) mod 1, and the wall moves exactly as meant",
    )
    .with_fix(
        Applicability::Safe,
        "use a positive frequency with the amplitude and phase that give the same motion",
        edits,
    )
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
