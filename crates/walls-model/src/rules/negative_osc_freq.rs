//! C113 `negative-osc-freq`: `osc-freq` is negative.
//!
//! `osc-freq` (`ValueRange::NonNegativeFrequency`) is read like any value, but a negative
//! one is reported when its block ends ([`at_block_end`]), and its fix is made once every
//! wall is read ([`add_fixes`]): a frequency in `defaults` reaches the walls made after it,
//! and the fix must give each of them the same motion, wherever its amplitude and phase
//! were set.

use crate::fix::{append, negated, normal_numbers, number};
use crate::scene::{Scene, Setting, Units, Value};
use std::collections::HashMap;
use std::ops::Range;
use walls_diagnostics::{Applicability, Code, Diagnostic, Edit, Fix};
use walls_keywords::Keyword;

/// `osc-freq` is negative.
pub static NEGATIVE_OSC_FREQ: Code = Code {
    id: "C113",
    name: "negative-osc-freq",
    summary: "`osc-freq` is negative",
    explanation: "The document allows a negative frequency but pkdgrav rejects it. Since
A·sin(−ωt + 2πφ) = (−A)·sin(ωt + 2π(1−φ)), the same motion is written with frequency
|ω|, amplitude −A and phase (1−φ) mod 1; the fix (safe) writes exactly that for every wall
the frequency reaches: it edits an amplitude or phase where it is set when only those
walls read it, and adds it after the frequency otherwise. Where no such edit keeps every
other wall's motion (a `defaults` frequency whose walls share their amplitude with walls
it does not reach), there is no fix: the help says what to write.

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

/// The error for a negative `osc-freq` (its values at `freq`), without its fix.
pub(crate) fn at_block_end(text: &str, freq: &Range<usize>) -> Diagnostic {
    Diagnostic::error(
        &NEGATIVE_OSC_FREQ,
        freq.clone(),
        format!("`osc-freq` is {}; pkdgrav rejects a negative frequency", &text[freq.clone()]),
    )
    .with_help(
        "A·sin(−ωt + 2πφ) = (−A)·sin(ωt + 2π(1−φ)): write the frequency |ω|, the amplitude −A and the phase (1−φ) mod 1, and the wall moves exactly as meant",
    )
}

/// A negative `osc-freq` reported when its block ended, waiting for its fix.
pub(crate) struct Pending {
    /// Where its diagnostic is in the resolver's output.
    pub(crate) at: usize,
    /// The frequency's values.
    pub(crate) freq: Range<usize>,
    /// In a wall's block (else in `defaults`).
    pub(crate) in_wall: bool,
    /// Where its block starts.
    pub(crate) block_start: usize,
    /// The first wall made after the block.
    pub(crate) first_after: usize,
    /// The units in force at the frequency (what a value added after it is read in).
    pub(crate) units: Units,
    /// The block's amplitude and phase when it ended.
    pub(crate) ampl: Setting,
    /// See `ampl`.
    pub(crate) phase: Setting,
}

/// The walls that take each amplitude, frequency and phase, by where it was set: the
/// start of its values.
type Users = HashMap<(Keyword, usize), Readers>;

/// The walls that take a value, in file order, and whether one of them has a frequency
/// that is not negative (no fix of this code takes such a wall from the value).
#[derive(Default)]
struct Readers {
    walls: Vec<usize>,
    steady: bool,
}

/// Gives each pending diagnostic of `out` its fix where one keeps every wall's motion.
pub(crate) fn add_fixes(pending: &[Pending], scene: &Scene, text: &str, out: &mut [Diagnostic]) {
    if pending.is_empty() {
        return;
    }
    let mut users = Users::new();
    for w in &scene.walls {
        let steady = w.number(Keyword::OscFreq) >= 0.0;
        for k in [Keyword::OscFreq, Keyword::OscAmpl, Keyword::OscPhase] {
            if let Some(s) = w.settings.get(k).and_then(|s| s.source.span()) {
                let readers = users.entry((k, s.start)).or_default();
                readers.walls.push(w.index);
                readers.steady |= steady;
            }
        }
    }
    for p in pending {
        if let Some(edits) = edits(p, scene, text, &users) {
            out[p.at].fix = Some(Fix {
                message: "use a positive frequency with the amplitude and phase that give the same motion"
                    .into(),
                applicability: Applicability::Safe,
                edits,
            });
        }
    }
}

