//! The pair pass of the soft-sphere run ([`pair_contacts`]): which candidate pairs touch
//! ([`scan_pairs`]), pkdgrav's overlap checks, and the forces of the contacts, one at a
//! time ([`PairContext::force`]) or four at a time ([`PairContext::force_lanes`]), on one
//! thread or many; and the particles' material as the pass uses it ([`PairMaterial`]).

use super::ahead::{fetch, fetch_state};
use super::law::Side;
use super::numbering::Numbering;
use super::{
    Bodies, ContactLaw, Deferred, Flow, Journal, Kicks, Law, Load, Overlapping, Rigid, Rules,
    Settings, State, Vec3, inertia,
};
use crate::broad::pairs::{NO_CONTACT, PairList};
use crate::contact::lanes::{self, LANES};
use crate::contact::ssdem::{
    Dashpot, Material, Optional, Record, Restitution, Rolling, Touch, contact,
    damping_per_root_mass, dashpot_contact_with, normal_contact, resistance,
};
use crate::dynamics::aggregate::Aggregates;
use crate::run::optional::OptionalPhysics;
use crate::run::plan::Plan;
use rayon::prelude::*;

/// The particles' material for their contacts with each other, with its constants
/// worked out once at set-up.
pub(super) struct PairMaterial {
    pub(super) mat: Material,
    /// The normal and tangential restitutions.
    restitution: (Restitution, Restitution),
    /// The linear law's normal damping over √m (the reduced mass's root).
    damping_per_root_mass: f64,
    /// A reduced mass and the damping coefficients (C_n, C_t) of a contact of that
    /// reduced mass: a contact of that mass (two free particles of the first one's mass;
    /// in a run of one size, every contact) takes them rather than two square roots.
    damping: Option<(f64, (f64, f64))>,
}

impl PairMaterial {
    /// The material `mat` between the particles `states`.
    pub(super) fn new(mat: Material, states: &[State]) -> PairMaterial {
        let (eps_n, eps_t) = (Restitution::new(mat.eps_n), Restitution::new(mat.eps_t));
        let damping = states.first().map(|s| {
            let m = s.particle.mass;
            let reduced = m * m / (m + m);
            let damping = |eps: Restitution, k: f64| eps.damping(k, reduced);
            (reduced, (damping(eps_n, mat.k_n), damping(eps_t, mat.k_t)))
        });
        PairMaterial {
            mat,
            restitution: (eps_n, eps_t),
            damping_per_root_mass: damping_per_root_mass(mat.eps_n, mat.k_n),
            damping,
        }
    }
}

/// The forces of the candidate pairs that overlap: which overlap, in the list's
/// order (their overlaps checked, their contacts opened and the others' closed);
/// then their forces, added to each load in the list's order. On one thread each
/// record is changed in place and each force added at once; in parallel, the
/// records are laid out anew in the order of the pairs that touch, and each range
/// of particles takes its forces in the list's order. The outcome does not depend
/// on the threads.
pub(super) fn pair_contacts(
    bodies: &mut Bodies,
    deferred: &mut Deferred,
    (candidates, pair_pass, journal): (&mut PairList, &mut PairPass, &mut Journal),
    rigid: &Rigid,
    rules: &Rules,
    t: f64,
) -> Flow {
    let aggregates = rigid.aggregates.as_ref();
    scan_pairs(
        &bodies.states,
        candidates,
        pair_pass,
        journal,
        aggregates,
        (rules.parallel, rules.ahead),
    );
    // …then, in the list's order, the overlaps checked (a deep one may stop the run,
    // before any contact is opened or closed)…
    if check_overlaps(candidates, pair_pass, (journal, &bodies.numbering), t) {
        return Flow::Stop;
    }
    let PairList {
        pairs,
        slots,
        contacts,
        ..
    } = candidates;
    let PairPass {
        touching,
        forces,
        scans,
        from,
        bounds,
    } = pair_pass;
    // …and the contacts closed and opened (the first since the list was built with
    // none open makes the pairs' slots).
    touching.clear();
    from.clear();
    if scans.iter().any(|scan| !scan.touching.is_empty()) {
        PairList::open_slots(slots, pairs.len());
    }
    for scan in scans.iter() {
        if !rules.parallel {
            for &k in &scan.apart {
                contacts.close(&mut slots[k as usize]);
            }
            for &(k, _) in &scan.touching {
                contacts.open(&mut slots[k as usize], &mut journal.pair_contacts);
                touching.push(k);
            }
            continue;
        }
        // In parallel, this step's records are laid out anew in the order of the
        // pairs that touch: each comes from its slot in the last step's (`from`).
        for &k in &scan.apart {
            slots[k as usize] = NO_CONTACT;
        }
        for &(k, _) in &scan.touching {
            let slot = &mut slots[k as usize];
            journal.pair_contacts += u64::from(*slot == NO_CONTACT);
            from.push(*slot);
            *slot = touching.len() as u32;
            touching.push(k);
        }
    }
    // The loads these forces go to, marked when few (`Deferred::loaded`).
    deferred.marks_valid = 8 * touching.len() <= bodies.states.len();
    if deferred.marks_valid {
        for &k in touching.iter() {
            let (i, j) = pairs[k as usize];
            deferred.loaded[i as usize] = true;
            deferred.loaded[j as usize] = true;
        }
    }
    let context = PairContext {
        states: &bodies.states,
        settings: rules.settings,
        plan: rules.plan,
        kicks: rules.kicks,
        contact: rules.contact,
        between: &rules.between,
        optional: &rules.optional,
    };
    let loads = &mut bodies.loads;
    // What the forces could add to an owed kick (`super::drift::surely_finite`): the
    // sum of their sizes, block by block, the same on any number of threads.
    let mut bound = 0.0;
    if !rules.parallel {
        // One thread: each contact's record changed where it lies, and its force
        // added at once, in the list's order.
        let lanes = context.lanes();
        for block in touching.chunks(BOUND_BLOCK) {
            let list = (block, pairs.as_slice(), slots.as_slice());
            let on = (&mut contacts.records[..], &mut loads[..]);
            bound += pair_block(&context, (lanes.as_ref(), rules.ahead), list, on);
        }
        deferred.force_bound += bound;
        return Flow::Continue;
    }
    // In parallel: the new records, in the order of the pairs that touch, each from
    // its last slot (a new contact's from nothing), and the forces beside them…
    let lanes = context.lanes();
    let n = touching.len();
    // (Every place is written below: only the places past the last step's length
    // are filled first.)
    contacts.next.resize(n, Record::default());
    forces.resize(n, PairForce::default());
    let last = contacts.records.as_slice();
    (contacts.next.par_chunks_mut(PAIR_CHUNK))
        .zip(forces.par_chunks_mut(PAIR_CHUNK))
        .zip(
            touching
                .par_chunks(PAIR_CHUNK)
                .zip(from.par_chunks(PAIR_CHUNK)),
        )
        .for_each(|((records, forces), (ks, from))| {
            let list = (pairs.as_slice(), last);
            pair_chunk(
                &context,
                (lanes.as_ref(), rules.ahead),
                (ks, from),
                list,
                (records, forces),
            );
        });
    std::mem::swap(&mut contacts.records, &mut contacts.next);
    contacts.free.clear();
    // …the bound, block by block as on one thread…
    (forces.par_chunks(BOUND_BLOCK))
        .map(|block| block.iter().fold(0.0, |sum, f| sum + f.size()))
        .collect_into_vec(bounds);
    for sum in bounds.iter() {
        bound += sum;
    }
    deferred.force_bound += bound;
    // …and each range of particles takes the forces on its own in the list's
    // order, so that each load adds them as on one thread.
    let range = loads.len().div_ceil(rayon::current_num_threads()).max(1);
    let pairs = pairs.as_slice();
    loads
        .par_chunks_mut(range)
        .enumerate()
        .for_each(|(c, part)| {
            let ij_of = |k: u32| (pairs[k as usize].0 as usize, pairs[k as usize].1 as usize);
            let first = c * range;
            for (n, (&k, f)) in touching.iter().zip(forces.iter()).enumerate() {
                // The loads of a contact a few on, if in this range, asked for now.
                if rules.ahead
                    && let Some(&k) = touching.get(n + CONTACT_AHEAD)
                {
                    let (i, j) = ij_of(k);
                    for p in [i, j] {
                        if let Some(load) = p.checked_sub(first).and_then(|p| part.get(p)) {
                            fetch(load);
                        }
                    }
                }
                let (i, j) = ij_of(k);
                f.add_to(part, first, i, j);
            }
        });
    Flow::Continue
}

