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
use walls_diagnostics::{Diagnostic, Severity};
use walls_geometry::shape::cull::Cull;

pub use walls_par::run_codes::wall_overlap::WALL_OVERLAP;

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
