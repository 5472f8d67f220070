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
//! run of that order, found by its key (no list of the cells is kept), so memory is
//! O(N) whatever the spread. The cells of one column
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
//! **Memory**: a particle's slot is its cell key, rank and index (16 bytes with packed
//! keys, 32 with wide ones; sorted in place: nothing else is made to sort them), not a
//! copy of where it is, and a cell costs nothing more: [`Bins`] are
//! queried with the spheres they binned, by index ([`Swollen`]), which a caller that
//! keeps its particles in the grid's order (the soft-sphere run's places) reads almost
//! in order. [`CellGrid`] is the bins with their own copy of the spheres (32 bytes a
//! particle), for callers that keep none.

use nalgebra::Vector3;
use rayon::prelude::*;
use std::ops::Range;

/// Into how many ranges of slots [`CellGrid::par_pairs`] cuts the grid.
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

/// A binned particle: its cell's key, its rank and its index, ordered so (the order
/// of the grid: cells by key, within a cell by rank; the ranks are distinct, so the
/// index never decides). 16 bytes with packed keys.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
struct Slot<K> {
    key: K,
    rank: u32,
    id: u32,
}

/// The binned particles, sorted: an occupied cell is a run of slots of one key.
#[derive(Debug, Clone)]
enum Cells {
    /// Keys packed.
    Packed(Vec<Slot<Packed>>),
    /// Keys as they are.
    Wide(Vec<Slot<[i64; 3]>>),
}

/// Where the binned particles are, by index, as a copy: (x, y, z, r), each radius `r`
/// swollen by `margin` (s = r + margin).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Spheres<'a> {
    pub(crate) xyzr: &'a [[f64; 4]],
    pub(crate) margin: f64,
}

/// Where the binned particles are, by index: each one's centre and swollen radius
/// (s = r + margin). A [`Bins`] is filled and queried with one such set: a copy
/// ([`Spheres`]), or the particles themselves, which the soft-sphere run's list bins.
pub(crate) trait Swollen: Copy + Sync {
    /// How many particles.
    fn len(&self) -> usize;
    /// Particle i's centre and swollen radius.
    fn get(&self, i: usize) -> ([f64; 3], f64);
}

impl Swollen for Spheres<'_> {
    #[inline]
    fn len(&self) -> usize {
        self.xyzr.len()
    }

    #[inline]
    fn get(&self, i: usize) -> ([f64; 3], f64) {
        let [x, y, z, r] = self.xyzr[i];
        ([x, y, z], r + self.margin)
    }
}

/// The cells of a uniform grid over spheres given by index ([`Spheres`]), the
/// particles binned in them in order (cells by key, within a cell by rank), without a
/// copy of where they are: 16 bytes a particle (its slot, kept for the next build,
/// which sorts it in place) and nothing a cell (a cell is the run of slots of its key).
/// The soft-sphere run's candidate list bins its spheres so, and [`CellGrid`] bins a
/// copy of its own.
#[derive(Debug, Clone)]
pub(crate) struct Bins {
    /// Cell edge h.
    h: f64,
    /// 1/h, for the cell keys.
    inv_h: f64,
    /// The binned particles.
    cells: Cells,
}

impl Default for Bins {
    fn default() -> Self {
        Bins {
            h: 1.0,
            inv_h: 1.0,
            cells: Cells::Wide(Vec::new()),
        }
    }
}