/// Which candidate pairs touch (with their overlaps as fractions of the smaller
/// radius) and which open contacts ended, in chunks of the list (in parallel for
/// many particles), in [`PairPass::scans`].
pub(super) fn scan_pairs(
    states: &[State],
    candidates: &mut PairList,
    pair_pass: &mut PairPass,
    journal: &Journal,
    aggregates: Option<&Aggregates>,
    (parallel, ahead): (bool, bool),
) {
    let PairList {
        pairs,
        slots,
        spheres,
        rounding,
        held,
        gone,
        uniform,
        ..
    } = candidates;
    let scans = &mut pair_pass.scans;
    let some_unfree = *held || *gone;
    // An overlap above this is one the ordered check must see (a NaN it would not
    // act on).
    let quiet = journal.overlaps.quiet_up_to();
    // (In chunks on one thread too: the overlaps' check looks again only at those
    // with a deep one.)
    let size = pairs.len().div_ceil(SCAN_CHUNKS).max(1);
    scans.resize_with(pairs.len().div_ceil(size), Scan::default);
    // Plain slices in the loop (not the list's vectors behind references, which the
    // compiler would read again at every pair).
    let (list, open, centres) = (pairs.as_slice(), slots.as_slice(), spheres.as_slice());
    let (uniform, rounding) = (*uniform, *rounding);
    // Whether a pair is out of the test's reach besides its distance: members of one
    // aggregate never meet (docs/pkdgrav-physics.md §9.1); a particle stuck to a wall
    // is an obstacle of infinite mass (pkdgrav's rule), and two stuck ones, or a
    // removed one, meet nothing. (The states are read only once some particle is
    // held or gone.)
    let unmet = |i: usize, j: usize| {
        aggregates.is_some_and(|a| a.same(i, j))
            || (some_unfree
                && (!states[i].alive
                    || !states[j].alive
                    || !(states[i].free() || states[j].free())))
    };
    let scan = |(c, scan): (usize, &mut Scan)| {
        scan.touching.clear();
        scan.apart.clear();
        let first = c * size;
        let end = (first + size).min(list.len());
        let with = (uniform, (centres, rounding, states), quiet);
        // The pairs from place `at` to `to`, tested.
        let range = |scan: &mut Scan, at: usize, to: usize| {
            let pairs = list[at..to].iter();
            if open.is_empty() {
                // No contact open (no slots kept): none to end.
                let pairs = pairs.map(|pair| (pair, NO_CONTACT));
                scan_range(scan, at, pairs.enumerate(), with, &unmet)
            } else {
                let pairs = pairs.zip(open[at..to].iter().copied());
                scan_range(scan, at, pairs.enumerate(), with, &unmet)
            }
        };
        // In blocks when asking ahead with a size mix, each asking first for the
        // spheres of the next one's partners (the first particles of the pairs come
        // in order; their partners do not): the polydisperse 10⁵ took 6 % less time.
        // With one radius the test is a few instructions a pair, and asking cost
        // the 10⁶ drop about a tenth more: it does not ask there.
        scan.deep = if ahead && uniform.is_none() {
            let mut deep = false;
            for at in (first..end).step_by(SCAN_BLOCK) {
                let to = (at + SCAN_BLOCK).min(end);
                for &(_, j) in &list[to..(to + SCAN_BLOCK).min(end)] {
                    fetch(&centres[j as usize]);
                }
                deep |= range(scan, at, to);
            }
            deep
        } else {
            range(scan, first, end)
        };
    };
    if parallel {
        scans.par_iter_mut().enumerate().for_each(scan);
    } else {
        scans.iter_mut().enumerate().for_each(scan);
    }
}

