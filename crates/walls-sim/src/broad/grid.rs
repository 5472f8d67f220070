//! The particle–particle broad phase: a uniform grid of cubic cells (linked cells) over
//! the particles' positions, rebuilt each step.
//!
//! Each particle is a sphere of *swollen radius* s = r + m: its radius r plus a margin
//! m ≥ 0. Two particles are reported when their swollen spheres overlap, strictly:
//!
//! ```text
//! dx·dx + dy·dy + dz·dz < (s_i + s_j)²      (d = p_i − p_j, in f64, in that order)
//! ```
//!
//! so spheres that touch exactly (distance = s_i + s_j) are *not* reported. One grid
//! serves both contact models:
//! - soft spheres (SSDEM) need the pairs that overlap now: margin 0 ([`CellGrid::new`]);
//! - hard spheres (HSDEM) need the pairs that could meet within a step of length dt:
//!   margin m_i = |v_i|·dt, so that s_i + s_j = r_i + r_j + (|v_i| + |v_j|)·dt
//!   ([`CellGrid::with_margin`]).
//!
//! **Cell size** h: the largest swollen diameter 2·s_max, made larger by 2⁻²⁰ of itself
//! and by 2⁻⁴⁸ of the largest coordinate magnitude M. Then two overlapping spheres are
//! less than one cell apart along each axis, so their cells (⌊p/h⌋) are neighbours, even
//! after rounding: p·(1/h) is off by at most about 2⁻⁵²·|p|/h cells, which the M term
//! outweighs eight times over, and the 2⁻²⁰ covers the rounding of the distance test.
//! The M term also keeps |p/h| ≤ 2⁴⁸, so the integer keys never overflow; it matters only
//! for huge spreads (a sphere at 10¹² with radii of 0.01 gives cells of 0.024 instead of
//! 0.02). h is at least 2⁻⁴⁸⁰ so that 1/h is finite. Smaller cells would need more than
//! the 27 neighbour cells searched; larger ones only hold more candidates.
//!
//! **Hashing**: no array over the bounding box. The particles are sorted by their cell's
//! key (i, j, k) = ⌊p/h⌋ (lexicographically, then by index) and each occupied cell is a
//! range of that order, so memory is O(N) whatever the spread. The cells of one column
//! (same i, j) are consecutive in that order, so the neighbours of a cell are one run of
//! particles in each of 4 columns (pairs: the half shell) or 9 (one particle's
//! neighbours). When the keys span fewer than 2²¹ − 2 cells along each axis (the usual
//! case), each key is packed into one u64 of the same order, which sorts and compares
//! faster; otherwise the keys stay three i64.
//!
//! **Cost**: O(N log N) to build; the pair loop checks the pairs of each cell with the
//! cell itself and its 13 forward neighbours. A cell holds about φ·(h/2s)³·6/π ≈ 1.9·φ
//! spheres at volume fraction φ when the radii are equal. Radii spread over orders of
//! magnitude make the cells as big as the largest sphere, so many small ones share a
//! cell: still correct, slower.
//!
//! **Determinism**: the order of the pairs depends only on the input: cells by key,
//! within a cell by rank (the particle's index, unless the builder ranks them otherwise:
//! [`CellGrid::refill_ranked`]), neighbour cells in a fixed order; each pair is reported
//! lower rank first. No hashing with random state; many particles are sorted on
//! rayon's threads, which the distinct ranks leave one order to find.
//!
//! **Left out**: a particle whose position has a non-finite coordinate, or whose swollen
//! radius is not finite or is negative, is not binned and meets nothing (no panic). To
//! leave out particles that are not alive while keeping their indices, use
//! [`CellGrid::from_fn`] and return `None` for them.
//!
//! The grid keeps its own copy of the positions and swollen radii, in cell order: the
//! pair loop reads them contiguously, and the grid cannot be queried with positions other
//! than those it binned. The copy is 40 bytes a particle, rebuilt each step with the rest.

