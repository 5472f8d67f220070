//! The cell grid's pairs and neighbours against brute force over all pairs: the same set,
//! each pair once with i < j, in an order that depends only on the input; and its edge
//! cases (no particle, one, all at one point, zero radii, exact touching, a sphere far
//! away, non-finite input).

use nalgebra::Vector3;
use proptest::prelude::*;
use std::collections::BTreeSet;
use walls_sim::broad::grid::CellGrid;

type Vec3 = Vector3<f64>;

/// Whether particle i is binned: finite position, finite swollen radius ≥ 0.
fn valid(p: &Vec3, s: f64) -> bool {
    p.iter().all(|x| x.is_finite()) && s.is_finite() && s >= 0.0
}

/// The grid's criterion, written out: |p_i − p_j|² < (s_i + s_j)².
fn overlap(p: &[Vec3], s: &[f64], i: usize, j: usize) -> bool {
    let d = p[i] - p[j];
    let reach = s[i] + s[j];
    valid(&p[i], s[i]) && valid(&p[j], s[j]) && d.x * d.x + d.y * d.y + d.z * d.z < reach * reach
}

/// Every overlapping pair i < j, by checking them all.
fn brute_pairs(p: &[Vec3], s: &[f64]) -> BTreeSet<(usize, usize)> {
    let mut pairs = BTreeSet::new();
    for i in 0..p.len() {
        for j in i + 1..p.len() {
            if overlap(p, s, i, j) {
                pairs.insert((i, j));
            }
        }
    }
    pairs
}

/// Every j ≠ i overlapping i, by checking them all.
fn brute_neighbours(p: &[Vec3], s: &[f64], i: usize) -> BTreeSet<usize> {
    (0..p.len())
        .filter(|&j| j != i && overlap(p, s, i, j))
        .collect()
}

/// The pairs as the grid visits them.
fn visited(grid: &CellGrid) -> Vec<(usize, usize)> {
    let mut pairs = Vec::new();
    grid.for_each_pair(|i, j| pairs.push((i, j)));
    pairs
}

/// Checks a grid over spheres `p` of swollen radii `s` against brute force: pairs (each
/// once, i < j, the brute-force set; `pairs()` in the same order) and every particle's
/// neighbours (each once, never itself, the brute-force set); `par_pairs()` the same list.
fn check_grid(grid: &CellGrid, p: &[Vec3], s: &[f64]) -> Result<(), TestCaseError> {
    let pairs = visited(grid);
    for &(i, j) in &pairs {
        prop_assert!(i < j, "pair ({i}, {j}) not ordered");
    }
    let set: BTreeSet<(usize, usize)> = pairs.iter().copied().collect();
    prop_assert_eq!(set.len(), pairs.len(), "a pair reported twice");
    prop_assert_eq!(&set, &brute_pairs(p, s));
    let as_u32: Vec<(usize, usize)> = grid
        .pairs()
        .into_iter()
        .map(|(i, j)| (i as usize, j as usize))
        .collect();
    prop_assert_eq!(&as_u32, &pairs);
    prop_assert_eq!(
        grid.par_pairs(),
        grid.pairs(),
        "found in parallel, another list"
    );
    for i in 0..p.len() {
        let mut found = Vec::new();
        grid.for_each_neighbour(i, |j| found.push(j));
        let set: BTreeSet<usize> = found.iter().copied().collect();
        prop_assert_eq!(
            set.len(),
            found.len(),
            "a neighbour of {} reported twice",
            i
        );
        prop_assert_eq!(set, brute_neighbours(p, s, i), "neighbours of {}", i);
    }
    Ok(())
}

fn swollen(r: &[f64], m: &[f64]) -> Vec<f64> {
    r.iter().zip(m).map(|(r, m)| r + m).collect()
}

/// Random spheres: up to 200, in 1 to 6 clusters of random width whose centres spread
/// over a random scale (clustered to sparse), radii all equal (many pairs near the
/// largest diameter, the cell size) or spread over up to two orders of magnitude below a
/// random scale, margins 0 or up to the radius.
#[derive(Debug, Clone)]
struct Spheres {
    p: Vec<Vec3>,
    r: Vec<f64>,
    m: Vec<f64>,
}