/// The pairs of one range of the candidate list, the first at place `first` of the
/// list, each `(n, ((i, j), slot))` (the n-th of the range), tested into `scan` (`with`:
/// the one sum of radii when every particle has the same radius; the rounded spheres,
/// their rounding and the states; and the overlap past which the ordered check must see
/// one); whether one is deep enough for that check. A pair whose rounded spheres tell
/// it apart ([`PairList::clear_beyond`]) is apart, as [`test`] would find from the
/// states, which it reads only for the others.
#[inline(always)]
fn scan_range<'a>(
    scan: &mut Scan,
    first: usize,
    pairs: impl Iterator<Item = (usize, (&'a (u32, u32), u32))>,
    (uniform, (centres, rounding, states), quiet): Scanned,
    unmet: &impl Fn(usize, usize) -> bool,
) -> bool {
    let mut deep = false;
    let sphere = |i: usize| PairList::sphere(&states[i]);
    // An apart pair's contact, if open, ends.
    let apart = |scan: &mut Scan, k: usize, slot: u32| {
        if slot != NO_CONTACT {
            scan.apart.push(k as u32);
        }
    };
    match uniform {
        // Every particle of one radius: the reach and its squares worked out once, the
        // same numbers as for each pair (10 % of the test's instructions).
        Some(reach) => {
            let beyond = reach * reach * (1.0 + 1e-9);
            let clear = PairList::clear_beyond(rounding, PairList::reach_up(reach));
            for (n, (&(i, j), slot)) in pairs {
                let (i, j) = (i as usize, j as usize);
                if PairList::rounded_distance2(&centres[i], &centres[j]) > clear {
                    apart(scan, first + n, slot);
                    continue;
                }
                let spheres = (&sphere(i), &sphere(j));
                let open = (slot != NO_CONTACT, quiet);
                let reach = (reach, beyond);
                deep |= test(scan, first + n, spheres, reach, open, || unmet(i, j));
            }
        }
        None => {
            for (n, (&(i, j), slot)) in pairs {
                let (i, j) = (i as usize, j as usize);
                let (a, b) = (&centres[i], &centres[j]);
                let clear =
                    PairList::clear_beyond(rounding, PairList::reach_of_rounded(a[3], b[3]));
                if PairList::rounded_distance2(a, b) > clear {
                    apart(scan, first + n, slot);
                    continue;
                }
                let (a, b) = (&sphere(i), &sphere(j));
                let reach = a[3] + b[3];
                let beyond = reach * reach * (1.0 + 1e-9);
                let open = (slot != NO_CONTACT, quiet);
                let reach = (reach, beyond);
                deep |= test(scan, first + n, (a, b), reach, open, || unmet(i, j));
            }
        }
    }
    deep
}

/// What [`scan_range`] tests the pairs with besides the pairs.
type Scanned<'a> = (Option<f64>, (&'a [[f32; 4]], f32, &'a [State]), f64);

/// One pair (spheres `a` and `b`, the sum of their radii `reach`, and `beyond`, the
/// square of the distance past which they are surely apart: the sum with a margin for
/// round-off): apart, and its contact if open ends; or touching, with its overlap as a
/// fraction of the smaller radius, which pkdgrav's warnings and abort judge. Whether
/// that overlap is one the ordered check must see.
#[inline(always)]
fn test(
    scan: &mut Scan,
    k: usize,
    (a, b): (&[f64; 4], &[f64; 4]),
    (reach, beyond): (f64, f64),
    (open, quiet): (bool, f64),
    unmet: impl Fn() -> bool,
) -> bool {
    // Most candidates do not touch: the square of the distance tells (as
    // [`separation`] has it, without its square root for the many apart); the
    // contact, if open, ends.
    let d2 = Vec3::new(a[0] - b[0], a[1] - b[1], a[2] - b[2]).norm_squared();
    let overlap = if d2 > beyond || unmet() {
        0.0
    } else {
        reach - d2.sqrt()
    };
    if overlap <= 0.0 {
        if open {
            scan.apart.push(k as u32);
        }
        false
    } else {
        let fraction = overlap / a[3].min(b[3]);
        scan.touching.push((k as u32, fraction));
        fraction > quiet
    }
}

/// pkdgrav's overlap warnings and abort for the pairs that touch, in the list's
/// order (only the chunks with an overlap they may act on are looked at); true when
/// one stops the run. The contacts the pairs before that one would have opened this
/// step are counted, as pkdgrav counts them before it aborts, though none is opened:
/// the run ends there (the stepper is not stepped again).
pub(super) fn check_overlaps(
    candidates: &PairList,
    pair_pass: &PairPass,
    (journal, numbering): (&mut Journal, &Numbering),
    t: f64,
) -> bool {
    let PairList { pairs, slots, .. } = candidates;
    let scans = &pair_pass.scans;
    for (c, scan) in scans.iter().enumerate().filter(|(_, scan)| scan.deep) {
        for (n, &(k, fraction)) in scan.touching.iter().enumerate() {
            let (i, j) = (pairs[k as usize].0 as usize, pairs[k as usize].1 as usize);
            let what = Overlapping::Particles(numbering.file(i), numbering.file(j));
            if journal
                .overlaps
                .check(fraction, what, t, &mut journal.warnings)
            {
                // The contacts the pairs before it opened.
                let before = scans[..c].iter().flat_map(|s| &s.touching);
                let opened = before.chain(&scan.touching[..n]);
                let opened =
                    opened.filter(|(k, _)| PairList::slot(slots, *k as usize) == NO_CONTACT);
                journal.pair_contacts += opened.count() as u64;
                return true;
            }
        }
    }
    false
}

/// Into how many chunks the candidate pairs are cut to find (in parallel, with many
/// particles) which touch.
pub(super) const SCAN_CHUNKS: usize = 64;

/// How many pairs the pairs' test takes at a time when it asks for the next ones'
/// partners' spheres.
const SCAN_BLOCK: usize = 32;

/// What one chunk of the candidate pairs found in a step: the pairs that touch, with
/// their overlaps as fractions of the smaller radius, and those with an open contact
/// that no longer touch.
#[derive(Default)]
pub(super) struct Scan {
    touching: Vec<(u32, f64)>,
    apart: Vec<u32>,
    /// Whether an overlap is deep enough for pkdgrav's warnings or abort to act on
    /// ([`crate::run::OverlapWarnings::quiet_up_to`]).
    deep: bool,
}

/// What the pair pass works in, kept from step to step to save allocating.
#[derive(Default)]
pub(super) struct PairPass {
    /// The pairs that touch this step.
    touching: Vec<u32>,
    /// In parallel, their forces, in the same order.
    forces: Vec<PairForce>,
    /// In parallel, the slot in the last step's records of each that touches (or
    /// [`NO_CONTACT`]).
    from: Vec<u32>,
    /// In parallel, the sums of the forces' sizes, block by block.
    bounds: Vec<f64>,
    /// What each chunk of the list found this step.
    scans: Vec<Scan>,
}

/// How many touching pairs' force sizes are summed in order before the sum is added to
/// the bound ([`super::drift::surely_finite`]): the blocks in parallel, the same sums.
pub(super) const BOUND_BLOCK: usize = 4096;

/// The force of one particle contact and its torques on particles i and j, and
/// whether each is free (a stuck one takes nothing).
#[derive(Clone, Copy, Default)]
pub(super) struct PairForce {
    force: Vec3,
    torques: (Vec3, Vec3),
    free: (bool, bool),
}

impl PairForce {
    /// The sum of the sizes (|x| + |y| + |z|) of the force and both torques.
    #[inline]
    pub(super) fn size(&self) -> f64 {
        self.force.abs().sum() + self.torques.0.abs().sum() + self.torques.1.abs().sum()
    }

    /// Adds the force and torques to the loads of particles i and j (of the free ones)
    /// among `loads`, the loads of the particles from `first` on.
    #[inline]
    pub(super) fn add_to(&self, loads: &mut [Load], first: usize, i: usize, j: usize) {
        if self.free.0
            && let Some(load) = loads.get_mut(i.wrapping_sub(first))
        {
            load.force += self.force;
            load.torque += self.torques.0;
        }
        if self.free.1
            && let Some(load) = loads.get_mut(j.wrapping_sub(first))
        {
            load.force -= self.force;
            load.torque += self.torques.1;
        }
    }
}

/// The vector from sphere b's centre to sphere a's, its length, and how far the two
/// overlap (x, y, z, r each).
#[inline]
pub(super) fn separation(a: &[f64; 4], b: &[f64; 4]) -> (Vec3, f64, f64) {
    let d = Vec3::new(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
    let distance = d.norm_squared().sqrt();
    (d, distance, a[3] + b[3] - distance)
}

/// How many contacts on the forces' pass asks for what a contact reads.
const CONTACT_AHEAD: usize = 8;

/// Asks for what a contact between particles `i` and `j` reads: their states, and its
/// record if it has one (each where the pair list sends it, not in order).
#[inline(always)]
fn fetch_contact(states: &[State], record: Option<&Record>, (i, j): (usize, usize)) {
    fetch_state(&states[i]);
    fetch_state(&states[j]);
    if let Some(record) = record {
        fetch(record);
        fetch(&record.twist);
    }
}

/// The forces of a block of the candidate pairs that touch (`list`: their places in the
/// candidate pairs, the pairs, and each pair's slot among the records), on one thread:
/// each contact's record stepped where it lies (`on`: the records and the loads), its
/// force added to the loads at once, in the list's order. Four contacts at a time
/// ([`crate::contact::lanes`]) when `lanes` says how and the eight particles are free,
/// else one (the last few, or the first of four with a particle held). Returns the sum
/// of the forces' sizes. Compiled as well for processors with AVX-512 and with AVX2,
/// the version chosen at run time for the processor it runs on: the lanes' vector
/// operations inline only into code compiled for them (docs/performance-history.md, "Tenth
/// round" and "Eleventh round"), and the numbers are the same in each, since Rust never
/// fuses a multiplication with an addition unless asked to.
#[multiversion::multiversion(targets(
    "x86_64+avx512f+avx512vl+avx512dq+avx2+fma",
    "x86_64+avx2+fma"
))]
pub(super) fn pair_block(
    context: &PairContext,
    (lanes, ahead): (Option<&lanes::Setting>, bool),
    (block, pairs, slots): (&[u32], &[(u32, u32)], &[u32]),
    (records, loads): (&mut [Record], &mut [Load]),
) -> f64 {
    let mut sum = 0.0;
    let mut rest = block;
    let ij_of = |k: usize| (pairs[k].0 as usize, pairs[k].1 as usize);
    // The contacts up to this far on have been asked for ([`fetch_contact`]).
    let mut asked = 0;
    while let Some((&first, after)) = rest.split_first() {
        if ahead {
            let to = (block.len() - rest.len() + CONTACT_AHEAD).min(block.len());
            for &k in &block[asked..to] {
                let (k, (i, j)) = (k as usize, ij_of(k as usize));
                fetch_contact(context.states, records.get(slots[k] as usize), (i, j));
                fetch(&loads[i]);
                fetch(&loads[j]);
            }
            asked = to;
        }
        if let (Some(setting), Some((group, _))) = (lanes, rest.split_first_chunk::<LANES>()) {
            let ks = group.map(|k| k as usize);
            let ij = ks.map(ij_of);
            // The four records stepped where they lie (each contact has a slot of its
            // own): copied out and back, they cost the oscillating floor about 3 % of
            // its time.
            if context.all_free(&ij)
                && let Ok(four) = records.get_disjoint_mut(ks.map(|k| slots[k] as usize))
            {
                let forces = context.force_lanes(&ij, four, setting);
                for l in 0..LANES {
                    let (i, j) = ij[l];
                    forces[l].add_to(loads, 0, i, j);
                    sum += forces[l].size();
                }
                rest = &rest[LANES..];
                continue;
            }
        }
        // One alone: the last few, or the first of four with a particle held.
        let k = first as usize;
        let (i, j) = ij_of(k);
        let record = &mut records[slots[k] as usize];
        let f = context.force(i, j, record);
        f.add_to(loads, 0, i, j);
        sum += f.size();
        rest = after;
    }
    sum
}

