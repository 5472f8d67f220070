//! R001 `initial-pair-overlap`: two particles of the initial conditions overlap beyond
//! one of pkdgrav's levels (docs/pkdgrav-physics.md §12, §15; start-up rows A129, B60).
//!
//! Pairs are found on the evaluator's cell grid ([`crate::broad::grid::CellGrid`]), in
//! parallel; x = r₁ + r₂ − d against frac·min(r₁, r₂), strictly above. Members of one
//! aggregate (the same negative `org_idx`, in an `AGGS` build) and pairs of two stuck
//! particles (negative colours) are skipped, as pkdgrav skips them. Only soft-sphere
//! (`DEM`) builds check overlaps so.

use super::{Levels, consequence};
use crate::broad::grid::CellGrid;
use crate::precheck::{Context, Findings, capped, percent};
use rayon::prelude::*;
use walls_diagnostics::{Code, Diagnostic};

/// Two particles that overlap at the start.
pub static PAIR_OVERLAP: Code = Code {
    id: "R001",
    name: "initial-pair-overlap",
    summary: "two particles of the initial conditions overlap beyond pkdgrav's dMinorFrac, dMajorFrac or dErrorFrac",
    explanation: concat!(
        "pkdgrav checks every touching pair at its first force evaluation, at step 0: an
overlap x = r₁ + r₂ − d above `dErrorFrac` (default 0.5) of the smaller radius aborts the
run at once, with nothing written; above `dMajorFrac` (0.15) it warns, above `dMinorFrac`
(0.03) it counts a minor overlap. `walls-lint` reports the pair at the first particle
(its record in the `.ss` file, particles numbered from 0 in file order) and names the
other: an error, a warning or an info by the level reached. Members of one aggregate
(`AGGS`) and two stuck particles do not interact and are skipped.

Bad (`ss.ic`: two particles of radius 1, their centres 0.9 apart):
```par\n",
        run_par!(),
        "dDelta               = 1e-7
nSteps               = 1000
dKn                  = 1e5
```

Good (the centres 2 apart, or `dErrorFrac` raised above the overlap):
```par\n",
        run_par!(),
        "dDelta               = 1e-7
nSteps               = 1000
dKn                  = 1e5
```
"
    ),
};

/// Reports the pairs that overlap beyond a level.
pub(crate) fn check(cx: &Context, out: &mut Findings) {
    let Some(ss) = cx.particles() else { return };
    if !cx.dem || ss.particles.len() < 2 {
        return;
    }
    let levels = Levels::of(cx.run.par);
    let aggs = cx.run.par.build.has("AGGS");
    let ps = ss.particles;
    let mut found: Vec<(walls_diagnostics::Severity, u32, u32, f64)> = candidates(ps, &cx.radii)
        .into_par_iter()
        .filter_map(|(i, j)| {
            let (i, j) = (i.min(j), i.max(j));
            let (a, b) = (&ps[i as usize], &ps[j as usize]);
            if aggs && a.index < 0 && a.index == b.index {
                return None;
            }
            if a.color < 0 && b.color < 0 {
                return None;
            }
            let (ra, rb) = (cx.radii[i as usize], cx.radii[j as usize]);
            let x = ra + rb - (a.pos - b.pos).norm();
            let fraction = x / ra.min(rb);
            let (severity, ..) = levels.of_overlap(fraction)?;
            Some((severity, i, j, fraction))
        })
        .collect();
    found.sort_by_key(|a| (a.0, a.1, a.2));
    // Only the first are built: at 10⁶ overlaps, a diagnostic each would take a GB.
    let total = found.len();
    found.truncate(crate::precheck::MAX_REPORTED + 1);
    let diagnostics = found
        .into_iter()
        .map(|(severity, i, j, fraction)| {
            let (_, key, level) = levels.of_overlap(fraction).expect("found at a level");
            let (i, j) = (i as usize, j as usize);
            Diagnostic::new(
                &PAIR_OVERLAP,
                severity,
                ss.span(i),
                format!(
                    "particles {i} and {j} overlap by {} % of the smaller radius at the start, above {key} = {level}: {}",
                    percent(fraction),
                    consequence(severity)
                ),
            )
            .in_record("particle", i)
            .with_label(ss.span(j), format!("particle {j}"))
            .with_help(help(severity))
        })
        .collect();
    out.particles.extend(capped(
        diagnostics,
        total,
        &PAIR_OVERLAP,
        "overlapping pairs",
    ));
}

/// A particle bigger than this many times the median radius is not binned: the grid's
/// cells are as big as its largest sphere, and one huge particle (a hostile `.ss`) would
/// put every other in one cell, every pair of them a candidate.
const BIG: f64 = 4.0;

/// The most distances the big particles are measured to the others one by one; beyond,
/// they go in the grid with the others (correct, slower).
const ONE_BY_ONE: usize = 500_000_000;

/// The pairs of `particles` (with `radii`) whose spheres may overlap, each once, lower
/// index first: from the cell grid of the particles of ordinary size, and each big
/// particle against every other.
fn candidates(particles: &[walls_geometry::Particle], radii: &[f64]) -> Vec<(u32, u32)> {
    let n = particles.len();
    let mut sorted = radii.to_vec();
    let median = *sorted.select_nth_unstable_by(n / 2, f64::total_cmp).1;
    drop(sorted);
    let big = |i: usize| radii[i] > BIG * median;
    let bigs: Vec<usize> = (0..n).filter(|&i| big(i)).collect();
    let split = !bigs.is_empty() && bigs.len().saturating_mul(n) <= ONE_BY_ONE;
    let grid = CellGrid::from_fn(n, |i| {
        (!split || !big(i)).then(|| (particles[i].pos, radii[i]))
    });
    let mut pairs = grid.par_pairs();
    drop(grid);
    if split {
        let near: Vec<(u32, u32)> = (bigs.par_iter())
            .flat_map_iter(|&b| {
                let (p, r) = (particles[b].pos, radii[b]);
                (0..n)
                    .filter(move |&j| j != b && !(big(j) && j < b))
                    .filter(move |&j| (particles[j].pos - p).norm() < r + radii[j])
                    .map(move |j| (b.min(j) as u32, b.max(j) as u32))
            })
            .collect();
        pairs.extend(near);
    }
    pairs
}

/// What to do about an overlap of `severity`'s level.
pub(super) fn help(severity: walls_diagnostics::Severity) -> &'static str {
    match severity {
        walls_diagnostics::Severity::Error => {
            "move the particles apart (or shrink them) in the initial conditions; raising dErrorFrac only hides a contact that starts with a huge force"
        }
        _ => {
            "the contact starts compressed and pushes the particles apart at once: place them apart if that is not meant"
        }
    }
}