use crate::permute;
use nalgebra::Vector3;
use rayon::prelude::*;
use std::ops::Range;

/// Into how many ranges of cells [`CellGrid::par_pairs`] cuts the grid.
const PAIR_RANGES: usize = 64;

/// From how many particles the grid sorts them on rayon's threads.
const PAR_SORT_FROM: usize = 1 << 15;

type Vec3 = Vector3<f64>;

/// The slot of a particle that is not binned.
const NONE: u32 = u32::MAX;

/// The columns (Δi, Δj) after (0, 0) in key order, whose cells with Δk ∈ {−1, 0, 1} are
/// the forward neighbours of a cell, besides (0, 0, +1).
const FORWARD_COLUMNS: [(i64, i64); 4] = [(0, 1), (1, -1), (1, 0), (1, 1)];

/// Bits of a packed key per axis.
const BITS: u32 = 21;

/// A binned particle: its position, swollen radius, index and rank (40 bytes, as
/// without the rank: it takes the index's padding).
#[derive(Debug, Clone, Copy)]
struct Slot {
    p: Vec3,
    s: f64,
    id: u32,
    rank: u32,
}

/// A cell key, ordered as (i, j, k) lexicographically.
trait Key: Copy + Ord + Send {
    /// The key of the cell (di, dj, dk) away, each in {−1, 0, 1}.
    fn shift(self, di: i64, dj: i64, dk: i64) -> Self;
}

impl Key for [i64; 3] {
    #[inline]
    fn shift(self, di: i64, dj: i64, dk: i64) -> Self {
        [self[0] + di, self[1] + dj, self[2] + dk]
    }
}

/// A key packed into 21 bits per axis, i highest, each counted from one below the
/// lowest key of the grid so that a neighbour's never leaves its field.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
struct Packed(u64);

impl Packed {
    /// `k` packed, for a grid whose lowest key along each axis is `lo`.
    #[inline]
    fn new(k: [i64; 3], lo: [i64; 3]) -> Self {
        let field = |d: usize| (k[d] - lo[d] + 1) as u64;
        Packed(field(0) << (2 * BITS) | field(1) << BITS | field(2))
    }
}

impl Key for Packed {
    #[inline]
    fn shift(self, di: i64, dj: i64, dk: i64) -> Self {
        Packed(
            self.0
                .wrapping_add_signed((di << (2 * BITS)) + (dj << BITS) + dk),
        )
    }
}

/// The occupied cells' keys, ascending.
#[derive(Debug, Clone)]
enum Keys {
    /// Packed, with the lowest key along each axis.
    Packed(Vec<Packed>, [i64; 3]),
    /// As they are.
    Wide(Vec<[i64; 3]>),
}

/// A uniform grid of cubic cells over a set of spheres, for finding the pairs whose
/// swollen spheres overlap (see the [module documentation](self)). The default grid holds
/// nothing (no cells).
#[derive(Debug, Clone)]
pub struct CellGrid {
    /// Cell edge h.
    h: f64,
    /// 1/h, for the cell keys.
    inv_h: f64,
    /// The binned particles, sorted by cell key then rank.
    slots: Vec<Slot>,
    /// The occupied cells' keys, ascending.
    keys: Keys,
    /// Cell c holds `slots[starts[c]..starts[c + 1]]`; one more entry than the keys.
    starts: Vec<u32>,
    /// Each particle's slot, or [`NONE`].
    slot_of: Vec<u32>,
}

impl Default for CellGrid {
    fn default() -> Self {
        CellGrid {
            h: 1.0,
            inv_h: 1.0,
            slots: Vec::new(),
            keys: Keys::Wide(Vec::new()),
            starts: vec![0],
            slot_of: Vec::new(),
        }
    }
}

