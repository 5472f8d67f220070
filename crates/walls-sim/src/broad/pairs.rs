//! The candidate particle pairs of the soft-sphere run, kept from step to step (a Verlet
//! list, [`PairList`]), with the records of their open contacts ([`PairContacts`]),
//! found on the cell grid ([`super::grid`]).

use super::grid::{Bins, Spheres};
use crate::contact::ssdem::Record;
use crate::run::State;
use nalgebra::Vector3;
use rayon::prelude::*;

type Vec3 = Vector3<f64>;

/// The candidate particle pairs, kept from step to step (a Verlet list): the pairs whose
/// spheres, swollen by half the skin each, overlapped when the list was built. It is
/// rebuilt on the cell grid once some particle has moved more than half the skin since,
/// so every pair that overlaps now is in it. The skin is 0.4 of the largest radius: in
/// a settled pile the list lasts many steps (docs/performance-history.md).
pub(crate) struct PairList {
    pub(crate) pairs: Vec<(u32, u32)>,
    /// Each particle's centre and radius (x, y, z, r) as it is now: the pairs' first
    /// test reads these, compact, rather than the states.
    pub(crate) spheres: Vec<[f64; 4]>,
    /// Each pair's open contact in `contacts`, or [`NO_CONTACT`]; empty while no
    /// contact is open (every pair's [`NO_CONTACT`]), so that a run whose particles do
    /// not touch keeps no 4 bytes a pair (12 MB for a million falling spheres). Made
    /// by the pair pass when a contact first opens ([`PairList::open_slots`]).
    pub(crate) slots: Vec<u32>,
    /// The open contacts' records.
    pub(crate) contacts: PairContacts,
    /// The cell grid the list was found with, over `spheres` swollen by half the skin:
    /// kept for the next build, which fills the same memory.
    pub(crate) bins: Bins,
    /// Whether the grid already bins the particles where they are, at the places
    /// [`PairList::grid_order`] found, for the next build (the first).
    placed: bool,
    pub(crate) built_at: Vec<Vec3>,
    pub(crate) skin: f64,
    /// Whether a particle drifted this step has moved more than half the skin (worked
    /// out in the drift of the soft-sphere run).
    pub(crate) drifted: bool,
    /// Whether some particle may be moved other than by the drift (stuck to a wall, or
    /// a member of an aggregate): then every particle is looked at.
    pub(crate) held: bool,
    /// Whether some particle has left the run (at a death wall): until then, with none
    /// held, every particle is alive and free, and the pairs' test need not look.
    pub(crate) gone: bool,
    /// Whether the pairs are wanted (particles meet each other).
    pub(crate) wanted: bool,
    /// The sum of two radii when every particle has the same radius (radii never
    /// change in a run): the pairs' test then takes it as it is rather than adding
    /// the two for each pair.
    pub(crate) uniform: Option<f64>,
    /// Whether the list is found on rayon's threads (many particles, and more than one
    /// thread), and whether there are many particles (then the held ones are looked at
    /// in parallel).
    pub(crate) parallel: bool,
    pub(crate) many: bool,
}

impl PairList {
    pub(crate) fn new(states: &[State], wanted: bool, parallel: bool, many: bool) -> PairList {
        let largest = states.iter().map(|s| s.particle.radius).fold(0.0, f64::max);
        PairList {
            pairs: Vec::new(),
            slots: Vec::new(),
            spheres: Vec::new(),
            contacts: PairContacts::default(),
            bins: Bins::default(),
            placed: false,
            built_at: Vec::new(),
            skin: 0.4 * largest,
            drifted: false,
            held: states.iter().any(|s| s.stuck_to.is_some() || s.member),
            gone: states.iter().any(|s| !s.alive),
            wanted,
            uniform: match states.split_first() {
                Some((first, rest)) => {
                    let r = first.particle.radius;
                    let same = |s: &State| s.particle.radius.to_bits() == r.to_bits();
                    rest.iter().all(same).then_some(r + r)
                }
                None => None,
            },
            parallel,
            many,
        }
    }