/// How many of the contacts that touch a thread takes at a time, in parallel.
pub(super) const PAIR_CHUNK: usize = 256;

/// In parallel, the forces of a chunk of the candidate pairs that touch (`ks`: their
/// places in the candidate pairs `pairs`; `from`: each one's slot in the last step's
/// records `last`, or [`NO_CONTACT`]), into `records` and `forces`: each contact's record,
/// from its last slot (a new contact's from nothing), stepped, and its force. Four
/// contacts at a time as in [`pair_block`], and compiled likewise.
#[multiversion::multiversion(targets(
    "x86_64+avx512f+avx512vl+avx512dq+avx2+fma",
    "x86_64+avx2+fma"
))]
pub(super) fn pair_chunk(
    context: &PairContext,
    (lanes, ahead): (Option<&lanes::Setting>, bool),
    (ks, from): (&[u32], &[u32]),
    (pairs, last): (&[(u32, u32)], &[Record]),
    (records, forces): (&mut [Record], &mut [PairForce]),
) {
    let record = |slot: u32| match slot {
        NO_CONTACT => Record::default(),
        slot => last[slot as usize],
    };
    let ij_of = |k: u32| (pairs[k as usize].0 as usize, pairs[k as usize].1 as usize);
    let mut done = 0;
    // The contacts up to this far on have been asked for ([`fetch_contact`]).
    let mut asked = 0;
    while done < ks.len() {
        if ahead {
            let to = (done + CONTACT_AHEAD).min(ks.len());
            for (&k, &slot) in ks[asked..to].iter().zip(&from[asked..]) {
                fetch_contact(context.states, last.get(slot as usize), ij_of(k));
            }
            asked = to;
        }
        if let Some(setting) = lanes
            && done + LANES <= ks.len()
        {
            let ij: [(usize, usize); LANES] = std::array::from_fn(|l| ij_of(ks[done + l]));
            if context.all_free(&ij) {
                let mut four: [Record; LANES] = std::array::from_fn(|l| record(from[done + l]));
                let f = context.force_lanes(&ij, four.each_mut(), setting);
                records[done..done + LANES].copy_from_slice(&four);
                forces[done..done + LANES].copy_from_slice(&f);
                done += LANES;
                continue;
            }
        }
        // One alone: the last few, or the first of four with a particle held.
        let (i, j) = ij_of(ks[done]);
        records[done] = record(from[done]);
        forces[done] = context.force(i, j, &mut records[done]);
        done += 1;
    }
}