/// What building a [`CellGrid`] works in besides the grid (the binned particles' keys to
/// sort, with their ranks), kept between builds by whoever builds one again and again
/// ([`CellGrid::refill`]).
#[derive(Debug, Default)]
pub struct GridScratch {
    order: Vec<(Packed, u32, u32)>,
}

impl CellGrid {
    /// Bins spheres of `radii` at `positions`, without margin: the pairs reported are
    /// those that overlap now (soft spheres).
    ///
    /// # Panics
    /// If the slices differ in length, or hold `u32::MAX` particles or more.
    pub fn new(positions: &[Vec3], radii: &[f64]) -> Self {
        assert_eq!(positions.len(), radii.len(), "one radius per position");
        Self::from_fn(positions.len(), |i| Some((positions[i], radii[i])))
    }

    /// Bins spheres of `radii` at `positions`, each swollen by `margin[i]` (≥ 0): the
    /// pairs reported are those whose swollen surfaces overlap. With margin |v_i|·dt,
    /// that is every pair of hard spheres that could meet within the step.
    ///
    /// # Panics
    /// If the slices differ in length, or hold `u32::MAX` particles or more.
    pub fn with_margin(positions: &[Vec3], radii: &[f64], margin: &[f64]) -> Self {
        assert_eq!(positions.len(), radii.len(), "one radius per position");
        assert_eq!(positions.len(), margin.len(), "one margin per position");
        Self::from_fn(positions.len(), |i| {
            Some((positions[i], radii[i] + margin[i]))
        })
    }

    /// Bins particles `0..len`, `sphere(i)` giving particle i's position and swollen
    /// radius, or `None` to leave it out (a particle that is not alive) while keeping the
    /// indices of the others. Called once per particle, in order.
    ///
    /// # Panics
    /// If `len` is `u32::MAX` or more.
    pub fn from_fn(len: usize, sphere: impl FnMut(usize) -> Option<(Vec3, f64)>) -> Self {
        let mut grid = CellGrid::default();
        grid.refill(len, sphere, &mut GridScratch::default());
        grid
    }

    /// [`CellGrid::from_fn`] in place: the same grid, in the arrays this one and
    /// `scratch` already hold, so that a grid built again and again (a candidate list's)
    /// does not ask for its memory anew each time.
    ///
    /// # Panics
    /// If `len` is `u32::MAX` or more.
    pub fn refill(
        &mut self,
        len: usize,
        sphere: impl FnMut(usize) -> Option<(Vec3, f64)>,
        scratch: &mut GridScratch,
    ) {
        self.refill_ranked(len, sphere, |i| i as u32, scratch);
    }

