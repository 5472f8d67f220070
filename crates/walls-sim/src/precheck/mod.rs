//! A run directory checked before the job: what pkdgrav would do with the `.par` file,
//! its walls file and its initial conditions together, before the queue does it.
//!
//! [`check`] takes a [`Run`] (the `.par` read as the build reads it, the walls file's
//! resolved scene and the `.ss` file's particles, each where it could be read) and
//! returns [`Findings`], diagnostics of the `R…` codes ([`rules::ALL`]) in the file each
//! is about:
//!
//! * in the `.par` file, at the key's value (at the start of the file when the key is
//!   left at its default);
//! * in the walls file, at the `wall` keyword or the token;
//! * in the `.ss` file, at a particle: the span is the byte range of its record (16 bytes
//!   of header, then 96 bytes a record), and the diagnostic's
//!   [`walls_diagnostics::Record`] names it (`particle 17`, which every output format
//!   shows in place of a line and column). Particles are numbered from 0 in file order,
//!   as pkdgrav's own overlap messages and `iOrder` number them.
//!
//! The rules, one a file in [`rules`]:
//!
//! * initial overlaps, pairs (`R001`) and walls (`R002`), at pkdgrav's levels
//!   (`dMinorFrac`, `dMajorFrac`, `dErrorFrac`; docs/pkdgrav-physics.md §15): an error
//!   above the error level, where pkdgrav aborts at step 0, a warning above the major, an
//!   info above the minor;
//! * a particle outside a closed container (an infinite cylinder or a whole shell) that
//!   holds nine in ten of the others (`R003`);
//! * too few steps per contact for the lightest particle (`R004`), by the rule of
//!   `walls-sim advise` and the evaluator's W202;
//! * a wall that moves more than a tenth of the smallest radius in a step (`R005`), the
//!   evaluator's W203;
//! * walls-file tokens that need a compile option the build lacks (`R006`);
//! * outputs that are never written, or that only the last step writes (`R007`), and step
//!   numbers wider than `nDigits` (`R008`).
//!
//! Each rule reports at most [`MAX_REPORTED`] places, then one info with the count of the
//! rest.

pub mod rules;

use std::ops::Range;
use walls_diagnostics::{Diagnostic, LineIndex};
use walls_geometry::{Particle, Wall};
use walls_par::check::File;

/// The most places one rule reports in a run; the rest are counted in one more info.
pub const MAX_REPORTED: usize = 100;

/// The bytes of a `.ss` file's header.
pub const SS_HEADER: usize = 16;

/// The bytes of a particle's standard record (pkdgrav starts from no other).
pub const SS_RECORD: usize = 96;

/// A run directory's inputs, each as far as it could be read.
pub struct Run<'a> {
    /// The `.par` file, read by the build it is checked for.
    pub par: &'a File<'a>,
    /// The walls file, when the `.par` names one that could be read.
    pub walls: Option<WallsFile<'a>>,
    /// The initial conditions, when they could be read.
    pub particles: Option<SsFile<'a>>,
}

/// A walls file: its name as shown, its text, its walls decoded and where each is.
pub struct WallsFile<'a> {
    /// The name messages give it.
    pub name: &'a str,
    /// Its text (the spans are in it).
    pub text: &'a str,
    /// Its walls, decoded, in file order.
    pub walls: &'a [Wall],
    /// Where each wall is, in the same order.
    pub places: &'a [WallPlace],
}

/// Where a wall is written: its `wall` keyword, and the values of each token that set
/// something for it (its own or a `defaults` block's), by the token's name.
#[derive(Debug, Clone, Default)]
pub struct WallPlace {
    /// The `wall` keyword.
    pub wall: Range<usize>,
    /// Each token's name and the span of its values.
    pub tokens: Vec<(&'static str, Range<usize>)>,
}

/// A `.ss` file's particles.
pub struct SsFile<'a> {
    /// The name messages give it.
    pub name: &'a str,
    /// The particles, in file order.
    pub particles: &'a [Particle],
    /// The time in its header.
    pub time: f64,
}

impl SsFile<'_> {
    /// The byte range of particle `k`'s record.
    pub fn span(&self, k: usize) -> Range<usize> {
        let start = SS_HEADER + SS_RECORD * k;
        start..start + SS_RECORD
    }
}

/// The findings, by the file each is in, each list sorted by place.
#[derive(Debug, Default)]
pub struct Findings {
    /// In the `.par` file.
    pub par: Vec<Diagnostic>,
    /// In the walls file.
    pub walls: Vec<Diagnostic>,
    /// In the `.ss` file, at particles' records.
    pub particles: Vec<Diagnostic>,
}

/// Checks a run directory before the job.
pub fn check(run: &Run) -> Findings {
    let mut out = Findings::default();
    let context = Context::new(run);
    rules::pair_overlap::check(&context, &mut out);
    rules::wall_overlap::check(&context, &mut out);
    rules::outside_container::check(&context, &mut out);
    rules::few_steps::check(&context, &mut out);
    rules::wall_too_fast::check(&context, &mut out);
    rules::build_lacks::check(&context, &mut out);
    rules::no_output::check(&context, &mut out);
    rules::wide_steps::check(&context, &mut out);
    rules::initial_conditions::check(&context, &mut out);
    for list in [&mut out.par, &mut out.walls, &mut out.particles] {
        list.sort_by_key(|d| (d.span.start, d.span.end, d.code.id));
    }
    out
}