/// The amplitude or phase that gives the same motion with the frequency negated.
fn rewritten(k: Keyword, x: f64) -> f64 {
    match k {
        Keyword::OscAmpl => -x,
        _ => (1.0 - x).rem_euclid(1.0),
    }
}

/// The edits that give every wall `p`'s frequency reaches the same motion with |ω|,
/// touching no other wall; `None` where there are none.
///
/// The frequency reaches the walls that take its value (`reached`). Each amplitude and
/// phase those walls read is edited where it is set when only walls of `reached` read
/// it; otherwise it is added after the frequency. In a wall's block that reaches the
/// wall alone; in `defaults` it reaches the walls made after the block that take the
/// value the block ended with, which is allowed only when they are all in `reached` and
/// the value was set before the block (so that the block does not set it twice). Either
/// way the place keeps a wall that no fix of this code takes from it (one with a frequency
/// that is not negative, else the last that reads it), so that no `defaults` is left that
/// no wall takes, whichever of these fixes are applied together.
fn edits(p: &Pending, scene: &Scene, text: &str, users: &Users) -> Option<Vec<Edit>> {
    let reached = &users.get(&(Keyword::OscFreq, p.freq.start))?.walls;
    let mut edits = vec![Edit {
        span: p.freq.clone(),
        replacement: negated(&text[p.freq.clone()]),
    }];
    let mut appended = String::new();
    for (k, end) in [(Keyword::OscAmpl, &p.ampl), (Keyword::OscPhase, &p.phase)] {
        // The places that set a value a reached wall needs rewritten, with how many
        // reached walls read each.
        let mut places: HashMap<usize, (Range<usize>, f64, usize)> = HashMap::new();
        for &i in reached {
            let setting = scene.walls[i].setting(k)?;
            let Value::Number(x) = setting.value else {
                return None;
            };
            if rewritten(k, x) == x {
                continue;
            }
            // A built-in amplitude or phase (0) needs no rewriting.
            let span = setting.source.span()?;
            places.entry(span.start).or_insert((span, x, 0)).2 += 1;
        }
        for (span, x, n) in places.into_values() {
            let readers = users.get(&(k, span.start));
            let read_by = readers.map_or(&[][..], |r| r.walls.as_slice());
            if read_by.len() == n {
                let replacement = match k {
                    Keyword::OscAmpl => negated(&text[span.clone()]),
                    _ => number(rewritten(k, x)),
                };
                edits.push(Edit { span, replacement });
                continue;
            }
            let from_before =
                end.source.span().is_some_and(|e| e == span) && span.start < p.block_start;
            let reaches_only_reached = p.in_wall || {
                let after = read_by.len() - read_by.partition_point(|&w| w < p.first_after);
                after == n
            };
            // Adding the value takes the reached walls from the place that set it, and
            // the fixes of other negative frequencies may take the rest: a wall must keep
            // it, one whose frequency is not negative, else the last wall that reads it
            // (whose fix waits until it is the only one, and then edits it in place).
            let kept = readers.is_some_and(|r| r.steady)
                || read_by
                    .last()
                    .is_some_and(|w| reached.binary_search(w).is_err());
            if !(from_before && reaches_only_reached && kept) {
                return None;
            }
            let factor = k
                .dimension()
                .factor(p.units.length, p.units.mass, p.units.time);
            let written = number(rewritten(k, x) / factor);
            // The value added must read back exactly, and as a normal double.
            if written.parse::<f64>().ok()? * factor != rewritten(k, x) || !normal_numbers(&written)
            {
                return None;
            }
            appended.push_str(&format!(" {} {written}", k.name()));
        }
    }
    if !appended.is_empty() {
        edits.push(append(text, p.freq.end, appended));
    }
    edits.sort_by_key(|e| e.span.start);
    Some(edits)
}