/// What the force of a particle contact depends on besides the two particles.
pub(super) struct PairContext<'a> {
    states: &'a [State],
    settings: &'a Settings,
    plan: &'a Plan,
    kicks: Kicks,
    contact: ContactLaw,
    between: &'a PairMaterial,
    optional: &'a OptionalPhysics,
}

impl PairContext<'_> {
    /// How the contacts go four at a time ([`crate::contact::lanes`]), when the run's
    /// contacts take pkdgrav's levers and law without its optional parts and the
    /// processor has the lanes' vector instructions ([`lanes::Simd`]).
    pub(super) fn lanes(&self) -> Option<lanes::Setting<'_>> {
        let settings = self.settings;
        let simd = lanes::Simd::new()?;
        let between = self.between;
        (self.contact.plain_dashpot() && !self.optional.any()).then_some(lanes::Setting {
            simd,
            dt: settings.dt,
            predict: self.kicks.predict_all,
            mat: &between.mat,
            sliding: self.contact.sliding,
            restitution: between.restitution,
            damping: between.damping,
        })
    }

    /// Whether the particles of four pairs are all free.
    #[inline(always)]
    pub(super) fn all_free(&self, ij: &[(usize, usize); LANES]) -> bool {
        ij.iter()
            .all(|&(i, j)| self.states[i].free() && self.states[j].free())
    }

    /// [`PairContext::force`] for four pairs of free particles, `ij`, with their records,
    /// four at a time as [`PairContext::lanes`] says.
    #[inline(always)]
    pub(super) fn force_lanes(
        &self,
        ij: &[(usize, usize); LANES],
        records: [&mut Record; LANES],
        setting: &lanes::Setting,
    ) -> [PairForce; LANES] {
        let states = self.states;
        let sphere = |pick: fn(&(usize, usize)) -> usize| {
            let each: [&walls_geometry::Particle; LANES] =
                std::array::from_fn(|l| &states[pick(&ij[l])].particle);
            (
                lanes::V::gather(|l| each[l].pos.into()),
                lanes::gather(|l| each[l].radius),
            )
        };
        let (ci, ri) = sphere(|p| p.0);
        let (cj, rj) = sphere(|p| p.1);
        let vector = |pick: fn(&(usize, usize)) -> usize, field: fn(&State) -> &Vec3| {
            lanes::V::gather(|l| (*field(&states[pick(&ij[l])])).into())
        };
        let both = |field: fn(&State) -> &Vec3| (vector(|p| p.0, field), vector(|p| p.1, field));
        let mass = |pick: fn(&(usize, usize)) -> usize| -> lanes::L {
            lanes::gather(|l| states[pick(&ij[l])].particle.mass)
        };
        let p = lanes::Pairs {
            centres: (ci, cj),
            radii: (ri, rj),
            vel: both(|s| &s.particle.vel),
            spin: both(|s| &s.particle.spin),
            acc: both(|s| &s.acc),
            alpha: both(|s| &s.alpha),
            mass: (mass(|p| p.0), mass(|p| p.1)),
        };
        let f = lanes::pair(&p, records, setting);
        let (force, torque, partner) = (
            f.force.each_lane(),
            f.torque.each_lane(),
            f.partner_torque.each_lane(),
        );
        std::array::from_fn(|l| PairForce {
            force: force[l].into(),
            torques: (torque[l].into(), partner[l].into()),
            free: (true, true),
        })
    }

    /// The force of the contact between particles i and j (which overlap), with its
    /// springs in `record`. Inlined always into its two callers
    /// (one thread, many): returned through memory, the force was written out in
    /// pieces and read back whole, and the one-thread loop's sums into the loads
    /// waited on those stores.
    #[inline(always)]
    pub(super) fn force(&self, i: usize, j: usize, record: &mut Record) -> PairForce {
        let states = self.states;
        let (a, b) = (PairList::sphere(&states[i]), PairList::sphere(&states[j]));
        let (d, distance, overlap) = separation(&a, &b);
        let (p, q) = (&states[i].particle, &states[j].particle);
        let (free_i, free_j) = (states[i].free(), states[j].free());
        let (dt, plan, mat) = (self.settings.dt, self.plan, &self.between.mat);
        let Kicks {
            predict_all,
            pkdgrav_levers,
            ..
        } = self.kicks;
        // `d`'s own normalisation, with its length already known.
        let n = if distance > 0.0 {
            d / distance
        } else {
            Vec3::z()
        };
        // The velocities and spins the contact sees: as they are, or (pkdgrav's)
        // predicted to the step's end, for a free particle; a stuck one's as they are.
        let seen = |s: &State, free: bool| {
            if predict_all != 0.0 && free {
                (
                    s.particle.vel + s.acc * (dt * predict_all),
                    s.particle.spin + s.alpha * (dt * predict_all),
                )
            } else {
                (s.particle.vel, s.particle.spin)
            }
        };
        let ((vi, wi), (vj, wj)) = (seen(&self.states[i], free_i), seen(&self.states[j], free_j));
        // The levers: the radii, or pkdgrav's distances from each centre to the
        // plane where the spheres intersect (docs/pkdgrav-physics.md §1.1).
        let (li, lj) = if pkdgrav_levers {
            pair_levers(p.radius, q.radius, distance)
        } else {
            (p.radius, q.radius)
        };
        let u = vi + wi.cross(&(-n * li)) - vj - wj.cross(&(n * lj));
        let reduced = match (free_i, free_j) {
            (true, true) => p.mass * q.mass / (p.mass + q.mass),
            (true, false) => p.mass,
            _ => q.mass,
        };
        if self.contact.law == Law::Pkdgrav {
            // pkdgrav's contact law, in its frame: particle 1 is i, the normal points
            // towards j, velocities and spins are j's relative to i's
            // (docs/pkdgrav-physics.md §1.1–§1.5).
            let a = self.contact.contact_radius(p.radius, li);
            let side = |s: &State, free: bool, lever: f64, spin: Vec3| Side {
                radius: s.particle.radius,
                lever,
                spin,
                inertia: if free {
                    inertia(s.particle.mass, s.particle.radius)
                } else {
                    f64::INFINITY
                },
            };
            let one = side(&states[i], free_i, li, wi);
            let (radius, constant_torque) =
                (self.contact).rolling(a, one, Some(side(&states[j], free_j, lj, wj)));
            let dashpot = Dashpot {
                overlap,
                normal: -n,
                velocity: -u,
                spin: wj - wi,
                turn: p.spin + q.spin,
                levers: (li, lj),
                mass: reduced,
                radius,
                wall: false,
                constant_torque,
                sliding: self.contact.sliding,
            };
            let mut extra = Optional {
                restitution: Some(self.between.restitution),
                ..self.optional.pair(i, j, p.radius, q.radius, a, mat)
            };
            if let (None, Some((mass, damping))) = (extra.layers, self.between.damping)
                && mass == reduced
            {
                // Two layers change the springs, and with them the damping.
                extra.damping = Some(damping);
            }
            let c = dashpot_contact_with(&dashpot, record, dt, mat, &extra);
            return PairForce {
                force: c.force,
                torques: (c.torque, c.partner_torque),
                free: (free_i, free_j),
            };
        }
        let touch = Touch {
            overlap,
            normal: n,
            velocity: u,
        };
        let c = if plan.sliding_friction {
            contact(reduced, li, &touch, &mut record.spring, dt, mat)
        } else {
            let c_n = self.between.damping_per_root_mass * reduced.sqrt();
            normal_contact(&touch, mat.k_n, c_n)
        };
        // The tangential force acts at the contact point: −R_i·n̂ from i, +R_j·n̂
        // from j.
        let mut torque = (c.torque, c.torque * (lj / li));
        if plan.rolling || plan.twisting {
            let lever = p.radius * q.radius / (p.radius + q.radius);
            // Equal and opposite torques change the relative spin through the
            // reduced inertia (or the free one's, against a stuck particle).
            let (ii, ij) = (inertia(p.mass, p.radius), inertia(q.mass, q.radius));
            let rolling = Rolling {
                spin: wi - wj,
                normal: n,
                normal_force: n.dot(&c.force).abs(),
                lever,
                contact_radius: lens_radius(p.radius, q.radius, distance),
                inertia: match (free_i, free_j) {
                    (true, true) => ii * ij / (ii + ij),
                    (true, false) => ii,
                    _ => ij,
                },
            };
            let m = resistance(&rolling, mat.mu_r, mat.mu_t, dt);
            torque.0 += m;
            torque.1 -= m;
        }
        PairForce {
            force: c.force,
            torques: torque,
            free: (free_i, free_j),
        }
    }
}