/// What the rules share: the run, its walls decoded and placed at the start, the radii
/// pkdgrav uses, and the `.par`'s values.
pub(crate) struct Context<'a> {
    pub run: &'a Run<'a>,
    /// The walls, decoded, their shapes where they are at the start.
    pub walls: Vec<Wall>,
    /// The walls file's lines.
    pub lines: Option<LineIndex>,
    /// Each particle's radius as pkdgrav uses it: `dSoft`'s, when the `.par` gives it
    /// (docs/pkdgrav-physics.md §19, C28).
    pub radii: Vec<f64>,
    /// Whether the build is a soft-sphere one (`DEM`).
    pub dem: bool,
}

impl<'a> Context<'a> {
    fn new(run: &'a Run<'a>) -> Self {
        // pkdgrav's t₀, where it places the walls before the first force evaluation
        // (docs/pkdgrav-physics.md §3, §5): `iStartStep`·`dDelta`.
        let t0 = match (run.par.real("iStartStep"), run.par.real("dDelta")) {
            (Some(step), Some(dt)) if (step * dt).is_finite() => step * dt,
            _ => 0.0,
        };
        let walls = run.walls.as_ref().map_or_else(Vec::new, |w| {
            (w.walls.iter())
                .map(|wall| {
                    let mut wall = wall.clone();
                    wall.shape = wall.shape.at(wall.motion.position_or_origin(t0));
                    wall
                })
                .collect()
        });
        let lines = run.walls.as_ref().map(|w| LineIndex::new(w.text));
        // Any `dSoft` the file gives replaces every radius, 0 and below too (P010); a
        // radius of 0 or less overlaps nothing.
        let soft = run
            .par
            .given("dSoft")
            .and_then(|_| run.par.real("dSoft"))
            .filter(|s| s.is_finite());
        let radii = run.particles.as_ref().map_or_else(Vec::new, |p| {
            p.particles
                .iter()
                .map(|p| soft.unwrap_or(p.radius))
                .collect()
        });
        Context {
            run,
            walls,
            lines,
            radii,
            dem: run.par.build.has("DEM"),
        }
    }

    /// The particles, when they were read.
    pub fn particles(&self) -> Option<&'a SsFile<'a>> {
        self.run.particles.as_ref()
    }

    /// Wall `w` as messages name it: `wall 2 (walls.dat line 7)`.
    pub fn wall_name(&self, w: usize) -> String {
        match (&self.run.walls, &self.lines) {
            (Some(file), Some(lines)) if w < file.places.len() => {
                let at = file.places[w].wall.start;
                let line = lines.line_col(file.text, at).line;
                format!("wall {w} ({} line {line})", file.name)
            }
            _ => format!("wall {w}"),
        }
    }

    /// The span of the `wall` keyword of wall `w`.
    pub fn wall_span(&self, w: usize) -> Range<usize> {
        (self.run.walls.as_ref())
            .and_then(|f| f.places.get(w))
            .map_or(0..0, |p| p.wall.clone())
    }

    /// The span of the values of the token `name` that set something for wall `w`.
    pub fn token_span(&self, w: usize, name: &str) -> Option<Range<usize>> {
        let place = self.run.walls.as_ref()?.places.get(w)?;
        (place.tokens.iter())
            .find(|(n, _)| *n == name)
            .map(|(_, span)| span.clone())
    }

    /// The value pkdgrav runs with for the `.par` key `key`, and where the file gives it
    /// (the value's span), or the start of the file when it leaves it at its default.
    pub fn par_value(&self, key: &str) -> Option<(f64, Range<usize>)> {
        let x = self.run.par.real(key)?;
        let span = self
            .run
            .par
            .given(key)
            .map_or(0..0, |e| e.value_span.clone());
        Some((x, span))
    }
}

/// The first [`MAX_REPORTED`] of `found` (sorted as wanted; the caller builds no more
/// than one past them), and one info of `code` at the first left out, saying how many
/// more of the `total` there are.
pub(crate) fn capped(
    mut found: Vec<Diagnostic>,
    total: usize,
    code: &'static walls_diagnostics::Code,
    what: &str,
) -> Vec<Diagnostic> {
    if total > MAX_REPORTED && found.len() > MAX_REPORTED {
        let rest = total - MAX_REPORTED;
        let at = found[MAX_REPORTED].span.clone();
        let record = found[MAX_REPORTED].record;
        found.truncate(MAX_REPORTED);
        let mut more = Diagnostic::new(
            code,
            walls_diagnostics::Severity::Info,
            at,
            format!("{rest} more {what} (the first {MAX_REPORTED} are reported)"),
        );
        more.record = record;
        found.push(more);
    }
    found
}

/// `x` as a percentage with three significant digits at most.
pub(crate) fn percent(fraction: f64) -> String {
    crate::advise::significant(100.0 * fraction, 3)
}

#[cfg(test)]
pub(crate) mod tests;