impl Bins {
    /// Bins particles `0..len` of `spheres`, those `kept` says and whose position is
    /// finite and swollen radius finite and ≥ 0, particle i ranked `rank(i)` (distinct
    /// ranks), in the memory this one holds ([`CellGrid::refill_ranked`]).
    ///
    /// # Panics
    /// If `len` is `u32::MAX` or more, or `spheres` holds fewer than `len`.
    pub(crate) fn refill_ranked(
        &mut self,
        len: usize,
        spheres: impl Swollen,
        kept: impl Fn(usize) -> bool,
        rank: impl Fn(usize) -> u32,
    ) {
        assert!(len < NONE as usize, "at most 2³² − 2 particles");
        assert!(spheres.len() >= len, "a sphere per particle");
        let binned = |i: usize| {
            let (p, s) = spheres.get(i);
            (kept(i) && p.iter().all(|x| x.is_finite()) && s.is_finite() && s >= 0.0)
                .then_some((p, s))
        };
        let (s_max, extent) =
            (0..len)
                .filter_map(binned)
                .fold((0.0, 0.0), |(s_max, extent), (p, s)| {
                    let far = p.iter().fold(0.0, |m: f64, x| m.max(x.abs()));
                    (f64::max(s_max, s), f64::max(extent, far))
                });
        let h =
            ((2.0 * s_max) * (1.0 + 2f64.powi(-20)) + extent * 2f64.powi(-48)).max(2f64.powi(-480));
        self.h = h;
        self.inv_h = 1.0 / h;
        // The slots' memory kept when they had packed keys (the usual kind); wide ones
        // are dropped.
        let mut slots = match std::mem::replace(&mut self.cells, Cells::Wide(Vec::new())) {
            Cells::Packed(slots) => slots,
            Cells::Wide(_) => Vec::new(),
        };
        slots.clear();
        if s_max == 0.0 {
            // Nothing overlaps: distance² < 0 never holds.
            self.cells = Cells::Packed(slots);
            return;
        }
        let (lo, hi) = (0..len).filter_map(binned).map(|(p, _)| self.key(p)).fold(
            ([i64::MAX; 3], [i64::MIN; 3]),
            |(lo, hi), k| {
                (
                    [0, 1, 2].map(|d| lo[d].min(k[d])),
                    [0, 1, 2].map(|d| hi[d].max(k[d])),
                )
            },
        );
        self.cells = if (0..3).all(|d| hi[d] - lo[d] < (1 << BITS) - 2) {
            let key = |p| Packed::new(self.key(p), lo);
            slots.reserve(len);
            slots.extend((0..len).filter_map(|i| binned(i).map(|(p, _)| slot(i, key(p), &rank))));
            sort(&mut slots);
            Cells::Packed(slots)
        } else {
            let mut slots: Vec<_> = (0..len)
                .filter_map(|i| binned(i).map(|(p, _)| slot(i, self.key(p), &rank)))
                .collect();
            sort(&mut slots);
            Cells::Wide(slots)
        };
    }

    /// The binned particles in the grid's order: cells by key, within a cell by rank.
    pub(crate) fn order(&self) -> Vec<u32> {
        match &self.cells {
            Cells::Packed(slots) => slots.iter().map(|slot| slot.id).collect(),
            Cells::Wide(slots) => slots.iter().map(|slot| slot.id).collect(),
        }
    }

    /// [`CellGrid::placed_in_order`], for spheres that the caller moves to their places.
    pub(crate) fn placed_in_order(&mut self) {
        fn place<K>(slots: &mut [Slot<K>]) {
            for (n, slot) in slots.iter_mut().enumerate() {
                slot.rank = slot.id;
                slot.id = n as u32;
            }
        }
        match &mut self.cells {
            Cells::Packed(slots) => place(slots),
            Cells::Wide(slots) => place(slots),
        }
    }

    /// The number of binned particles, whose slots [`Bins::for_each_pair_in`] splits.
    pub(crate) fn binned(&self) -> usize {
        match &self.cells {
            Cells::Packed(slots) => slots.len(),
            Cells::Wide(slots) => slots.len(),
        }
    }

    /// The number of occupied cells (counted).
    pub(crate) fn cell_count(&self) -> usize {
        fn runs<K: Key>(slots: &[Slot<K>]) -> usize {
            let starts = slots.windows(2).filter(|w| w[0].key != w[1].key).count();
            if slots.is_empty() { 0 } else { starts + 1 }
        }
        match &self.cells {
            Cells::Packed(slots) => runs(slots),
            Cells::Wide(slots) => runs(slots),
        }
    }

    /// [`CellGrid::for_each_pair_in`], the spheres given.
    pub(crate) fn for_each_pair_in(
        &self,
        spheres: impl Swollen,
        range: Range<usize>,
        mut f: impl FnMut(usize, usize),
    ) {
        assert!(range.end <= self.binned(), "slots past the grid's");
        match &self.cells {
            Cells::Packed(slots) => pairs_in(spheres, slots, range, &mut f),
            Cells::Wide(slots) => pairs_in(spheres, slots, range, &mut f),
        }
    }

