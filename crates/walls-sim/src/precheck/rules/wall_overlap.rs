//! R002 `initial-wall-overlap`: a particle of the initial conditions overlaps a wall
//! beyond one of pkdgrav's levels (docs/pkdgrav-physics.md §6, §12, §15; start-up rows
//! A129, B60).
//!
//! x = r − d against frac·r, strictly above, with the walls where they are at the start.
//! The walls are taken in file order, as pkdgrav takes them: a death wall (`epsn` < 0)
//! the particle overlaps deletes it first (no later wall counts), a sticky wall
//! (`epsn` 0) holds it (no later wall counts either). Particles stuck already (negative
//! colours) have no wall contacts. Only soft-sphere (`DEM`) builds check overlaps so.

use super::{Levels, consequence};
use crate::precheck::{Context, Findings, capped, percent};
use rayon::prelude::*;
use walls_diagnostics::{Code, Diagnostic, Severity};
use walls_geometry::shape::cull::Cull;

/// A particle that overlaps a wall at the start.
pub static WALL_OVERLAP: Code = Code {
    id: "R002",
    name: "initial-wall-overlap",
    summary: "a particle of the initial conditions overlaps a wall beyond pkdgrav's dMinorFrac, dMajorFrac or dErrorFrac",
    explanation: concat!(
        "pkdgrav checks every particle against the walls at its first force evaluation, at
step 0: an overlap x = r − d above `dErrorFrac` (default 0.5) of the particle's radius
aborts the run at once, with nothing written; above `dMajorFrac` (0.15) it warns, above
`dMinorFrac` (0.03) it counts a minor overlap. `walls-lint` reports it at the particle
(its record in the `.ss` file, particles numbered from 0 in file order), naming the wall
and its line in the walls file: an error, a warning or an info by the level reached. The
walls are where their motion puts them at the start; a death wall the particle overlaps
deletes it first, a sticky one holds it.

Bad (`walls.dat`: a plane through the origin, normal +z; `ss.ic`: a particle of radius 1 at z = 0.4):
```par\n",
        run_par!(),
        "dDelta               = 1e-7
nSteps               = 1000
dKn                  = 1e5
```

Good (the particle at height 1 or more):
```par\n",
        run_par!(),
        "dDelta               = 1e-7
nSteps               = 1000
dKn                  = 1e5
```
"
    ),
};

/// Reports the particles that overlap a wall beyond a level.
pub(crate) fn check(cx: &Context, out: &mut Findings) {
    let Some(ss) = cx.particles() else { return };
    if !cx.dem || cx.walls.is_empty() {
        return;
    }
    let levels = Levels::of(cx.run.par);
    let culls: Vec<Cull> = cx.walls.iter().map(|w| Cull::of(&w.shape)).collect();
    let mut found: Vec<(Severity, usize, usize, f64)> = (ss.particles)
        .par_iter()
        .enumerate()
        .filter(|(_, p)| p.color >= 0)
        .filter_map(|(k, p)| {
            let r = cx.radii[k];
            // The deepest overlap at a level, over the walls pkdgrav reaches.
            let mut worst: Option<(Severity, usize, usize, f64)> = None;
            for (w, wall) in cx.walls.iter().enumerate() {
                if culls[w].clear_of(&p.pos, r) {
                    continue;
                }
                let x = r - wall.shape.nearest(&p.pos).distance;
                if x <= 0.0 {
                    continue;
                }
                let eps_n = wall.material.eps_n;
                if eps_n < 0.0 {
                    // Deleted before the overlap is looked at.
                    break;
                }
                if let Some((severity, ..)) = levels.of_overlap(x / r)
                    && worst.is_none_or(|(.., f)| x / r > f)
                {
                    worst = Some((severity, k, w, x / r));
                }
                if eps_n == 0.0 {
                    break;
                }
            }
            worst
        })
        .collect();
    found.sort_by_key(|a| (a.0, a.1));
    // Only the first are built: at 10⁶ overlaps, a diagnostic each would take a GB.
    let total = found.len();
    found.truncate(crate::precheck::MAX_REPORTED + 1);
    let diagnostics = found
        .into_iter()
        .map(|(severity, k, w, fraction)| {
            let (_, key, level) = levels.of_overlap(fraction).expect("found at a level");
            Diagnostic::new(
                &WALL_OVERLAP,
                severity,
                ss.span(k),
                format!(
                    "particle {k} overlaps {} by {} % of its radius at the start, above {key} = {level}: {}",
                    cx.wall_name(w),
                    percent(fraction),
                    consequence(severity)
                ),
            )
            .in_record("particle", k)
            .with_help(super::pair_overlap::help(severity))
        })
        .collect();
    out.particles.extend(capped(
        diagnostics,
        total,
        &WALL_OVERLAP,
        "particles overlapping walls",
    ));
}