/// pkdgrav's levers of a pair contact (docs/pkdgrav-physics.md §1.1): the distances from
/// the centres of spheres of radii `a` and `b`, `d` apart, to the plane where they
/// intersect; exactly d/2 each when the radii are equal.
pub(super) fn pair_levers(a: f64, b: f64, d: f64) -> (f64, f64) {
    if a == b {
        (0.5 * d, 0.5 * d)
    } else {
        let la = (a * a - b * b + d * d) / (2.0 * d);
        (la, d - la)
    }
}

/// The radius of the circle where spheres of radii `a` and `b`, `d` apart, intersect.
pub(super) fn lens_radius(a: f64, b: f64, d: f64) -> f64 {
    let h = (d * d + a * a - b * b) / (2.0 * d);
    (a * a - h * h).max(0.0).sqrt()
}

#[cfg(test)]
mod tests {
    //! [`PairContext::force_lanes`] against [`PairContext::force`], contact by contact:
    //! the same forces, torques and records, bit for bit, for random free particles
    //! (radii and masses equal or not, the step's damping cached for some pairs and not
    //! others, two centres at one place, predicted or not, rolling and twisting on or
    //! off, either sliding rule, new and old records, small and large steps); and the
    //! run's pair loops, four at a time and one at a time. `tests/lanes.rs` holds the law
    //! alone.