    /// The particles in the order of the grid the list is found on (cells by key, within
    /// a cell by index), those it leaves out (not alive, or not finite) last: where the
    /// soft-sphere run keeps them, so that a pair's two are near each other in memory.
    /// The next build takes the grid as it is, for the particles moved to those places
    /// and ranked by their indices (`Bins::placed_in_order`).
    pub(crate) fn grid_order(&mut self, states: &[State]) -> Vec<u32> {
        // The spheres in the file's order, to bin them; the build that follows sets them
        // anew from the particles at their places before anything reads them.
        self.spheres.clear();
        self.spheres.extend(states.iter().map(Self::sphere));
        let alive = |i: usize| states[i].alive;
        let swollen = Self::swollen(&self.spheres, self.skin);
        (self.bins).refill_ranked(states.len(), swollen, alive, |i| i as u32);
        let mut order = self.bins.order();
        if order.len() < states.len() {
            let mut binned = vec![false; states.len()];
            for &i in &order {
                binned[i as usize] = true;
            }
            order.extend((0..states.len() as u32).filter(|&i| !binned[i as usize]));
        }
        self.bins.placed_in_order();
        self.placed = true;
        order
    }

    /// The candidate pairs (when wanted) where the particles are now, particle i ranked
    /// `rank(i)` ([`CellGrid::refill_ranked`]: the order of the pairs, and of the two of
    /// a pair, is that of the ranks).
    pub(crate) fn build(&mut self, states: &[State], rank: impl Fn(usize) -> u32) {
        self.built_at.clear();
        self.spheres.clear();
        if self.parallel {
            (self.built_at).par_extend(states.par_iter().map(|s| s.particle.pos));
            (self.spheres).par_extend(states.par_iter().map(Self::sphere));
        } else {
            self.built_at.extend(states.iter().map(|s| s.particle.pos));
            self.spheres.extend(states.iter().map(Self::sphere));
        }
        if !self.wanted {
            return;
        }
        // The grid, the pairs and their slots in the memory they held at the last build:
        // made anew each time, they took 15–20 MiB more for a moment at 10⁵ particles.
        if !std::mem::take(&mut self.placed) {
            let alive = |i: usize| states[i].alive;
            let swollen = Self::swollen(&self.spheres, self.skin);
            (self.bins).refill_ranked(states.len(), swollen, alive, rank);
        }
        // The open contacts go with their pairs into the new list (every pair that
        // touches is in it); any other ends.
        let index = self.open_index(states.len());
        self.find_pairs(states);
        // Their records are laid out again in the new list's order, which the force
        // pass follows: one after the other in memory rather than where each happened
        // to open. The others are dropped.
        let mut records = Vec::new();
        self.slots.clear();
        if let Some(OpenIndex { starts, open }) = &index {
            records.reserve(open.len());
            let last = &self.contacts.records;
            self.slots.extend(self.pairs.iter().map(|&(i, j)| {
                let of_i = &open[starts[i as usize] as usize..starts[i as usize + 1] as usize];
                match of_i.iter().find(|(second, _)| *second == j) {
                    Some(&(_, slot)) => {
                        records.push(last[slot as usize]);
                        (records.len() - 1) as u32
                    }
                    None => NO_CONTACT,
                }
            }));
        }
        self.contacts = PairContacts {
            records,
            free: Vec::new(),
            next: std::mem::take(&mut self.contacts.next),
        };
    }

    /// Each pair's slot ([`PairList::slots`]), made (every pair's [`NO_CONTACT`]) if
    /// none is kept, for a contact about to open.
    pub(crate) fn open_slots(slots: &mut Vec<u32>, pairs: usize) -> &mut [u32] {
        if slots.is_empty() {
            slots.resize(pairs, NO_CONTACT);
        }
        slots
    }

    /// The slot of pair `k`: [`NO_CONTACT`] when no slots are kept.
    #[inline]
    pub(crate) fn slot(slots: &[u32], k: usize) -> u32 {
        slots.get(k).copied().unwrap_or(NO_CONTACT)
    }

    /// The open contacts of the list as it stands, by their first particle (of `len`);
    /// `None` when none is open: no index (4 bytes a particle, which would stay
    /// resident) to find none in.
    fn open_index(&self, len: usize) -> Option<OpenIndex> {
        let open_pairs = || {
            (self.pairs.iter())
                .zip(&self.slots)
                .filter(|(_, slot)| **slot != NO_CONTACT)
        };
        open_pairs().next()?;
        let mut starts = vec![0u32; len + 1];
        for (&(i, _), _) in open_pairs() {
            starts[i as usize + 1] += 1;
        }
        for i in 0..len {
            starts[i + 1] += starts[i];
        }
        // Each particle's start taken as where its next contact goes, which leaves it
        // at the next particle's start: moved back after.
        let mut open = vec![(0, 0); starts[len] as usize];
        for (&(i, j), &slot) in open_pairs() {
            let next = &mut starts[i as usize];
            open[*next as usize] = (j, slot);
            *next += 1;
        }
        starts.copy_within(0..len, 1);
        starts[0] = 0;
        Some(OpenIndex { starts, open })
    }