    /// [`CellGrid::pairs_into`], the spheres given.
    pub(crate) fn pairs_into(&self, spheres: impl Swollen, pairs: &mut Vec<(u32, u32)>) {
        pairs.clear();
        let all = 0..self.binned();
        self.for_each_pair_in(spheres, all, |i, j| pairs.push((i as u32, j as u32)));
    }

    /// [`CellGrid::par_pairs_into`], the spheres given.
    pub(crate) fn par_pairs_into(&self, spheres: impl Swollen, pairs: &mut Vec<(u32, u32)>) {
        let binned = self.binned();
        let size = binned.div_ceil(PAIR_RANGES).max(1);
        let parts: Vec<Vec<(u32, u32)>> = (0..binned.div_ceil(size))
            .into_par_iter()
            .map(|c| {
                let mut pairs = Vec::new();
                let range = c * size..((c + 1) * size).min(binned);
                self.for_each_pair_in(spheres, range, |i, j| pairs.push((i as u32, j as u32)));
                pairs
            })
            .collect();
        pairs.clear();
        pairs.extend(parts.into_iter().flatten());
    }

    /// [`CellGrid::for_each_neighbour`] for the particle in slot `a`, the spheres given.
    fn for_each_neighbour(&self, spheres: impl Swollen, a: usize, mut f: impl FnMut(usize)) {
        match &self.cells {
            Cells::Packed(slots) => neighbours(spheres, slots, a, &mut f),
            Cells::Wide(slots) => neighbours(spheres, slots, a, &mut f),
        }
    }

    /// The key of the cell holding `p`: ⌊p/h⌋ per axis.
    #[inline]
    fn key(&self, p: [f64; 3]) -> [i64; 3] {
        p.map(|x| (x * self.inv_h).floor() as i64)
    }
}

/// Sorts the slots: on rayon's threads when there are many (the ranks are distinct,
/// so any sort gives the one order).
fn sort<K: Key>(slots: &mut [Slot<K>]) {
    if slots.len() >= PAR_SORT_FROM {
        slots.par_sort_unstable();
    } else {
        slots.sort_unstable();
    }
}

/// The end of the run of slots from `n` whose keys are at most `hi`: from a cell's
/// first slot and its key, the cell; from a column's first cell at or after some key,
/// that column's cells up to `hi` (the cells of one column are consecutive in key
/// order, so their slots are one run).
#[inline]
fn run_end<K: Key>(slots: &[Slot<K>], mut n: usize, hi: K) -> usize {
    while n < slots.len() && slots[n].key <= hi {
        n += 1;
    }
    n
}

/// The pairs with a first cell that begins in `range` of the slots.
fn pairs_in<K: Key>(
    spheres: impl Swollen,
    slots: &[Slot<K>],
    range: Range<usize>,
    f: &mut impl FnMut(usize, usize),
) {
    // The first cell that begins in the range.
    let mut c = range.start;
    while c > 0 && c < range.end && slots[c - 1].key == slots[c].key {
        c += 1;
    }
    if c >= range.end {
        return;
    }
    let first = slots[c].key;
    let mut cursor =
        FORWARD_COLUMNS.map(|(di, dj)| slots.partition_point(|s| s.key < first.shift(di, dj, -1)));
    while c < range.end {
        let k = slots[c].key;
        let here = c..run_end(slots, c, k);
        // The cell with itself and with (0, 0, +1), the next cell if present: the
        // slots after each of its own up to the end of that next cell.
        let above = k.shift(0, 0, 1);
        let end = match slots.get(here.end) {
            Some(next) if next.key == above => run_end(slots, here.end, above),
            _ => here.end,
        };
        for a in here.clone() {
            for b in a + 1..end {
                check(spheres, &slots[a], &slots[b], f);
            }
        }
        for (col, &(di, dj)) in FORWARD_COLUMNS.iter().enumerate() {
            // The column's first cell at or after k + (di, dj, −1) only moves forward
            // as k does: walk to it from where it was for the previous cell.
            let lo = k.shift(di, dj, -1);
            let mut n = cursor[col];
            while n < slots.len() && slots[n].key < lo {
                n += 1;
            }
            cursor[col] = n;
            let there = n..run_end(slots, n, k.shift(di, dj, 1));
            for a in here.clone() {
                for b in there.clone() {
                    check(spheres, &slots[a], &slots[b], f);
                }
            }
        }
        c = here.end;
    }
}

