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
use walls_diagnostics::Diagnostic;

pub use walls_par::run_codes::pair_overlap::PAIR_OVERLAP;

/// Reports the pairs that overlap beyond a level.
pub(crate) fn check(cx: &Context, out: &mut Findings) {
    let Some(ss) = cx.particles() else { return };
    if !cx.dem || ss.particles.len() < 2 {
        return;
    }
    let levels = Levels::of(cx.run.par);
    let aggs = cx.run.par.build.has("AGGS");
    let ps = ss.particles;
    let radii = &cx.radii;
    let judge = |i: usize, j: usize| -> Option<Found> {
        let (i, j) = (i.min(j), i.max(j));
        let (a, b) = (&ps[i], &ps[j]);
        if aggs && a.index < 0 && a.index == b.index {
            return None;
        }
        if a.color < 0 && b.color < 0 {
            return None;
        }
        let (ra, rb) = (radii[i], radii[j]);
        if ra.min(rb) <= 0.0 {
            // pkdgrav's x > frac·min(r) never holds for a radius of 0 or less (`dSoft`).
            return None;
        }
        let x = ra + rb - (a.pos - b.pos).norm();
        let fraction = x / ra.min(rb);
        let (severity, ..) = levels.of_overlap(fraction)?;
        Some((severity, i as u32, j as u32, fraction))
    };
    // Only the first are kept, however many pairs overlap (10⁴ particles at one point
    // are 5·10⁷ overlapping pairs): a count, and the first places in report order.
    let (total, found) = overlapping(ps, radii, &judge);
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

/// An overlap found: its severity, the pair (lower index first) and its fraction.
type Found = (walls_diagnostics::Severity, u32, u32, f64);

/// How many of the found overlaps are kept: the reported ones and the first beyond.
const KEPT: usize = crate::precheck::MAX_REPORTED + 1;

/// The found overlaps kept while counting: at most [`KEPT`] of them, the first in report
/// order (severity, then the pair).
#[derive(Default)]
struct Kept {
    count: usize,
    first: Vec<Found>,
}

impl Kept {
    fn push(&mut self, found: Found) {
        self.count += 1;
        self.first.push(found);
        if self.first.len() >= 4 * KEPT {
            self.trim();
        }
    }

    fn trim(&mut self) {
        self.first.sort_by_key(|a| (a.0, a.1, a.2));
        self.first.truncate(KEPT);
    }

    fn merge(mut self, other: Kept) -> Kept {
        self.count += other.count;
        self.first.extend(other.first);
        self.trim();
        self
    }
}

/// A particle bigger than this many times the median radius is not binned: the grid's
/// cells are as big as its largest sphere, and one huge particle (a hostile `.ss`) would
/// put every other in one cell, every pair of them a candidate. The big ones are found
/// on a grid of their own, with cells as big as the biggest.
const BIG: f64 = 4.0;

/// The overlapping pairs of `particles` (with `radii`) that `judge` finds: how many, and
/// the first [`KEPT`] in report order. The particles of ordinary size meet on the cell
/// grid; each big one meets the others on a coarse grid of the big ones.
fn overlapping(
    particles: &[walls_geometry::Particle],
    radii: &[f64],
    judge: &(impl Fn(usize, usize) -> Option<Found> + Sync),
) -> (usize, Vec<Found>) {
    let n = particles.len();
    let mut sorted = radii.to_vec();
    let median = *sorted.select_nth_unstable_by(n / 2, f64::total_cmp).1;
    drop(sorted);
    // A radius of 0 or less (`dSoft`) overlaps nothing, and is left out.
    let big = |i: usize| radii[i] > 0.0 && radii[i] > BIG * median;
    let grid = CellGrid::from_fn(n, |i| {
        (radii[i] > 0.0 && !big(i)).then(|| (particles[i].pos, radii[i]))
    });
    let binned = grid.binned();
    let size = binned.div_ceil(256).max(1);
    let mut kept = (0..binned.div_ceil(size))
        .into_par_iter()
        .map(|c| {
            let mut kept = Kept::default();
            grid.for_each_pair_in(c * size..((c + 1) * size).min(binned), |i, j| {
                if let Some(f) = judge(i, j) {
                    kept.push(f);
                }
            });
            kept
        })
        .reduce(Kept::default, Kept::merge);
    drop(grid);
    let bigs: Vec<usize> = (0..n).filter(|&i| big(i)).collect();
    if !bigs.is_empty() {
        kept = kept.merge(with_bigs(particles, radii, &bigs, &big, judge));
    }
    kept.trim();
    (kept.count, kept.first)
}

/// The overlaps of the big particles `bigs` (each against every particle, once a pair),
/// found on a hash grid of the big ones whose cells are twice the biggest radius: a
/// particle looks in the 27 cells around its own.
fn with_bigs(
    particles: &[walls_geometry::Particle],
    radii: &[f64],
    bigs: &[usize],
    big: &(impl Fn(usize) -> bool + Sync),
    judge: &(impl Fn(usize, usize) -> Option<Found> + Sync),
) -> Kept {
    let biggest = bigs.iter().map(|&b| radii[b]).fold(0.0, f64::max);
    let cell = 2.0 * biggest;
    let key = |p: &nalgebra::Vector3<f64>| p.map(|x| (x / cell).floor() as i64).into();
    let mut grid: std::collections::HashMap<[i64; 3], Vec<usize>> =
        std::collections::HashMap::new();
    for &b in bigs {
        grid.entry(key(&particles[b].pos)).or_default().push(b);
    }
    (0..particles.len())
        .into_par_iter()
        .filter(|&j| radii[j] > 0.0)
        .fold(Kept::default, |mut kept, j| {
            let k: [i64; 3] = key(&particles[j].pos);
            for dx in -1..=1 {
                for dy in -1..=1 {
                    for dz in -1..=1 {
                        let at = [
                            k[0].saturating_add(dx),
                            k[1].saturating_add(dy),
                            k[2].saturating_add(dz),
                        ];
                        for &b in grid.get(&at).map_or(&[][..], Vec::as_slice) {
                            // A pair of two big ones is met from its higher index only.
                            if b == j || (big(j) && b > j) {
                                continue;
                            }
                            if let Some(f) = judge(b, j) {
                                kept.push(f);
                            }
                        }
                    }
                }
            }
            kept
        })
        .reduce(Kept::default, Kept::merge)
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
