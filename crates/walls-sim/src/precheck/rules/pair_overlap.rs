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
    let positions: Vec<_> = ps.iter().map(|p| p.pos).collect();
    let grid = CellGrid::new(&positions, &cx.radii);
    drop(positions);
    let mut found: Vec<(walls_diagnostics::Severity, u32, u32, f64)> = grid
        .par_pairs()
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
    out.particles
        .extend(capped(diagnostics, &PAIR_OVERLAP, "overlapping pairs"));
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