    use super::*;
    use crate::contact::ssdem::Sliding;
    use crate::run::Integrator;
    use proptest::prelude::*;
    use walls_geometry::Particle;
    use walls_test_support::exact::{bits, number};

    /// The particles' material: pkdgrav's springs, friction, and rolling and twisting
    /// resistance as given.
    fn material(mu_r: f64, mu_t: f64) -> Material {
        Material {
            eps_n: 0.5,
            eps_t: 0.5,
            k_n: 1000.0,
            k_t: 2.0 / 7.0 * 1000.0,
            mu_s: 0.5,
            mu_r,
            mu_t,
            beta_s: 0.5,
        }
    }

    /// `test` given the pair contacts' context of a run of `states` in `settings` (whose
    /// material is the particles'), with `kicks`, and how they go four at a time; nothing
    /// to test where there are no lanes (off x86-64, or on a processor without
    /// x86-64-v3, where `tests/lanes.rs`'s `the_processor_has_the_lanes` fails instead).
    fn in_context(
        states: &[State],
        settings: &Settings,
        kicks: Kicks,
        test: impl FnOnce(&PairContext, &lanes::Setting) -> Result<(), TestCaseError>,
    ) -> Result<(), TestCaseError> {
        let plan = Plan::everything();
        let optional = OptionalPhysics::new(&[], states, settings);
        let between = PairMaterial::new(settings.material, states);
        let context = PairContext {
            states,
            settings,
            plan: &plan,
            kicks,
            contact: ContactLaw::of(settings, &kicks, &plan, &optional),
            between: &between,
            optional: &optional,
        };
        match context.lanes() {
            Some(setting) => test(&context, &setting),
            None => Ok(()),
        }
    }

    fn vector(size: f64) -> impl Strategy<Value = Vec3> {
        (-size..size, -size..size, -size..size).prop_map(|(x, y, z)| Vec3::new(x, y, z))
    }

    /// A particle of radius about 1 mm near the origin, moving and spinning, with
    /// accelerations; of one size and mass or not.
    fn state(same: bool) -> impl Strategy<Value = State> {
        (
            vector(1e-3),
            vector(0.5),
            vector(100.0),
            vector(10.0),
            vector(1e4),
            prop_oneof![Just(1.0), Just(1.1), 0.8..1.2f64],
        )
            .prop_map(move |(pos, vel, spin, acc, alpha, size)| {
                let size = if same { 1.0 } else { size };
                let radius = 1e-3 * size;
                let mut s = State::from(Particle {
                    mass: 4e-6 * size * size * size,
                    radius,
                    pos,
                    vel,
                    spin,
                    color: 3,
                    index: 0,
                });
                s.acc = acc;
                s.alpha = alpha;
                s
            })
    }

