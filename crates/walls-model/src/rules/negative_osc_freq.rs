//! C113 `negative-osc-freq`: `osc-freq` is negative.
//!
//! `osc-freq` (`ValueRange::NonNegativeFrequency`) is read like any value, but a negative
//! one is reported when its block ends, so the fix can use the block's final amplitude
//! and phase: the resolver keeps the frequency until then and calls [`at_block_end`].

use crate::fix::{negated, number};
use crate::scene::{Setting, Source, Value};
use std::ops::Range;
use walls_diagnostics::{Applicability, Code, Diagnostic, Edit};
use walls_keywords::Keyword;

/// `osc-freq` is negative.
pub static NEGATIVE_OSC_FREQ: Code = Code {
    id: "C113",
    name: "negative-osc-freq",
    summary: "`osc-freq` is negative",
    explanation: "The document allows a negative frequency but pkdgrav rejects it. Since
A·sin(−ωt + 2πφ) = (−A)·sin(ωt + 2π(1−φ)), the same motion is written with frequency
|ω|, amplitude −A and phase (1−φ) mod 1; the fix (safe) writes exactly that, editing the
amplitude and phase where the same block sets them and adding them after the frequency
otherwise.

Bad:
```walls
wall type plane
  osc-ampl 0.1
  osc-freq -2
  osc-phase 0.25
```

Good:
```walls
wall type plane
  osc-ampl -0.1
  osc-freq 2
  osc-phase 0.75
```
",
};

/// Whether an `osc-freq` value is to be reported when its block ends.
pub(crate) fn is_negative(value: Value) -> bool {
    matches!(value, Value::Number(w) if w < 0.0)
}

/// The error for a negative `osc-freq` in the block that starts at `block_start`, with
/// the exact rewrite A·sin(−ωt + 2πφ) = (−A)·sin(ωt + 2π(1−φ)): frequency |ω|,
/// amplitude −A, phase (1−φ) mod 1. Values set in the same block are edited in place;
/// inherited ones are appended after the frequency (later tokens win). `length_unit`
/// is the unit in force at the frequency, for writing an inherited amplitude;
/// `effective` gives the block's value of a keyword.
pub(crate) fn at_block_end(
    text: &str,
    block_start: usize,
    length_unit: f64,
    freq_values: &Range<usize>,
    effective: impl Fn(Keyword) -> Setting,
) -> Diagnostic {
    let (ampl, phase) = (effective(Keyword::OscAmpl), effective(Keyword::OscPhase));
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
        match in_block(&ampl) {
            Some(span) => edits.push(Edit {
                replacement: negated(&text[span.clone()]),
                span,
            }),
            None => appended.push_str(&format!(" osc-ampl {}", number(-a / length_unit))),
        }
    }
    let new_phi = (1.0 - phi).rem_euclid(1.0);
    if new_phi != phi {
        match in_block(&phase) {
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
        &NEGATIVE_OSC_FREQ,
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
