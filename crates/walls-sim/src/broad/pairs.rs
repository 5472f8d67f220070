//! The candidate particle pairs of the soft-sphere run, kept from step to step (a Verlet
//! list, [`PairList`]), with the records of their open contacts ([`PairContacts`]),
//! found on the cell grid ([`super::grid`]).

use super::grid::{Bins, Swollen};
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
    /// Each particle's centre and radius (x, y, z, r) as it is now, rounded to `f32`
    /// (16 bytes a particle): the pairs' first test reads these, compact, and tells
    /// most pairs apart from them ([`PairList::clear_beyond`]); it reads the states
    /// only for the others.
    pub(crate) spheres: Vec<[f32; 4]>,
    /// How far the distance between two rounded centres may be from the distance
    /// between the centres: set at each build from the farthest coordinate then
    /// ([`PairList::rounding`]).
    pub(crate) rounding: f32,
    /// Each pair's open contact in `contacts`, or [`NO_CONTACT`]; empty while no
    /// contact is open (every pair's [`NO_CONTACT`]), so that a run whose particles do
    /// not touch keeps no 4 bytes a pair (12 MB for a million falling spheres). Made
    /// by the pair pass when a contact first opens ([`PairList::open_slots`]).
    pub(crate) slots: Vec<u32>,
    /// The open contacts' records.
    pub(crate) contacts: PairContacts,
    /// The cell grid the list was found with, over the particles swollen by half the
    /// skin: kept for the next build, which fills the same memory.
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
            rounding: f32::INFINITY,
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
        let alive = |i: usize| states[i].alive;
        let swollen = Self::swollen(states, self.skin);
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
            (self.spheres).par_extend(states.par_iter().map(Self::rounded));
        } else {
            self.built_at.extend(states.iter().map(|s| s.particle.pos));
            self.spheres.extend(states.iter().map(Self::rounded));
        }
        self.rounding = Self::rounding(states, &self.built_at, self.skin, self.parallel);
        if !self.wanted {
            return;
        }
        // The grid, the pairs and their slots in the memory they held at the last build:
        // made anew each time, they took 15–20 MiB more for a moment at 10⁵ particles.
        if !std::mem::take(&mut self.placed) {
            let alive = |i: usize| states[i].alive;
            let swollen = Self::swollen(states, self.skin);
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

    /// The pairs' slots ([`PairList::slots`]) made (every pair's [`NO_CONTACT`]) if none
    /// are kept, for a contact about to open.
    pub(crate) fn open_slots(slots: &mut Vec<u32>, pairs: usize) {
        if slots.is_empty() {
            slots.resize(pairs, NO_CONTACT);
        }
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

    /// The candidate pairs found on the grid [`PairList::build`] has just filled, in the
    /// memory the last build's held. The first build makes room for 8 a
    /// particle (a close packing has 6; room not filled is never touched) rather than
    /// growing the list one doubling at a time, whose smaller copies, freed, stay
    /// resident under mimalloc.
    fn find_pairs(&mut self, states: &[State]) {
        if self.pairs.capacity() == 0 {
            let _ = self.pairs.try_reserve(8 * states.len());
        }
        let swollen = Self::swollen(states, self.skin);
        if self.parallel {
            self.bins.par_pairs_into(swollen, &mut self.pairs);
        } else {
            self.bins.pairs_into(swollen, &mut self.pairs);
        }
    }

    /// The particles as the grid bins them: each radius swollen by half the skin (the
    /// particles that have left the run are left out).
    fn swollen(states: &[State], skin: f64) -> SwollenStates<'_> {
        SwollenStates {
            states,
            margin: skin / 2.0,
        }
    }

    /// A particle's centre and radius.
    #[inline]
    pub(crate) fn sphere(s: &State) -> [f64; 4] {
        let p = &s.particle;
        [p.pos.x, p.pos.y, p.pos.z, p.radius]
    }

    /// A particle's centre and radius rounded to `f32`, as the pairs' first test reads
    /// them ([`PairList::spheres`]).
    #[inline]
    pub(crate) fn rounded(s: &State) -> [f32; 4] {
        Self::sphere(s).map(|x| x as f32)
    }

    /// How far the distance between two rounded centres may be from the distance between
    /// the centres (rounded up), while no particle is farther than half the skin from
    /// where the list was built (`built_at`; the list's own condition: a particle moved
    /// farther has it built again before its pairs are tested). A coordinate x rounded
    /// to `f32` moves by at most 2⁻²⁴·|x| (and 2⁻¹⁴⁹ below `f32`'s normal numbers), so
    /// each centre by at most √3·2⁻²⁴·M, M the largest coordinate's size: the distance
    /// by twice that, less than 4·2⁻²⁴·M. M is taken over the particles binned then
    /// (alive, at finite places: the others are in no pair), plus the skin. It is never
    /// below 2⁻⁶⁰, so that [`PairList::clear_beyond`] is at least 2⁻¹²⁰, a normal
    /// `f32`, and the round-off of the test's few operations below `f32`'s normal
    /// numbers (2⁻¹⁵⁰ each) is far inside its margin. A coordinate past `f32`'s range
    /// makes the rounding, and so `clear_beyond`, infinite or past its range too: no
    /// pair is then told apart from the rounded spheres.
    fn rounding(states: &[State], built_at: &[Vec3], skin: f64, parallel: bool) -> f32 {
        let size = |(s, at): (&State, &Vec3)| {
            let far = at.amax();
            if s.alive && far.is_finite() { far } else { 0.0 }
        };
        let far = if parallel {
            (states.par_iter().zip(built_at))
                .map(size)
                .reduce(|| 0.0, f64::max)
        } else {
            (states.iter().zip(built_at)).map(size).fold(0.0, f64::max)
        };
        let rounding = 4.0 * (far + skin) * 2f64.powi(-24) + 2f64.powi(-60);
        // Rounded up: the nearest `f32` may be below by 2⁻²⁴ of it.
        (rounding * (1.0 + 2f64.powi(-20))) as f32
    }

    /// At least `reach`, as an `f32`.
    #[inline]
    pub(crate) fn reach_up(reach: f64) -> f32 {
        (reach + reach.abs() * 2f64.powi(-20)) as f32
    }

    /// At least the sum of two radii whose rounded values are `a` and `b` (each within
    /// 2⁻²⁴ of its size, or 2⁻¹⁴⁹ below `f32`'s normal numbers, of the radius; the
    /// rounding of the sum and of this bound's terms within 2⁻²⁴ of each): the sum with
    /// 2⁻²⁰ of the radii's sizes.
    #[inline]
    pub(crate) fn reach_of_rounded(a: f32, b: f32) -> f32 {
        a + b + (a.abs() + b.abs()) * 2f32.powi(-20)
    }

    /// The square of the distance between two rounded centres ([`PairList::spheres`]),
    /// as [`PairList::rounded_distance2`] works it out, past which two particles whose
    /// radii sum to at most `reach` (as an `f32`, rounded up) are surely apart: their
    /// distance exceeds `reach`, by more than the round-off of the test that would
    /// otherwise look at them ([`crate::run`]'s pair test). It is (`reach` +
    /// `rounding`)², with 2⁻¹⁸ of it for the round-off of this sum and square and of
    /// the rounded distance (each operation in `f32` within 2⁻²⁴ of its result, or
    /// 2⁻¹⁵⁰ below `f32`'s normal numbers, which this square, at least 2⁻¹²⁰, leaves
    /// far inside the margin: under 8·2⁻²⁴ in all). NaN or infinite tells no pair
    /// apart.
    #[inline]
    pub(crate) fn clear_beyond(rounding: f32, reach: f32) -> f32 {
        let clear = (reach + rounding) * (1.0 + 2f32.powi(-18));
        clear * clear
    }

    /// The square of the distance between two rounded centres, in `f32`: within 5·2⁻²⁴
    /// of its size of the square of the distance between them, and 2⁻¹⁴⁷ besides (the
    /// round-off of its operations below `f32`'s normal numbers).
    #[inline]
    pub(crate) fn rounded_distance2(a: &[f32; 4], b: &[f32; 4]) -> f32 {
        let (x, y, z) = (a[0] - b[0], a[1] - b[1], a[2] - b[2]);
        x * x + y * y + z * z
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
                *sphere = Self::rounded(s);
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

/// The particles as the list's grid bins them, each radius swollen by `margin`: read
/// from their states, so that the grid keys and tests the centres as they are, not
/// rounded.
#[derive(Clone, Copy)]
struct SwollenStates<'a> {
    states: &'a [State],
    margin: f64,
}

impl Swollen for SwollenStates<'_> {
    #[inline]
    fn len(&self) -> usize {
        self.states.len()
    }

    #[inline]
    fn get(&self, i: usize) -> ([f64; 3], f64) {
        let p = &self.states[i].particle;
        (p.pos.into(), p.radius + self.margin)
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

#[cfg(test)]
mod tests {
    //! The pairs' first test, from the rounded spheres, against the test from the
    //! particles: a pair it tells apart is apart, for centres far from the origin or
    //! near it, radii equal or not, and particles moved up to half the skin since the
    //! list was built; and it does tell apart the pairs clearly apart.

    use super::*;
    use proptest::prelude::*;
    use walls_geometry::Particle;

    /// A particle of radius `r` at `pos`.
    fn at(pos: Vec3, r: f64) -> State {
        State::from(Particle {
            mass: 1.0,
            radius: r,
            pos,
            vel: Vec3::zeros(),
            spin: Vec3::zeros(),
            color: 3,
            index: 0,
        })
    }

    /// Whether the particles touch as the soft-sphere run's pair test finds it from
    /// their states (its distance's square within the reach's, with its margin, and
    /// the overlap positive).
    fn touch(a: &State, b: &State) -> bool {
        let (a, b) = (PairList::sphere(a), PairList::sphere(b));
        let reach = a[3] + b[3];
        let d2 = Vec3::new(a[0] - b[0], a[1] - b[1], a[2] - b[2]).norm_squared();
        d2 <= reach * reach * (1.0 + 1e-9) && reach - d2.sqrt() > 0.0
    }

    /// Whether the first test tells the pair apart, the list built where the particles
    /// were (`built_at`), with the radii's sum given (`uniform`, as a run of one
    /// radius does) or from the rounded radii.
    fn told_apart(states: &[State; 2], built_at: &[Vec3; 2], uniform: bool) -> bool {
        let skin = 0.4 * states[0].particle.radius.max(states[1].particle.radius);
        let rounding = PairList::rounding(states, built_at, skin, false);
        let (a, b) = (PairList::rounded(&states[0]), PairList::rounded(&states[1]));
        let reach = if uniform {
            PairList::reach_up(states[0].particle.radius + states[1].particle.radius)
        } else {
            PairList::reach_of_rounded(a[3], b[3])
        };
        PairList::rounded_distance2(&a, &b) > PairList::clear_beyond(rounding, reach)
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(20_000))]

        #[test]
        fn a_pair_told_apart_from_the_rounded_spheres_is_apart(
            scale in prop_oneof![-6i32..7, -40i32..-6],
            centre in (-1.0..1.0f64, -1.0..1.0f64, -1.0..1.0f64),
            size in prop_oneof![Just(-3i32), -30i32..3],
            (ra, rb) in (1.0..10.0f64, prop_oneof![Just(None), (1.0..10.0f64).prop_map(Some)]),
            direction in (-1.0..1.0f64, -1.0..1.0f64, -1.0..1.0f64),
            gap in prop_oneof![Just(0.0), -1e-6..1e-6f64, -1e-3..1e-3f64, -0.5..0.5f64],
            moved in (0.0..1.0f64, 0.0..1.0f64),
        ) {
            let c = Vec3::new(centre.0, centre.1, centre.2) * 10f64.powi(scale);
            let u = Vec3::new(direction.0, direction.1, direction.2);
            prop_assume!(u.norm() > 1e-3);
            let u = u.normalize();
            let (ra, rb) = (ra * 10f64.powi(size), rb.unwrap_or(ra) * 10f64.powi(size));
            let b = c + u * ((ra + rb) * (1.0 + gap));
            let states = [at(c, ra), at(b, rb)];
            // Where the list was built: up to half the skin away, across the line.
            let half = 0.2 * ra.max(rb);
            let side = u.cross(&Vec3::z()).try_normalize(1e-9).unwrap_or(Vec3::x());
            let built_at = [c + side * (half * moved.0), b - side * (half * moved.1)];
            for uniform in [false, ra == rb] {
                if told_apart(&states, &built_at, uniform) {
                    prop_assert!(!touch(&states[0], &states[1]), "{states:?}");
                }
            }
        }
    }

    #[test]
    fn the_rounded_spheres_tell_apart_the_pairs_clearly_apart() {
        // Spheres of 1 mm a tenth of their radius apart, near the origin and a hundred
        // metres from it; and not when the centres are so far out (a kilometre) that
        // rounding may hide the gap.
        for (x, apart) in [(0.0, true), (0.2, true), (1e2, true), (1e3, false)] {
            let c = Vec3::new(x, -x, 0.5 * x);
            let states = [at(c, 1e-3), at(c + Vec3::new(2.1e-3, 0.0, 0.0), 1e-3)];
            let built_at = [states[0].particle.pos, states[1].particle.pos];
            for uniform in [true, false] {
                assert_eq!(told_apart(&states, &built_at, uniform), apart, "{x} m");
            }
        }
        // Spheres of 6e−23 overlapping by 2.7 % of their radius, whose rounded distance's
        // square and the square it is held against fall below `f32`'s normal numbers:
        // not told apart (the rounding is never below 2⁻⁶⁰).
        let tiny = [
            at(Vec3::zeros(), 6e-23),
            at(Vec3::new(6.1e-23, 8e-23, 6.24e-23), 6e-23),
        ];
        assert!(touch(&tiny[0], &tiny[1]));
        let built_at = [tiny[0].particle.pos, tiny[1].particle.pos];
        for uniform in [true, false] {
            assert!(!told_apart(&tiny, &built_at, uniform));
        }
        // Touching, they are never told apart; nor is any pair once a coordinate is
        // not finite.
        let states = [
            at(Vec3::zeros(), 1e-3),
            at(Vec3::new(1.9e-3, 0.0, 0.0), 1e-3),
        ];
        let built_at = [states[0].particle.pos, states[1].particle.pos];
        assert!(!told_apart(&states, &built_at, true));
        let far = [
            at(Vec3::new(f64::MAX, 0.0, 0.0), 1e-3),
            at(Vec3::zeros(), 1e-3),
        ];
        let built_at = [far[0].particle.pos, far[1].particle.pos];
        assert!(!told_apart(&far, &built_at, false));
    }
}