    fn record() -> impl Strategy<Value = Record> {
        (any::<bool>(), vector(1e-4), vector(1e-3), -1e-3..1e-3f64).prop_map(
            |(new, spring, roll, twist)| {
                if new {
                    Record::default()
                } else {
                    Record {
                        spring,
                        normal: Vec3::new(0.3, -0.2, 0.9).normalize(),
                        roll,
                        twist,
                        layer: 0,
                    }
                }
            },
        )
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(500))]

        #[test]
        fn four_pairs_at_a_time_are_each_alone(
            same in any::<bool>(),
            states in prop::collection::vec(state(false), 8),
            equal in prop::collection::vec(state(true), 8),
            records in prop::array::uniform4(record()),
            (mu_r, mu_t) in (prop_oneof![Just(0.0), 0.0..0.5f64], prop_oneof![Just(0.0), 0.0..0.5f64]),
            (clamp, predict) in (any::<bool>(), any::<bool>()),
            (dt, coincide) in (prop_oneof![Just(5e-6), Just(1e-3)], any::<bool>()),
        ) {
            let mut states = if same { equal } else { states };
            if coincide {
                // Two centres at one place: the normal falls back to z.
                states[1].particle.pos = states[0].particle.pos;
            }
            let mut settings = Settings::new(dt, 1.0, material(mu_r, mu_t));
            settings.sliding = if clamp { Sliding::Clamp } else { Sliding::Reset };
            let mut kicks = Kicks::of(Integrator::Pkdgrav);
            if !predict {
                kicks.predict_all = 0.0;
            }
            in_context(&states, &settings, kicks, |context, setting| {
                let ij = [(0, 1), (2, 3), (4, 5), (6, 7)];
                let mut four = records;
                let forces = context.force_lanes(&ij, four.each_mut(), setting);
                for (l, &(i, j)) in ij.iter().enumerate() {
                    let mut alone = records[l];
                    let want = context.force(i, j, &mut alone);
                    prop_assert_eq!(bits(forces[l].force), bits(want.force), "force, lane {}", l);
                    prop_assert_eq!(bits(forces[l].torques.0), bits(want.torques.0), "torque, lane {}", l);
                    prop_assert_eq!(bits(forces[l].torques.1), bits(want.torques.1), "partner, lane {}", l);
                    prop_assert_eq!(bits(four[l].spring), bits(alone.spring), "spring, lane {}", l);
                    prop_assert_eq!(bits(four[l].normal), bits(alone.normal), "normal, lane {}", l);
                    prop_assert_eq!(bits(four[l].roll), bits(alone.roll), "roll, lane {}", l);
                    prop_assert_eq!(number(four[l].twist), number(alone.twist), "twist, lane {}", l);
                }
                Ok(())
            })?;
        }
    }

    /// A run's pair loops, four at a time and one at a time, over `n` touching pairs of
    /// random free particles and one held by a wall: the same records, loads, force
    /// sizes and forces, bit for bit, in the list's order (a tail not a multiple of
    /// four, and groups with the held particle taken one by one).
    fn loops_agree(
        states: Vec<State>,
        pairs: Vec<(u32, u32)>,
        records: Vec<Record>,
    ) -> Result<(), TestCaseError> {
        let settings = Settings::new(5e-6, 1.0, material(0.1, 0.1));
        in_context(
            &states,
            &settings,
            Kicks::of(Integrator::Pkdgrav),
            |context, setting| {
                let n = pairs.len();
                let touching: Vec<u32> = (0..n as u32).collect();
                // Every other contact new, the others in slots in reverse order.
                let slots: Vec<u32> = (0..n as u32).rev().collect();
                let from: Vec<u32> = (0..n)
                    .map(|k| if k % 2 == 0 { NO_CONTACT } else { slots[k] })
                    .collect();
                let record_bits = |r: &Record| {
                    (
                        bits(r.spring),
                        bits(r.normal),
                        bits(r.roll),
                        number(r.twist),
                    )
                };
                // One thread (four at a time asking for memory ahead, one at a time
                // not: the hint changes nothing).
                let one = |lanes: Option<&lanes::Setting>| {
                    let mut records = records.clone();
                    let mut loads: Vec<Load> = states
                        .iter()
                        .map(|s| Load::gravity(s, &Vec3::zeros()))
                        .collect();
                    let list = (touching.as_slice(), pairs.as_slice(), slots.as_slice());
                    let how = (lanes, lanes.is_some());
                    let sum = pair_block(context, how, list, (&mut records, &mut loads));
                    (records, loads, sum)
                };
                let (four, alone) = (one(Some(setting)), one(None));
                for (a, b) in four.0.iter().zip(&alone.0) {
                    prop_assert_eq!(record_bits(a), record_bits(b));
                }
                for (a, b) in four.1.iter().zip(&alone.1) {
                    prop_assert_eq!(
                        (bits(a.force), bits(a.torque)),
                        (bits(b.force), bits(b.torque))
                    );
                }
                prop_assert_eq!(number(four.2), number(alone.2));
                // In parallel, in chunks.
                let chunks = |lanes: Option<&lanes::Setting>| {
                    let mut out = vec![Record::default(); n];
                    let mut forces = vec![PairForce::default(); n];
                    for ((out, forces), (ks, from)) in (out.chunks_mut(PAIR_CHUNK))
                        .zip(forces.chunks_mut(PAIR_CHUNK))
                        .zip(touching.chunks(PAIR_CHUNK).zip(from.chunks(PAIR_CHUNK)))
                    {
                        let list = (pairs.as_slice(), records.as_slice());
                        let how = (lanes, lanes.is_some());
                        pair_chunk(context, how, (ks, from), list, (out, forces));
                    }
                    (out, forces)
                };
                let (four, alone) = (chunks(Some(setting)), chunks(None));
                for (a, b) in four.0.iter().zip(&alone.0) {
                    prop_assert_eq!(record_bits(a), record_bits(b));
                }
                for (a, b) in four.1.iter().zip(&alone.1) {
                    let torques = |f: &PairForce| (bits(f.torques.0), bits(f.torques.1));
                    prop_assert_eq!(
                        (bits(a.force), torques(a), a.free),
                        (bits(b.force), torques(b), b.free)
                    );
                }
                Ok(())
            },
        )
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(20))]

        #[test]
        fn the_pair_loops_four_at_a_time_are_the_loops_one_at_a_time(
            states in prop::collection::vec(state(false), 64),
            pairs in prop::collection::vec((0..64u32, 1..64u32), 600..700),
            records in prop::collection::vec(record(), 700),
        ) {
            let mut states = states;
            // One particle held by a sticky wall.
            states[5].stuck_to = Some(Box::new((0, Vec3::zeros())));
            let pairs: Vec<(u32, u32)> = pairs.into_iter().map(|(i, d)| (i, (i + d) % 64)).collect();
            let records = records[..pairs.len()].to_vec();
            loops_agree(states, pairs, records)?;
        }
    }
}