/// The neighbours of slot `a`.
fn neighbours<K: Key>(
    spheres: impl Swollen,
    slots: &[Slot<K>],
    a: usize,
    f: &mut impl FnMut(usize),
) {
    let k = slots[a].key;
    for di in -1..=1 {
        for dj in -1..=1 {
            let first = slots.partition_point(|s| s.key < k.shift(di, dj, -1));
            for b in first..run_end(slots, first, k.shift(di, dj, 1)) {
                if b != a && overlap(spheres, &slots[a], &slots[b]) {
                    f(slots[b].id as usize);
                }
            }
        }
    }
}

/// Particle i's slot in the cell of key `key`.
#[inline]
fn slot<K>(i: usize, key: K, rank: &impl Fn(usize) -> u32) -> Slot<K> {
    Slot {
        key,
        rank: rank(i),
        id: i as u32,
    }
}

/// Whether the swollen spheres of slots `a` and `b` overlap (module documentation).
#[inline]
fn overlap<K>(spheres: impl Swollen, a: &Slot<K>, b: &Slot<K>) -> bool {
    let (pa, sa) = spheres.get(a.id as usize);
    let (pb, sb) = spheres.get(b.id as usize);
    let d = [pa[0] - pb[0], pa[1] - pb[1], pa[2] - pb[2]];
    let reach = sa + sb;
    d[0] * d[0] + d[1] * d[1] + d[2] * d[2] < reach * reach
}

/// Reports slots `a` and `b` if they overlap, the lower ranked first.
#[inline]
fn check<K>(spheres: impl Swollen, a: &Slot<K>, b: &Slot<K>, f: &mut impl FnMut(usize, usize)) {
    if overlap(spheres, a, b) {
        let (i, j) = (a.id as usize, b.id as usize);
        if a.rank < b.rank { f(i, j) } else { f(j, i) }
    }
}