    /// [`CellGrid::refill`] with particle i ranked `rank(i)` (distinct ranks): the ranks
    /// order the particles of a cell and the two of a pair in place of their indices,
    /// so that particles numbered anew (the soft-sphere run's places) give the pairs of
    /// their old numbers (the ranks), in the same order.
    ///
    /// # Panics
    /// If `len` is `u32::MAX` or more.
    pub fn refill_ranked(
        &mut self,
        len: usize,
        mut sphere: impl FnMut(usize) -> Option<(Vec3, f64)>,
        rank: impl Fn(usize) -> u32,
        scratch: &mut GridScratch,
    ) {
        assert!(len < NONE as usize, "at most 2³² − 2 particles");
        // The particles kept, in index order, in the slots, which are then sorted in
        // place (a second array of them was 40 bytes a particle more at each build).
        let mut kept = std::mem::take(&mut self.slots);
        kept.clear();
        kept.reserve(len);
        for i in 0..len {
            let Some((p, s)) = sphere(i) else { continue };
            if p.iter().all(|x| x.is_finite()) && s.is_finite() && s >= 0.0 {
                kept.push(Slot {
                    p,
                    s,
                    id: i as u32,
                    rank: rank(i),
                });
            }
        }
        let s_max = kept.iter().map(|k| k.s).fold(0.0, f64::max);
        let extent = kept.iter().map(|k| k.p.amax()).fold(0.0, f64::max);
        let h =
            ((2.0 * s_max) * (1.0 + 2f64.powi(-20)) + extent * 2f64.powi(-48)).max(2f64.powi(-480));
        self.h = h;
        self.inv_h = 1.0 / h;
        self.starts.clear();
        self.starts.push(0);
        self.slot_of.clear();
        self.slot_of.resize(len, NONE);
        // The keys' array, whichever kind it held, kept for the kind needed now.
        let mut packed = match std::mem::replace(&mut self.keys, Keys::Wide(Vec::new())) {
            Keys::Packed(keys, _) => keys,
            Keys::Wide(_) => Vec::new(),
        };
        packed.clear();
        if s_max == 0.0 {
            // Nothing overlaps: distance² < 0 never holds.
            kept.clear();
            self.slots = kept;
            return;
        }
        let (lo, hi) = kept.iter().map(|slot| self.key(&slot.p)).fold(
            ([i64::MAX; 3], [i64::MIN; 3]),
            |(lo, hi), k| {
                (
                    [0, 1, 2].map(|d| lo[d].min(k[d])),
                    [0, 1, 2].map(|d| hi[d].max(k[d])),
                )
            },
        );
        // Sorting (key, rank, position in `kept`) sorts by key then rank (the ranks
        // are distinct: the positions only come along).
        self.keys = if (0..3).all(|d| hi[d] - lo[d] < (1 << BITS) - 2) {
            let order = &mut scratch.order;
            order.clear();
            order.extend(
                kept.iter()
                    .zip(0..)
                    .map(|(slot, n)| (Packed::new(self.key(&slot.p), lo), slot.rank, n)),
            );
            self.bin(kept, order, &mut packed);
            Keys::Packed(packed, lo)
        } else {
            let mut order: Vec<_> = kept
                .iter()
                .zip(0..)
                .map(|(slot, n)| (self.key(&slot.p), slot.rank, n))
                .collect();
            let mut keys = Vec::new();
            self.bin(kept, &mut order, &mut keys);
            Keys::Wide(keys)
        };
    }

    /// Sorts `order` (key, rank, position in `kept`) and the slots `kept` with it, and
    /// fills the cells from it, and `keys` (empty) with the cells' keys.
    fn bin<K: Key>(&mut self, mut kept: Vec<Slot>, order: &mut [(K, u32, u32)], keys: &mut Vec<K>) {
        // On rayon's threads when there are many: the ranks are distinct, so any sort
        // gives the one order.
        if order.len() >= PAR_SORT_FROM {
            order.par_sort_unstable();
        } else {
            order.sort_unstable();
        }
        permute::gather(&mut kept, |n| order[n].2 as usize);
        for (n, (&(key, _, _), slot)) in order.iter().zip(&kept).enumerate() {
            if keys.last() != Some(&key) {
                if !keys.is_empty() {
                    self.starts.push(n as u32);
                }
                keys.push(key);
            }
            self.slot_of[slot.id as usize] = n as u32;
        }
        self.starts.push(order.len() as u32);
        self.slots = kept;
    }