fn spheres() -> impl Strategy<Value = Spheres> {
    let unit = || (-1.0..1.0f64, -1.0..1.0f64, -1.0..1.0f64);
    let particle = (0usize..6, unit(), -2.0..0.0f64, 0.0..1.0f64, any::<bool>());
    (
        1usize..=6,
        prop::collection::vec(unit(), 6),
        -2.0..2.0f64,
        -3.0..0.5f64,
        -3.0..0.0f64,
        prop_oneof![Just(0.0), Just(1.0), 0.0..1.0f64],
        prop::collection::vec(particle, 0..200),
    )
        .prop_map(|(k, centres, spread, width, radius, orders, particles)| {
            let (spread, width, radius) =
                (10f64.powf(spread), 10f64.powf(width), 10f64.powf(radius));
            let v = |(x, y, z): (f64, f64, f64)| Vec3::new(x, y, z);
            let mut out = Spheres {
                p: vec![],
                r: vec![],
                m: vec![],
            };
            for (c, u, lr, frac, has_margin) in particles {
                let r = radius * 10f64.powf(lr * orders);
                out.p.push(v(centres[c % k]) * spread + v(u) * width);
                out.r.push(r);
                out.m.push(if has_margin { frac * r } else { 0.0 });
            }
            out
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    #[test]
    fn pairs_and_neighbours_are_brute_force_with_margin(sp in spheres(), cut in 0.0..1.0f64) {
        let grid = CellGrid::with_margin(&sp.p, &sp.r, &sp.m);
        let s = swollen(&sp.r, &sp.m);
        check_grid(&grid, &sp.p, &s)?;
        // Deterministic: a second grid visits the same pairs in the same order.
        let again = CellGrid::with_margin(&sp.p, &sp.r, &sp.m);
        prop_assert_eq!(visited(&again), visited(&grid));
        // Two ranges of slots, one after the other, cut anywhere (within a cell too),
        // visit the pairs of the whole loop.
        let n = grid.binned();
        let split = ((n as f64) * cut) as usize;
        let mut parts = Vec::new();
        grid.for_each_pair_in(0..split, |i, j| parts.push((i, j)));
        grid.for_each_pair_in(split..n, |i, j| parts.push((i, j)));
        prop_assert_eq!(parts, visited(&grid));
    }

    #[test]
    fn pairs_and_neighbours_are_brute_force_without_margin(sp in spheres()) {
        let grid = CellGrid::new(&sp.p, &sp.r);
        check_grid(&grid, &sp.p, &sp.r)?;
        let zeros = vec![0.0; sp.p.len()];
        prop_assert_eq!(visited(&CellGrid::with_margin(&sp.p, &sp.r, &zeros)), visited(&grid));
    }

    #[test]
    fn a_grid_filled_again_is_the_grid_made_anew(a in spheres(), b in spheres()) {
        // One grid filled with one set, another, and the first again (each in the
        // memory the last left), as a candidate list's grid is.
        let mut grid = CellGrid::default();
        for sp in [&a, &b, &a] {
            let s = swollen(&sp.r, &sp.m);
            grid.refill(sp.p.len(), |i| Some((sp.p[i], s[i])));
            let fresh = CellGrid::with_margin(&sp.p, &sp.r, &sp.m);
            prop_assert_eq!(visited(&grid), visited(&fresh));
            prop_assert_eq!(grid.cell_count(), fresh.cell_count());
            check_grid(&grid, &sp.p, &s)?;
            // Into lists that held something: emptied first.
            let (mut one, mut par) = (vec![(7, 7)], vec![(7, 7); 300]);
            grid.pairs_into(&mut one);
            grid.par_pairs_into(&mut par);
            prop_assert_eq!(&one, &fresh.pairs());
            prop_assert_eq!(&par, &fresh.pairs());
        }
    }

    #[test]
    fn ranked_particles_moved_to_the_grids_order_give_the_same_pairs(
        sp in spheres(),
        alive in prop::collection::vec(any::<bool>(), 200),
    ) {
        // The soft-sphere run's places: each binned particle moved to its place in the
        // grid's order (the others after them) and ranked by its index before. Built
        // anew there, or taken as it was, the grid gives the same pairs in the same
        // order, each pair its lower rank first, and brute force's pairs.
        let s = swollen(&sp.r, &sp.m);
        let sphere = |i: usize| alive[i].then(|| (sp.p[i], s[i]));
        let mut grid = CellGrid::from_fn(sp.p.len(), sphere);
        let mut order: Vec<usize> = grid.order().into_iter().map(|i| i as usize).collect();
        let left_out: Vec<usize> = (0..sp.p.len()).filter(|i| !order.contains(i)).collect();
        order.extend(left_out);
        let old: Vec<(usize, usize)> = (grid.pairs().into_iter())
            .map(|(i, j)| (i as usize, j as usize))
            .collect();
        grid.placed_in_order();
        let mut anew = CellGrid::default();
        let placed = |place: usize| sphere(order[place]);
        anew.refill_ranked(sp.p.len(), placed, |place| order[place] as u32);
        let to_old = |pairs: Vec<(u32, u32)>| -> Vec<(usize, usize)> {
            pairs.into_iter().map(|(a, b)| (order[a as usize], order[b as usize])).collect()
        };
        prop_assert_eq!(to_old(grid.pairs()), old.clone());
        prop_assert_eq!(to_old(anew.pairs()), old.clone());
        prop_assert!(old.iter().all(|(i, j)| i < j));
        let s_alive: Vec<f64> = (0..sp.p.len()).map(|i| if alive[i] { s[i] } else { f64::NAN }).collect();
        prop_assert_eq!(old.into_iter().collect::<BTreeSet<_>>(), brute_pairs(&sp.p, &s_alive));
    }

    #[test]
    fn left_out_particles_meet_nothing_and_keep_the_indices(
        sp in spheres(),
        alive in prop::collection::vec(any::<bool>(), 200),
    ) {
        let grid = CellGrid::from_fn(sp.p.len(), |i| alive[i].then(|| (sp.p[i], sp.r[i] + sp.m[i])));
        // A particle that is not alive is, for brute force, one with a NaN radius.
        let s: Vec<f64> = (0..sp.p.len())
            .map(|i| if alive[i] { sp.r[i] + sp.m[i] } else { f64::NAN })
            .collect();
        check_grid(&grid, &sp.p, &s)?;
    }
}

fn v(x: f64, y: f64, z: f64) -> Vec3 {
    Vec3::new(x, y, z)
}

#[test]
fn no_particle_and_one_particle() {
    let grid = CellGrid::new(&[], &[]);
    assert_eq!(grid.cell_count(), 0);
    assert!(grid.pairs().is_empty());
    grid.for_each_pair_in(0..0, |_, _| panic!("no pair"));

    let grid = CellGrid::new(&[v(1.0, 2.0, 3.0)], &[0.5]);
    assert_eq!(grid.cell_count(), 1);
    assert_eq!(grid.binned(), 1);
    // One left out (not alive): not binned, and its index kept for the other.
    let grid = CellGrid::from_fn(2, |i| (i == 1).then(|| (v(1.0, 2.0, 3.0), 0.5)));
    assert_eq!((grid.binned(), grid.order()), (1, vec![1]));
    assert!(grid.pairs().is_empty());
    grid.for_each_neighbour(0, |j| panic!("neighbour {j} of the only particle"));
}

#[test]
fn all_at_one_point_is_every_pair() {
    let n = 60;
    let p = vec![v(0.3, -0.3, 7.0); n];
    let r = vec![0.1; n];
    let grid = CellGrid::new(&p, &r);
    assert_eq!(grid.cell_count(), 1);
    let pairs = grid.pairs();
    assert_eq!(pairs.len(), n * (n - 1) / 2);
    let expected: Vec<(u32, u32)> = (0..n as u32)
        .flat_map(|i| (i + 1..n as u32).map(move |j| (i, j)))
        .collect();
    assert_eq!(pairs, expected, "one cell: pairs in index order");
    let mut count = 0;
    grid.for_each_neighbour(17, |j| {
        assert_ne!(j, 17);
        count += 1;
    });
    assert_eq!(count, n - 1);
}

#[test]
fn zero_radii_touch_nothing_but_a_point_inside_a_sphere_does() {
    // All zero: distance² < 0 never holds, even at one point.
    let p = vec![v(1.0, 1.0, 1.0); 50];
    let grid = CellGrid::new(&p, &[0.0; 50]);
    assert!(grid.pairs().is_empty());
    grid.for_each_neighbour(3, |j| panic!("neighbour {j}"));
    // A point (radius 0) within a sphere's radius overlaps it; on its surface it does not.
    let p = [
        v(0.0, 0.0, 0.0),
        v(0.5, 0.0, 0.0),
        v(1.0, 0.0, 0.0),
        v(0.5, 0.0, 0.0),
    ];
    let r = [1.0, 0.0, 0.0, 0.0];
    assert_eq!(CellGrid::new(&p, &r).pairs(), vec![(0, 1), (0, 3)]);
}

#[test]
fn touching_exactly_is_not_a_pair_and_a_hair_closer_is() {
    // Distances and radii exact in binary: |d|² = (r_i + r_j)² exactly.
    let cases = [
        (v(0.0, 0.0, 0.0), 1.0, v(2.0, 0.0, 0.0), 1.0),
        (v(0.0, 0.0, 0.0), 2.0, v(3.0, 4.0, 0.0), 3.0),
        (v(-1.0, 5.0, 2.0), 0.25, v(-1.0, 5.0, 2.75), 0.5),
    ];
    for (a, ra, b, rb) in cases {
        let grid = CellGrid::new(&[a, b], &[ra, rb]);
        assert!(
            grid.pairs().is_empty(),
            "{a:?} {b:?}: touching is not overlapping"
        );
        grid.for_each_neighbour(0, |j| panic!("neighbour {j}"));
        // Move b towards a by one ulp of its largest coordinate.
        let d = b - a;
        let axis = d.iamax();
        let mut c = b;
        c[axis] = next_towards(c[axis], a[axis]);
        let grid = CellGrid::new(&[a, c], &[ra, rb]);
        assert_eq!(grid.pairs(), vec![(0, 1)], "{a:?} {c:?}");
    }
    // With margins: distance 3, radii 1, margins 0.5 touch exactly; 0.5 + a bit overlap.
    let p = [v(0.0, 0.0, 0.0), v(0.0, 3.0, 0.0)];
    assert!(
        CellGrid::with_margin(&p, &[1.0, 1.0], &[0.5, 0.5])
            .pairs()
            .is_empty()
    );
    assert!(CellGrid::new(&p, &[1.0, 1.0]).pairs().is_empty());
    assert_eq!(
        CellGrid::with_margin(&p, &[1.0, 1.0], &[0.5, 0.5 + 1e-9]).pairs(),
        vec![(0, 1)]
    );
}

#[test]
fn pairs_just_inside_reach_straddling_cell_boundaries() {
    // Two spheres of radius 0.5 a hair less than their diameter apart, slid across the
    // cell boundaries near 1 and 2 along an axis and a diagonal: the pair is always found,
    // so no overlapping pair is ever two cells apart.
    let gap = 1.0 - 1e-9;
    for dir in [
        v(1.0, 0.0, 0.0),
        v(0.0, 1.0, 1.0).normalize(),
        v(1.0, 1.0, 1.0).normalize(),
    ] {
        for step in 0..20_000 {
            let a = v(1.0, 1.0, 1.0) * (step as f64 * 1e-4) + v(0.1, -0.7, 0.3);
            let p = [a, a + dir * gap];
            let grid = CellGrid::new(&p, &[0.5, 0.5]);
            assert_eq!(
                grid.pairs(),
                vec![(0, 1)],
                "{p:?}, cells of {}",
                grid.cell_size()
            );
            let mut found = Vec::new();
            grid.for_each_neighbour(1, |j| found.push(j));
            assert_eq!(found, vec![0]);
        }
    }
}

/// The next double after `x` towards `to`.
fn next_towards(x: f64, to: f64) -> f64 {
    let bits = x.to_bits();
    match (x < to, x > 0.0) {
        (true, true) | (false, false) if x != 0.0 => f64::from_bits(bits + 1),
        _ if x == 0.0 => {
            if to > 0.0 {
                f64::from_bits(1)
            } else {
                -f64::from_bits(1)
            }
        }
        _ => f64::from_bits(bits - 1),
    }
}

#[test]
fn a_sphere_far_away_costs_nothing_and_is_still_correct() {
    // 200 small spheres near 0 and a pair touching at 10¹².
    let mut p: Vec<Vec3> = (0..200)
        .map(|i| {
            let f = |a: f64| (i as f64 * a).fract();
            v(f(0.754_877_666), f(0.569_840_291), f(0.430_159_709)) * 0.3
        })
        .collect();
    let mut r = vec![0.01; 200];
    p.push(v(1e12, 0.0, 0.0));
    p.push(v(1e12, 0.015, 0.0));
    r.extend([0.01, 0.01]);
    let grid = CellGrid::new(&p, &r);
    assert!(grid.cell_size() < 0.03, "cells of {}", grid.cell_size());
    assert!(grid.cell_count() <= p.len());
    check_grid(&grid, &p, &r).unwrap();
    assert!(grid.pairs().contains(&(200, 201)));
    // Spread to the end of f64: no panic, no allocation by volume, still brute force.
    let p = vec![
        v(f64::MAX, 0.0, 0.0),
        v(-f64::MAX, f64::MAX, 0.0),
        v(1e300, 1e300, -1e300),
        v(1e300, 1e300, -1e300),
        v(0.0, 0.0, 0.0),
        v(0.5, 0.0, 0.0),
        v(1e-300, 0.0, 0.0),
    ];
    let r = [1.0, 1.0, 1e-3, 1e-3, 0.3, 0.3, 1e-300];
    let grid = CellGrid::new(&p, &r);
    check_grid(&grid, &p, &r).unwrap();
    assert!(grid.pairs().contains(&(2, 3)));
    // Huge radii: one cell, everything overlaps.
    let r = [1e300; 7];
    check_grid(&CellGrid::new(&p, &r), &p, &r).unwrap();
}

#[test]
fn non_finite_input_is_left_out() {
    let nan = f64::NAN;
    let p = [
        v(0.0, 0.0, 0.0),
        v(nan, 0.0, 0.0),
        v(0.1, 0.0, 0.0),
        v(0.0, f64::INFINITY, 0.0),
        v(0.0, 0.1, 0.0),
        v(0.0, 0.0, 0.1),
        v(0.0, 0.0, -0.1),
        v(0.1, 0.1, 0.1),
    ];
    let r = [0.1, 0.1, 0.1, 0.1, nan, f64::INFINITY, -0.5, 0.1];
    let grid = CellGrid::new(&p, &r);
    assert_eq!(grid.pairs(), vec![(0, 2), (0, 7), (2, 7)]);
    check_grid(&grid, &p, &r).unwrap();
    for i in [1, 3, 4, 5, 6] {
        grid.for_each_neighbour(i, |j| panic!("left-out {i} has neighbour {j}"));
    }
    // All NaN: nothing binned.
    let grid = CellGrid::new(&[v(nan, nan, nan); 5], &[1.0; 5]);
    assert_eq!(grid.cell_count(), 0);
    assert!(grid.pairs().is_empty());
}

#[test]
fn a_grid_filled_again_goes_between_packed_wide_and_no_keys() {
    // Close together (packed keys); a pair 10⁹ away from the rest (keys spanning more
    // than 2²¹ cells: wide); radii of zero (nothing can overlap: no cells); close again.
    let near = [v(0.0, 0.0, 0.0), v(1.5, 0.0, 0.0), v(0.5, 0.5, 0.0)];
    let far = [v(0.0, 0.0, 0.0), v(1e9, 0.0, 0.0), v(1e9 + 0.5, 0.0, 0.0)];
    let all: &[(u32, u32)] = &[(0, 1), (0, 2), (1, 2)];
    let scenes = [
        (&near, 1.0, all),
        (&far, 0.3, &[(1, 2)][..]),
        (&near, 0.0, &[][..]),
        (&near, 1.0, all),
    ];
    let mut grid = CellGrid::default();
    for (p, r, expected) in scenes {
        grid.refill(p.len(), |i| Some((p[i], r)));
        let mut pairs = grid.pairs();
        pairs.sort_unstable();
        assert_eq!(pairs, expected, "radius {r}");
        let fresh = CellGrid::new(p, &vec![r; p.len()]);
        assert_eq!(grid.pairs(), fresh.pairs());
        assert_eq!(grid.cell_count(), fresh.cell_count());
        assert_eq!(grid.cell_size(), fresh.cell_size());
        for i in 0..p.len() {
            let (mut mine, mut theirs) = (Vec::new(), Vec::new());
            grid.for_each_neighbour(i, |j| mine.push(j));
            fresh.for_each_neighbour(i, |j| theirs.push(j));
            assert_eq!(mine, theirs, "neighbours of {i}");
        }
    }
}

#[test]
fn many_particles_are_sorted_by_cell_then_index_on_any_thread() {
    // 40,000 spheres, more than the grid sorts on rayon's threads: the grid's order is
    // the cells' keys ascending, then the indices, on one thread or three.
    let n = 40_000;
    let at = |k: usize, a: f64| ((k as f64 * a).fract() - 0.5) * 0.2;
    let p: Vec<Vec3> = (0..n)
        .map(|k| {
            v(
                at(k, 0.754_877_666),
                at(k, 0.569_840_291),
                at(k, 0.430_159_709),
            )
        })
        .collect();
    let r = vec![1e-3; n];
    for threads in [1, 3] {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        let grid = pool.install(|| CellGrid::new(&p, &r));
        let h = grid.cell_size();
        let inv_h = 1.0 / h;
        let key = |i: usize| p[i].map(|x| (x * inv_h).floor() as i64);
        let order: Vec<usize> = grid.order().into_iter().map(|i| i as usize).collect();
        assert_eq!(order.len(), n);
        assert!(order.windows(2).all(|w| {
            let (a, b) = (key(w[0]), key(w[1]));
            (a[0], a[1], a[2], w[0]) < (b[0], b[1], b[2], w[1])
        }));
    }
}