/// A uniform grid of cubic cells over a set of spheres, for finding the pairs whose
/// swollen spheres overlap (see the [module documentation](self)): [`Bins`] with its
/// own copy of the spheres, by index. The default grid holds nothing (no cells).
#[derive(Debug, Clone, Default)]
pub struct CellGrid {
    bins: Bins,
    /// Each particle's position and swollen radius (x, y, z, s); NaN for one left out.
    spheres: Vec<[f64; 4]>,
    /// Each particle's slot, or [`NONE`]: made when a neighbour is first asked for (the
    /// hard-sphere run builds a grid each step and asks only for its pairs).
    slot_of: std::sync::OnceLock<Vec<u32>>,
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
        grid.refill(len, sphere);
        grid
    }

    /// [`CellGrid::from_fn`] in place: the same grid, in the arrays this one already
    /// holds.
    ///
    /// # Panics
    /// If `len` is `u32::MAX` or more.
    pub fn refill(&mut self, len: usize, sphere: impl FnMut(usize) -> Option<(Vec3, f64)>) {
        self.refill_ranked(len, sphere, |i| i as u32);
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
    ) {
        assert!(len < NONE as usize, "at most 2³² − 2 particles");
        self.spheres.clear();
        self.spheres.extend((0..len).map(|i| match sphere(i) {
            Some((p, s)) => [p.x, p.y, p.z, s],
            None => [f64::NAN; 4],
        }));
        let spheres = Spheres {
            xyzr: &self.spheres,
            margin: 0.0,
        };
        self.bins.refill_ranked(len, spheres, |_| true, rank);
        self.slot_of = std::sync::OnceLock::new();
    }

    /// The spheres as the bins read them.
    fn spheres(&self) -> Spheres<'_> {
        Spheres {
            xyzr: &self.spheres,
            margin: 0.0,
        }
    }

    /// The binned particles in the grid's order: cells by key, within a cell by rank.
    pub fn order(&self) -> Vec<u32> {
        self.bins.order()
    }

    /// The grid as [`CellGrid::refill_ranked`] would find it once each particle is
    /// moved to its place in [`CellGrid::order`] (the n-th binned at n, those left out
    /// after them) and ranked by its index before: the same cells and slots, each slot's
    /// particle its place, its rank the particle's index (for a grid built with the
    /// indices as ranks).
    pub fn placed_in_order(&mut self) {
        let order = self.order();
        let mut placed: Vec<[f64; 4]> = order.iter().map(|&i| self.spheres[i as usize]).collect();
        placed.resize(self.spheres.len(), [f64::NAN; 4]);
        self.spheres = placed;
        self.bins.placed_in_order();
        self.slot_of = std::sync::OnceLock::new();
    }

    /// The cell edge: the largest swollen diameter, a little more (module documentation).
    pub fn cell_size(&self) -> f64 {
        self.bins.h
    }

    /// The number of occupied cells (counted: the grid keeps no list of its cells).
    pub fn cell_count(&self) -> usize {
        self.bins.cell_count()
    }

    /// The number of particles binned, whose slots in the grid's order
    /// [`CellGrid::for_each_pair_in`] splits: those not left out, or none when every
    /// swollen radius is 0 (nothing can overlap).
    pub fn binned(&self) -> usize {
        self.bins.binned()
    }

    /// Calls `f(i, j)` once for each unordered pair whose swollen spheres overlap, i the
    /// lower ranked (i < j unless ranked otherwise), in an order that depends only on
    /// the input.
    pub fn for_each_pair(&self, f: impl FnMut(usize, usize)) {
        self.for_each_pair_in(0..self.binned(), f);
    }

    /// [`CellGrid::for_each_pair`] for the pairs whose first cell (in key order) begins
    /// in `slots`, a range of `0..binned()` (the binned particles in the grid's order,
    /// [`CellGrid::order`]): the ranges of a partition of the slots visit each pair
    /// exactly once, wherever they cut, so they can go to separate threads; visited in
    /// turn, they give the order of `for_each_pair`.
    ///
    /// # Panics
    /// If `slots` reaches past `binned()`.
    pub fn for_each_pair_in(&self, slots: Range<usize>, f: impl FnMut(usize, usize)) {
        self.bins.for_each_pair_in(self.spheres(), slots, f);
    }

    /// The pairs of [`CellGrid::for_each_pair`], in its order, as (i, j), i the lower ranked.
    pub fn pairs(&self) -> Vec<(u32, u32)> {
        let mut pairs = Vec::new();
        self.pairs_into(&mut pairs);
        pairs
    }

    /// [`CellGrid::pairs`] into `pairs` (emptied first), in the memory it already holds.
    pub fn pairs_into(&self, pairs: &mut Vec<(u32, u32)>) {
        self.bins.pairs_into(self.spheres(), pairs);
    }

    /// [`CellGrid::pairs`], the same list in the same order, found by ranges of slots in
    /// parallel.
    pub fn par_pairs(&self) -> Vec<(u32, u32)> {
        let mut pairs = Vec::new();
        self.par_pairs_into(&mut pairs);
        pairs
    }

    /// [`CellGrid::par_pairs`] into `pairs` (emptied first), in the memory it already
    /// holds.
    pub fn par_pairs_into(&self, pairs: &mut Vec<(u32, u32)>) {
        self.bins.par_pairs_into(self.spheres(), pairs);
    }

    /// Calls `f(j)` once for each particle j ≠ i whose swollen sphere overlaps particle
    /// i's (the candidates to re-predict after i collides), in an order that depends only
    /// on the input. Nothing if i was left out.
    ///
    /// # Panics
    /// If `i` is not below the number of particles the grid was built for.
    pub fn for_each_neighbour(&self, i: usize, f: impl FnMut(usize)) {
        let slot_of = self.slot_of.get_or_init(|| {
            let mut slot_of = vec![NONE; self.spheres.len()];
            for (n, i) in self.bins.order().into_iter().enumerate() {
                slot_of[i as usize] = n as u32;
            }
            slot_of
        });
        let a = slot_of[i];
        if a != NONE {
            self.bins.for_each_neighbour(self.spheres(), a as usize, f);
        }
    }
}