    /// The binned particles in the grid's order: cells by key, within a cell by rank.
    pub fn order(&self) -> impl ExactSizeIterator<Item = u32> + '_ {
        self.slots.iter().map(|slot| slot.id)
    }

    /// The grid as [`CellGrid::refill_ranked`] would find it once each particle is
    /// moved to its place in [`CellGrid::order`] (the n-th binned at n, those left out
    /// after them) and ranked by its index before: the same cells and slots, each slot's
    /// particle its place, its rank the particle's index (for a grid built with the
    /// indices as ranks).
    pub fn placed_in_order(&mut self) {
        for (n, slot) in self.slots.iter_mut().enumerate() {
            slot.rank = slot.id;
            slot.id = n as u32;
        }
        let binned = self.slots.len();
        for (n, slot) in self.slot_of.iter_mut().enumerate() {
            *slot = if n < binned { n as u32 } else { NONE };
        }
    }

    /// The cell edge: the largest swollen diameter, a little more (module documentation).
    pub fn cell_size(&self) -> f64 {
        self.h
    }

    /// The number of occupied cells, which [`CellGrid::for_each_pair_in`] splits.
    pub fn cell_count(&self) -> usize {
        self.starts.len() - 1
    }

    /// Calls `f(i, j)` once for each unordered pair whose swollen spheres overlap, i the
    /// lower ranked (i < j unless ranked otherwise), in an order that depends only on
    /// the input.
    pub fn for_each_pair(&self, f: impl FnMut(usize, usize)) {
        self.for_each_pair_in(0..self.cell_count(), f);
    }

    /// [`CellGrid::for_each_pair`] for the pairs whose first cell (in key order) is in
    /// `cells`, a range of `0..cell_count()`: the ranges of a partition of the cells visit
    /// each pair exactly once, so they can go to separate threads; visited in turn, they
    /// give the order of `for_each_pair`.
    ///
    /// # Panics
    /// If `cells` reaches past `cell_count()`.
    pub fn for_each_pair_in(&self, cells: Range<usize>, mut f: impl FnMut(usize, usize)) {
        assert!(cells.end <= self.cell_count(), "cells past the grid's");
        if cells.is_empty() {
            return;
        }
        match &self.keys {
            Keys::Packed(keys, _) => self.pairs_in(keys, cells, &mut f),
            Keys::Wide(keys) => self.pairs_in(keys, cells, &mut f),
        }
    }

    /// The pairs of [`CellGrid::for_each_pair`], in its order, as (i, j), i the lower ranked.
    pub fn pairs(&self) -> Vec<(u32, u32)> {
        let mut pairs = Vec::new();
        self.pairs_into(&mut pairs);
        pairs
    }

    /// [`CellGrid::pairs`] into `pairs` (emptied first), in the memory it already holds.
    pub fn pairs_into(&self, pairs: &mut Vec<(u32, u32)>) {
        pairs.clear();
        self.for_each_pair(|i, j| pairs.push((i as u32, j as u32)));
    }

    /// [`CellGrid::pairs`], the same list in the same order, found by ranges of cells in
    /// parallel.
    pub fn par_pairs(&self) -> Vec<(u32, u32)> {
        let mut pairs = Vec::new();
        self.par_pairs_into(&mut pairs);
        pairs
    }

    /// [`CellGrid::par_pairs`] into `pairs` (emptied first), in the memory it already
    /// holds.
    pub fn par_pairs_into(&self, pairs: &mut Vec<(u32, u32)>) {
        let cells = self.cell_count();
        let size = cells.div_ceil(PAIR_RANGES).max(1);
        let parts: Vec<Vec<(u32, u32)>> = (0..cells.div_ceil(size))
            .into_par_iter()
            .map(|c| {
                let mut pairs = Vec::new();
                let range = c * size..((c + 1) * size).min(cells);
                self.for_each_pair_in(range, |i, j| pairs.push((i as u32, j as u32)));
                pairs
            })
            .collect();
        pairs.clear();
        pairs.extend(parts.into_iter().flatten());
    }

    /// Calls `f(j)` once for each particle j ≠ i whose swollen sphere overlaps particle
    /// i's (the candidates to re-predict after i collides), in an order that depends only
    /// on the input. Nothing if i was left out.
    ///
    /// # Panics
    /// If `i` is not below the number of particles the grid was built for.
    pub fn for_each_neighbour(&self, i: usize, mut f: impl FnMut(usize)) {
        let a = self.slot_of[i];
        if a == NONE {
            return;
        }
        let a = a as usize;
        let k = self.key(&self.slots[a].p);
        match &self.keys {
            Keys::Packed(keys, lo) => self.neighbours(keys, Packed::new(k, *lo), a, &mut f),
            Keys::Wide(keys) => self.neighbours(keys, k, a, &mut f),
        }
    }

    /// The pairs with a first cell in `cells` (non-empty), for cell keys `keys`.
    fn pairs_in<K: Key>(&self, keys: &[K], cells: Range<usize>, f: &mut impl FnMut(usize, usize)) {
        let first = keys[cells.start];
        let mut cursor =
            FORWARD_COLUMNS.map(|(di, dj)| keys.partition_point(|&c| c < first.shift(di, dj, -1)));
        for c in cells {
            let k = keys[c];
            let here = self.cell(c);
            // The cell with itself and with (0, 0, +1), the next cell if present: the
            // slots after each of its own up to the end of that next cell.
            let end = if keys.get(c + 1) == Some(&k.shift(0, 0, 1)) {
                self.starts[c + 2] as usize
            } else {
                here.end
            };
            for a in here.clone() {
                for b in a + 1..end {
                    self.check(a, b, f);
                }
            }
            for (col, &(di, dj)) in FORWARD_COLUMNS.iter().enumerate() {
                // The column's first cell at or after k + (di, dj, −1) only moves forward
                // as k does: walk to it from where it was for the previous cell.
                let lo = k.shift(di, dj, -1);
                let mut n = cursor[col];
                while n < keys.len() && keys[n] < lo {
                    n += 1;
                }
                cursor[col] = n;
                let there = self.column_run(keys, n, k.shift(di, dj, 1));
                for a in here.clone() {
                    for b in there.clone() {
                        self.check(a, b, f);
                    }
                }
            }
        }
    }

    /// The neighbours of slot `a`, in the cell of key `k`, for cell keys `keys`.
    fn neighbours<K: Key>(&self, keys: &[K], k: K, a: usize, f: &mut impl FnMut(usize)) {
        for di in -1..=1 {
            for dj in -1..=1 {
                let first = keys.partition_point(|&c| c < k.shift(di, dj, -1));
                for b in self.column_run(keys, first, k.shift(di, dj, 1)) {
                    if b != a && self.overlap(a, b) {
                        f(self.slots[b].id as usize);
                    }
                }
            }
        }
    }

    /// The key of the cell holding `p`: ⌊p/h⌋ per axis.
    #[inline]
    fn key(&self, p: &Vec3) -> [i64; 3] {
        p.map(|x| (x * self.inv_h).floor() as i64).into()
    }

    /// The slots of cell `c`.
    #[inline]
    fn cell(&self, c: usize) -> Range<usize> {
        self.starts[c] as usize..self.starts[c + 1] as usize
    }

    /// The slots of the cells from `first` up to key `hi`, in `first`'s column: the
    /// cells of one column are consecutive in key order, so their slots are one run.
    #[inline]
    fn column_run<K: Key>(&self, keys: &[K], first: usize, hi: K) -> Range<usize> {
        let mut n = first;
        while n < keys.len() && keys[n] <= hi {
            n += 1;
        }
        self.starts[first] as usize..self.starts[n] as usize
    }

    /// Whether the swollen spheres of slots `a` and `b` overlap (module documentation).
    #[inline]
    fn overlap(&self, a: usize, b: usize) -> bool {
        let (sa, sb) = (&self.slots[a], &self.slots[b]);
        let d = sa.p - sb.p;
        let reach = sa.s + sb.s;
        d.x * d.x + d.y * d.y + d.z * d.z < reach * reach
    }

    /// Reports slots `a` and `b` if they overlap.
    #[inline]
    fn check(&self, a: usize, b: usize, f: &mut impl FnMut(usize, usize)) {
        if self.overlap(a, b) {
            let (a, b) = (&self.slots[a], &self.slots[b]);
            let (i, j) = (a.id as usize, b.id as usize);
            if a.rank < b.rank { f(i, j) } else { f(j, i) }
        }
    }
}