    /// The candidate pairs found on the grid over the spheres [`PairList::build`] has just
    /// set, in the memory the last build's held. The first build makes room for 8 a
    /// particle (a close packing has 6; room not filled is never touched) rather than
    /// growing the list one doubling at a time, whose smaller copies, freed, stay
    /// resident under mimalloc.
    fn find_pairs(&mut self, states: &[State]) {
        if self.pairs.capacity() == 0 {
            let _ = self.pairs.try_reserve(8 * states.len());
        }
        let swollen = Self::swollen(&self.spheres, self.skin);
        if self.parallel {
            self.bins.par_pairs_into(swollen, &mut self.pairs);
        } else {
            self.bins.pairs_into(swollen, &mut self.pairs);
        }
    }

    /// The spheres as the grid bins them: each radius swollen by half the skin (the
    /// particles that have left the run are left out).
    fn swollen(spheres: &[[f64; 4]], skin: f64) -> Spheres<'_> {
        Spheres {
            xyzr: spheres,
            margin: skin / 2.0,
        }
    }

    /// A particle's centre and radius, as the pairs' first test reads them.
    #[inline]
    pub(crate) fn sphere(s: &State) -> [f64; 4] {
        let p = &s.particle;
        [p.pos.x, p.pos.y, p.pos.z, p.radius]
    }

    /// The square of half the skin: how far a particle may move before a rebuild.
    pub(crate) fn limit(&self) -> f64 {
        (self.skin / 2.0).powi(2)
    }

    /// Whether `s`, in the run, has moved more than √`limit` from `at` (or its position
    /// is not a number).
    #[inline]
    pub(crate) fn moved_far(s: &State, at: &Vec3, limit: f64) -> bool {
        let d2 = (s.particle.pos - at).norm_squared();
        s.alive && (d2 > limit || d2.is_nan())
    }

    /// Whether the list is stale: some particle (free, or carried by its wall) has moved
    /// more than half the skin (the drift has said so of the free ones; the others are
    /// looked at only once some particle is held, stuck or in an aggregate, and then
    /// all), or `walls_moved`. The spheres of held particles are set anew.
    pub(crate) fn stale(&mut self, states: &[State], walls_moved: bool) -> bool {
        let limit = self.limit();
        let moved = |(s, at): (&State, &Vec3)| Self::moved_far(s, at, limit);
        if self.held {
            // Particles the drift did not move may have been carried.
            for (sphere, s) in self.spheres.iter_mut().zip(states) {
                *sphere = Self::sphere(s);
            }
        }
        let stale = self.drifted
            || walls_moved
            || (self.held
                && if self.many {
                    states.par_iter().zip(&self.built_at).any(moved)
                } else {
                    states.iter().zip(&self.built_at).any(moved)
                });
        self.drifted = false;
        stale
    }
}

/// The open contacts of a candidate list by their first particle: particle i's, as
/// (second particle, slot), are `open[starts[i]..starts[i + 1]]`.
struct OpenIndex {
    starts: Vec<u32>,
    open: Vec<(u32, u32)>,
}

/// A pair without an open contact.
pub(crate) const NO_CONTACT: u32 = u32::MAX;

/// The records of the open contacts between particles, in slots that the candidate
/// pairs point to ([`PairList::slots`]): on one thread, a closed contact's slot is
/// reused; in parallel, the records are laid out anew each step.
#[derive(Default)]
pub(crate) struct PairContacts {
    pub(crate) records: Vec<Record>,
    pub(crate) free: Vec<u32>,
    /// In parallel, where the next step's records are laid out (kept to save
    /// allocating).
    pub(crate) next: Vec<Record>,
}

impl PairContacts {
    /// The record of the contact in `slot`, opened (and counted in `began`) if it is
    /// not.
    #[inline]
    pub(crate) fn open(&mut self, slot: &mut u32, began: &mut u64) -> &mut Record {
        if *slot == NO_CONTACT {
            *began += 1;
            *slot = match self.free.pop() {
                Some(k) => {
                    self.records[k as usize] = Record::default();
                    k
                }
                None => {
                    self.records.push(Record::default());
                    (self.records.len() - 1) as u32
                }
            };
        }
        &mut self.records[*slot as usize]
    }

    /// Ends the contact in `slot`, if one is open.
    #[inline]
    pub(crate) fn close(&mut self, slot: &mut u32) {
        if *slot != NO_CONTACT {
            self.free.push(*slot);
            *slot = NO_CONTACT;
        }
    }
}
